// Wall-clock seconds since a time point: the one clock behind every timing the programs report.
#pragma once
#include <chrono>

namespace plate {
using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
}  // namespace plate
