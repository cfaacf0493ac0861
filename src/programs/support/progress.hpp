// The stages of a long run on stderr, as it goes. A run shorter than a second prints nothing: what
// it says in its first second is held back, and shown only once the run outlasts that second.
#pragma once
#include <string>
#include <vector>

#include "stopwatch.hpp"

namespace plate {

class Progress {
 public:
  Progress(std::string program, bool quiet) : program_(std::move(program)), quiet_(quiet) {}
  // A stage: always reported (held back during the first second).
  void stage(const std::string& what);
  // A step of an iteration: reported at most once a second, so a long loop cannot flood stderr.
  void step(const std::string& what);
  bool quiet() const { return quiet_; }

 private:
  void print(double at, const std::string& what) const;
  std::string program_;
  bool quiet_;
  Clock::time_point t0_ = Clock::now();
  double last_ = -1;  // when a line was last printed; < 0: none yet
  std::vector<std::pair<double, std::string>> held_;
};

}  // namespace plate
