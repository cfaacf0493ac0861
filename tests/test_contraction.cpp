// Theorem 2 at the discrete level. With e_n = w^n - w^{n-1} and ||v||_M = ||S v||_W, (6) gives
//   ||e_{n+1}||_M <= ||e_n||_M / (1 + eps lambda_1h),
// lambda_1h the smallest eigenvalue of K relative to M = S^T W S; without contact it is attained.
#include <gtest/gtest.h>

#include <cstdio>

#include "contraction.hpp"
#include "paper_case.hpp"
#include "schemes.hpp"

using namespace plate;

// Bjorstad & Tjostheim (1999), the first eigenvalue of the clamped unit square: reference/plate_constants.csv.
const double kClampedSquareLambda1 = plate_constant("lambda1");

TEST(Contraction, Lambda1hConvergesToTheClampedPlateEigenvalue) {
  double previous = INFINITY;
  for (int n : {16, 32, 64}) {
    const Problem g = paper_problem(n, SamplingKind::Gauss), v = paper_problem(n, SamplingKind::Nodes);
    const double lg = smallest_eigenpair(g.K, g.M).lambda, ln = smallest_eigenpair(v.K, v.M).lambda;
    std::printf("  n = %2d  lambda_1h: gauss %.7f  nodes %.7f  (published %.7f)\n", n, lg, ln, kClampedSquareLambda1);
    // Conforming elements with the exact mass: a Rayleigh-Ritz upper bound, decreasing with h.
    EXPECT_GE(lg, kClampedSquareLambda1 * (1 - 1e-12));
    EXPECT_LT(lg, previous);
    previous = lg;
    EXPECT_NEAR(ln, kClampedSquareLambda1, 2e-4 * kClampedSquareLambda1 * (16.0 / n) * (16.0 / n));
  }
  EXPECT_NEAR(previous, kClampedSquareLambda1, 2e-7 * kClampedSquareLambda1);  // n = 64
}


TEST(Contraction, WithoutContactTheLinearSchemeContractsByOneOverOnePlusEpsLambda) {
  for (SamplingKind kind : {SamplingKind::Gauss, SamplingKind::Nodes}) {
    // Uniform load f = 1 lifts the plate; phi = -1 is never reached, so every step is linear.
    const Problem p = make_problem(Scene::rectangle(1, 1).over([](double, double) { return -1.0; }).loaded([](double, double) { return 1.0; }), make_grid(8), SamplingSpec{kind});
    const double lambda = smallest_eigenpair(p.K, p.M).lambda;
    for (double eps : {1e-3, 3e-4, 1e-4}) {
      const double q = sharp_contraction(lambda, eps);
      const double measured = asymptotic_factor(linear_step_norms(p, eps, 400));
      std::printf("  %s eps = %g: lambda_1h = %.6f, measured factor %.9f, 1/(1 + eps lambda_1h) = %.9f, "
                  "paper's rho = %.9f\n",
                  to_string(kind), eps, lambda, measured, q, paper_rho(1 / lambda, eps));
      EXPECT_NEAR(measured, q, 1e-6 * q);
      // The paper's rho bounds the energy E_n, which shrinks by q^2 per step; it is weaker than q^2.
      EXPECT_GT(paper_rho(1 / lambda, eps), q * q);
    }
  }
}

TEST(Contraction, ARescaledDifferenceGivesTheSharpFactorToRoundOff) {
  // Without contact the settled factor is the largest eigenvalue of (K + M/eps)^{-1} M/eps, found by
  // a power iteration; lambda_1h comes from an inverse iteration on K^{-1} M. The two agree to the
  // round-off of the iterations, where the runs' step ratios agree only to 1e-6.
  for (SamplingKind kind : {SamplingKind::Gauss, SamplingKind::Nodes}) {
    const Problem p = make_problem(Scene::rectangle(1, 1).over([](double, double) { return -1.0; }).loaded([](double, double) { return 1.0; }), make_grid(8), SamplingSpec{kind});
    const double lambda = smallest_eigenpair(p.K, p.M).lambda;
    for (double eps : {1e-2, 1e-3, 1e-4})
      EXPECT_NEAR(settled_factor(p, eps, VectorXd::Zero(p.grid.unknowns())), sharp_contraction(lambda, eps),
                  1e-11 * sharp_contraction(lambda, eps))
          << to_string(kind) << " eps = " << eps;
  }
}

TEST(Contraction, OnTheContactSetTheSettledFactorIsBelowTheFreeOne) {
  // Samples in contact stop feeding the difference back (max(s, phi) is flat there), so the
  // settled factor with the paper's obstacle is smaller than without it, and is what the run's
  // late step ratios tend to.
  const Problem p = paper_problem(8, SamplingKind::Nodes);
  const double lambda = smallest_eigenpair(p.K, p.M).lambda;
  const double eps = 1e-3;
  VectorXd last;
  const std::vector<double> steps = linear_step_norms(p, eps, 60, &last);
  const double settled = settled_factor(p, eps, last);
  EXPECT_LT(settled, sharp_contraction(lambda, eps));
  size_t k = 1;  // the last ratio of steps that round-off has not reached
  while (k + 1 < steps.size() && steps[k + 1] > 1e-8 * steps[0]) ++k;
  ASSERT_GT(k, 5u);
  EXPECT_NEAR(steps[k] / steps[k - 1], settled, 1e-5 * settled) << "at step " << k;
}

TEST(Contraction, WithContactNoStepIsSlowerThanTheBound) {
  for (SamplingKind kind : {SamplingKind::Gauss, SamplingKind::Nodes}) {
    const Problem p = paper_problem(8, kind);
    const double lambda = smallest_eigenpair(p.K, p.M).lambda;
    for (double eps : {1e-3, 1e-4}) {
      const double q = sharp_contraction(lambda, eps);
      VectorXd last;
      const std::vector<double> steps = linear_step_norms(p, eps, 200, &last);
      const double worst = slowest_factor(steps, settled_factor(p, eps, last));
      std::printf("  %s eps = %g: slowest step ratio %.9f, bound %.9f\n", to_string(kind), eps, worst, q);
      // Active points contract faster (max(s, phi) is flat there), so the bound need not be attained.
      EXPECT_LE(worst, q * (1 + 1e-9));
    }
  }
}
