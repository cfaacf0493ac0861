// The tables in results/ must say the same on any machine, and what this build writes must say what
// the committed files say. Round-off is what differs between machines: here the number of BLAS
// threads (the order of CHOLMOD's sums) and OpenBLAS's kernels, chosen by processor type and forced
// with OPENBLAS_CORETYPE, stand in for other machines. Each fast driver runs with 1 and 2 threads on
// this processor's kernels and with 1 thread on Prescott's (which every x86-64 runs); the three
// outputs and the committed file must agree number by number (table_diff.hpp), never byte for byte.
// This is the fast part of `make check-results`: the drivers that take seconds, the slow ones on
// their coarse grids, compared line by line with the committed rows of the same key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_program.hpp"
#include "scratch.hpp"
#include "table_diff.hpp"

namespace {
namespace fs = std::filesystem;
using plate::Scratch;

// One way of running a driver: its BLAS threads and, if not empty, the OpenBLAS core type.
struct Machine {
  const char* name;
  int threads;
  const char* coretype;  // "": the one the environment gives (this processor's own)
};
const std::vector<Machine> kMachines = {{"1 thread", 1, ""}, {"2 threads", 2, ""}, {"Prescott kernels", 1, "Prescott"}};

// Runs `driver args --out DIR` from the source folder as `m` says.
void run_as(const Machine& m, const std::string& driver, const std::string& args, const fs::path& dir) {
  fs::create_directories(dir);
  const std::string coretype = *m.coretype ? std::string(" OPENBLAS_CORETYPE=") + m.coretype : "";
  const std::string command = "cd '" PLATE_SOURCE_DIR "' && OPENBLAS_NUM_THREADS=" + std::to_string(m.threads) +
                              " OMP_NUM_THREADS=" + std::to_string(m.threads) + coretype + " '" BUILD_DIR "/" + driver +
                              "' " + args + " --out '" + dir.string() + "' 2>&1";
  const plate::Captured c = plate::run_captured(command);
  ASSERT_EQ(c.status, 0) << command << "\n" << c.output;
}

// A file the driver writes, and how it compares with the committed one: whole, or (for a run on
// fewer grids than the committed one) by the rows whose first `key` fields the committed file has.
struct Output {
  std::string name;
  int key = 0;  // 0: whole
};

void expect_agree(const std::string& expected, const std::string& actual, const Output& o, const std::string& what) {
  const plate::TableDiff d = plate::compare_table_files(expected, actual, plate::TablePairing{o.key > 0, o.key});
  EXPECT_TRUE(d.agrees) << what << ": " << o.name << ": " << d.first_difference;
  EXPECT_GT(d.numbers_compared, 0) << what << ": " << o.name << " compared no number";
}

void expect_reproducible(const std::string& driver, const std::string& args, const std::vector<Output>& outputs) {
  const Scratch scratch("reproducible_" + driver);
  std::vector<fs::path> dirs;
  for (const Machine& m : kMachines) {
    dirs.push_back(scratch.dir() / std::to_string(dirs.size()));
    run_as(m, driver, args, dirs.back());
    if (::testing::Test::HasFatalFailure()) return;
  }
  for (const Output& o : outputs) {
    for (size_t i = 1; i < dirs.size(); ++i)
      expect_agree((dirs[0] / o.name).string(), (dirs[i] / o.name).string(), Output{o.name, 0},
                   std::string(kMachines[0].name) + " against " + kMachines[i].name);
    expect_agree(std::string(PLATE_SOURCE_DIR "/results/") + o.name, (dirs[0] / o.name).string(), o,
                 "the committed file against this build");
  }
}
}  // namespace

// n = 16 is the grid where the old step-ratio reading of the factors differed in the 3rd digit.
TEST(Reproducible, ContractionTables) {
  expect_reproducible("contraction", "", {{"contraction.csv"}, {"contraction.md"}, {"linear_history.csv"}});
}

TEST(Reproducible, Fig1Data) {
  expect_reproducible("fig1", "", {{"fig1_points.csv"}, {"fig1_surface.dat"}, {"fig1_contact.dat"}});
}

// The h = 1/4 table whole; the finer grids' rows to h = 1/16 (key: n, sampling, OS, the paper's and
// GLT's counts, scheme).
TEST(Reproducible, IterationTables) {
  expect_reproducible("table", "--fine 16", {{"table.csv"}, {"table.md"}, {"table_fine.csv", 6}});
}

