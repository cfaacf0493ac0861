// The FreeFEM penalty script (reference/penalty_hct.edp) checked against what it must reproduce
// without being told: the exact script's answer as eps -> 0 at the rate the penalty derivation gives,
// its two schemes agreeing at a fixed eps, the first eigenvalue of the clamped square
// (Bjorstad & Tjostheim) and the linear scheme's contraction 1/(1 + eps lambda_1h) (Theorem 2). Also
// that it refuses bad arguments and says so when it does not converge or a solve fails. The meshes
// are the coarsest two of the cross-check: a few seconds each.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "freefem.hpp"
#include "msh.hpp"
#include "paper_case.hpp"
#include "published.hpp"
#include "run_program.hpp"
#include "scratch.hpp"

using namespace plate;

namespace {
const std::string kRef = std::string(PLATE_SOURCE_DIR) + "/reference";
const std::string kPenalty = kRef + "/penalty_hct.edp";
const std::string kExact = kRef + "/contact_hct.edp";

// The scratch folder of this test's process (ctest runs each test in a process of its own).
const Scratch& scratch() {
  static const Scratch s("penalty_freefem");
  return s;
}

// The paper's square meshed at level n (4 n cells per quarter circle), and the check points file.
std::string mesh(int n) {
  const std::string msh = scratch().path("square" + std::to_string(n) + ".msh");
  if (!std::filesystem::exists(msh)) gmsh_mesh(kRef + "/square_with_circle.geo", circle_numbers(paper_scene(), n), msh);
  return msh;
}
std::string points() {
  const std::string pts = scratch().path("points.txt");
  if (!std::filesystem::exists(pts)) write_points(pts, {{0.5, 0.25}, {0.25, 0.25}});
  return pts;
}

int runs = 0;
PenaltyRun penalty(int n, const std::string& args) {
  const std::string out = scratch().path("run" + std::to_string(++runs) + ".json");
  return penalty_values(run_freefem(kPenalty, mesh(n), scene_args(paper_scene(), points()) + " " + args, out));
}

// The script run as a user would, its exit status and what it printed.
Captured run_script(const std::string& edp, const std::string& args) {
  setenv("FF_LOADPATH", "/usr/lib/freefem++", 0);
  return run_captured("FreeFem++ -nw -v 0 '" + edp + "' " + args);
}
}  // namespace

TEST(PenaltyFreeFem, RefusesBadArgumentsNamingThem) {
  const std::string base = "-mesh '" + mesh(1) + "' -points '" + points() + "' -out '" + scratch().path("bad.json") + "'";
  const struct {
    std::string args, names;
  } cases[] = {
      {"-tol nan", "-tol"},          {"-tol -1", "-tol"},           {"-eps 0", "-eps"},
      {"-eps-min 1", "-eps-min"},    {"-scheme newton", "-scheme"}, {"-sampling edges", "-sampling"},
      {"-maxit 0", "-maxit"},        {"-nu 0.5", "-nu"},            {"-R inf", "-R"},
      {"-r nan", "-r"},              {"-continuation 3", "-continuation"},
      {"-eigen yes", "-eigen"},      {"-unknown 1", "-unknown"},    {"-tol", "-tol"},
      {"-kink-split 0", "-kink-split"}, {"-kink-split 2.5", "-kink-split"},
      {"-start w.txt", "-start"},    {"-start-mesh m.msh", "-start-mesh"},
  };
  for (const auto& c : cases) {
    const Captured r = run_script(kPenalty, base + " " + c.args);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.names), std::string::npos) << c.args << "\n" << r.output;
  }
  EXPECT_FALSE(std::filesystem::exists(scratch().path("bad.json")));
  const Captured nomesh = run_script(kPenalty, "-points '" + points() + "'");
  EXPECT_EQ(nomesh.status, 2) << nomesh.output;
}

TEST(PenaltyFreeFem, SaysSoWhenALevelRunsOutOfIterations) {
  const std::string out = scratch().path("maxit.json");
  const Captured r = run_script(kPenalty, "-mesh '" + mesh(1) + "' -points '" + points() + "' -maxit 1 -out '" + out + "'");
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_NE(r.output.find("did not converge"), std::string::npos) << r.output;
  std::ifstream in(out);
  const PenaltyRun run = penalty_values(nlohmann::json::parse(in));
  EXPECT_FALSE(run.converged);
  EXPECT_NE(run.why.find("-maxit"), std::string::npos) << run.why;
}

