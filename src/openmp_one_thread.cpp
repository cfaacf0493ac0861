// CHOLMOD's supernodal factorisation opens an OpenMP region for every supernode, most of them with
// an `if` clause that asks for one thread. libgomp still builds a team of one for each and wakes its
// barrier with a futex call when the region ends: about a million system calls for the rim series,
// 2 s of system time (issue 44). A region that will run on one thread is run here as a plain call,
// which is what a team of one does (omp_get_thread_num() = 0, omp_get_num_threads() = 1; loops and
// barriers inside an orphaned region run on the calling thread). Only a region opened outside every
// other is run so: inside a team, even one of one thread, libgomp keeps the outer team's state apart
// from the inner one's, and a plain call would not. Every other region goes to libgomp unchanged, so
// OMP_NUM_THREADS and OMP_THREAD_LIMIT keep their meaning (but for a list such as OMP_NUM_THREADS=1,4,
// whose second entry a plain call leaves unused: CHOLMOD opens no region inside another).
//
// This definition in the executable takes the place of libgomp's for the shared libraries it loads
// (ELF symbol interposition; CMakeLists.txt has every program link it); libgomp's own is found
// with dlsym(RTLD_NEXT).
#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>

namespace {
using Region = void (*)(void*);
using Parallel = void (*)(Region, void*, unsigned, unsigned);
using Count = int (*)();

template <class F>
F libgomp(const char* name, void* where) {
  void* f = dlsym(where, name);
  if (!f) {
    std::fprintf(stderr, "openmp_one_thread: libgomp's %s is not loaded\n", name);
    std::abort();
  }
  return reinterpret_cast<F>(f);
}
}  // namespace

extern "C" void GOMP_parallel(Region fn, void* data, unsigned num_threads, unsigned flags) {
  static const Parallel real = libgomp<Parallel>("GOMP_parallel", RTLD_NEXT);
  static const Count thread_limit = libgomp<Count>("omp_get_thread_limit", RTLD_DEFAULT);
  static const Count max_threads = libgomp<Count>("omp_get_max_threads", RTLD_DEFAULT);
  static const Count level = libgomp<Count>("omp_get_level", RTLD_DEFAULT);
  // num_threads is 1 when the region's `if` clause is false; 0 means "as many as the runtime gives".
  const bool one = num_threads == 1 || thread_limit() == 1 || (num_threads == 0 && max_threads() == 1);
  if (one && level() == 0) {
    fn(data);
    return;
  }
  real(fn, data, num_threads, flags);
}
