// The settings every figure in results/ was measured under, for a program run by hand.
#pragma once
#include <array>

namespace plate {

struct MeasuredSetting {
  const char* name;
  const char* value;
};
// The Makefile exports the same (tests/test_cli.cpp holds the two to each other).
extern const std::array<MeasuredSetting, 3> kMeasuredSettings;

// kMeasuredSettings: BLAS and OpenMP on one thread, and memory that malloc keeps once freed, as
// every step of the Makefile runs. Run by hand without them, OpenBLAS starts a thread per core and
// CHOLMOD asks OpenMP for four, which on our blocks mostly wait on each other in the kernel (plate
// -n 64 took 0.095 s against 0.080 s, n = 256 1.36 s against 1.19 s), and GLIBC_TUNABLES is read
// only as a program starts. So this sets whichever of them the caller left unset and starts `exe`
// again in place with the same arguments. A setting the caller made is kept, and so are the thread
// counts when the caller set OMP_NUM_THREADS (or GOTO_NUM_THREADS, for OpenBLAS). It returns at
// once when nothing is left to set, when `exe` is not the program argv[0] names (run through the
// loader or under valgrind: set the three yourself there), and when the new start fails.
void run_as_measured(char** argv, const char* exe = "/proc/self/exe");

}  // namespace plate
