// Iterative refinement, with the residual of the discrete equilibrium K w = F + S^T mu computed in
// extended precision.
//
// An exact solve in double leaves w with an error of about u cond(K) |w|, and cond(K) grows like
// n^4: on n = 512 the clamped square under a uniform load comes out 8e-7 (relative) below its
// series, the same on every machine, because the rounding of the assembled K is itself of that
// effect. Iterative refinement removes it if the residual is computed more accurately than the
// solve: here element by element, with the element stiffness and every sum in long double (64-bit
// significand), so the rounded K never enters.
#pragma once
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

#include "cholesky.hpp"
#include "problem.hpp"

namespace plate {

// Eq. (D21): F + S^T mu - K w, mu a force per sample row, rounded to double only at the end.
VectorXd extended_residual(const Problem& p, const VectorXd& w, const VectorXd& mu);

// phi_q - (S w)_q at the rows `rows`, each sum in long double.
VectorXd extended_gap(const Problem& p, const VectorXd& w, const std::vector<int>& rows);

// The size of each correction, relative: max |dw| / max |w| and max |dmu| / max |mu|. The last
// entry is the correction that stopped the refinement (down to a few units of round-off, or no
// longer shrinking: then it was not applied), so it is about what round-off still moves in w and mu
// on any machine: the floor to which the refined answer is reproducible.
struct Refinement {
  std::vector<double> w, mu;
  // The first correction, when it was undone because the next did not confirm it (see refine): the
  // answer then carries the double solve's round-off, which may be that large. 0 otherwise.
  double undone = 0;
  double floor_w() const { return w.empty() ? NAN : w.back(); }
  double floor_mu() const { return mu.empty() ? NAN : mu.back(); }
  // What round-off can still change in the refined w (any entry) and, relatively, in the forces:
  // the last correction's size, never below a few units of round-off. Sizes are relative to the
  // largest entry of the whole vector (slopes included), so w's is scaled by that.
  double noise_w(const VectorXd& refined) const {
    return std::max(floor_w(), 4 * DBL_EPSILON) * refined.lpNorm<Eigen::Infinity>();
  }
  double relative_noise_mu() const { return std::max(floor_mu(), 4 * DBL_EPSILON); }
};

// A first correction (relative) of kRefineLargestFirst or more stands only if the second is at most
// kRefineContraction times it: round-off being removed shrinks that fast; noise amplified by a
// near-singular block does not (a factor of 4K, in tests/test_refinement.cpp, shrinks by 3/4).
constexpr double kRefineLargestFirst = 1e-3, kRefineContraction = 0.1;

// Eq. (D22): refines w and the forces mu on the rows `rows` (those that push; G_AA their block of
// G = S K^{-1} S^T) so that K w - S_A^T mu = F and S_A w = phi_A hold to the residual's precision.
// `chol` holds K's factor. Stops when a correction is down to a few units of round-off of w, or
// stops shrinking, or is as large as kRefineLargestFirst after the first; undoes everything (and
// records `undone`) when the second does not confirm a large first.
Refinement refine(const Problem& p, const Cholesky& chol, const std::vector<int>& rows, const Eigen::MatrixXd& G_AA,
                  VectorXd& mu, VectorXd& w);

// Throws std::runtime_error naming `what` if r was undone: the answer's round-off is then unknown,
// and a study that prints digits to its estimate must not print them.
void require_not_undone(const Refinement& r, const std::string& what);

// The plate with no constraint, K w = F, refined: eq. (D22) with no rows.
VectorXd solve_refined(const Problem& p, const Cholesky& chol, Refinement* record = nullptr);

}  // namespace plate
