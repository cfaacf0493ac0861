#include "run_as_measured.hpp"

#include <unistd.h>

#include <climits>
#include <cstdlib>
#include <cstring>

namespace plate {

const std::array<MeasuredSetting, 3> kMeasuredSettings{{
    {"OMP_THREAD_LIMIT", "1"},
    {"OPENBLAS_NUM_THREADS", "1"},
    {"GLIBC_TUNABLES", "glibc.malloc.mmap_max=0:glibc.malloc.trim_threshold=4294967295"},
}};

namespace {
const char* base_name(const char* path) {
  const char* slash = std::strrchr(path, '/');
  return slash ? slash + 1 : path;
}
// OpenMP also takes its team from OMP_NUM_THREADS, and OpenBLAS its threads from GOTO_NUM_THREADS
// or OMP_NUM_THREADS when OPENBLAS_NUM_THREADS is unset: a caller who set one of those chose.
bool caller_chose(const MeasuredSetting& s) {
  if (std::getenv(s.name)) return true;
  if (std::strcmp(s.name, "OMP_THREAD_LIMIT") == 0) return std::getenv("OMP_NUM_THREADS");
  if (std::strcmp(s.name, "OPENBLAS_NUM_THREADS") == 0) return std::getenv("OMP_NUM_THREADS") || std::getenv("GOTO_NUM_THREADS");
  return false;
}
}  // namespace

void run_as_measured(char** argv, const char* exe) {
  // Started through the loader (ld.so build/plate) or under valgrind, exe names that runner, which
  // would take argv[1] for its program: only a program that is the one argv[0] names starts again.
  char target[PATH_MAX];
  if (!argv || !argv[0] || !realpath(exe, target) || std::strcmp(base_name(target), base_name(argv[0])) != 0) return;
  bool added = false;
  for (const MeasuredSetting& s : kMeasuredSettings)
    if (!caller_chose(s)) added = setenv(s.name, s.value, 0) == 0 || added;
  if (added) execv(exe, argv);
}

}  // namespace plate
