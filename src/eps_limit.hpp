// The fully converged discrete solution: the limit as eps -> 0 of the penalised discrete
// solutions w_eps, against which the stopped iterates of the table are measured.
#pragma once
#include <vector>

#include "problem.hpp"

namespace plate {

// The exact discrete penalised solutions w_eps for eps = 0.1, 0.01, ..., down to `eps`: each by
// the nonlinear scheme (3a), started from the previous one, run until its active set repeats
// (then its step is exactly zero). Throws std::runtime_error if a level does not settle.
std::vector<VectorXd> penalised_path(const Problem& p, double eps);

struct EpsLimit {
  VectorXd w;          // the extrapolated limit
  double eps = 0;      // smallest eps used
  double ratio = 0;    // ||w_{10 eps} - w_{100 eps}||_C / ||w_eps - w_{10 eps}||_C: 10 when linear in eps
  double difference = 0;  // ||w_eps - w_{10 eps}||_C, the smaller term of the ratio
  double estimate = 0; // ||limit from (eps, 10 eps) - limit from (10 eps, 100 eps)||_C
  double roundoff = 0; // round-off in w_eps at the nodes (solve_roundoff): what a machine that
                       // rounds differently may change in the path, and so in the limit
};

// w_eps = w + eps z + O(eps^2) (the discrete penalty error is linear in eps, which `ratio`
// checks), so w ~ w_eps + (w_eps - w_{10 eps}) / 9. Each w_eps is the exact solution of the
// discrete (2a) from penalised_path (default eps = 1e-12: below it round-off in
// K + eps^{-1} S^T W S spoils the linear trend on coarse grids with Gauss sampling).
// Throws std::runtime_error if some level does not converge.
EpsLimit eps_limit(const Problem& p, double eps = 1e-12);

// The size of the round-off in the nodal values of the exact w_eps when it is computed as w by a
// backward-stable solve (Cholesky) of the penalised system at w's active set.
double solve_roundoff(const Problem& p, const VectorXd& w, double eps);

}  // namespace plate
