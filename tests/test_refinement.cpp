// Iterative refinement (D22) with residuals in long double (D21): it removes the error of a factor
// that is not K's own, as long as each correction confirms the one before, and it leaves the answer
// as it was when the corrections do not shrink.
#include <gtest/gtest.h>

#include <cmath>

#include "refinement.hpp"

using namespace plate;

namespace {
// The clamped unit square under a uniform load: K and F, no rows.
Problem loaded_square(int n) {
  return make_problem(Scene::rectangle(1, 1).over([](double, double) { return -1.0; }).loaded(1.0), make_grid(n),
                      SamplingSpec{SamplingKind::Nodes});
}

// The factor of (1 + d) K: each refinement step shrinks the error by d / (1 + d), as a double solve
// whose round-off is d of the answer would (on a grid fine enough, d reaches a hundredth).
SpMat scaled(const SpMat& K, double d) { return (1 + d) * K; }

double relative_difference(const VectorXd& a, const VectorXd& b) {
  return (a - b).lpNorm<Eigen::Infinity>() / b.lpNorm<Eigen::Infinity>();
}
}  // namespace

// The first correction is a hundredth of the answer, far above the thousandth that once stopped
// the refinement; the second confirms it, and the refined answer is K's own to round-off.
TEST(Refinement, KeepsALargeFirstCorrectionThatTheNextConfirms) {
  const Problem p = loaded_square(16);
  Cholesky exact, off;
  exact.factorize(p.K);
  off.factorize(scaled(p.K, 1e-2));
  const VectorXd reference = solve_refined(p, exact);
  const VectorXd start = off.solve(p.F);
  ASSERT_GT(relative_difference(start, reference), 1e-3) << "the test needs a first correction above the threshold";
  Refinement record;
  const VectorXd w = solve_refined(p, off, &record);
  ASSERT_FALSE(record.w.empty()) << "the refinement was refused";
  EXPECT_GE(record.w.front(), 1e-3);
  EXPECT_EQ(record.undone, 0.0);
  EXPECT_LE(relative_difference(w, reference), 1e-13);
}

// A factor so far off (d = 3) that each correction is three quarters of the one before, as noise
// amplified by a near-singular block would be: no step is confirmed, so the answer stays the
// unrefined solve and the record says it was not refined.
TEST(Refinement, UndoesALargeFirstCorrectionThatTheNextDoesNotConfirm) {
  const Problem p = loaded_square(16);
  Cholesky off;
  off.factorize(scaled(p.K, 3.0));
  const VectorXd start = off.solve(p.F);
  Refinement record;
  const VectorXd w = solve_refined(p, off, &record);
  EXPECT_TRUE(record.w.empty());
  EXPECT_GE(record.undone, 1e-3);
  EXPECT_EQ(relative_difference(w, start), 0.0);
}
