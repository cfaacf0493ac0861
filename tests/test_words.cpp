// The reports' words live in reports/words.md and reach a report through a marker
// (src/programs/support/words.hpp). These tests hold the marker's rules: a value fills its slot, and
// every way a marker and its entry can disagree is an error that names them.
#include <gtest/gtest.h>

#include <fstream>

#include "scratch.hpp"
#include "words.hpp"
#include "words_file.hpp"

using namespace plate;

namespace {
// A words file with the given text, in a scratch folder that goes with the returned object.
struct WordsFile {
  Scratch dir{"words"};
  std::string path;
  explicit WordsFile(const std::string& text) : path(dir.path("words.md")) { std::ofstream(path) << text; }
};

std::string error_of(const Words& w, const std::string& text) {
  try {
    w.render(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Words, AMarkerBecomesItsEntryWithTheValuesInPlace) {
  const WordsFile f("# heading, not an entry\n\n## a.caption\nThe plate at n = @{n},\nread down (@{what}) in $\\lambda_{1h}$.\n\n## a.other\nOther.\n");
  const Words w(f.path);
  const std::string report = "| x |\n\nTable: " + words("a.caption", {{"n", "64"}, {"what", "max w"}}) + "\n" + words("a.other") + "\n";
  EXPECT_EQ(w.render(report), "| x |\n\nTable: The plate at n = 64, read down (max w) in $\\lambda_{1h}$.\nOther.\n");
  EXPECT_EQ(w.render("no marker here\n"), "no marker here\n");
}

// A program that chooses between phrases passes the chosen phrase's marker as a value, so that the
// phrase's words, too, live in the words file.
TEST(Words, AValueThatIsAMarkerIsRenderedInItsPlace) {
  const WordsFile f("## a.answer\nmax w = @{w} (@{how}).\n\n## a.richardson\nRichardson, order @{order}\n\n## a.finest\nthe finest grid\n");
  const Words w(f.path);
  EXPECT_EQ(w.render(words("a.answer", {{"w", "0.0977"}, {"how", words("a.richardson", {{"order", "3.0"}})}})),
            "max w = 0.0977 (Richardson, order 3.0).");
  EXPECT_EQ(w.render(words("a.answer", {{"w", "0.0977"}, {"how", words("a.finest")}})), "max w = 0.0977 (the finest grid).");
  // The inner marker is held to the same rules as any other.
  EXPECT_NE(error_of(w, words("a.answer", {{"w", "1"}, {"how", words("a.richardson")}})).find("@{order}"), std::string::npos);
}

TEST(Words, AMarkerAndItsEntryThatDisagreeAreErrorsNamingThem) {
  const WordsFile f("## a.caption\nThe plate at n = @{n}.\n");
  const Words w(f.path);
  EXPECT_NE(error_of(w, words("a.missing")).find("a.missing"), std::string::npos);
  EXPECT_NE(error_of(w, words("a.caption")).find("@{n}"), std::string::npos);  // a slot no value fills
  EXPECT_NE(error_of(w, words("a.caption", {{"n", "8"}, {"m", "9"}})).find("@{m}"), std::string::npos);  // a value no slot takes
  EXPECT_EQ(error_of(w, words("a.caption", {{"n", "8"}})), "");
}

// A program's message may hold quotes and an option "--edge"; neither may stand in an HTML comment's
// attribute, so they are escaped there and come back as they were.
TEST(Words, AValueWithQuotesDashesOrEntitiesReadsBackAsItWas) {
  const WordsFile f("## k\nSaid: @{v}.\n");
  const Words w(f.path);
  for (const std::string v : {"say \"this\"", "--edge", "a---b -1.5e-05 -", "&amp; is & and &#45;", "-->"}) {
    const std::string marker = words("k", {{"v", v}});
    EXPECT_EQ(marker.find("--", 4), marker.size() - 3) << marker;  // the only "--" is the comment's end
    EXPECT_EQ(w.render(marker), "Said: " + v + ".") << marker;
  }
  // Numbers stay as they are in the marker, for compare_tables.
  EXPECT_EQ(words("k", {{"v", "-1.5e-05"}}), "<!--words k v=\"-1.5e-05\"-->");
}

TEST(Words, AMarkerThatWouldNotReadBackIsRefusedWhenWritten) {
  EXPECT_THROW(words("k", {{"v", "two\nlines"}}), std::invalid_argument);
  EXPECT_THROW(words("k", {{"v", "two\rlines"}}), std::invalid_argument);
  EXPECT_THROW(words("a--key"), std::invalid_argument);
  EXPECT_THROW(words("a-"), std::invalid_argument);
  EXPECT_THROW(words("a key"), std::invalid_argument);
  EXPECT_THROW(words("k", {{"bad-name", "1"}}), std::invalid_argument);
  EXPECT_THROW(words("k", {{"n", "1"}, {"n", "2"}}), std::invalid_argument);
}

// What the pattern does not take must not pass through as an invisible HTML comment, and a value
// given twice must not silently take the last.
TEST(Words, AMarkerWrittenByHandThatDoesNotReadIsAnError) {
  const WordsFile f("## k\nThe plate at n = @{n}.\n");
  const Words w(f.path);
  EXPECT_NE(error_of(w, "<!--words k bad-name=\"1\"-->").find("cannot be read"), std::string::npos);
  EXPECT_NE(error_of(w, "<!--words k  n=\"1\"-->").find("cannot be read"), std::string::npos);
  EXPECT_NE(error_of(w, "<!--words k n=\"1\" n=\"2\"-->").find("twice"), std::string::npos);
}

TEST(Words, AFileWithAnEntryTwiceAnEmptyEntryOrAHeadingInsideIsRefused) {
  const WordsFile twice("## k\nOne.\n## k\nTwo.\n"), empty("## k\n\n## j\nJ.\n"), heading("## k\nOne.\n# Notes\nmore\n");
  EXPECT_THROW(Words{twice.path}, std::invalid_argument);
  EXPECT_THROW(Words{empty.path}, std::invalid_argument);
  EXPECT_THROW(Words{heading.path}, std::invalid_argument);
  EXPECT_THROW(Words{"/nonexistent/words.md"}, std::invalid_argument);
  // A key followed by a carriage return or spaces (a file saved elsewhere) is the same key.
  const WordsFile crlf("## k \r\nOne.\r\n");
  EXPECT_EQ(Words(crlf.path).render(words("k")), "One.");
}