// Both constrain the same vertex values, so the penalised solution tends to the exact one at the
// rate eps (the document's penalty estimate): each decade of eps divides the difference by about 10.
TEST(PenaltyFreeFem, TendsToTheExactScriptsAnswerAtTheRateEps) {
  const nlohmann::json exact =
      run_freefem(kExact, mesh(1), scene_args(paper_scene(), points()), scratch().path("exact.json"));
  ASSERT_TRUE(exact.at("converged").get<bool>());
  const double w0 = exact.at("max_w").get<double>(), f0 = exact.at("total_contact_force").get<double>();
  std::vector<double> dw, df;
  for (double eps : {1e-6, 1e-7, 1e-8}) {
    std::ostringstream a;
    a << "-scheme nonlinear -continuation 0 -eps " << eps << " -tol 1e-13";
    const PenaltyRun r = penalty(1, a.str());
    ASSERT_TRUE(r.converged) << r.why;
    EXPECT_LT(r.residual, 1e-9);
    EXPECT_LT(r.max_w, w0);  // the penalty lets the plate sink into the obstacle a little
    dw.push_back(w0 - r.max_w);
    df.push_back(std::abs(f0 - r.force));
  }
  for (size_t k = 0; k + 1 < dw.size(); ++k) {
    EXPECT_NEAR(dw[k] / dw[k + 1], 10, 1) << "max w, step " << k;
    EXPECT_NEAR(df[k] / df[k + 1], 10, 1) << "force, step " << k;
  }
  EXPECT_LT(dw.back(), 1e-4 * w0);
}

// -continuation 2 reaches one eps by the levels eps, eps / 100, ..., eps-min, each started from
// the one before: the same discrete solution as a start from w = 0 (unique: (2a)'s energy is
// strictly convex), its last level eps-min, and that level starts close, so it takes fewer
// iterations than the cold start does.
TEST(PenaltyFreeFem, ThePathToOneEpsEndsAtTheColdStartsSolution) {
  const PenaltyRun cold = penalty(1, "-scheme nonlinear -continuation 0 -eps 1e-10 -eps-min 1e-10 -tol 1e-13");
  const PenaltyRun path = penalty(1, "-scheme nonlinear -continuation 2 -eps 1e-6 -eps-min 1e-10 -tol 1e-13");
  ASSERT_TRUE(cold.converged && path.converged) << cold.why << path.why;
  ASSERT_EQ(path.levels.size(), 3u);
  EXPECT_DOUBLE_EQ(path.levels[0].eps, 1e-6);
  EXPECT_DOUBLE_EQ(path.levels[1].eps, 1e-8);
  EXPECT_DOUBLE_EQ(path.levels[2].eps, 1e-10);
  EXPECT_DOUBLE_EQ(path.eps, 1e-10);
  EXPECT_LT(path.levels[2].iterations, cold.iterations);
  EXPECT_NEAR(path.max_w, cold.max_w, 2 * (cold.max_w_roundoff + path.max_w_roundoff));
  EXPECT_NEAR(path.force, cold.force, 2 * (cold.force_roundoff + path.force_roundoff));
  for (size_t k = 0; k < cold.w_at.size(); ++k) EXPECT_NEAR(path.w_at[k], cold.w_at[k], 1e-11) << k;
  // A path whose last level would not be eps-min is no path: 1e-6 / 100^k never lands on 3e-9, so
  // the last level is cut to it.
  const PenaltyRun odd = penalty(1, "-scheme nonlinear -continuation 2 -eps 1e-6 -eps-min 3e-9 -tol 1e-13");
  ASSERT_TRUE(odd.converged) << odd.why;
  ASSERT_EQ(odd.levels.size(), 3u);
  EXPECT_DOUBLE_EQ(odd.levels[1].eps, 1e-8);
  EXPECT_DOUBLE_EQ(odd.levels[2].eps, 3e-9);
}

