#include "progress.hpp"

#include <cstdio>

namespace plate {

void Progress::print(double at, const std::string& what) const {
  std::fprintf(stderr, "%s: %7.1f s  %s\n", program_.c_str(), at, what.c_str());
}

void Progress::stage(const std::string& what) {
  if (quiet_) return;
  const double now = seconds_since(t0_);
  if (now < 1.0) {
    held_.emplace_back(now, what);
    return;
  }
  for (const auto& [at, w] : held_) print(at, w);
  held_.clear();
  print(now, what);
  last_ = now;
}

void Progress::step(const std::string& what) {
  if (quiet_) return;
  const double now = seconds_since(t0_);
  if (now < 1.0 || now - last_ < 1.0) return;
  stage(what);
}

}  // namespace plate
