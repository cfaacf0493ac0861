// The peer of `make bench`, PETSc's SNESVI, must solve the identical discrete problem: its answer,
// judged by our certificate, must match our exact solver's node by node.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <map>

#include "active_set.hpp"
#include "measurements.hpp"
#include "paper_case.hpp"
#include "run_program.hpp"
#include "scratch.hpp"

using namespace plate;

namespace {
// The peer is built only where PETSc is installed (CMakeLists.txt): without it these tests say so.
bool have_peer() { return std::filesystem::exists(BUILD_DIR "/peer_snesvi"); }

Measurements run_peer(int n, const std::string& method, const std::string& start) {
  const Scratch scratch("peer");
  const std::string out = scratch.path(method);
  const Captured run = run_captured("'" BUILD_DIR "/peer_snesvi' -n " + std::to_string(n) + " --method " + method +
                                    " --start " + start +
                                    " --reference '" PLATE_SOURCE_DIR "/reference' --out '" + out + "' 2>&1");
  EXPECT_EQ(run.status, 0) << run.output;
  const Measurements a = read_measurements(out);
  return a;
}

// Each peer configuration the bench reports, against ours: the same nodal values within the
// certificates' tolerance (1e-10 of the largest); and the sequenced peer's finest grid taking far
// fewer Newton steps than the cold one, as a start one grid away from the answer should.
void agree_with_ours(int n, const std::string& start, std::map<std::string, double>& fine_steps) {
  Problem p = make_problem(paper_scene(), make_grid(n), SamplingSpec{SamplingKind::Nodes});
  const ExactResult ours = solve_sequenced(p, ExactOptions{});
  ASSERT_TRUE(ours.converged);
  const double scale = ours.w.cwiseAbs().maxCoeff();
  for (const char* method : {"rsls", "ssls"}) {
    const Measurements a = run_peer(n, method, start);
    ASSERT_EQ(a.nodal.size(), static_cast<size_t>(ours.w.size() / 4)) << method;
    EXPECT_LE(a.v.at("certificate"), 1e-10) << method << " " << start;
    double diff = 0;
    for (size_t q = 0; q < a.nodal.size(); ++q) diff = std::max(diff, std::abs(a.nodal[q] - ours.w[4 * q]));
    std::printf("  SNESVI %s (%s), n = %d: %g Newton iterations (%g on the finest grid), certificate %.1e, max nodal "
                "difference to ours %.1e\n", method, start.c_str(), n, a.v.at("iterations"), a.v.at("fine_iterations"),
                a.v.at("certificate"), diff);
    EXPECT_LE(diff, 1e-10 * scale) << method << " " << start;
    fine_steps[std::string(method) + " " + start] = a.v.at("fine_iterations");
  }
}
}  // namespace

TEST(Peers, SnesviColdAndSequencedAndOurExactSolverAgreeOnTheDiscreteSolution) {
  if (!have_peer()) GTEST_SKIP() << "peer_snesvi was not built (PETSc is not installed)";
  std::map<std::string, double> steps;
  agree_with_ours(64, "sequenced", steps);
  agree_with_ours(64, "cold", steps);
  // rsls: 2 steps on the finest grid instead of 20 here. ssls gains one step at most (8 against 9),
  // which is why the bench reports both starts and takes each peer's faster one.
  EXPECT_LE(steps.at("rsls sequenced"), steps.at("rsls cold") / 4);
}

TEST(Peers, TheSnesviProgramRefusesAnUnknownMethodOrStartByName) {
  if (!have_peer()) GTEST_SKIP() << "peer_snesvi was not built (PETSc is not installed)";
  for (const std::string& args : {std::string("--method newton"), std::string("--start warm")}) {
    const Captured run = run_captured("'" BUILD_DIR "/peer_snesvi' -n 8 " + args + " --out /dev/null 2>&1");
    EXPECT_EQ(run.status, 2) << run.output;
    EXPECT_NE(run.output.find(args.substr(0, args.find(' '))), std::string::npos) << run.output;
  }
}

// make bench runs to n = 512 and make bench-large the grid of 1024 alone (--min-n): the range is
// honoured, the report says which grids it left out and where they are run, and a range with no
// grid in it is refused by name before any solve.
TEST(Bench, RunsOnlyTheGridsOfItsRangeAndRefusesAnEmptyOne) {
  const Scratch scratch("bench_range");
  const std::string out = scratch.path("out"), answer = PLATE_SOURCE_DIR "/results/rim_answer.csv";
  const std::string bench = "'" BUILD_DIR "/bench' --answer '" + answer + "' --paper-numbers '" PLATE_SOURCE_DIR "/reference/paper_numbers.csv'";
  const Captured empty = run_captured(bench + " --min-n 1024 --max-exact 512 --out '" + out + "' 2>&1");
  EXPECT_EQ(empty.status, 2) << empty.output;
  EXPECT_NE(empty.output.find("--min-n"), std::string::npos) << empty.output;
  EXPECT_FALSE(std::filesystem::exists(out));
  const Captured run = run_captured(bench + " --min-n 16 --max-exact 16 --max-rsls 0 --max-ssls 0 --out '" + out + "' 2>&1");
  ASSERT_EQ(run.status, 0) << run.output;
  std::ifstream csv(out + "/speed_vs_error.csv");
  int rows = 0;
  for (std::string line; std::getline(csv, line);)
    if (!line.empty() && line[0] != '#' && line.rfind("solver,", 0) != 0) {
      ++rows;
      EXPECT_EQ(line.substr(line.find(',') + 1, 3), "16,") << line;
    }
  EXPECT_GE(rows, 3);  // baseline, exact and the penalty schemes on n = 16
  std::ifstream md(out + "/speed_vs_error.md");
  const std::string report((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
  EXPECT_NE(report.find("<!--words bench.not_run n=\"1024\" min=\"16\" max=\"16\"-->"), std::string::npos) << report;
}
