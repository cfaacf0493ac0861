// The `plate` program as a user meets it: help, a good run, and every kind of bad input, each of
// which must name the offending input and exit nonzero without leaving an output file behind.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

namespace {
struct PlateRun {
  int status;
  std::string output;  // stdout and stderr together
};

PlateRun run_plate(const std::string& args) {
  const std::string cmd = std::string(PLATE_EXE) + " " + args + " 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  std::string out;
  std::array<char, 4096> buf;
  size_t got;
  while ((got = std::fread(buf.data(), 1, buf.size(), pipe.get())) > 0) out.append(buf.data(), got);
  const int raw = pclose(pipe.release());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out};
}

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("plate_cli_test_" + name)).string();
}
}  // namespace

TEST(Cli, HelpExplainsEveryOption) {
  const PlateRun r = run_plate("--help");
  EXPECT_EQ(r.status, 0);
  for (const char* opt : {"--cells", "--lx", "--ly", "--obstacle", "--obstacle-height", "--radius", "--centre", "--load",
                          "--scheme", "--sampling", "--eps", "--eps-start", "--eps-min", "--tol", "--max-iter", "--nu",
                          "--point", "--csv", "--json", "--rate", "--no-globalise", "--no-nested"})
    EXPECT_NE(r.output.find(opt), std::string::npos) << opt;
}

TEST(Cli, PaperCaseRunsAndWritesItsOutputs) {
  const std::string json = temp_path("paper.json"), csv = temp_path("paper.csv");
  std::filesystem::remove(json);
  std::filesystem::remove(csv);
  const PlateRun r = run_plate("-n 4 -R 0.0625 --sampling nodes --point 0.5,0.5 --json " + json + " --csv " + csv);
  ASSERT_EQ(r.status, 0) << r.output;
  std::ifstream j(json);
  std::stringstream js;
  js << j.rdbuf();
  EXPECT_NE(js.str().find("\"converged\": true"), std::string::npos);
  EXPECT_NE(js.str().find("\"w_at_points\""), std::string::npos);
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
  EXPECT_NE(r.output.find("--sampling = nodes"), std::string::npos) << r.output;  // its default, echoed
  std::ifstream j(json);
  std::stringstream js;
  js << j.rdbuf();
  for (const char* key : {"\"converged\": true", "\"certificate\": {\"violation\": 0", "\"residual_ok\": true"})
    EXPECT_NE(js.str().find(key), std::string::npos) << key << "\n" << js.str();
}

struct BadInput {
  const char* args;
  const char* names;  // the message must contain this
};

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, IsRejectedWithAMessageNamingItAndNoOutputFile) {
  const std::string json = temp_path("bad.json");
  std::filesystem::remove(json);
  const PlateRun r = run_plate(std::string(GetParam().args) + " --json " + json);
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find(GetParam().names), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(json));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CliBadInput,
    ::testing::Values(BadInput{"-n 0", "--cells"}, BadInput{"-n -4", "--cells"}, BadInput{"-n 2.5", "--cells"},
                      BadInput{"-n four", "--cells"}, BadInput{"--eps 0", "--eps"}, BadInput{"--eps -1e-3", "--eps"},
                      BadInput{"--eps nan", "--eps"}, BadInput{"--eps inf", "--eps"}, BadInput{"--tol 0", "--tol"},
                      BadInput{"--tol nan", "--tol"}, BadInput{"-R nan", "--obstacle-height"},
                      BadInput{"--lx -1", "--lx"}, BadInput{"--ly 0.3", "ly"}, BadInput{"--radius 0", "--radius"},
                      BadInput{"--centre 0.5", "--centre"}, BadInput{"--scheme newton", "--scheme"},
                      BadInput{"--sampling edges", "--sampling"},
                      BadInput{"--obstacle 0.01", "obstacle must be below zero on the boundary"},
                      BadInput{"--obstacle 'x > 0.5 ? 0.1 : -1'", "obstacle must be below zero on the boundary"},
                      BadInput{"--obstacle '0.1 - (x-0.5)^2 +* 1'", "--obstacle expression"},
                      BadInput{"--obstacle 'z - 1'", "--obstacle expression"},
                      BadInput{"--load 'sin(x'", "--load expression"}, BadInput{"--load 'x / 0'", "load is not finite"},
                      BadInput{"--obstacle '-1 + sqrt(x - 2)'", "obstacle"},
                      BadInput{"--point 2,0.5", "--point"}, BadInput{"--point a,b", "--point"},
                      BadInput{"--max-iter 0", "--max-iter"},
                      BadInput{"--eps-min 1 --eps-start 0.1", "eps-min"},
                      BadInput{"--scheme exact --sampling gauss", "--sampling nodes"},
                      BadInput{"--scheme exact --eps 1e-3", "--eps"}, BadInput{"--scheme exact --tol 1e-20", "tol"},
                      BadInput{"--scheme exact --rate", "--rate"}, BadInput{"--no-globalise", "--no-globalise"}));

TEST(Cli, UnwritableOutputIsAnErrorNamingThePath) {
  const PlateRun r = run_plate("-q --json /nonexistent-dir/summary.json");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("/nonexistent-dir/summary.json"), std::string::npos) << r.output;
}

TEST(Cli, NonConvergenceExitsWithStatus3AndSaysSo) {
  const std::string json = temp_path("capped.json");
  const PlateRun r = run_plate("-q --eps 1e-6 --tol 1e-12 --max-iter 5 --json " + json);
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_NE(r.output.find("did not converge"), std::string::npos) << r.output;
  std::ifstream j(json);
  std::stringstream js;
  js << j.rdbuf();
  EXPECT_NE(js.str().find("\"converged\": false"), std::string::npos);  // outputs say so too
}