// The disk's rule follows the kink of (R - w)^+ on the curve w = R by cutting the sub-triangles the
// curve crosses into k x k pieces (penalty_hct.edp, region penalty-disk): each crossed piece misses
// the kink by (s / k)^3 and about k of them are crossed, so what the kink leaves falls like k^-2.
// At eps = 1e-6 the curve crosses the disk; from k = 4 to 8 the answer must then move by well under
// a quarter of what it moved from 1 to 4 (k^-2 gives 1/20). At eps = 1e-3 the plate stays below R
// on the whole disk, nothing is crossed, and k must change nothing.
TEST(PenaltyFreeFem, CuttingTheCrossedSubTrianglesFollowsTheKink) {
  const std::string args = "-scheme nonlinear -continuation 0 -tol 1e-13 -sampling disk";
  PenaltyRun crossed[3], clear[2];
  const int ks[3] = {1, 4, 8};
  for (int i = 0; i < 3; ++i) {
    crossed[i] = penalty(1, args + " -eps 1e-6 -eps-min 1e-6 -kink-split " + std::to_string(ks[i]));
    ASSERT_TRUE(crossed[i].converged) << crossed[i].why;
  }
  const double moved_first = std::abs(crossed[1].max_w - crossed[0].max_w);
  const double moved_next = std::abs(crossed[2].max_w - crossed[1].max_w);
  EXPECT_GT(moved_first, 100 * crossed[0].max_w_roundoff);  // the kink matters here
  EXPECT_LT(moved_next, 0.25 * moved_first) << moved_first << " then " << moved_next;
  EXPECT_LT(std::abs(crossed[2].force - crossed[1].force), 0.25 * std::abs(crossed[1].force - crossed[0].force));
  for (int i = 0; i < 2; ++i) {
    clear[i] = penalty(1, args + " -eps 1e-3 -eps-min 1e-3 -kink-split " + std::to_string(ks[2 * i]));
    ASSERT_TRUE(clear[i].converged) << clear[i].why;
  }
  EXPECT_EQ(clear[0].max_w, clear[1].max_w);
  EXPECT_EQ(clear[0].force, clear[1].force);
}

