// The tables in results/ must rebuild byte for byte on any machine. Round-off is what differs
// between machines; the number of BLAS threads changes the order of CHOLMOD's sums, and so the
// round-off, on this one. Each driver runs with one and with two threads, and every file it
// writes (its timings aside) must come out the same.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "run_program.hpp"

namespace {
namespace fs = std::filesystem;

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `driver args --out DIR` from the source folder with `threads` BLAS threads.
fs::path run_with_threads(const std::string& driver, const std::string& args, int threads) {
  const fs::path dir = fs::temp_directory_path() / ("plate_threads_" + driver + "_" + std::to_string(threads));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string command = "cd '" PLATE_SOURCE_DIR "' && OPENBLAS_NUM_THREADS=" + std::to_string(threads) +
                              " OMP_NUM_THREADS=" + std::to_string(threads) + " '" BUILD_DIR "/" + driver + "' " + args +
                              " --out '" + dir.string() + "'";
  const plate::Captured c = plate::run_captured(command);
  EXPECT_EQ(c.status, 0) << command << "\n" << c.output;
  return dir;
}

void expect_same_tables(const std::string& driver, const std::string& args) {
  const fs::path one = run_with_threads(driver, args, 1), two = run_with_threads(driver, args, 2);
  int files = 0;
  for (const auto& e : fs::directory_iterator(one)) {
    const std::string name = e.path().filename().string();
    if (name.find("timings") != std::string::npos) continue;
    ++files;
    ASSERT_TRUE(fs::exists(two / name)) << driver << ": " << name << " written with one thread only";
    EXPECT_EQ(read_all(e.path()), read_all(two / name)) << driver << ": " << name << " differs between 1 and 2 BLAS threads";
  }
  EXPECT_GT(files, 0) << driver << " wrote nothing";
}
}  // namespace

// n = 16 is the grid where the old step-ratio reading of the factors differed in the 3rd digit.
TEST(Reproducible, ContractionTableIsTheSameWithOneAndTwoBlasThreads) { expect_same_tables("contraction", ""); }

TEST(Reproducible, IterationTableIsTheSameWithOneAndTwoBlasThreads) { expect_same_tables("table", "--fine 16"); }

TEST(Reproducible, ContinuumTablesAreTheSameWithOneAndTwoBlasThreads) {
  expect_same_tables("continuum", "--coarsest 8 --finest 64");
}

TEST(Reproducible, Fig2TablesAreTheSameWithOneAndTwoBlasThreads) {
  expect_same_tables("fig2", "--fine 16 --steps 3 --mesh 4,8,16");
}
