// The document and the code must not drift. paper/paper.md names code regions and numbers
// equations; these tests fail when a named region is missing from src/, when a numbered equation
// of the paper has no code tagged "Eq. (N)" (unless the document lists it as derivation-only),
// and when code is tagged with an equation the document does not derive.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>
#include <fstream>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <vector>
#include <regex>
#include <set>
#include <sstream>

#include <unistd.h>

#include "published.hpp"
#include "run_program.hpp"
#include "scratch.hpp"
#include "words.hpp"
#include "words_file.hpp"

namespace {
namespace fs = std::filesystem;
const fs::path kRoot = PLATE_SOURCE_DIR;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  EXPECT_TRUE(in) << "cannot read " << p;
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::set<std::string> matches(const std::string& text, const std::regex& re, int group = 1) {
  std::set<std::string> out;
  for (std::sregex_iterator it(text.begin(), text.end(), re), end; it != end; ++it) out.insert((*it)[group]);
  return out;
}

std::string all_sources() {
  std::string s;
  for (const auto& e : fs::recursive_directory_iterator(kRoot / "src"))
    if (e.path().extension() == ".cpp" || e.path().extension() == ".hpp") s += slurp(e.path());
  return s;
}

std::vector<fs::path> sources(const fs::path& dir, bool recursive) {
  std::vector<fs::path> out;
  auto take = [&](const fs::path& p) {
    if (p.extension() == ".cpp" || p.extension() == ".hpp") out.push_back(p);
  };
  if (recursive)
    for (const auto& e : fs::recursive_directory_iterator(dir)) take(e.path());
  else
    for (const auto& e : fs::directory_iterator(dir)) take(e.path());
  return out;
}
}  // namespace

// The layout: src/ holds the mathematics, which starts no process and opens no file; what does
// (FreeFEM, gmsh, `plate` as a child, reference/ and results/) lives in src/programs/.
TEST(Layout, TheMathematicsLaunchesNoProcessAndOpensNoFile) {
  const std::regex io(R"((std::system|popen|fork\(|exec[lv]p?\(|fstream|fopen|<sys/wait.h>|<unistd.h>))");
  int files = 0;
  for (const auto& p : sources(kRoot / "src", false)) {
    ++files;
    std::smatch m;
    const std::string code = slurp(p);
    EXPECT_FALSE(std::regex_search(code, m, io)) << p.filename() << " uses " << m.str();
  }
  EXPECT_GE(files, 40);
}