// A finer mesh started from a coarser one's solution (-save, -start, as crosscheck_penalty chains its
// fixed-eps runs) must reach the same discrete solution as from w = 0, within the two runs'
// round-off, and in fewer steps: the start is where (3a) begins, not what it solves. A start written
// on another mesh than the one named is refused.
TEST(PenaltyFreeFem, AStartFromACoarserMeshReachesTheSameSolutionSooner) {
  const std::string args = "-scheme nonlinear -sampling disk -continuation 0 -tol 1e-13 -eps 1e-6 -eps-min 1e-6";
  const std::string saved = scratch().path("coarse_w.txt");
  const PenaltyRun coarse = penalty(1, args + " -save '" + saved + "'");
  ASSERT_TRUE(coarse.converged) << coarse.why;
  const PenaltyRun cold = penalty(2, args);
  const PenaltyRun warm = penalty(2, args + " -start '" + saved + "' -start-mesh '" + mesh(1) + "'");
  ASSERT_TRUE(cold.converged) << cold.why;
  ASSERT_TRUE(warm.converged) << warm.why;
  EXPECT_LT(warm.iterations, cold.iterations);
  EXPECT_LE(std::abs(warm.max_w - cold.max_w), 2 * (warm.max_w_roundoff + cold.max_w_roundoff));
  EXPECT_LE(std::abs(warm.force - cold.force), 2 * (warm.force_roundoff + cold.force_roundoff));
  EXPECT_GT(std::abs(coarse.max_w - cold.max_w), 100 * cold.max_w_roundoff);  // the meshes' answers differ
  const Captured r = run_script(kPenalty, "-mesh '" + mesh(2) + "' -points '" + points() + "' " + args + " -start '" + saved +
                                              "' -start-mesh '" + mesh(2) + "' -out '" + scratch().path("mismatch.json") + "'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("-start"), std::string::npos) << r.output;
}

// (3a) and (5a) solve the same discrete problem (2a): at one eps, stopped far below the difference
// that matters, they must give the same w_eps.
TEST(PenaltyFreeFem, NonlinearAndLinearSchemesGiveTheSameSolutionAtOneEps) {
  const PenaltyRun a = penalty(1, "-scheme nonlinear -continuation 0 -eps 1e-4 -tol 1e-12");
  const PenaltyRun b = penalty(1, "-scheme linear -continuation 0 -eps 1e-4 -tol 1e-12");
  ASSERT_TRUE(a.converged && b.converged) << a.why << b.why;
  EXPECT_GT(b.iterations, 5 * a.iterations);  // the linear scheme contracts only by 1/(1 + eps lambda_1h)
  // (5a) stopped at a step tol is within tol q / (1 - q) of its fixed point; q < 0.9 at eps = 1e-4.
  EXPECT_NEAR(a.max_w, b.max_w, 1e-10);
  EXPECT_NEAR(a.force, b.force, 1e-8 * a.force);
  for (size_t k = 0; k < a.w_at.size(); ++k) EXPECT_NEAR(a.w_at[k], b.w_at[k], 1e-10) << k;
}

// With no contact (the obstacle far below, a uniform load), (5a) is a linear iteration whose slowest
// mode contracts by exactly 1/(1 + eps lambda_1h), measured at steps of 1e-6: the other modes are gone
// by then, and round-off, which moves the ratio by about 4 rho / step (crosscheck_penalty.cpp,
// measured_factor_noise), is still below 1e-7 there, where at 1e-8 it reached 1e-6; and lambda_1h
// tends, from below with the lumped mass, to the published first eigenvalue of the clamped square.
TEST(PenaltyFreeFem, LinearSchemeContractsByTheFirstEigenvalueWhichTendsToThePublishedOne) {
  const double lambda1 = plate_constant(kRef, "lambda1");
  std::vector<double> err;
  for (int n : {1, 2}) {
    const double eps = 1e-4;
    const PenaltyRun r = penalty(n, "-R -1 -load 1 -continuation 0 -eps 1e-4 -tol 1e-6 -eigen 1");
    ASSERT_TRUE(r.converged) << r.why;
    ASSERT_EQ(r.levels.size(), 1u);
    EXPECT_NEAR(r.levels[0].last_ratio, 1 / (1 + eps * r.lambda1h), 1e-6) << "n = " << n;
    EXPECT_LT(r.lambda1h, lambda1);
    err.push_back(lambda1 - r.lambda1h);
  }
  EXPECT_LT(err[1], err[0] / 2);
}

// f = 0 and an obstacle of height R: the answer is R times the answer for R = 1.
TEST(PenaltyFreeFem, AnswerIsProportionalToTheObstaclesHeight) {
  const PenaltyRun a = penalty(1, "-scheme nonlinear -R 0.025 -eps 1e-8 -eps-min 1e-8 -continuation 0 -tol 1e-14");
  const PenaltyRun b = penalty(1, "-scheme nonlinear -R 0.1 -eps 1e-8 -eps-min 1e-8 -continuation 0 -tol 1e-14");
  ASSERT_TRUE(a.converged && b.converged);
  EXPECT_NEAR(b.max_w, 4 * a.max_w, 1e-12);
  EXPECT_NEAR(b.force, 4 * a.force, 1e-9 * b.force);
  EXPECT_NEAR(b.max_m12, 4 * a.max_m12, 1e-9 * b.max_m12);
}

// A factorisation that runs out of memory must not pass for an answer: a nonzero exit, and no JSON
// that says "converged". The address space is capped at 385 MB, below what UMFPACK needs to factor the
// mesh n = 8 (31 000 unknowns; about 7 s uncapped). (At 400 MB the exact script, which now assembles
// its matrix once, has room; and at 380 MB it returned zeros with exit 0 until its solve check also
// tested the rows held by tgv.) The cap is chosen for the default environment: the Makefile's
// thread limits (fewer threads, fewer stacks) and GLIBC_TUNABLES change how much address space the
// same run takes, so the scripts run here without them. OpenBLAS, asked for memory it cannot have, waits
// for it forever, so the scripts run here on the reference BLAS (libblas3), which just fails. UMFPACK
// reports status -1 (out of memory) and FreeFEM then stops, mostly by a segmentation fault that
// loses the buffered message: what is asserted is the nonzero status and the missing answer.
TEST(PenaltyFreeFem, AFailedSolveGivesANonzeroExitAndNoAnswer) {
  const std::string refblas = "/usr/lib/x86_64-linux-gnu/blas";
  if (!std::filesystem::exists(refblas + "/libblas.so.3")) GTEST_SKIP() << "no reference BLAS in " << refblas << " (libblas3)";
  const std::string msh = mesh(8);
  const std::string capped = "ulimit -v 385000; env -u GLIBC_TUNABLES -u OMP_THREAD_LIMIT -u OPENBLAS_NUM_THREADS LD_LIBRARY_PATH=" + refblas + " FF_LOADPATH=/usr/lib/freefem++ timeout 120 FreeFem++ -nw -v 0 '";
  // The control: under the same cap, the coarsest mesh solves, so the failure below is the factorisation's.
  const Captured control = run_captured(capped + kExact + "' -mesh '" + mesh(1) + "' -points '" + points() + "' -out '" + scratch().path("control.json") + "'");
  ASSERT_EQ(control.status, 0) << control.output;
  for (const std::string& edp : {kPenalty, kExact}) {
    const std::string out = scratch().path("oom.json");
    std::filesystem::remove(out);
    const Captured r = run_captured(capped + edp + "' -mesh '" + msh + "' -points '" + points() + "' -out '" + out + "'");
    EXPECT_NE(r.status, 0) << edp << "\n" << r.output;
    EXPECT_NE(r.status, 124) << edp << ": did not end within two minutes";
    std::ifstream in(out);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str().find("\"converged\": true"), std::string::npos) << edp << "\n" << text.str();
  }
}

