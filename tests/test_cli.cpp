// The `plate` program as a user meets it: help, a good run, and every kind of bad input, each of
// which must name the offending input and exit nonzero without leaving an output file behind.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <vector>

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
  std::string args;
  int status;         // the exit status expected
  std::string names;  // the message must contain this
};
void PrintTo(const BadInput& c, std::ostream* os) { *os << "plate " << c.args; }

// The cases live in tests/bad_input.tsv, which build/hard_cases also reads to list their messages.
std::vector<BadInput> bad_inputs() {
  std::ifstream in(std::string(PLATE_SOURCE_DIR) + "/tests/bad_input.tsv");
  std::vector<BadInput> cases;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    BadInput c;
    std::string status;
    std::getline(fields, c.args, '\t');
    std::getline(fields, status, '\t');
    std::getline(fields, c.names);
    c.status = std::stoi(status);
    cases.push_back(c);
  }
  return cases;
}

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, ExitsWithItsStatusAndAMessageNamingTheInput) {
  const BadInput& c = GetParam();
  const std::string json = temp_path("bad_" + std::to_string(getpid()) + ".json");  // ctest runs cases in parallel
  std::filesystem::remove(json);
  const bool own_json = c.args.find("--json") == std::string::npos;
  const PlateRun r = run_plate(c.args + (own_json ? " -q --json " + json : " -q"));
  EXPECT_EQ(r.status, c.status) << r.output;
  EXPECT_NE(r.output.find(c.names), std::string::npos) << r.output;
  if (!own_json) return;
  if (c.status == 3) {  // not converged: the outputs are written, and say so
    std::ifstream j(json);
    std::stringstream js;
    js << j.rdbuf();
    EXPECT_NE(js.str().find("\"converged\": false"), std::string::npos) << js.str();
    const std::string csv = temp_path("bad_" + std::to_string(getpid()) + ".csv");
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
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "plate_cli_interrupt";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string json = (dir / "run.json").string(), csv = (dir / "run.csv").string(),
                    err = (dir / "stderr.txt").string();
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (!std::freopen(err.c_str(), "w", stderr)) _exit(126);
    execl(PLATE_EXE, PLATE_EXE, "-n", "256", "-q", "--json", json.c_str(), "--csv", csv.c_str(), (char*)nullptr);
    _exit(127);
  }
  usleep(500 * 1000);  // n = 256 takes over a minute: the signal arrives mid-solve
  kill(child, SIGINT);
  int raw = 0;
  waitpid(child, &raw, 0);
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 128 + SIGINT);
  std::ifstream e(err);
  std::stringstream es;
  es << e.rdbuf();
  EXPECT_NE(es.str().find("interrupted"), std::string::npos) << es.str();
  int left = 0;  // neither output nor a temporary file
  for (const auto& entry : std::filesystem::directory_iterator(dir)) left += entry.path().filename() != "stderr.txt";
  EXPECT_EQ(left, 0);
  std::filesystem::remove_all(dir);
}
