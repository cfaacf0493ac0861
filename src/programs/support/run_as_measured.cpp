#include "run_as_measured.hpp"

#include <unistd.h>

#include <cstdlib>

namespace plate {

const std::array<MeasuredSetting, 3> kMeasuredSettings{{
    {"OMP_THREAD_LIMIT", "1"},
    {"OPENBLAS_NUM_THREADS", "1"},
    {"GLIBC_TUNABLES", "glibc.malloc.mmap_max=0:glibc.malloc.trim_threshold=4294967295"},
}};

void run_as_measured(char** argv, const char* exe) {
  bool added = false;
  for (const MeasuredSetting& s : kMeasuredSettings)
    if (!std::getenv(s.name)) added = setenv(s.name, s.value, 0) == 0 || added;
  if (added) execv(exe, argv);
}

}  // namespace plate
