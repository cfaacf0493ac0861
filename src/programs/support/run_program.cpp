#include "run_program.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace plate {

std::vector<BadInputCase> read_bad_inputs(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<BadInputCase> cases;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    BadInputCase c;
    std::string status;
    if (!std::getline(fields, c.args, '\t') || !std::getline(fields, status, '\t') || !std::getline(fields, c.names) ||
        status.empty())
      throw std::runtime_error(path + ":" + std::to_string(number) + ": expected args<TAB>status<TAB>text");
    c.status = std::stoi(status);
    cases.push_back(c);
  }
  return cases;
}

Captured run_captured(const std::string& command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen((command + " 2>&1").c_str(), "r"), pclose);
  if (!pipe) throw std::runtime_error("cannot run " + command);
  Captured c;
  std::array<char, 4096> buf;
  size_t got;
  while ((got = std::fread(buf.data(), 1, buf.size(), pipe.get())) > 0) c.output.append(buf.data(), got);
  const int raw = pclose(pipe.release());
  c.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return c;
}

Interrupted interrupt_run(const std::string& program, const std::vector<std::string>& args, const std::string& dir,
                          int delay_ms) {
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string err = dir + "/stderr.txt";
  std::vector<std::string> argv_text = {program};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  for (const char* extra : {"--json", "run.json", "--csv", "run.csv"})
    argv_text.push_back(extra[0] == '-' ? extra : dir + "/" + extra);
  std::vector<char*> argv;
  for (auto& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t child = fork();
  if (child < 0) throw std::runtime_error("fork failed");
  if (child == 0) {
    if (!std::freopen(err.c_str(), "w", stderr)) _exit(126);
    execv(program.c_str(), argv.data());
    _exit(127);
  }
  usleep(delay_ms * 1000);
  kill(child, SIGINT);
  int raw = 0;
  waitpid(child, &raw, 0);
  Interrupted r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream e(err);
  std::stringstream es;
  es << e.rdbuf();
  r.message = es.str();
  for (const auto& entry : std::filesystem::directory_iterator(dir)) r.files_left += entry.path().filename() != "stderr.txt";
  return r;
}

}  // namespace plate
