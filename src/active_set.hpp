// The obstacle problem with the constraint imposed exactly, no eps: with nodal sampling, find w and
// nodal forces lambda with  K w - F = S^T W lambda,  lambda >= 0,  w_p >= phi_p,  lambda_p (w_p - phi_p) = 0.
// Primal-dual active sets (semismooth Newton), a monotone fallback that cannot cycle, grid sequencing.
#pragma once
#include <string>
#include <vector>

#include "assemble.hpp"
#include "fixed_set.hpp"
#include "problem.hpp"

namespace plate {

// How far (w, lambda) is from solving the complementarity problem; each entry is relative.
struct Certificate {
  double violation = 0;            // max_p (phi_p - w_p)_+ / max_p |w_p|
  double negative_multiplier = 0;  // max_p (-lambda_p)_+ / max_p |lambda_p|
  double complementarity = 0;      // max_p |lambda_p (w_p - phi_p)| / (max |lambda| max |w|)
  double stationarity = 0;         // max_i |K w - F - S^T W lambda|_i / (|K| |w| + |F| + |S^T W lambda|)_i
  double worst() const;
};
Certificate certify(const Problem& p, const VectorXd& w, const VectorXd& lambda);

struct ExactOptions {
  double tol = 1e-10;       // every certificate entry must end <= tol
  int max_iter = 1000;      // active-set iterations per grid, both methods together
  bool globalise = true;    // false: a repeated active set ends the solve as a failure
  bool nested = true;       // start from the solution on the grid with twice the cell size
  int coarsest = 8;         // cells along x on the coarsest grid of the sequence
  int max_correction = 64;  // largest active-set change solved from the last factorisation
};
void validate(const ExactOptions& o);

struct ExactLevel {
  int cells = 0;
  int predicted = 0;           // size of the starting active set
  int active = 0;              // size of the final active set
  int pdas_iterations = 0;     // primal-dual active-set iterations
  int primal_steps = 0;        // steps of the monotone fallback (0 unless it was needed)
  int factorizations = 0;
  long correction_columns = 0; // solves spent on small active-set changes
  double seconds = 0;
};

struct ExactResult {
  VectorXd w;
  VectorXd lambda;  // force density at the interior nodes (the xi of (9)); zero off the active set
  NodeSet active;
  bool converged = false;
  bool cycled = false;  // the primal-dual iteration met an active set it had seen before
  std::string message;  // why not, when not converged
  Certificate certificate;
  std::vector<double> fallback_energies;  // energy at each minimiser the fallback visits
  std::vector<ExactLevel> levels;         // coarsest first; the last is this grid
};

// One grid, from the starting active set `initial` (empty: no node held).
ExactResult solve_exact(const Problem& p, const ExactOptions& o, NodeSet initial = {});

// Grid sequencing: solve on the grid with nx / 2 cells first (while nx is even and above
// o.coarsest) and start from the active set its solution predicts.
ExactResult solve_exact(const Grid& g, const Field& obstacle, const Field& load, const ExactOptions& o);
// The same on a problem already assembled (from the same obstacle and load, nodal sampling).
ExactResult solve_exact(const Problem& p, const Field& obstacle, const Field& load, const ExactOptions& o);

// 1/2 w^T K w - F^T w.
double energy(const Problem& p, const VectorXd& w);

}  // namespace plate