// The graded ring of the fixed-eps comparison (crosscheck_penalty's layer_grading): the circle keeps
// its 4 n vertices a quarter, and along a spoke the ring's nodes follow one map of k / M1 whatever
// the level, (1 - grade^(-k/M1)) / (1 - 1/grade): each level's nodes are every other node of the next,
// and the cells shrink towards the circle, the first grade^((M1 - 1) / M1) times the last. A grade
// below 1 is refused by gmsh, which gmsh_mesh reports as a failure.
TEST(PenaltyFreeFem, TheGradedRingFollowsOneMapOnEveryLevel) {
  const Scene scene = paper_scene();
  const Cylinder& c = *scene.cylinder;
  const double grade = 30, a = 0.4 * c.radius;
  // The nodes along the spoke from the central square's lower-right corner to the circle.
  auto spoke = [&](int n, const std::string& name) {
    auto numbers = circle_numbers(paper_scene(), n);
    numbers.insert(numbers.end(), {{"grade", grade}, {"ring", 2}});
    const std::string msh = scratch().path(name);
    gmsh_mesh(kRef + "/square_with_circle.geo", numbers, msh);
    std::ifstream in(msh);
    const std::vector<std::pair<double, double>> nodes = read_msh_nodes(in);
    int on_circle = 0;
    std::vector<double> d;
    for (size_t k = 1; k < nodes.size(); ++k) {
      const double dx = nodes[k].first - c.cx, dy = nodes[k].second - c.cy, r = std::hypot(dx, dy);
      if (std::abs(r - c.radius) < 1e-12) ++on_circle;
      if (dx > 0 && std::abs(dx + dy) < 1e-12 && r >= a * std::sqrt(2.0) - 1e-12 && r <= c.radius + 1e-12) d.push_back(r);
    }
    EXPECT_TRUE(in.good()) << msh;
    EXPECT_EQ(on_circle, 4 * 4 * n) << msh;
    std::sort(d.begin(), d.end());
    return d;
  };
  const std::vector<double> coarse = spoke(2, "graded2.msh"), fine = spoke(4, "graded4.msh");
  ASSERT_EQ(coarse.size(), 5u);  // ring 2 n = 4 cells
  ASSERT_EQ(fine.size(), 9u);
  const double width = coarse.back() - coarse.front();
  // gmsh places a progression's nodes to about 1e-9 of the ring's width here.
  for (size_t k = 0; k < coarse.size(); ++k) EXPECT_NEAR(coarse[k], fine[2 * k], 1e-7 * width) << k;
  const double cells = coarse.size() - 1, first = coarse[1] - coarse[0], last = coarse.back() - coarse[cells - 1];
  EXPECT_NEAR(first / last, std::pow(grade, (cells - 1) / cells), 1e-5 * grade);
  for (size_t k = 2; k < fine.size(); ++k) EXPECT_LT(fine[k] - fine[k - 1], fine[k - 1] - fine[k - 2]);

  auto refused = circle_numbers(paper_scene(), 2);
  refused.insert(refused.end(), {{"grade", 0.5}, {"ring", 1}});
  EXPECT_THROW(gmsh_mesh(kRef + "/square_with_circle.geo", refused, scratch().path("refused.msh")), std::runtime_error);
}

