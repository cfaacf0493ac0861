// How far round-off moves one deflection-like output of an exact solve, estimated per quantity in
// place of the worst case u n^3 |v| (exact_solve_roundoff), so that tables print the digits the run
// can vouch for.
//
// The computed w satisfies K w = F + S^T W lambda + r, with r the residual that round-off leaves
// (the certificate's stationarity). A linear output J(w) = g^T w then sits, to first order, z^T r
// from the value that the same lambda would give exactly, z = K^{-1} g. Another machine leaves
// another r of the same size whose entries have other signs, so the estimate is the size of a sum
// of terms of random sign, sqrt(sum_i z_i^2 r_i^2), with u (|K||w| + |F| + |S^T W lambda|)_i beside
// r_i for the error in computing r itself. It is an estimate, not a bound, and it does not follow
// the round-off in lambda: measured on the paper's scene (n = 16 ... 256, 1 and 2 BLAS threads,
// Haswell and Prescott kernels) max w moved by 4 to 9 times less than it says, but the total force,
// read off lambda, by up to 3 times more; so the force keeps the worst case.
#pragma once
#include <vector>

#include "cholesky.hpp"
#include "problem.hpp"

namespace plate {

class SolutionRoundoff {
 public:
  // Factorises K once (the solver's own factor is not kept); lambda: the multipliers at the samples.
  SolutionRoundoff(const Problem& p, const VectorXd& w, const VectorXd& lambda);

  // The estimate for several outputs at once, g given as columns.
  std::vector<double> of(const Eigen::MatrixXd& g) const;
  // The coefficient vector g of common outputs: w at a point, one unknown (a nodal value or slope).
  VectorXd point_value(double x, double y) const;
  VectorXd point_twist(double x, double y) const;  // of w_xy at a point
  VectorXd unknown(int dof) const;

 private:
  const Problem& p_;
  VectorXd residual_abs_, scale_;  // |r| and |K||w| + |F| + |S^T W lambda|
  Cholesky chol_;
};

}  // namespace plate
