// Running the `plate` program as a user would, for the bad-input test and for results/hard_cases.md:
// one list of cases, one way to capture a run, one way to interrupt one.
#pragma once
#include <string>
#include <vector>

namespace plate {

struct BadInputCase {
  std::string args;   // as a shell reads them
  int status = 0;     // the exit status expected
  std::string names;  // text the message must contain
};

// tests/bad_input.tsv: args, status, text, tab-separated; '#' lines are comments.
// Throws std::runtime_error naming the file if it cannot be read or a line is malformed.
std::vector<BadInputCase> read_bad_inputs(const std::string& path);

struct Captured {
  int status = -1;     // exit status; -1 if killed by a signal
  std::string output;  // stdout and stderr together
};
Captured run_captured(const std::string& command);

struct Interrupted {
  int status = -1;         // exit status; -1 if killed by the signal itself
  std::string message;     // what it wrote on stderr
  int files_left = 0;      // files it left in `dir` (outputs or temporaries)
};
// Starts `program args... --json dir/run.json --csv dir/run.csv` (dir emptied first), sends SIGINT
// after `delay_ms`, and reports what the interrupted run left behind.
Interrupted interrupt_run(const std::string& program, const std::vector<std::string>& args, const std::string& dir,
                          int delay_ms);

}  // namespace plate
