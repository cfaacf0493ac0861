// The penalty of (2) integrated over the true disk (D30). With the paper's obstacle, phi = height on
// the closed disk and no constraint outside, the penalised equation (2a) in weak form reads
//     (Lap w, Lap v) - eps^-1 int_{disk, w < phi} (phi - w) v = (f, v),
// and its integrand jumps across the circle and has a kink on the curve w = phi. A rule that only
// tests fixed points (the Gauss sampling of sampling.hpp) integrates both with an error that changes
// sign from grid to grid, so no observed order settles. Here each square of (8) gets the rule of
// implicit_quadrature.hpp for its part of {inside the circle, w_h < phi}: the integral is then that
// of w_h itself, to round-off, and what is left is the discretisation's own error.
#pragma once
#include <vector>

#include "implicit_quadrature.hpp"
#include "problem.hpp"

namespace plate {

// Points and weights of a rule on {inside the scene's cylinder, w_h < its height} (w == nullptr:
// the whole disk), and S taking the unknowns to the values of w_h at the points.
struct PenaltyRule {
  std::vector<double> x, y;
  VectorXd weights;
  RowSpMat S;
};
// Throws std::invalid_argument if the scene's obstacle is not a cylinder.
PenaltyRule penalty_rule(const Problem& p, const VectorXd* w, ImplicitOrders orders = {});

// w_eps of (2a) with the penalty integrated by penalty_rule at each iterate: the nonlinear scheme
// (3a), which with the integral exact is Newton's method (the penalty's derivative is the integral
// over the region where w < phi), from the starting guess w. Stops when a step moves no nodal value
// by more than tol times the largest of them, or when the steps, below 1e-12 of w, stop falling
// (round-off, kRoundoffStep); converged = false if max_iter steps do neither.
struct PenalisedSolve {
  VectorXd w;
  int iterations = 0;
  double last_step = 0;
  bool converged = false;
};
PenalisedSolve solve_penalised_exactly(const Problem& p, double eps, VectorXd w, double tol = 1e-14,
                                       int max_iter = 60, ImplicitOrders orders = {});

// w_eps at each eps of `eps` (decreasing), by solve_penalised_exactly from w = 0 along the
// continuation eps = 0.1, 0.01, ... (each level starts from the last: Newton then needs a handful of
// steps each). Throws std::runtime_error naming the eps where Newton did not converge.
std::vector<VectorXd> penalised_path_exactly(const Problem& p, const std::vector<double>& eps, ImplicitOrders orders = {});

// The total force of the obstacle on the plate, eps^-1 int_{disk} (phi - w_h)^+, by the rule that
// penalty_rule(p, &w) gives (a caller that needs the rule too makes it once).
double penalised_force(const Problem& p, const PenaltyRule& rule, const VectorXd& w, double eps);

}  // namespace plate
