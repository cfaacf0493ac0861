// How far an iterate can be from the penalised solution w_eps of (2a), from its residual alone.
// The paper's stopping rules look at steps; this is what lets a run say "within tol" and mean it.
#pragma once
#include "cholesky.hpp"
#include "problem.hpp"

namespace plate {

struct PenaltyBound {
  double green = 0;     // g = (K^{-1})_cc at the value unknown nearest the centre
  double residual = 0;  // ||r||_{K^{-1}} = sqrt(r^T K^{-1} r), r the residual of (2a)
  double bound = 0;     // sqrt(g) ||r||_{K^{-1}}: bounds max over nodes |w - w_eps|
  double roundoff = 0;  // the same for the round-off expected in r alone: the smallest bound one can hope for
};

// Eq. (2a): a posteriori bound on max_nodes |w - w_eps|. `chol` must hold the analysis of K's
// pattern; it is refactorised with K itself.
PenaltyBound penalty_error_bound(const Problem& p, const VectorXd& w, double eps, Cholesky& chol);

// Value unknown of the grid node nearest the centre of the rectangle.
int centre_value_dof(const Grid& g);

}  // namespace plate