// make all runs the paper's table and the finer grids as two steps (--which): each writes its own
// files only, the same numbers as together, and the finer grids may include the paper's h = 1/4.
TEST(Reproducible, EachIterationTableIsWrittenApart) {
  const Scratch scratch("table_which");
  run_as(kMachines[0], "table", "--which paper", scratch.dir() / "paper");
  run_as(kMachines[0], "table", "--which fine --fine 8", scratch.dir() / "fine");
  run_as(kMachines[0], "table", "--which fine --fine 4", scratch.dir() / "fine4");
  if (::testing::Test::HasFatalFailure()) return;
  EXPECT_FALSE(fs::exists(scratch.dir() / "paper" / "table_fine.csv"));
  EXPECT_FALSE(fs::exists(scratch.dir() / "fine" / "table.csv"));
  expect_agree(std::string(PLATE_SOURCE_DIR "/results/table.csv"), (scratch.dir() / "paper" / "table.csv").string(), {"table.csv"},
               "--which paper");
  expect_agree(std::string(PLATE_SOURCE_DIR "/results/table_fine.csv"), (scratch.dir() / "fine" / "table_fine.csv").string(),
               {"table_fine.csv", 6}, "--which fine");
  // h = 1/4 among the finer grids: its rows are the paper table's, in table_fine.csv.
  std::ifstream in(scratch.dir() / "fine4" / "table_fine.csv");
  int rows_at_4 = 0;
  for (std::string line; std::getline(in, line);) rows_at_4 += line.rfind("4,", 0) == 0;
  EXPECT_GT(rows_at_4, 0);
}

TEST(Reproducible, ContinuumTablesOnTheCoarseGrids) {
  expect_reproducible("continuum", "--coarsest 8 --finest 64", {{"continuum.csv", 2}});
}

// The yardstick: the rim-contact series uses no BLAS, but its least squares and searches still
// sum in an order the compiler chooses.
TEST(Reproducible, RimSeriesTables) {
  expect_reproducible("rim_series", "--finest 64",
                      {{"rim_series.csv"}, {"rim_series.md"}, {"rim_answer.csv"}, {"uniform_load.csv", 1}});
}

// h = 1/4 in both panels (the committed fine panel is h = 1/64, a minute's work); key: n, sampling, R.
TEST(Reproducible, Fig2TablesOnTheCoarseGrids) {
  expect_reproducible("fig2", "--fine 4 --mesh 4,8,16", {{"fig2.csv", 3}, {"fig2_mesh.csv", 3}});
}

// The rule itself, on a committed table: a number moved within one unit of its last digit agrees,
// one moved by more does not, and a changed word does not.
TEST(Reproducible, TheComparisonCatchesANumberChangedBeyondItsLastDigit) {
  std::ifstream in(PLATE_SOURCE_DIR "/results/contraction.csv");
  std::stringstream s;
  s << in.rdbuf();
  const std::string committed = s.str();
  const std::string value = "0.434758795";  // q on h = 1/4, Gauss sampling, eps = 1e-3
  const size_t at = committed.find(value);
  ASSERT_NE(at, std::string::npos);
  auto with = [&](const std::string& v) { return std::string(committed).replace(at, value.size(), v); };
  EXPECT_TRUE(plate::compare_tables(committed, with("0.434758796")).agrees);
  const plate::TableDiff far = plate::compare_tables(committed, with("0.434758798"));
  EXPECT_FALSE(far.agrees);
  EXPECT_NE(far.first_difference.find("0.434758798"), std::string::npos) << far.first_difference;
  EXPECT_FALSE(plate::compare_tables(committed, std::string(committed).replace(committed.find("gauss"), 5, "nodes")).agrees);
  // Digits printed to a different depth compare at the coarser one; a bound holds a value below it.
  EXPECT_TRUE(plate::compare_tables("x,0.0976921,2", "x,0.09769209522,2").agrees);
  EXPECT_FALSE(plate::compare_tables("e,1e-09", "e,1e-08").agrees);  // a tenfold change is not a lost digit
  EXPECT_FALSE(plate::compare_tables("n,16,1", "n,16,0").agrees);     // flags and counts are exact
  EXPECT_FALSE(plate::compare_tables("(5a)", "(6a)").agrees);
  EXPECT_FALSE(plate::compare_tables("x,0.0976921,2", "x,0.09769229522,2").agrees);
  EXPECT_TRUE(plate::compare_tables("e,< 3e-11", "e,2.9e-11").agrees);
  EXPECT_FALSE(plate::compare_tables("e,< 3e-11", "e,5e-11").agrees);
  EXPECT_TRUE(plate::compare_tables("w_0.5_0.125,1", "w_0.5_0.125,1").agrees);
  EXPECT_FALSE(plate::compare_tables("w_0.5_0.125,1", "w_0.5_0.124,1").agrees);  // names compare as text
  EXPECT_FALSE(plate::compare_tables("a\nb\n", "a\n").agrees);
}
