// src/openmp_one_thread.cpp: a region that runs on one thread is a plain call on the calling thread;
// any other goes to libgomp. Both halves are asserted, whatever OMP_THREAD_LIMIT the test runs under.
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <pthread.h>

#include <atomic>
#include <stdexcept>
#include <string>

extern "C" void GOMP_parallel(void (*fn)(void*), void* data, unsigned num_threads, unsigned flags);

namespace {
// libgomp's own queries, found at run time as the interposer finds them (the tests do not link
// libgomp themselves: CHOLMOD does).
int omp(const char* name) {
  void* f = dlsym(RTLD_DEFAULT, name);
  if (!f) throw std::runtime_error(std::string("libgomp is not loaded: no ") + name);
  return reinterpret_cast<int (*)()>(f)();
}

struct Seen {
  pthread_t caller{};
  std::atomic<int> calls{0};
  std::atomic<int> on_caller{0};
  std::atomic<int> level{-1};
  std::atomic<int> team{-1};
};

void region(void* data) {
  auto& seen = *static_cast<Seen*>(data);
  seen.calls++;
  if (pthread_equal(pthread_self(), seen.caller)) seen.on_caller++;
  seen.level = omp("omp_get_level");
  seen.team = omp("omp_get_num_threads");
}
}  // namespace

// What CHOLMOD's `if` clauses ask for on small supernodes: no team is formed (level 0), the body
// runs once on the calling thread and sees a team of one, as it would in libgomp's team of one.
TEST(OpenMpOneThread, AOneThreadRegionIsAPlainCallOnTheCallingThread) {
  // CHOLMOD's calls reach it only if the executable links and exports it: the dynamic linker must
  // find this definition, not libgomp's.
  EXPECT_EQ(dlsym(RTLD_DEFAULT, "GOMP_parallel"), reinterpret_cast<void*>(&GOMP_parallel));
  Seen seen;
  seen.caller = pthread_self();
  GOMP_parallel(region, &seen, 1, 0);
  EXPECT_EQ(seen.calls, 1);
  EXPECT_EQ(seen.on_caller, 1);
  EXPECT_EQ(seen.level, 0);
  EXPECT_EQ(seen.team, 1);
}

// Two threads asked for: libgomp forms the team (level 1, two calls) unless the thread limit is one,
// where it too would run one thread, and the call is plain.
TEST(OpenMpOneThread, ARegionOfTwoGoesToLibgompUnlessTheLimitIsOne) {
  Seen seen;
  seen.caller = pthread_self();
  GOMP_parallel(region, &seen, 2, 0);
  if (omp("omp_get_thread_limit") >= 2) {
    EXPECT_EQ(seen.calls, 2);
    EXPECT_EQ(seen.level, 1);
    EXPECT_EQ(seen.team, 2);
  } else {
    EXPECT_EQ(seen.calls, 1);
    EXPECT_EQ(seen.level, 0);
  }
}

namespace {
void inner(void* data) {
  auto& seen = *static_cast<Seen*>(data);
  seen.level = omp("omp_get_level");  // 2 in libgomp's team inside the outer one, 1 as a plain call
}
void outer(void* data) { GOMP_parallel(inner, data, 1, 0); }
}  // namespace

// A region inside another, even inside a team of one thread (which omp_in_parallel() calls not
// parallel), is libgomp's: a plain call there would share the outer team's work shares and barriers.
TEST(OpenMpOneThread, ARegionInsideATeamOfOneGoesToLibgomp) {
  using Parallel = void (*)(void (*)(void*), void*, unsigned, unsigned);
  const auto libgomps = reinterpret_cast<Parallel>(dlsym(RTLD_NEXT, "GOMP_parallel"));
  ASSERT_NE(libgomps, nullptr);
  ASSERT_NE(reinterpret_cast<void*>(libgomps), reinterpret_cast<void*>(&GOMP_parallel));
  Seen seen;
  libgomps(outer, &seen, 1, 0);  // libgomp's own team of one: level 1
  EXPECT_EQ(seen.level, 2);
}