// The modules of src/ (a header and its .cpp: their path under src/ without the extension) and the
// modules each includes with quotes, found as the compiler finds them: beside the including file,
// then in src/ and src/programs/support/ (a configured header by its .in).
std::map<std::string, std::set<std::string>> include_graph() {
  std::map<std::string, std::set<std::string>> g;
  const fs::path src = kRoot / "src";
  const auto module = [&](const fs::path& p) {
    std::string name = fs::relative(p, src).replace_extension().string();
    if (p.extension() == ".in") name = fs::path(name).replace_extension().string();  // x.hpp.in
    return name;
  };
  const std::regex include(R"re(#include "([^"]+)")re");
  for (const auto& p : sources(src, true)) {
    const std::string from = module(p);
    g[from];
    for (const std::string& header : matches(slurp(p), include))
      for (const fs::path& dir : {p.parent_path(), src, src / "programs" / "support"}) {
        const fs::path found = fs::exists(dir / header) ? dir / header : dir / (header + ".in");
        if (!fs::exists(found)) continue;
        if (const std::string to = module(found); to != from) g[from].insert(to);
        break;
      }
  }
  return g;
}

// A cycle of the graph as "a -> b -> ... -> a", or empty: a depth-first search that meets a module
// still on its path has closed one.
std::string find_cycle(const std::map<std::string, std::set<std::string>>& g) {
  std::map<std::string, int> state;  // 0 unseen, 1 on the path, 2 done
  std::vector<std::string> path;
  std::function<std::string(const std::string&)> visit = [&](const std::string& m) -> std::string {
    state[m] = 1, path.push_back(m);
    if (const auto it = g.find(m); it != g.end())
      for (const std::string& to : it->second) {
        if (state[to] == 1) {
          std::string c;
          for (auto k = std::find(path.begin(), path.end(), to); k != path.end(); ++k) c += *k + " -> ";
          return c + to;
        }
        if (state[to] == 0)
          if (std::string c = visit(to); !c.empty()) return c;
      }
    state[m] = 2, path.pop_back();
    return "";
  };
  for (const auto& [m, _] : g)
    if (state[m] == 0)
      if (std::string c = visit(m); !c.empty()) return c;
  return "";
}

// The layers: no include closes a cycle, and the library (src/) includes nothing of the programs
// (src/programs/ and its support/), which sit above it.
TEST(Layout, TheIncludesFormLayersWithNoCycle) {
  const auto g = include_graph();
  EXPECT_GE(g.size(), 60u);  // the scan found the modules
  EXPECT_EQ(find_cycle(g), "");
  // The search finds a cycle when there is one.
  auto broken = g;
  ASSERT_EQ(broken.at("scene").count("grid"), 1u);
  broken["grid"].insert("scene");
  EXPECT_NE(find_cycle(broken), "");
  for (const auto& [from, to] : g) {
    if (from.rfind("programs/", 0) == 0) continue;
    for (const std::string& t : to) EXPECT_NE(t.rfind("programs/", 0), 0u) << from << " includes " << t;
  }
}

// A scene travels whole (scene.hpp): no function takes the rectangle together with the obstacle or
// the load as separate parameters.
TEST(Layout, NoSignatureCarriesTheRectangleTheObstacleAndTheLoadApart) {
  const std::regex params(R"(\(([^()]*)\))");
  const std::regex rectangle(R"(\bdouble l[xy]\b)"), obstacle(R"(\b(obstacle|phi|Cylinder)\b)"), load(R"(\bload\b)");
  int lists = 0;
  for (const auto& p : sources(kRoot / "src", true)) {
    const std::string code = slurp(p);
    for (std::sregex_iterator it(code.begin(), code.end(), params), end; it != end; ++it, ++lists) {
      const std::string list = (*it)[1];
      const int parts = std::regex_search(list, rectangle) + std::regex_search(list, obstacle) + std::regex_search(list, load);
      EXPECT_LT(parts, 3) << p.filename() << ": (" << list << ")";
    }
  }
  EXPECT_GE(lists, 1000);
  // The scan sees the signature the Scene replaced.
  const std::string old = "Scene field_scene(double lx, double ly, Field obstacle, Field load);";
  std::smatch m;
  ASSERT_TRUE(std::regex_search(old, m, params));
  const std::string list = m[1];
  EXPECT_EQ(std::regex_search(list, rectangle) + std::regex_search(list, obstacle) + std::regex_search(list, load), 3);
}

// No function of src/ or tests/ runs over 100 lines. A function starts at a line in the first
// column that opens a body, and ends at the next line that begins with "}".
TEST(Layout, NoFunctionRunsOverAHundredLines) {
  std::vector<fs::path> files = sources(kRoot / "src", true);
  for (const auto& p : sources(kRoot / "tests", false)) files.push_back(p);
  const std::regex not_a_function(R"(^(namespace|using|template|extern|struct|class|enum|union|#|//|\}))");
  int functions = 0;
  for (const auto& p : files) {
    std::istringstream in(slurp(p));
    std::string line, signature;
    int start = -1, candidate = -1;
    for (int k = 1; std::getline(in, line); ++k) {
      const bool first_column = !line.empty() && !std::isspace(static_cast<unsigned char>(line[0]));
      if (start < 0) {
        if (candidate < 0 && first_column && !std::regex_search(line, not_a_function)) candidate = k, signature = line;
        if (candidate < 0) continue;
        const char last = line.find_last_not_of(" ") == std::string::npos ? ' ' : line[line.find_last_not_of(" ")];
        if (last == ';' || last == '}' || (last == '{' && signature.find('(') == std::string::npos)) candidate = -1;
        else if (last == '{') start = candidate, candidate = -1;
      } else if (line.rfind("}", 0) == 0) {
        ++functions;
        EXPECT_LE(k - start + 1, 100) << p.filename() << ":" << start << " " << signature;
        start = -1;
      }
    }
  }
  EXPECT_GE(functions, 300);  // the scan found the functions
}

TEST(Paper, EveryCodeRegionItNamesExistsInSrc) {
  const std::string doc = slurp(kRoot / "paper/paper.md");
  const std::regex block(R"re(file="([^"]+)" region="([^"]+)")re");
  int count = 0;
  for (std::sregex_iterator it(doc.begin(), doc.end(), block), end; it != end; ++it, ++count) {
    const std::string file = (*it)[1], name = (*it)[2];
    const std::string code = slurp(kRoot / file);
    const auto open = code.find("// @region " + name + "\n"), close = code.find("// @end " + name + "\n");
    EXPECT_NE(open, std::string::npos) << file << " has no region " << name;
    EXPECT_NE(close, std::string::npos) << file << " never closes region " << name;
    if (open != std::string::npos && close != std::string::npos) {
      EXPECT_LT(open, close) << name;
    }
  }
  EXPECT_GE(count, 10) << "the document shows fewer code regions than expected";
}

TEST(Paper, NumberedEquationsAndTaggedCodeMatch) {
  const std::string doc = slurp(kRoot / "paper/paper.md");
  const std::set<std::string> in_doc = matches(doc, std::regex(R"(\\tag\{([0-9]+[a-z]?)\})"));
  const std::set<std::string> in_code = matches(all_sources(), std::regex(R"(Eq\. \(([0-9]+[a-z]?)\))"));
  std::smatch m;
  ASSERT_TRUE(std::regex_search(doc, m, std::regex(R"(derivation-only:([^\n]*))"))) << "no derivation-only line";
  const std::string only_line = m[1];
  const std::set<std::string> derivation_only = matches(only_line, std::regex(R"(\(([0-9]+[a-z]?)\))"));
  // The paper's equations that the document derives.
  for (const char* eq : {"1", "2a", "2b", "3a", "5a", "6", "8", "9", "10"})
    EXPECT_TRUE(in_doc.count(eq)) << "the document does not number equation (" << eq << ")";
  for (const auto& eq : in_doc) {
    if (!derivation_only.count(eq)) {
      EXPECT_TRUE(in_code.count(eq)) << "no code is tagged Eq. (" << eq << ")";
    }
  }
  for (const auto& eq : in_code) EXPECT_TRUE(in_doc.count(eq)) << "code is tagged Eq. (" << eq << ") but the document does not number it";
  for (const auto& eq : derivation_only) EXPECT_FALSE(in_code.count(eq)) << "(" << eq << ") is listed as derivation-only but is tagged in code";
  // The document's own equations (D1, D2, ...): every one the code names is numbered there.
  const std::set<std::string> d_doc = matches(doc, std::regex(R"(\\tag\{(D[0-9]+)\})"));
  const std::set<std::string> d_code = matches(all_sources(), std::regex(R"(\((D[0-9]+)\))"));
  for (const auto& eq : d_code) EXPECT_TRUE(d_doc.count(eq)) << "code names (" << eq << ") but the document does not number it";
}

// A reader meets (D1), (D2), ... in that order, each once: a number out of sequence sends them
// looking backwards for an equation that comes later.
TEST(Paper, TheDocumentsOwnEquationsAreNumberedInTheOrderTheyAppear) {
  const std::string doc = slurp(kRoot / "paper/paper.md");
  const std::regex tag(R"(\\tag\{D([0-9]+)\})");
  int expected = 1;
  for (std::sregex_iterator it(doc.begin(), doc.end(), tag), end; it != end; ++it, ++expected)
    EXPECT_EQ(std::stoi((*it)[1]), expected) << "equation (D" << (*it)[1] << ") appears where (D" << expected << ") should";
  EXPECT_GE(expected, 10) << "fewer of the document's own equations than expected";
}

TEST(Paper, EveryIncludedResultIsMadeByTheMakefile) {
  const std::string doc = slurp(kRoot / "paper/paper.md"), make = slurp(kRoot / "Makefile");
  for (const auto& path : matches(doc, std::regex(R"re(include="(results/[^"]+)")re"))) {
    EXPECT_NE(make.find(path), std::string::npos) << path << " is included but no Makefile rule names it";
  }
}

// The prose of paper/paper.md with what may carry digits taken out: HTML comments, fenced code,
// inline code, {{key}} numbers (filled in from results/ by paper/filters/numbers.lua), include
// blocks, link targets and the reference list (bibliographic data, not results).
std::string prose_of(std::string doc) {
  const auto cut = [&](const std::regex& re, const char* with = " ") { doc = std::regex_replace(doc, re, with); };
  cut(std::regex(R"(<!--[\s\S]*?-->)"));
  cut(std::regex(R"(```[\s\S]*?```)"));
  cut(std::regex(R"(`[^`\n]*`)"));
  cut(std::regex(R"(\{\{[^}]*\}\})"), " KEY ");
  cut(std::regex(R"(::: \{include="[^"]*"\})"));
  cut(std::regex(R"(\]\([^)]*\))"), "]");
  cut(std::regex(R"(\\tag\{[^}]*\})"));
  const auto refs = doc.find("\n# References");
  if (refs != std::string::npos) {
    const auto next = doc.find("\n# ", refs + 1);
    doc.erase(refs, next == std::string::npos ? std::string::npos : next - refs);
  }
  return doc;
}

// A number in the prose is either a {{key}} or one of the paper's own data (reference/
// paper_numbers.csv); a measured number typed by hand drifts from results/ when they are rebuilt.
// Decimals, exponents and percentages are numbers; so are the words that stand for a measured size.
TEST(Paper, EveryNumberInTheProseComesFromResults) {
  const std::string prose = prose_of(slurp(kRoot / "paper/paper.md"));
  const auto around = [&](long at) { return prose.substr(std::max<long>(0, at - 40), 90); };
  std::set<double> data;
  for (const auto& [key, v] : plate::read_paper_numbers(kRoot / "reference/paper_numbers.csv")) data.insert(v);
  const std::regex number(R"((\d+\.\d+|\d(\.\d+)?e[-+]?\d+|\d+\s*%|\bper cent\b))");
  int checked = 0;
  for (std::sregex_iterator it(prose.begin(), prose.end(), number), end; it != end; ++it) {
    ++checked;
    const std::string n = it->str();
    const bool paper_data = n.find_first_of("e%p") == std::string::npos && data.count(std::stod(n));
    EXPECT_TRUE(paper_data) << "\"" << n << "\" in the prose has no source: \"" << around(it->position())
                            << "\"; write it as {{key}} (build/prose_numbers) or say it without a number";
  }
  EXPECT_GT(checked, 0) << "the paper's own data (0.0625, 0.25) should be among the numbers seen";
  const std::regex vague(R"(\b(tens|hundreds|thousands|dozens?|twenty|thirty|forty|fifty|fortieth|several|a few dozen)\b)",
                         std::regex::icase);
  for (std::sregex_iterator it(prose.begin(), prose.end(), vague), end; it != end; ++it)
    ADD_FAILURE() << "\"" << it->str() << "\" stands for a measured size: \"" << around(it->position())
                  << "\"; give the number as {{key}}";
  // Every key the prose names is one that build/prose_numbers writes.
  const std::string doc = slurp(kRoot / "paper/paper.md");
  const std::string written = slurp(kRoot / "results/numbers.csv") + slurp(kRoot / "results/numbers_machine.csv");
  for (const auto& key : matches(doc, std::regex(R"(\{\{([^}]+)\}\})")))
    EXPECT_NE(written.find("\n" + key + ","), std::string::npos) << "{{" << key << "}} is in no results/numbers*.csv";
}

// What a reader's browser shows must not carry Markdown that pandoc did not turn into a table
// (a row cut from its header becomes a "line block" of raw pipes), nor an option whose two
// dashes smart punctuation turned into a dash (a copied "--scheme" would then not run).
TEST(Paper, TheBuiltPageHasNoRawTableRowsOrMangledOptions) {
  const std::string html = slurp(kRoot / "results/paper.html");
  ASSERT_FALSE(html.empty());
  EXPECT_EQ(html.find("class=\"line-block\""), std::string::npos) << "a table row rendered as a line block";
  std::smatch m;
  EXPECT_FALSE(std::regex_search(html, m, std::regex(R"(<p>\s*\|[^<]*\|)"))) << "raw pipe row: " << m.str();
  const std::regex dashed(R"((^|[\s(>"'`])(\xE2\x80\x93|\xE2\x80\x94)[a-z][a-z-]+)");
  EXPECT_FALSE(std::regex_search(html, m, dashed)) << "an option with its dashes made into a dash: " << m.str();
  EXPECT_EQ(html.find("{{"), std::string::npos) << "a {{key}} was left unfilled";
}

// The reports write their symbols in ASCII (eps, lambda_1h, +-) for a terminal; the document sets
// them as mathematics (paper/filters/include.lua). Outside code, none may reach the reader as typed.
TEST(Paper, TheBuiltPageSetsNoMathematicsInAscii) {
  const std::string html = slurp(kRoot / "results/paper.html");
  ASSERT_FALSE(html.empty());
  // The reader's text: tags dropped, and code, MathML, styles and scripts dropped whole (found by
  // hand: std::regex recurses per character and the page is megabytes).
  std::string text;
  for (size_t at = 0; at < html.size();) {
    if (html[at] != '<') {
      text += html[at++];
      continue;
    }
    size_t end = html.find('>', at);
    if (end == std::string::npos) break;
    for (const char* element : {"pre", "code", "math", "style", "script"}) {
      const std::string open = std::string("<") + element;
      if (html.compare(at, open.size(), open) == 0 && (html[at + open.size()] == '>' || html[at + open.size()] == ' ')) {
        const size_t close = html.find(std::string("</") + element + ">", at);
        end = close == std::string::npos ? html.size() - 1 : html.find('>', close);
        break;
      }
    }
    text += ' ';
    at = end + 1;
  }
  std::smatch m;
  const std::regex ascii(R"((^|[\s(])(eps|w_eps|eps\^-1|lambda_1h|lambda_1|m12|phi|C\^1|Lap\^2|\+-|&lt;=|&gt;=)([\s),.;:]|$))");
  EXPECT_FALSE(std::regex_search(text, m, ascii)) << "ASCII mathematics in the page: \"" << m.str() << "\"";
}

TEST(Published, TheTableIsTheOneInThePaper) {
  // Independent of the CSV: the first and last rows and the row count, read off the paper's text.
  const auto t = plate::read_paper_table(kRoot / "reference/paper_table.csv");
  ASSERT_EQ(t.size(), 8u);
  EXPECT_DOUBLE_EQ(t.front().tolerance, 1.3e-4);
  EXPECT_EQ(t.front().iterations, 45);
  EXPECT_EQ(t.back().iterations_glt, 750);
  for (size_t i = 1; i < t.size(); ++i) {
    EXPECT_LT(t[i].tolerance, t[i - 1].tolerance);  // tighter tolerance,
    EXPECT_GT(t[i].iterations, t[i - 1].iterations);  // more iterations
  }
  const auto n = plate::read_paper_numbers(kRoot / "reference/paper_numbers.csv");
  EXPECT_DOUBLE_EQ(plate::published(n, "h") * plate::published(n, "h") * plate::published(n, "cells"), 1.0);
  EXPECT_THROW(plate::published(n, "no such key"), std::runtime_error);
}

// The README quotes the continuum answer; it must be the one results/ holds, with its words put in.
TEST(Readme, QuotesTheContinuumAnswerOfResults) {
  const std::string readme = slurp(kRoot / "README.md"),
                    answer = plate::Words((kRoot / "reports/words.md").string()).render(slurp(kRoot / "results/continuum_answer.md"));
  ASSERT_FALSE(answer.empty());
  EXPECT_NE(readme.find(answer.substr(0, answer.find_last_not_of('\n') + 1)), std::string::npos)
      << "README.md does not contain:\n" << answer;
}

namespace {
// Each <table>...</table> of the built page, in order.
std::vector<std::string> tables_of(const std::string& html) {
  std::vector<std::string> out;
  for (size_t at = html.find("<table"); at != std::string::npos; at = html.find("<table", at + 1))
    out.push_back(html.substr(at, html.find("</table>", at) - at));
  return out;
}
// The number of cells in each <tr> of a table, header row first.
std::vector<size_t> cells_per_row(const std::string& table) {
  std::vector<size_t> out;
  const std::regex row(R"(<tr[^>]*>([\s\S]*?)</tr>)"), cell(R"(<t[hd][ >])");
  for (std::sregex_iterator it(table.begin(), table.end(), row), end; it != end; ++it) {
    const std::string r = (*it)[1];
    out.push_back(std::distance(std::sregex_iterator(r.begin(), r.end(), cell), std::sregex_iterator()));
  }
  return out;
}
}  // namespace

// A table cell that holds a pipe (a header "max |m12|") splits the row in pandoc's Markdown: the
// row then has more or fewer cells than its header, and a reader sees numbers under the wrong names.
TEST(Paper, EveryTableRowHasAsManyCellsAsItsHeader) {
  const std::vector<std::string> tables = tables_of(slurp(kRoot / "results/paper.html"));
  ASSERT_GT(tables.size(), 10u);
  for (size_t t = 0; t < tables.size(); ++t) {
    const std::vector<size_t> cells = cells_per_row(tables[t]);
    ASSERT_GE(cells.size(), 2u) << "table " << t + 1 << " has no body";
    for (size_t r = 1; r < cells.size(); ++r)
      EXPECT_EQ(cells[r], cells[0]) << "table " << t + 1 << ", row " << r << ":\n" << tables[t].substr(0, 400);
  }
}

// Every figure and every table carries a number in its caption (paper/filters/numbering.lua), and
// no number is used twice, so that the prose and a printed page can point at it.
TEST(Paper, EveryFigureAndTableHasANumberedCaption) {
  const std::string html = slurp(kRoot / "results/paper.html");
  std::set<std::string> seen;
  size_t figures = 0;
  for (size_t at = html.find("<figure"); at != std::string::npos; at = html.find("<figure", at + 1), ++figures) {
    const std::string f = html.substr(at, html.find("</figure>", at) - at);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(f, m, std::regex(R"(<figcaption[^>]*>\s*<strong>(Fig\. \d+)\.</strong>)")))
        << "a figure without a numbered caption:\n" << f.substr(0, 300);
    EXPECT_TRUE(seen.insert(m[1]).second) << m[1] << " is used twice";
  }
  EXPECT_GE(figures, 9u);
  for (const std::string& t : tables_of(html)) {
    std::smatch m;
    ASSERT_TRUE(std::regex_search(t, m, std::regex(R"(<caption>\s*(?:<p>)?\s*<strong>(Table (?:[A-D]\.)?\d+)\.</strong>)")))
        << "a table without a numbered caption:\n" << t.substr(0, 300);
    EXPECT_TRUE(seen.insert(m[1]).second) << m[1] << " is used twice";
  }
}

// The first section a reader meets states the answer (the yardstick's max w, as results/ holds it)
// and how to reproduce everything.
TEST(Paper, TheFirstScreenHoldsTheAnswerAndHowToReproduceIt) {
  const std::string html = slurp(kRoot / "results/paper.html");
  const size_t first = html.find("<h1", html.find("</nav>"));
  ASSERT_NE(first, std::string::npos);
  const std::string section = html.substr(first, html.find("<h1", first + 1) - first);
  EXPECT_NE(section.find("id=\"the-answer\""), std::string::npos) << "the first section is not the answer";
  const std::string answer = slurp(kRoot / "results/rim_answer.csv");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(answer, m, std::regex(R"(\nmax_w,([0-9.e+-]+),)"))) << "no max_w in rim_answer.csv";
  EXPECT_NE(section.find(m[1].str()), std::string::npos) << "the answer " << m[1] << " is not on the first screen";
  for (const char* command : {"make all", "make document", "make test"})
    EXPECT_NE(section.find(command), std::string::npos) << command << " is not on the first screen";
}

// The lines between "// @region name" and "// @end name" of a source file, as the document shows them.
std::vector<std::string> region_lines(const fs::path& file, const std::string& name) {
  std::istringstream in(slurp(file));
  std::vector<std::string> out;
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (line.find("// @end " + name) != std::string::npos) break;
    if (inside) out.push_back(line);
    if (line.find("// @region " + name) != std::string::npos) inside = true;
  }
  return out;
}

// The words of a region's first line of code that is not a comment, up to its bracket, as the
// source has it: a signature, not a number, so that neither a rebuild nor a typed copy can match it.
std::string first_code_words(const fs::path& file, const std::string& region) {
  for (const std::string& l : region_lines(file, region))
    if (l.find("//") == std::string::npos && l.size() > 20) return l.substr(0, l.find('('));
  return "";
}

struct Printed {
  int pages = 0;     // as scripts/page_count.sh counts them; 0 if printing failed
  std::string text;  // pdftotext of that print
  std::string error;
};
// Prints the start of results/paper.html as scripts/page_count.sh does (`mode`: "" for the main
// text, "--part-i" for Part I) and reads the PDF's text; the PDF and the text are removed after.
Printed print_document(const std::string& mode) {
  const fs::path pdf = fs::temp_directory_path() / ("paper-print-" + std::to_string(::getpid()) + ".pdf");
  const fs::path text = pdf.string() + ".txt";
  Printed p;
  const std::string command = "cd '" + kRoot.string() + "' && PAGE_COUNT_KEEP='" + pdf.string() +
                              "' scripts/page_count.sh " + mode + " results/paper.html 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  char buffer[512] = {0};
  const std::string out = pipe && fgets(buffer, sizeof buffer, pipe) ? buffer : "";
  if (!pipe || pclose(pipe) != 0) p.error = "scripts/page_count.sh failed: " + out;
  else if (std::system(("pdftotext -raw '" + pdf.string() + "' '" + text.string() + "'").c_str()) != 0) p.error = "pdftotext failed";
  else p.pages = std::atoi(out.c_str()), p.text = slurp(text);
  fs::remove(pdf);
  fs::remove(text);
  return p;
}

// Part I, the paper reproduced, prints on at most ten pages of Chromium's default size, with the
// code of both schemes on the page: a reader of the printed copy must find (3a) and (5a) there.
TEST(Paper, PartIPrintsOnTenPagesWithTheCodeOfBothSchemes) {
  const Printed part = print_document("--part-i");
  ASSERT_TRUE(part.error.empty()) << part.error;
  std::cout << "Part I: " << part.pages << " printed pages\n";
  EXPECT_GE(part.pages, 5);
  EXPECT_LE(part.pages, 10);
  for (const char* scheme : {"nonlinear-scheme", "linear-scheme"}) {
    const std::string words = first_code_words(kRoot / "src/schemes.cpp", scheme);
    ASSERT_FALSE(words.empty()) << "no code line in region " << scheme;
    EXPECT_NE(part.text.find(words), std::string::npos) << "the printed Part I lacks the code of " << scheme << ": " << words;
  }
}

// A listing folded on screen opens when the page is printed (paper/print.html): paper has no click.
// The probe is the edge rows' listing, folded in Part II because it is long.
TEST(Paper, AFoldedListingOpensInPrint) {
  const std::string html = slurp(kRoot / "results/paper.html");
  ASSERT_NE(html.find("<details><summary>The code of the edge rows"), std::string::npos)
      << "the edge rows' listing is not folded on screen, so it proves nothing here";
  const std::string words = first_code_words(kRoot / "src/sampling.cpp", "edge-sampling");
  ASSERT_FALSE(words.empty());
  const Printed main_text = print_document("");
  ASSERT_TRUE(main_text.error.empty()) << main_text.error;
  EXPECT_NE(main_text.text.find(words), std::string::npos) << "the folded listing is not on the printed page: " << words;
}

// Every figure is readable at the size it prints: the smallest font its gnuplot script sets, scaled
// as Chromium scales the drawing to fit the page, is at least 7 pt. A gnuplot SVG has no size of its
// own (a viewBox only), so it fills the column (A4 less Chromium's margins of 0.4 in: 717 CSS px)
// unless the print style's max-height for its image stops it first; an image of class "tall" has
// its own max-height. 1 CSS px is 0.75 pt, and gnuplot's SVG font sizes are in those px.
namespace {
double print_max_height_px(const std::string& css, const std::string& selector) {
  const std::string print = css.substr(css.find("@media print"));
  std::smatch m;
  const std::regex rule(std::regex_replace(selector, std::regex(R"([.])"), R"(\.)") + R"(\s*\{[^}]*max-height:\s*([0-9.]+)cm)");
  if (!std::regex_search(print, m, rule)) return 0;
  return std::stod(m[1]) / 2.54 * 96;
}
}  // namespace

TEST(Paper, EveryFigurePrintsWithFontsOfSevenPointsAtLeast) {
  const std::string css = slurp(kRoot / "paper/style.css");
  const double normal = print_max_height_px(css, "figure img"), tall = print_max_height_px(css, "figure img.tall");
  ASSERT_GT(normal, 0) << "style.css sets no max-height for figure img in print";
  ASSERT_GT(tall, normal) << "style.css sets no larger max-height for figure img.tall in print";
  const double column = 8.27 * 96 - 2 * 0.4 * 96;
  const std::string md = slurp(kRoot / "paper/paper.md");
  const std::regex figure(R"(\]\(results/([a-z0-9_]+)\.svg\)\{([^}]*)\})");
  int checked = 0;
  for (std::sregex_iterator it(md.begin(), md.end(), figure), end; it != end; ++it, ++checked) {
    const std::string name = (*it)[1], attributes = (*it)[2];
    const std::string gp = slurp(kRoot / "paper/figures" / (name + ".gp"));
    std::smatch m;
    ASSERT_TRUE(std::regex_search(gp, m, std::regex(R"(terminal svg size (\d+),(\d+)[^}\n]*font '[^,']*,(\d+)')")))
        << name << ".gp sets no svg size and font";
    const double width = std::stod(m[1]), height = std::stod(m[2]);
    double smallest = std::stod(m[3]);
    // Every other font the script sets: font ',10', font 'Helvetica,10'.
    // (the PNG terminal's fonts are for the screen's pixels, not for print, and are left out).
    const std::string rest = std::regex_replace(gp.substr(m.position(0) + m.length(0)), std::regex(R"(set terminal pngcairo[^}\n]*)"), "");
    for (const std::string& size : matches(rest, std::regex(R"(font '[^,']*,(\d+(?:\.\d+)?)')")))
      smallest = std::min(smallest, std::stod(size));
    const double max_height = attributes.find(".tall") != std::string::npos ? tall : normal;
    const double scale = std::min(column / width, max_height / height);
    const double points = smallest * scale * 0.75;
    EXPECT_GE(points, 7.0) << "Fig. " << name << " prints its smallest font (" << smallest << " px in " << width << " x "
                           << height << ") at " << points << " pt";
  }
  EXPECT_GE(checked, 9);
}

// A figure's alt text is what a reader without the image gets: a plain sentence, not TeX.
TEST(Paper, EveryFigureHasAPlainAltText) {
  const std::string html = slurp(kRoot / "results/paper.html");
  int images = 0;
  // Found by hand: a regex over the whole page (several MB of embedded images) overflows the stack.
  for (size_t at = html.find("<img "); at != std::string::npos; at = html.find("<img ", at + 1)) {
    const std::string tag = html.substr(at, html.find('>', at) - at);
    const size_t a = tag.find(" alt=\"");
    ++images;
    ASSERT_NE(a, std::string::npos) << "an image without alt text: " << tag.substr(0, 120);
    const std::string alt = tag.substr(a + 6, tag.find('"', a + 6) - a - 6);
    EXPECT_EQ(alt.find_first_of("\\$^_{}"), std::string::npos) << "alt text with TeX: " << alt;
    EXPECT_GE(alt.size(), 20u) << "alt text too short to say anything: " << alt;
  }
  EXPECT_GE(images, 9);
}

// The reports' words (reports/words.md, src/programs/support/words.hpp): every marker a report in
// results/ holds has its entry, with the values that entry needs; and every entry is named by a
// program, so that no caption is left behind when the code that wrote it goes.
TEST(Reports, EveryMarkerHasItsWordsAndEveryEntryIsWrittenByAProgram) {
  const plate::Words w((kRoot / "reports/words.md").string());
  int markers = 0;
  for (const auto& e : fs::directory_iterator(kRoot / "results")) {
    if (e.path().extension() != ".md") continue;
    const std::string raw = slurp(e.path());
    markers += static_cast<int>(matches(raw, std::regex(R"(<!--words ([A-Za-z0-9_.\-]+))")).size());
    std::string text;
    EXPECT_NO_THROW(text = w.render(raw)) << e.path();
    EXPECT_EQ(text.find("<!--words"), std::string::npos) << e.path() << ": a marker that does not parse";
  }
  EXPECT_GT(markers, 30);  // the reports do hold markers: the loop above had something to check
  const std::string src = all_sources();
  for (const auto& [key, text] : w.entries())
    EXPECT_NE(src.find("\"" + key + "\""), std::string::npos) << key << " is in reports/words.md, and no program writes it";
}

// Mending a caption is a change to reports/words.md alone: render_report, which the document's
// include filter calls, shows the new words from the report as it stands, and no result depends on
// the words file in the Makefile, so no program reruns.
TEST(Reports, ACaptionIsMendedWithoutRerunningItsProgram) {
  const plate::Scratch scratch("mend_caption");
  std::string words = slurp(kRoot / "reports/words.md");
  const std::string old = "Theorem 2 measured.", mended = "Theorem 2, measured again.";
  ASSERT_NE(words.find(old), std::string::npos);
  words.replace(words.find(old), old.size(), mended);
  std::ofstream(scratch.path("words.md")) << words;
  const fs::path report = kRoot / "results/contraction.md";
  const auto written = fs::last_write_time(report);
  const plate::Captured r = plate::run_captured("'" BUILD_DIR "/render_report' --words '" + scratch.path("words.md") + "' '" +
                                                report.string() + "'");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("Table: " + mended), std::string::npos) << r.output;
  EXPECT_EQ(fs::last_write_time(report), written);
  // In the Makefile the words file is an input of the document only.
  std::istringstream makefile(slurp(kRoot / "Makefile"));
  for (std::string line; std::getline(makefile, line);) {
    if (line.find("reports/words.md") == std::string::npos) continue;
    EXPECT_EQ(line.rfind("PAPER_INPUTS :=", 0), 0u) << "a Makefile rule other than the document's names the words file: " << line;
  }
}
