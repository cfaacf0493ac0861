// The `plate` program as a user meets it: help, a good run, and every kind of bad input, each of
// which must name the offending input and exit nonzero without leaving an output file behind.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "paper_case.hpp"
#include "run_as_measured.hpp"
#include "run_program.hpp"
#include "scratch.hpp"

namespace {
struct PlateRun {
  int status;
  std::string output;  // stdout and stderr together
};

PlateRun run_plate(const std::string& args) {
  const plate::Captured c = plate::run_captured(std::string(PLATE_EXE) + " " + args);
  return {c.status, c.output};
}

// Every file a test here writes goes into one folder, removed when the test's process ends.
std::string temp_path(const std::string& name) {
  static const plate::Scratch scratch("cli");
  return scratch.path(name);
}

// A summary `plate` wrote; an empty object if there is none or it is not JSON (the checks then fail).
nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  return j.is_discarded() ? nlohmann::json::object() : j;
}
}  // namespace

TEST(Cli, HelpExplainsEveryOption) {
  const PlateRun r = run_plate("--help");
  EXPECT_EQ(r.status, 0);
  for (const char* opt : {"--cells", "--lx", "--ly", "--obstacle", "--obstacle-height", "--radius", "--centre", "--load",
                          "--scheme", "--sampling", "--eps", "--eps-start", "--eps-min", "--tol", "--max-iter", "--nu",
                          "--point", "--csv", "--json", "--rate", "--no-globalise", "--no-nested", "--edge", "--line-csv",
                          "semi-analytic"})
    EXPECT_NE(r.output.find(opt), std::string::npos) << opt;
}

TEST(Cli, PaperCaseRunsAndWritesItsOutputs) {
  const std::string json = temp_path("paper.json"), csv = temp_path("paper.csv");
  std::filesystem::remove(json);
  std::filesystem::remove(csv);
  const PlateRun r = run_plate("-n 4 -R 0.0625 --sampling nodes --point 0.5,0.5 --json " + json + " --csv " + csv);
  ASSERT_EQ(r.status, 0) << r.output;
  const auto js = read_json(json);
  EXPECT_EQ(js.value("converged", false), true) << js.dump();
  ASSERT_EQ(js.value("w_at_points", nlohmann::json::array()).size(), 1u) << js.dump();
  EXPECT_NEAR(js["w_at_points"][0]["w"].get<double>(), js["max_w"].get<double>(), 1e-12);  // the centre is the top
  std::ifstream c(csv);
  int lines = 0;
  for (std::string line; std::getline(c, line);) lines += (!line.empty() && line[0] != '#');
  EXPECT_EQ(lines, 1 + 5 * 5);  // header and the 25 nodes of the 4 x 4 grid
}

TEST(Cli, ExactSchemeWritesItsCertificate) {
  const std::string json = temp_path("exact.json");
  std::filesystem::remove(json);
  const PlateRun r = run_plate("-n 16 --scheme exact --json " + json);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("--sampling = edge"), std::string::npos) << r.output;  // the default, echoed
  const auto js = read_json(json);
  EXPECT_EQ(js.value("converged", false), true) << js.dump();
  EXPECT_EQ(js.value("residual_ok", false), true) << js.dump();
  ASSERT_TRUE(js.contains("certificate")) << js.dump();
  for (const char* entry : {"violation", "negative_multiplier", "complementarity", "stationarity"})
    EXPECT_LE(js["certificate"][entry].get<double>(), js["certificate"]["tol"].get<double>()) << entry;
}

// The JSON is read by programs that compare answers far below ten digits (time_to_accuracy measures
// the kink space's max w within 1e-10 of the series), so it carries more than the ten digits the
// summary rounds to for a reader. Rounded as before, the JSON value would equal its own ten-digit
// rounding; a double off the ten-digit grid has digits beyond it.
TEST(Cli, JsonCarriesEveryDigitTheSummaryRounds) {
  const std::string json = temp_path("digits.json");
  std::filesystem::remove(json);
  const PlateRun r = run_plate("-n 16 --json " + json);
  ASSERT_EQ(r.status, 0) << r.output;
  const auto js = read_json(json);
  for (const char* key : {"max_w", "total_contact_force"}) {
    ASSERT_TRUE(js.contains(key) && js[key].is_number()) << js.dump();
    const double v = js[key].get<double>();
    char ten[32];
    std::snprintf(ten, sizeof ten, "%.10g", v);
    EXPECT_NE(v, std::stod(ten)) << key << " = " << ten << ": the JSON holds only ten digits";
    EXPECT_NE(r.output.find(ten), std::string::npos) << key << " = " << ten << " is not in the summary:\n" << r.output;
  }
}

