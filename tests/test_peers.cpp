// The peer of `make bench`, PETSc's SNESVI, must solve the identical discrete problem: its answer,
// judged by our certificate, must match our exact solver's node by node.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "active_set.hpp"
#include "measurements.hpp"
#include "paper_case.hpp"
#include "run_program.hpp"
#include "scratch.hpp"

using namespace plate;

namespace {
// The peer is built only where PETSc is installed (CMakeLists.txt): without it these tests say so.
bool have_peer() { return std::filesystem::exists(BUILD_DIR "/peer_snesvi"); }

Measurements run_peer(int n, const std::string& method) {
  const Scratch scratch("peer");
  const std::string out = scratch.path(method);
  const Captured run = run_captured("'" BUILD_DIR "/peer_snesvi' -n " + std::to_string(n) + " --method " + method +
                                    " --reference '" PLATE_SOURCE_DIR "/reference' --out '" + out + "' 2>&1");
  EXPECT_EQ(run.status, 0) << run.output;
  const Measurements a = read_measurements(out);
  return a;
}
}  // namespace

TEST(Peers, SnesviAndOurExactSolverAgreeOnTheDiscreteSolution) {
  if (!have_peer()) GTEST_SKIP() << "peer_snesvi was not built (PETSc is not installed)";
  const int n = 32;
  Problem p = make_problem(paper_scene(), make_grid(n), SamplingSpec{SamplingKind::Nodes});
  const ExactResult ours = solve_sequenced(p, ExactOptions{});
  ASSERT_TRUE(ours.converged);
  const double scale = ours.w.cwiseAbs().maxCoeff();
  for (const char* method : {"rsls", "ssls"}) {
    const Measurements a = run_peer(n, method);
    ASSERT_EQ(a.nodal.size(), static_cast<size_t>(ours.w.size() / 4)) << method;
    EXPECT_LE(a.v.at("certificate"), 1e-10) << method;
    double diff = 0;
    for (size_t q = 0; q < a.nodal.size(); ++q) diff = std::max(diff, std::abs(a.nodal[q] - ours.w[4 * q]));
    std::printf("  SNESVI %s: %g Newton iterations, certificate %.1e, max nodal difference to ours %.1e\n", method,
                a.v.at("iterations"), a.v.at("certificate"), diff);
    EXPECT_LE(diff, 1e-10 * scale) << method;
  }
}

TEST(Peers, TheSnesviProgramRefusesAnUnknownMethodByName) {
  if (!have_peer()) GTEST_SKIP() << "peer_snesvi was not built (PETSc is not installed)";
  const Captured run = run_captured("'" BUILD_DIR "/peer_snesvi' -n 8 --method newton --out /dev/null 2>&1");
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("--method"), std::string::npos) << run.output;
}