// The total force is read from the equation (penalty_hct.edp's dual-force region): tested with a v
// that is 1 on the disk, (D30) gives it as (Lap w, Lap v) - (f, v), which carries no 1/eps. It must
// be the penalty's own integral wherever that is still well conditioned (eps = 1e-4 here, where the
// two differ only by the solve's residual), for the vertex and the disk samplings, and for a load;
// quadrature sampling, and a disk that holds clamped vertices, fall back to the integral.
TEST(PenaltyFreeFem, TheForceFromTheEquationIsThePenaltysIntegral) {
  for (const std::string sampling : {"vertices", "disk"})
    for (const std::string load : {"0", "-30"}) {
      const std::string out = scratch().path("dual_" + sampling + load + ".json");
      const nlohmann::json j = run_freefem(kPenalty, mesh(2), scene_args(paper_scene(), points()) + " -scheme nonlinear -continuation 0 -tol 1e-13 -eps 1e-4 -eps-min 1e-4 -sampling " + sampling + " -load " + load, out);
      const double dual = j.at("total_contact_force").get<double>(), integral = j.at("force_by_penalty_integral").get<double>();
      EXPECT_GT(integral, 1) << sampling << " " << load;
      EXPECT_NEAR(dual, integral, 1e-10 * integral) << sampling << " load " << load;
    }
  // Quadrature sampling puts penalty points where chi_h is not 1, so the script keeps the integral.
  const nlohmann::json q = run_freefem(kPenalty, mesh(2), scene_args(paper_scene(), points()) + " -scheme nonlinear -continuation 0 -tol 1e-13 -eps 1e-4 -eps-min 1e-4 -sampling quadrature", scratch().path("dual_quadrature.json"));
  EXPECT_EQ(q.at("total_contact_force").get<double>(), q.at("force_by_penalty_integral").get<double>());
  // A disk (radius 0.6 about the centre) that holds clamped vertices: chi_h would not be admissible.
  Scene wide = paper_scene();
  wide.cylinder->radius = 0.6;
  const nlohmann::json c = run_freefem(kPenalty, mesh(2), scene_args(wide, points()) + " -scheme nonlinear -continuation 0 -tol 1e-13 -eps 1e-4 -eps-min 1e-4 -sampling vertices", scratch().path("dual_clamped.json"));
  EXPECT_EQ(c.at("total_contact_force").get<double>(), c.at("force_by_penalty_integral").get<double>());
}

// The script's round-off estimate (penalty_hct.edp, region ff-roundoff) from its own residual: it
// must hold what another summation order leaves, measured by solving again with two OpenBLAS
// threads instead of one (UMFPACK's dense blocks then add in another order), and it must lie below
// the worst case u h^-4 it replaces. The quadrature fallback's force has no estimate and
// keeps the worst case.
TEST(PenaltyFreeFem, ItsRoundoffEstimateHoldsWhatAnotherSummationOrderLeaves) {
  // OPENBLAS_NUM_THREADS as it was, put back however the test ends.
  struct Restore {
    const char* before = std::getenv("OPENBLAS_NUM_THREADS");
    std::string saved = before ? before : "";
    ~Restore() { before ? setenv("OPENBLAS_NUM_THREADS", saved.c_str(), 1) : unsetenv("OPENBLAS_NUM_THREADS"); }
  } restore;
  int moved = 0;
  for (int n : {2, 4}) {
    PenaltyRun run[2];
    for (int t = 0; t < 2; ++t) {
      setenv("OPENBLAS_NUM_THREADS", t ? "2" : "1", 1);
      run[t] = penalty_values(run_freefem(kPenalty, mesh(n), scene_args(paper_scene(), points()) +
                                                                 " -scheme nonlinear -continuation 0 -tol 1e-13 -eps 1e-6 -eps-min 1e-6 -sampling disk",
                                          scratch().path("roundoff" + std::to_string(n) + "_" + std::to_string(t) + ".json")));
    }
    const double dw = std::abs(run[0].max_w - run[1].max_w), df = std::abs(run[0].force - run[1].force);
    moved += (dw > 0) + (df > 0);
    for (const PenaltyRun& r : run) {
      EXPECT_GE(r.max_w_roundoff, dw) << n;
      EXPECT_GE(r.force_roundoff, df) << n;
      EXPECT_LT(r.max_w_roundoff, freefem_roundoff(r.h, r.max_w)) << n;
      EXPECT_LT(r.force_roundoff, freefem_roundoff(r.h, r.force)) << n;
    }
  }
  EXPECT_GT(moved, 0) << "one and two BLAS threads gave identical answers: the test measured nothing";
  const PenaltyRun q = penalty_values(run_freefem(kPenalty, mesh(2), scene_args(paper_scene(), points()) +
                                                                         " -scheme nonlinear -continuation 0 -tol 1e-13 -eps 1e-4 -eps-min 1e-4 -sampling quadrature",
                                                  scratch().path("roundoff_quadrature.json")));
  EXPECT_EQ(q.force_roundoff, freefem_roundoff(q.h, q.force));  // the worst case: the script made no estimate
  EXPECT_GT(q.max_w_roundoff, 0);
}

