// The contraction of the linear scheme (5a), Theorem 2 and its estimate (6), at the discrete level.
// lambda_1h = min over v with S v != 0 of (v^T K v) / (v^T M v), M = S^T W S, is the discrete
// counterpart of the clamped plate's first eigenvalue (1294.93... on the unit square).
#pragma once
#include <vector>

#include "problem.hpp"

namespace plate {

struct Eigenpair {
  double lambda = 0;
  VectorXd v;
  int iterations = 0;
};

// Smallest eigenvalue of K v = lambda M v (K positive definite, M semidefinite) by inverse
// iteration v <- K^{-1} M v with the Rayleigh quotient; stops when lambda changes by < rtol.
Eigenpair smallest_eigenpair(const SpMat& K, const SpMat& M, double rtol = 1e-12, int max_iter = 500);

// Sharp factor by which the linear scheme shrinks ||S(w^{n+1} - w^n)||_W per iteration:
// 1 / (1 + eps lambda_1h). Attained by the first eigenmode when no constraint is active.
double sharp_contraction(double lambda1h, double eps);

// Eq. (6): the paper's factor rho = (1 + c eps) / ((1 + 2 c eps)(1 + eps / c)), with c the
// Friedrichs constant in ||s||_0^2 <= c ||Lap s||_0^2, c = 1 / lambda_1.
double paper_rho(double c, double eps);

// ||w^{n+1} - w^n||_M for n = 0 .. iterations - 1 of the linear scheme at fixed eps, from w^0 = 0;
// the last iterate in *last_iterate if given, and in *energies the energy of each step,
// E = e^T K e + eps^{-1} e^T M e, the quantity (D6) and the paper's rho bound.
std::vector<double> linear_step_norms(const Problem& p, double eps, int iterations, VectorXd* last_iterate = nullptr,
                                      std::vector<double>* energies = nullptr);

// The factor by which (5a) shrinks the difference of two runs once both have settled on the
// contact set of w (its asymptotic contraction there), to full precision by a rescaled difference.
// With no contact it is the sharp factor 1/(1 + eps lambda_1h), measured rather than derived.
double settled_factor(const Problem& p, double eps, const VectorXd& w, int max_iter = 20000);

// The factor per step read off a sequence of step norms where they have fallen to 1e-7 of the
// first: the faster modes have died out (relative to the first they shrink by
// (1 + eps l1) / (1 + eps l2) per step) and rounding has not yet set in.
double asymptotic_factor(const std::vector<double>& steps);

// The largest ratio of successive steps, over the steps above 1e-6 of the first (below that, round-off
// in the iterates starts to show in the ratios, in the 9th digit), and the settled factor, which
// holds for all the steps after.
double slowest_factor(const std::vector<double>& steps, double settled);

}  // namespace plate
