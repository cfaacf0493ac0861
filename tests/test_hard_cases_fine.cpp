// The hard cases on a million unknowns (n = 512): every scheme, and the linear scheme's slow
// convergence against the rate its theory predicts with the published first eigenvalue. The
// penalty schemes run on the quarter of the plate that the square's mirror lines leave, the same
// discrete problem (mirror.hpp, tested in test_mirror.cpp) at a quarter of the cost; the exact
// solver runs on the whole plate, whose symmetry it is asked to show.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>

#include "active_set.hpp"
#include "contraction.hpp"
#include "eps_sweep.hpp"
#include "norms.hpp"
#include "paper_case.hpp"

using namespace plate;

namespace {
constexpr int kFine = 512;
Grid quarter(int n) { return part_of(make_grid(n), Mirrors{true, true}); }
Problem paper_quarter(int n) {
  return make_problem(quarter(n), SamplingKind::Nodes, paper_scene().obstacle(), [](double, double) { return 0.0; });
}
}  // namespace

TEST(FineGrid, LinearSchemeContractsAtTheRateOfTheFirstEigenvalue) {
  // No contact (phi = -1 is never reached under f = 1): (5a) is then a linear iteration whose
  // error shrinks, mode by mode, by 1/(1 + eps lambda_k). The slowest mode is the first, so the
  // ratio of successive steps tends to 1/(1 + eps lambda_1h), and lambda_1h -> lambda_1. (From the
  // symmetric start w = 0 only symmetric modes are excited, the first among them.)
  const Problem p = make_problem(quarter(kFine), SamplingKind::Nodes, [](double, double) { return -1.0; },
                                 [](double, double) { return 1.0; });
  const double eps = 1e-4;
  const std::vector<double> steps = linear_step_norms(p, eps, 40);
  ASSERT_EQ(steps.size(), 40u);
  const double ratio = steps[39] / steps[38], measured = (1 / ratio - 1) / eps;
  std::printf("n = %d: step ratio %.9f, so lambda_1h = %.4f (published lambda_1 = %.5f)\n", kFine, ratio, measured,
              plate_constant("lambda1"));
  for (size_t k = 1; k < steps.size(); ++k) EXPECT_LE(steps[k], steps[k - 1] / (1 + eps * plate_constant("lambda1")) * (1 + 1e-6));
  EXPECT_NEAR(measured, plate_constant("lambda1"), 1e-5 * plate_constant("lambda1"));
}

TEST(FineGrid, ExactSolverCertifiesAMillionUnknowns) {
  Problem p = paper_problem(kFine, SamplingKind::Nodes);
  const ExactResult exact =  // grid-sequenced from n = 8, as `plate --scheme exact` runs it
      solve_exact(p, paper_scene().obstacle(), [](double, double) { return 0.0; }, ExactOptions{});
  ASSERT_TRUE(exact.converged) << exact.message;
  EXPECT_LE(exact.certificate.worst(), 1e-10);
  // Symmetric up to round-off magnified by the condition of K, ~ n^4 (measured: 4e-10 relative).
  EXPECT_LE(asymmetry(p.grid, exact.w), std::pow(kFine, 4) * DBL_EPSILON * max_nodal_abs(exact.w));
  EXPECT_LE(exact.levels.back().pdas_iterations, 10);  // sequencing leaves little to do on the finest grid
}

TEST(FineGrid, NonlinearSchemeAgreesWithTheExactSolver) {
  // (3a) refactorises whenever its active set changes: on the quarter of n = 512 a few seconds a time.
  const int n = kFine;
  Problem p = paper_quarter(n);
  const ExactResult exact =
      solve_exact(p, paper_scene().obstacle(), [](double, double) { return 0.0; }, ExactOptions{});
  ASSERT_TRUE(exact.converged) << exact.message;
  const double eps = 1e-7;
  const SweepRow row = sweep_row(p, Scheme::Nonlinear, eps, 1e-6, 100, exact.w);
  std::printf("(3a) at n = %d, eps = %g: %d steps, %d factorisations, %.1f s, bound %.2e, %.2e from the exact "
              "solution\n", n, eps, row.iterations, row.factorizations, row.seconds, row.bound.bound, row.error);
  ASSERT_TRUE(row.converged) << row.message;
  EXPECT_LE(row.error, 1e-6 + 2 * eps * exact.lambda.maxCoeff());  // within tol of w_eps, which sinks by ~eps xi
}

TEST(FineGrid, LinearSchemeOnTheContactProblemStaysWithinTheoremTwo) {
  // With contact, Theorem 2 still bounds every step by 1/(1 + eps lambda_1) = 0.885 times the last
  // (the nodes held by the obstacle make it faster in practice), and the stopped iterate is not w_eps.
  const Problem p = paper_quarter(kFine);
  const double eps = 1e-4, tol = 1e-6;
  const SweepRow r = sweep_row(p, Scheme::Linear, eps, tol, 400, VectorXd::Zero(p.grid.unknowns()));
  ASSERT_TRUE(r.stopped) << r.message;
  const double rho = 1 / (1 + eps * plate_constant("lambda1"));
  for (size_t k = 1; k < r.steps.size(); ++k)
    EXPECT_LE(r.steps[k], r.steps[k - 1] * rho * (1 + 1e-6)) << "step " << k;
  std::printf("(5a) at eps = %g: %d steps (contraction bound %.4f), error bound %.2e against tol %.0e\n", eps,
              r.iterations, rho, r.bound.bound, tol);
  // Stopped on a step below tol, but |w - w_eps| can be up to rho / (1 - rho) ~ 7.7 steps: not certified.
  EXPECT_FALSE(r.converged);
  EXPECT_NE(r.message.find("stopped before it solved (2a)"), std::string::npos) << r.message;
}