// The line load's header says what the curve is made of. Where the plate lifts off part of the rim
// the rows are splines on the contact arcs and points elsewhere (D28), and the header counts those,
// not the periodic knots, which there are none of; the JSON says the same.
TEST(Cli, LineLoadHeaderCountsTheArcsWhereThePlateLiftsOff) {
  const std::string line = temp_path("liftoff_line.csv");
  const std::string json = temp_path("liftoff.json");
  const PlateRun r = run_plate("-q -n 32 --lx 2 --ly 1 --centre 1,0.5 --line-csv " + line + " --json " + json);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_json(json)["line_force"].value("rows_are", ""), "spline bases on the contact arcs and points off them");
  std::ifstream in(line);
  std::string header;
  std::getline(in, header);
  EXPECT_NE(header.find(" arcs; off them the nearest of "), std::string::npos) << header;
  EXPECT_EQ(header.find(" 0 knots"), std::string::npos) << header;
}

// The semi-analytic scheme answers the paper's scene with the keys the grid schemes use, within the
// exact finite-element solve's own distance on n = 64 (its last increment to n = 128 bounds it there:
// edge sampling converges at an order above 2), and refuses what it does not model by name.
TEST(Cli, SemiAnalyticSchemeAnswersThePapersSceneAndRefusesWhatItDoesNotModel) {
  const std::string json = temp_path("series.json"), line = temp_path("series_line.csv"), fe = temp_path("fe.json");
  const PlateRun r = run_plate("-q --scheme semi-analytic --point 0.5,0.125 --json " + json + " --line-csv " + line);
  ASSERT_EQ(r.status, 0) << r.output;
  const auto js = read_json(json);
  EXPECT_EQ(js.value("converged", false), true) << js.dump();
  std::vector<nlohmann::json> grid;
  for (int n : {64, 128}) {
    ASSERT_EQ(run_plate("-q -n " + std::to_string(n) + " --point 0.5,0.125 --json " + fe).status, 0);
    grid.push_back(read_json(fe));
  }
  for (const char* key : {"max_w", "total_contact_force"}) {
    const double series = js[key].get<double>(), coarse = grid[0][key].get<double>(), fine = grid[1][key].get<double>();
    EXPECT_LT(std::abs(fine - series), std::abs(coarse - fine)) << key << ": the series is not nearer n = 128 than n = 64 is";
    EXPECT_LT(std::abs(js[key + std::string("_bar")].get<double>()), 1e-10 * series) << key;
  }
  EXPECT_NEAR(js["w_at_points"][0]["w"].get<double>(), grid[1]["w_at_points"][0]["w"].get<double>(), 1e-6);
  std::ifstream in(line);
  int rows = 0;
  for (std::string l; std::getline(in, l);) rows += !l.empty() && l[0] != '#';
  EXPECT_EQ(rows, 1 + 720);  // the header and the fixed angles
  for (const auto& [args, names] : std::vector<std::pair<std::string, std::string>>{
           {"-n 8", "--cells"}, {"--sampling gauss", "--sampling"}, {"--eps 1e-6", "--eps"}, {"--load x", "--load"},
           {"--obstacle 'x - 1'", "--obstacle"}, {"--radius 0.6", "radius"}, {"--csv " + temp_path("no.csv"), "--csv"}}) {
    const PlateRun bad = run_plate("-q --scheme semi-analytic " + args);
    EXPECT_EQ(bad.status, 2) << args << ": " << bad.output;
    EXPECT_NE(bad.output.find(names), std::string::npos) << args << ": " << bad.output;
  }
  // Off centre the plate lifts off part of the rim: the series says it does not apply.
  const PlateRun off = run_plate("-q --scheme semi-analytic --centre 0.35,0.6 --json " + json);
  EXPECT_EQ(off.status, 3) << off.output;
  EXPECT_NE(off.output.find("not the whole rim"), std::string::npos) << off.output;
  EXPECT_EQ(read_json(json).value("converged", true), false);
}

