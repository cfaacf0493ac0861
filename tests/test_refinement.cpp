// Iterative refinement (D22) with residuals in long double (D21): it removes the error of a factor
// that is not K's own, as long as each correction confirms the one before, and it leaves the answer
// as it was when the corrections do not shrink.
#include <gtest/gtest.h>

#include <cmath>

#include "paper_case.hpp"
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

// A factor so far off (d = 3) that each correction is three quarters of the one before: no step is
// confirmed, so the answer stays the unrefined solve and the record says it was undone.
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

namespace {
// The paper's plate on a coarse grid held at its first few rim rows: the rows, their block
// G_AA = S_A K^-1 S_A^T, and the forces mu* and plate w* that satisfy both equations of (D22).
struct Held {
  Problem p = paper_problem(8, SamplingKind::Edge);
  Cholesky chol;
  std::vector<int> rows;
  Eigen::MatrixXd S_A, G;
  VectorXd mu, w;
  Held() {
    chol.factorize(p.K);
    for (int k = 0; k < 3; ++k) rows.push_back(p.sampling.edge_begin + 2 * k);
    S_A = Eigen::MatrixXd::Zero(rows.size(), p.unknowns());
    VectorXd phi_A(rows.size());
    for (size_t i = 0; i < rows.size(); ++i) {
      for (RowSpMat::InnerIterator it(p.sampling.S, rows[i]); it; ++it) S_A(i, it.col()) = it.value();
      phi_A[i] = p.phi[rows[i]];
    }
    const Eigen::MatrixXd Z = chol.solve_many(S_A.transpose());
    G = S_A * Z;
    mu = G.ldlt().solve(phi_A - S_A * chol.solve(p.F));
    w = plate_under(mu);
  }
  VectorXd plate_under(const VectorXd& forces) const { return chol.solve(p.F + S_A.transpose() * forces); }
};
}  // namespace

// Forces 1 % off, the plate consistent with them: the first correction (a hundredth, in the forces)
// is confirmed by the second, and the forces come back to mu*.
TEST(Refinement, ConfirmsALargeCorrectionOfTheForces) {
  const Held h;
  VectorXd mu = 1.01 * h.mu, w = h.plate_under(mu);
  const Refinement record = refine(h.p, h.chol, h.rows, h.G, mu, w);
  ASSERT_FALSE(record.mu.empty());
  EXPECT_GE(record.mu.front(), 1e-3);
  EXPECT_EQ(record.undone, 0.0);
  EXPECT_LE(relative_difference(mu, h.mu), 1e-12);
  EXPECT_LE(relative_difference(w, h.w), 1e-12);
}

// The same start with G_AA a tenth of what it is, as a near-singular block amplifies noise: each
// correction of the forces overshoots ninefold, the second does not confirm the first, and both
// the forces and the plate are put back as they were.
TEST(Refinement, UndoesForcesThatANearSingularBlockWouldAmplify) {
  const Held h;
  const VectorXd mu0 = 1.01 * h.mu, w0 = h.plate_under(mu0);
  VectorXd mu = mu0, w = w0;
  const Refinement record = refine(h.p, h.chol, h.rows, 0.1 * h.G, mu, w);
  EXPECT_TRUE(record.mu.empty());
  EXPECT_GE(record.undone, 1e-3);
  EXPECT_EQ(relative_difference(mu, mu0), 0.0);
  EXPECT_EQ(relative_difference(w, w0), 0.0);
}