// -symmetry quarter: on the quarter mesh (graded as at fixed eps) with the mirror lines held by the
// normal-slope penalty, the script solves the discrete problem of the whole plate meshed by the
// quarter and its mirror images (unfold_quarter_mesh): max w and w at points in all four quarters
// agree within twice the two runs' round-off estimates, the force within the worst case u h^-4 that
// the exact script's quarter is held to (tests/test_crosscheck.cpp). The force's own estimate is
// too tight here: at n = 4 the two forces differ by 6e-9 (2e-10 of it), though each solve's
// first-order round-off, z'r, is below 4e-10, and a mirror penalty 1e4 times stiffer moves it by
// 3e-10 only; what else separates the two problems at that level is not found. A whole mesh is refused.
TEST(PenaltyFreeFem, OnAQuarterMeshItSolvesTheWholePlate) {
  const Scene s = paper_scene();
  const std::string pts = scratch().path("quarter_points.txt");
  write_points(pts, {{0.5, 0.5}, {0.3, 0.2}, {0.8, 0.3}, {0.65, 0.9}});
  const std::string args = " -scheme nonlinear -continuation 0 -tol 1e-13 -eps 1e-6 -eps-min 1e-6 -sampling disk";
  for (int n : {2, 4}) {
    const std::string q = scratch().path("pquarter" + std::to_string(n) + ".msh"), w = scratch().path("punfolded" + std::to_string(n) + ".msh");
    auto numbers = circle_numbers(s, n);
    numbers.insert(numbers.end(), {{"grade", 12}, {"ring", 2}});
    gmsh_mesh(kRef + "/quarter_square_with_circle.geo", numbers, q);
    unfold_quarter_mesh(q, w, s.cylinder->cx, s.cylinder->cy);
    const PenaltyRun quarter = penalty_values(run_freefem(kPenalty, q, scene_args(s, pts) + args + " -symmetry quarter", q + ".json")),
                     whole = penalty_values(run_freefem(kPenalty, w, scene_args(s, pts) + args, w + ".json"));
    ASSERT_TRUE(quarter.converged && whole.converged) << "n = " << n;
    const double bar_w = 2 * (quarter.max_w_roundoff + whole.max_w_roundoff);
    EXPECT_NEAR(quarter.max_w, whole.max_w, bar_w) << n;
    EXPECT_NEAR(quarter.force, whole.force, 2 * freefem_roundoff(whole.h, whole.force)) << n;
    for (size_t k = 0; k < whole.w_at.size(); ++k) EXPECT_NEAR(quarter.w_at[k], whole.w_at[k], bar_w) << "point " << k << ", n = " << n;
    EXPECT_LT(3 * quarter.unknowns, whole.unknowns);
  }
  const Captured run = run_captured("FF_LOADPATH=/usr/lib/freefem++ FreeFem++ -nw -v 0 '" + kPenalty + "' -mesh '" + mesh(1) +
                                    "' -points '" + pts + "' -symmetry quarter -out /dev/null 2>&1");
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("-symmetry quarter"), std::string::npos) << run.output;
}