using BadInput = plate::BadInputCase;
void PrintTo(const BadInput& c, std::ostream* os) { *os << "plate " << c.args; }

// The cases live in tests/bad_input.tsv, which build/hard_cases also runs for results/hard_cases.md.
std::vector<BadInput> bad_inputs() { return plate::read_bad_inputs(std::string(PLATE_SOURCE_DIR) + "/tests/bad_input.tsv"); }

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, ExitsWithItsStatusAndAMessageNamingTheInput) {
  const BadInput& c = GetParam();
  const std::string json = temp_path("bad.json");
  std::filesystem::remove(json);
  const bool own_json = c.args.find("--json") == std::string::npos;
  const PlateRun r = run_plate(c.args + (own_json ? " -q --json " + json : " -q"));
  EXPECT_EQ(r.status, c.status) << r.output;
  EXPECT_NE(r.output.find(c.names), std::string::npos) << r.output;
  if (!own_json) return;
  if (c.status == 3) {  // not converged: the outputs are written, and say so
    const auto js = read_json(json);
    EXPECT_EQ(js.value("converged", true), false) << js.dump();
    const std::string csv = temp_path("bad.csv");
    ASSERT_EQ(run_plate(c.args + " -q --csv " + csv).status, 3);
    std::ifstream in(csv);
    std::string first;
    std::getline(in, first);
    EXPECT_EQ(first.rfind("# NOT CONVERGED: ", 0), 0u) << first;
    std::filesystem::remove(csv);
  } else {
    EXPECT_FALSE(std::filesystem::exists(json));
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, CliBadInput, ::testing::ValuesIn(bad_inputs()),
                         [](const ::testing::TestParamInfo<BadInput>& info) {
                           std::string name = "line" + std::to_string(info.index) + "_";
                           for (char ch : info.param.args)
                             name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
                           return name;
                         });

TEST(Cli, BadInputListIsReadWhole) {
  // A list that failed to load would pass vacuously: make sure it did not.
  EXPECT_GE(bad_inputs().size(), 50u);
}

TEST(Cli, InterruptedRunLeavesNoFileBehind) {
  const std::string dir = temp_path("interrupt");
  // n = 256 takes over a minute: the signal arrives mid-solve.
  const plate::Interrupted r = plate::interrupt_run(PLATE_EXE, {"-n", "256", "-q"}, dir, 500);
  EXPECT_EQ(r.status, 128 + SIGINT);
  EXPECT_NE(r.message.find("interrupted"), std::string::npos) << r.message;
  EXPECT_EQ(r.files_left, 0);  // neither an output nor a temporary file
  std::filesystem::remove_all(dir);
}

// The defaults answer: a certified exact solution (exit 0) on coarse and fine grids, even and odd,
// for the paper's cylinder and for a smooth obstacle that the plate touches on an area.
TEST(Cli, DefaultsGiveACertifiedAnswer) {
  for (const std::string obstacle : {"", "--obstacle '0.05 - 2*((x-0.5)^2 + (y-0.5)^2)'"})
    for (int n : {2, 3, 4, 7, 16, 64, 128}) {
      const PlateRun r = run_plate("-q -n " + std::to_string(n) + " " + obstacle);
      EXPECT_EQ(r.status, 0) << "n = " << n << " " << obstacle << "\n" << r.output;
    }
}

// Where a run has no error bar, it says why, and the n it suggests does give one: on the paper's
// scene n = 8 is too coarse for the kink functions (D31), so n = 16 has no coarser grid of its own
// space, and 32 has one. A value the same on every grid (a plate pushed down onto a floor peaks at
// 0, at its clamped edge) carries a bar of 0, marked as holding only if the scene fixes the value,
// and is not called swinging.
TEST(Cli, AnAnswerWithoutABarSaysWhyAndAFixedValueIsNotCalledSwinging) {
  const std::string json = temp_path("bars.json");
  std::filesystem::remove(json);
  const PlateRun r16 = run_plate("-n 16 --json " + json);
  ASSERT_EQ(r16.status, 0) << r16.output;
  const auto j16 = read_json(json);
  const std::string note = j16["error_bars"].value("note", "");
  EXPECT_NE(note.find("n = 8 is solved in the plain space"), std::string::npos) << note;
  EXPECT_NE(note.find("use n = 32, 64, ..."), std::string::npos) << note;
  EXPECT_NE(r16.output.find("error bar (continuum): none: " + note), std::string::npos) << r16.output;
  std::filesystem::remove(json);
  const PlateRun r32 = run_plate("-n 32 --json " + json);
  ASSERT_EQ(r32.status, 0) << r32.output;
  EXPECT_EQ(read_json(json)["error_bars"]["grids"].size(), 2u) << r32.output;
  std::filesystem::remove(json);
  const PlateRun odd = run_plate("-n 7 --json " + json);
  ASSERT_EQ(odd.status, 0) << odd.output;
  EXPECT_NE(read_json(json)["error_bars"].value("note", "").find("no coarser grid"), std::string::npos) << odd.output;
  std::filesystem::remove(json);
  const PlateRun down = run_plate("-n 32 --load -2000 --obstacle -0.01 --json " + json);
  ASSERT_EQ(down.status, 0) << down.output;
  const auto jd = read_json(json);
  EXPECT_EQ(jd["max_w"].get<double>(), 0.0) << down.output;
  EXPECT_EQ(jd["error_bars"]["max w"]["basis"], "the same on every grid") << jd.dump();
  EXPECT_EQ(jd["error_bars"]["max w"]["bar"].get<double>(), 0.0) << jd.dump();
  EXPECT_NE(down.output.find("max w = 0 +- 0  (the same value on every grid"), std::string::npos) << down.output;
  EXPECT_NE(jd["error_bars"]["min w"]["basis"], "the same on every grid") << jd.dump();
}

// The plate's own answer keeps above the obstacle, so a dip below it between rows is a distance of
// w_h from that answer. Rows eight to the circle (--edge-rows spline:3,50 at n = 64: the same rows on
// every grid of the sequence) let the plate dip 5e-4 while the grids agree on max w to 4e-8, and max
// w is 1e-4 off: the run must say that the dip exceeds its bars. The default rows dip far less than
// the bars and say nothing.
TEST(Cli, ADipBelowTheObstacleBeyondTheBarsIsAWarning) {
  const std::string json = temp_path("dip.json");
  std::filesystem::remove(json);
  const PlateRun coarse_rows = run_plate("-n 64 --edge-rows spline:3,50 --json " + json);
  ASSERT_EQ(coarse_rows.status, 0) << coarse_rows.output;
  const auto j = read_json(json);
  EXPECT_TRUE(j.value("dip_beyond_w_bars", false)) << j.dump();
  EXPECT_GT(j["dip_below_edge"].get<double>(), j["error_bars"]["max w"]["bar"].get<double>());
  EXPECT_NE(coarse_rows.output.find("WARNING: the dip below the edge exceeds every error bar on w"), std::string::npos) << coarse_rows.output;
  std::filesystem::remove(json);
  const PlateRun fine_rows = run_plate("-n 64 --json " + json);
  ASSERT_EQ(fine_rows.status, 0) << fine_rows.output;
  EXPECT_FALSE(read_json(json).value("dip_beyond_w_bars", true));
  EXPECT_EQ(fine_rows.output.find("WARNING"), std::string::npos) << fine_rows.output;
}

// A cylinder written as an expression, with no --edge, is sampled at nodes alone where it ends:
// the run must say so, and name --edge; given its edge, it says nothing. The paper's cylinder with
// --sampling nodes has its edge, but no rows on it: that is a warning too.
TEST(Cli, AnObstacleThatEndsWhereNoEdgeIsGivenIsAWarning) {
  const std::string json = temp_path("jumps.json"), disk = " --obstacle '(x-0.5)^2+(y-0.5)^2 < 0.04 ? 0.05 : -inf'";
  std::filesystem::remove(json);
  const PlateRun bare = run_plate("-n 32" + disk + " --json " + json);
  ASSERT_EQ(bare.status, 0) << bare.output;
  const auto j = read_json(json);
  EXPECT_GT(j.value("obstacle_jumps_without_edge", 0), 0) << j.dump();
  ASSERT_TRUE(j["first_jump_at"].is_array()) << j.dump();
  EXPECT_NEAR(std::hypot(j["first_jump_at"][0].get<double>() - 0.5, j["first_jump_at"][1].get<double>() - 0.5), 0.2, 1e-9);
  EXPECT_NE(bare.output.find("WARNING: the obstacle ends"), std::string::npos) << bare.output;
  EXPECT_NE(bare.output.find("--edge"), std::string::npos) << bare.output;
  std::filesystem::remove(json);
  const PlateRun edged = run_plate("-n 32" + disk + " --edge circle:0.5,0.5,0.2 --json " + json);
  ASSERT_EQ(edged.status, 0) << edged.output;
  EXPECT_EQ(read_json(json).value("obstacle_jumps_without_edge", -1), 0);
  EXPECT_EQ(edged.output.find("WARNING"), std::string::npos) << edged.output;
  std::filesystem::remove(json);
  const PlateRun nodes = run_plate("-n 32 --sampling nodes --json " + json);
  ASSERT_EQ(nodes.status, 0) << nodes.output;
  EXPECT_GT(read_json(json).value("obstacle_jumps_without_edge", 0), 0) << nodes.output;
}

// Outputs are written whole (a temporary file renamed over the path), so a path that is not a
// regular file or a new one is refused by name before any solve: a symbolic link (the rename would
// replace it), a device, a FIFO. An existing file keeps its permissions when it is replaced.
TEST(Cli, OutputsAreRegularFilesAndKeepTheirPermissions) {
  namespace fs = std::filesystem;
  const fs::path target = temp_path("link_target.json"), link = temp_path("link.json"), fifo = temp_path("fifo.csv");
  for (const auto& p : {target, link, fifo}) fs::remove(p);
  { std::ofstream(target) << "old"; }
  fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write);
  fs::create_symlink(target, link);
  const PlateRun through_link = run_plate("-q -n 4 --json " + link.string());
  EXPECT_EQ(through_link.status, 2);
  EXPECT_NE(through_link.output.find("--json '" + link.string() + "': a symbolic link"), std::string::npos) << through_link.output;
  std::ifstream untouched(target);
  std::string old;
  untouched >> old;
  EXPECT_EQ(old, "old");
  ASSERT_EQ(run_plate("-q -n 4 --json " + target.string()).status, 0);
  EXPECT_EQ(read_json(target.string()).value("converged", false), true);
  EXPECT_EQ(fs::status(target).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
  const PlateRun device = run_plate("-q -n 4 --csv /dev/null");
  EXPECT_EQ(device.status, 2);
  EXPECT_NE(device.output.find("--csv '/dev/null': a device"), std::string::npos) << device.output;
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const PlateRun to_fifo = run_plate("-q -n 4 --line-csv " + fifo.string());
  EXPECT_EQ(to_fifo.status, 2) << to_fifo.output;
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
  for (const auto& p : {target, link, fifo}) fs::remove(p);
}

namespace {
// max w and the total force from a run's JSON (the run's exit status as well).
struct Answer {
  int status;
  double max_w, force;
};
Answer answer_of(const std::string& args) {
  const std::string json = temp_path("scale_" + std::to_string(getpid()) + ".json");
  std::filesystem::remove(json);
  const PlateRun r = run_plate("-q " + args + " --json " + json);
  const auto js = read_json(json);
  auto number = [&](const char* key) { return js.contains(key) && js[key].is_number() ? js[key].get<double>() : NAN; };
  return {r.status, number("max_w"), number("total_contact_force")};
}
}  // namespace

// The series stated in other units: in micrometres its changes in double once stopped shrinking at
// round-off, and it refused a right answer as "not settled" (exit 3); at 1e20 too.
TEST(Cli, SemiAnalyticSchemeAnswersInOtherUnits) {
  const Answer unit = answer_of("--scheme semi-analytic");
  ASSERT_EQ(unit.status, 0);
  for (const double L : {1e-6, 1e-3, 1e20}) {
    char args[256];
    std::snprintf(args, sizeof args, "--scheme semi-analytic --lx %.17g --ly %.17g --radius %.17g --centre %.17g,%.17g -R %.17g", L, L,
                  0.25 * L, 0.5 * L, 0.5 * L, 0.0625 * L);
    const Answer a = answer_of(args);
    EXPECT_EQ(a.status, 0) << args;
    EXPECT_NEAR(a.max_w / L, unit.max_w, 1e-12 * unit.max_w) << args;
    EXPECT_NEAR(a.force * L, unit.force, 1e-10 * unit.force) << args;
  }
}

// The same problem stated in millimetres, or with a 6250 times lower obstacle, must give the
// answer scaled exactly: w by the length (or the height), the total force by length^-2 (or the
// height). Tolerances and eps that were absolute would stop somewhere else.
TEST(Cli, AnswerScalesWithUnitsAndHeightForEveryScheme) {
  for (const std::string scheme : {"exact", "nonlinear", "linear"}) {
    const std::string base = "-n 8 --scheme " + scheme + (scheme == "exact" ? "" : " --sampling gauss");
    const Answer unit = answer_of(base);
    const Answer mm = answer_of(base + " --lx 1000 --ly 1000 --radius 250 --centre 500,500 -R 62.5");
    const Answer low = answer_of(base + " -R 1e-5");
    // Far down the normal range, where a floor of 1e-300 in a scale, or a tolerance that underflows,
    // would refuse or pass what it should not.
    const Answer tiny = answer_of(base + " -R 1e-300");
    SCOPED_TRACE(scheme);
    EXPECT_EQ(mm.status, unit.status);
    EXPECT_EQ(low.status, unit.status);
    EXPECT_EQ(tiny.status, unit.status);
    EXPECT_NEAR(tiny.max_w / unit.max_w / (1e-300 / 0.0625), 1.0, 1e-9);
    // A penalty force is eps^-1 (phi - S w): the rounding of phi, amplified by phi / (phi - S w), about
    // 1e8 at eps = 1e-12, gives it a relative floor near 1e-8. The exact solver has no such loss: 1e-9
    // leaves room for the round-off of two solves at different scales.
    const double force_tol = scheme == "exact" ? 1e-9 : 1e-7;
    EXPECT_NEAR(mm.max_w / unit.max_w / 1000.0, 1.0, 1e-9);
    EXPECT_NEAR(mm.force / unit.force / 1e-3, 1.0, force_tol);
    EXPECT_NEAR(low.max_w / unit.max_w / (1e-5 / 0.0625), 1.0, 1e-9);
    EXPECT_NEAR(low.force / unit.force / (1e-5 / 0.0625), 1.0, force_tol);
  }
}

// `plate` runs from anywhere, so its defaults are baked in at build time from the one source of
// the paper's numbers, reference/paper_numbers.csv; this reads that file now and holds them to it.
TEST(Cli, DefaultsAreThePapersProblem) {
  const std::string json = temp_path("defaults_" + std::to_string(getpid()) + ".json");
  ASSERT_EQ(run_plate("-q --json " + json).status, 0);
  const auto config = read_json(json).value("config", nlohmann::json::object());
  const auto numbers = plate::read_paper_numbers(std::string(PLATE_SOURCE_DIR) + "/reference/paper_numbers.csv");
  ASSERT_TRUE(config.contains("--obstacle-height")) << config.dump();
  EXPECT_EQ(std::stod(config["--obstacle-height"].get<std::string>()), plate::published(numbers, "obstacle_height"));
  EXPECT_EQ(std::stod(config["--radius"].get<std::string>()), plate::published(numbers, "obstacle_radius"));
  const std::string centre = config["--centre"].get<std::string>();
  EXPECT_EQ(std::stod(centre.substr(0, centre.find(','))), plate::published(numbers, "obstacle_cx"));
  EXPECT_EQ(std::stod(centre.substr(centre.find(',') + 1)), plate::published(numbers, "obstacle_cy"));
  EXPECT_EQ(std::stoi(config["--cells"].get<std::string>()), std::lround(1 / plate::published(numbers, "h")));
  EXPECT_EQ(config["--load"].get<std::string>(), "0");
  std::filesystem::remove(json);
}

// The paper's table, run by a user: on its grid and with each of its tolerances OS, the linear
// scheme's step rule is met while the error bound (D26) is not, so `plate` must say "not converged"
// (status 3); the nonlinear scheme at the same settings must be certified (status 0).
TEST(Cli, ThePapersLinearRunsAreRefusedAndItsNonlinearRunsCertified) {
  const auto rows = plate::read_paper_table(std::string(PLATE_SOURCE_DIR) + "/reference/paper_table.csv");
  ASSERT_FALSE(rows.empty());
  for (const auto& row : rows)
    for (const char* sampling : {"gauss", "nodes"}) {
      // plate's --tol is relative to the size of the answer, the obstacle's height here.
      std::ostringstream tol;
      tol.precision(17);
      tol << row.tolerance / plate::paper_scene().cylinder->height;
      const std::string args = "-q -n 4 --sampling " + std::string(sampling) + " --tol " + tol.str();
      const PlateRun linear = run_plate(args + " --scheme linear");
      EXPECT_EQ(linear.status, 3) << args;
      // Refused for the reason the document gives: the steps met the rule, the bound did not.
      EXPECT_NE(linear.output.find("only bounds the error by"), std::string::npos) << args << "\n" << linear.output;
      EXPECT_EQ(run_plate(args + " --scheme nonlinear").status, 0) << args;
    }
}

// Where the plate dips deepest, and between which rows: on the 2 x 1 lift-off scene (h = 1/32) the
// default rows let it dip on a spline arc, at an angle where w_h, asked for as a --point of a second
// run, lies below the rim by the dip, and at most half the arc's length inside it (the arcs lie
// about pi/2 and 3 pi/2 and are shorter than pi / 2); rows at points let it dip among points, with
// no arc to be inside. The summary names the same rows as the JSON.
TEST(Cli, TheDeepestDipNamesTheRowsThatLetThePlateDip) {
  const std::string json = temp_path("dip_rows.json");
  const std::string scene = "--lx 2 --ly 1 --centre 1,0.5 -n 64 ";
  std::filesystem::remove(json);
  const PlateRun def = run_plate(scene + "--json " + json);
  ASSERT_EQ(def.status, 0) << def.output;
  const auto j = read_json(json);
  ASSERT_TRUE(j.contains("dip_below_edge_theta") && j.contains("dip_below_edge_cells_inside_arc")) << j.dump();
  EXPECT_EQ(j["dip_below_edge_rows"], "on a spline arc") << j.dump();
  const double cells = j["dip_below_edge_cells_inside_arc"].get<double>(), cell = (2.0 / 64) / 0.25;
  EXPECT_GE(cells, 0.0) << j.dump();
  EXPECT_LE(cells, 0.5 * (M_PI / 2) / cell) << j.dump();
  EXPECT_NE(def.output.find("deepest at theta = "), std::string::npos) << def.output;
  EXPECT_NE(def.output.find(", on a spline arc "), std::string::npos) << def.output;
  const double theta = j["dip_below_edge_theta"].get<double>(), dip = j["dip_below_edge"].get<double>();
  ASSERT_GT(dip, 0);
  char point[80];
  std::snprintf(point, sizeof point, "%.17g,%.17g", 1 + 0.25 * std::cos(theta), 0.5 + 0.25 * std::sin(theta));
  std::filesystem::remove(json);
  const PlateRun at = run_plate(scene + "--point " + point + " --json " + json);
  ASSERT_EQ(at.status, 0) << at.output;
  EXPECT_NEAR(0.0625 - read_json(json)["w_at_points"][0]["w"].get<double>(), dip, 1e-14) << at.output;
  std::filesystem::remove(json);
  const PlateRun points = run_plate(scene + "--edge-rows points --json " + json);
  ASSERT_EQ(points.status, 0) << points.output;
  const auto jp = read_json(json);
  ASSERT_TRUE(jp.contains("dip_below_edge_rows")) << jp.dump();
  EXPECT_EQ(jp["dip_below_edge_rows"], "off the spline arcs, among point rows") << jp.dump();
  EXPECT_FALSE(jp.contains("dip_below_edge_cells_inside_arc")) << jp.dump();
  EXPECT_NE(points.output.find(", off the spline arcs, among point rows"), std::string::npos) << points.output;
  std::filesystem::remove(json);
}

namespace {
// Runs run_as_measured in a child whose environment lacks the settings and OMP_NUM_THREADS but for
// `preset` (each set to "7"), with /usr/bin/env (its output sent to `out`) as the program started
// again under the name `name`. Returns what that program printed and the child's exit status: 0
// when env ran, 3 when run_as_measured returned.
std::pair<std::string, int> run_as_measured_in_child(const std::string& out, std::vector<const char*> preset, const char* name = "env") {
  const pid_t pid = fork();
  if (pid < 0) {
    ADD_FAILURE() << "fork failed";
    return {"", -1};
  }
  if (pid == 0) {
    for (const plate::MeasuredSetting& s : plate::kMeasuredSettings) unsetenv(s.name);
    unsetenv("OMP_NUM_THREADS"), unsetenv("GOTO_NUM_THREADS");
    for (const char* p : preset) setenv(p, "7", 1);
    if (!std::freopen(out.c_str(), "w", stdout)) _exit(4);
    char* argv[] = {const_cast<char*>(name), nullptr};
    plate::run_as_measured(argv, "/usr/bin/env");
    _exit(3);  // run_as_measured returned
  }
  int status = 0;
  EXPECT_EQ(waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(WIFEXITED(status));
  std::ifstream in(out);
  return {"\n" + std::string(std::istreambuf_iterator<char>(in), {}), WEXITSTATUS(status)};  // each line then starts after a newline
}
bool has(const std::string& env, const std::string& line) { return env.find("\n" + line + "\n") != std::string::npos; }
}  // namespace

// A program run by hand runs as the Makefile runs it: each setting the caller left unset is made,
// one the caller made is kept, and a thread count chosen through OMP_NUM_THREADS keeps both.
TEST(RunAsMeasured, SetsWhatTheCallerLeftUnsetAndKeepsTheCallersChoices) {
  plate::Scratch dir("measured");
  const auto [fresh, fresh_status] = run_as_measured_in_child(dir.path("fresh"), {});
  EXPECT_EQ(fresh_status, 0);
  for (const plate::MeasuredSetting& s : plate::kMeasuredSettings) EXPECT_TRUE(has(fresh, std::string(s.name) + "=" + s.value)) << s.name << " in\n" << fresh;
  const auto [kept, kept_status] = run_as_measured_in_child(dir.path("kept"), {"OPENBLAS_NUM_THREADS"});
  EXPECT_EQ(kept_status, 0);
  EXPECT_TRUE(has(kept, "OPENBLAS_NUM_THREADS=7")) << kept;
  EXPECT_TRUE(has(kept, "OMP_THREAD_LIMIT=1")) << kept;
  const auto [omp, omp_status] = run_as_measured_in_child(dir.path("omp"), {"OMP_NUM_THREADS"});
  EXPECT_EQ(omp_status, 0);
  EXPECT_EQ(omp.find("\nOMP_THREAD_LIMIT="), std::string::npos) << omp;
  EXPECT_EQ(omp.find("\nOPENBLAS_NUM_THREADS="), std::string::npos) << omp;
  EXPECT_TRUE(has(omp, std::string("GLIBC_TUNABLES=") + plate::kMeasuredSettings[2].value)) << omp;
}

// Nothing is started again when nothing is left to set (so it cannot loop), nor when the running
// executable is not the program argv[0] names (plate run through the loader or valgrind).
TEST(RunAsMeasured, ReturnsWhenAllIsSetOrTheExecutableIsAnother) {
  plate::Scratch dir("measured");
  EXPECT_EQ(run_as_measured_in_child(dir.path("all"), {"OMP_THREAD_LIMIT", "OPENBLAS_NUM_THREADS", "GLIBC_TUNABLES"}).second, 3);
  EXPECT_EQ(run_as_measured_in_child(dir.path("other"), {}, "plate").second, 3);
}

// The Makefile exports the same values for every step, so results/ and a run by hand agree.
TEST(RunAsMeasured, TheMakefileExportsTheSameSettings) {
  std::ifstream in(std::string(PLATE_SOURCE_DIR) + "/Makefile");
  const std::string makefile(std::istreambuf_iterator<char>(in), {});
  for (const plate::MeasuredSetting& s : plate::kMeasuredSettings)
    EXPECT_NE(makefile.find(std::string("\nexport ") + s.name + " ?= " + s.value + "\n"), std::string::npos) << s.name;
}
