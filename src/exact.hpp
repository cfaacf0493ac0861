// The obstacle problem with the constraint imposed exactly, no eps: find w and forces lambda at the
// samples with  K w - F = S^T W lambda,  lambda >= 0,  (S w)_p >= phi_p,  lambda_p ((S w)_p - phi_p) = 0.
// What every exact solver shares: its options, its result and the certificate that says how far the
// result is from solving the discrete problem. The solvers are below (primal_dual.hpp for bounds on
// nodal values, dual_active_set.hpp for any rows); active_set.hpp chooses between them.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "contact.hpp"
#include "extrema.hpp"
#include "fixed_set.hpp"
#include "problem.hpp"
#include "refinement.hpp"

namespace plate {

// How far (w, lambda) is from solving the complementarity problem; each entry is relative.
struct Certificate {
  double violation = 0;            // max_p (phi_p - (S w)_p)_+ / W, W = max(max over nodes |w|, max_p phi_p)
  double negative_multiplier = 0;  // max_p (-lambda_p)_+ / max_p |lambda_p|
  double complementarity = 0;      // max_p |lambda_p (w_p - phi_p)| / (max |lambda| W)
  double stationarity = 0;         // max_i |K w - F - S^T W lambda|_i / (|K| |w| + |F| + |S^T W lambda|)_i
  double worst() const;
};
Certificate certify(const Problem& p, const VectorXd& w, const VectorXd& lambda);
// Why a certificate fails tol, entry by entry.
std::string certificate_failure(const Certificate& c, double tol);

struct ExactResult;

struct ExactOptions {
  double tol = 1e-10;       // every certificate entry must end <= tol
  int max_iter = 1000;      // active-set iterations per grid, both methods together
  bool globalise = true;    // false: a repeated active set ends the solve as a failure
  bool nested = true;       // start from the solution on the grid with twice the cell size
  int coarsest = 8;         // cells along x on the coarsest grid of the sequence
  int max_correction = 64;  // largest active-set change solved from the last factorisation
  bool refine = true;       // iterative refinement with residuals in long double (any sampling but nodes)
  // Progress, on every grid as it starts (iteration 0, the rows predicted) and after each of its
  // active-set iterations: the grid's cells along x, the iteration, the rows held, and how many
  // join or leave next. Empty: silent.
  std::function<void(int cells, int iteration, int held, int changed)> on_iterate;
  // Measure every grid's answer of a sequence as it is done (extrema.hpp: FieldMeasures, with this
  // nu, at these points), into its ExactLevel: the values error bars are put on. Unset: none.
  struct LevelMeasures {
    double nu = kPoissonRatio;
    std::vector<std::pair<double, double>> points;
    bool coarser = true;  // false: the finest grid alone (its measures are the answer's; no error bars wanted)
  };
  std::optional<LevelMeasures> measure_levels;
};
void validate(const ExactOptions& o);

struct ExactLevel {
  int cells = 0;
  int predicted = 0;           // size of the starting active set
  int active = 0;              // size of the final active set
  int pdas_iterations = 0;     // primal-dual active-set iterations (dual solver: rounds of candidate rows)
  int dual_steps = 0;          // dual solver: steps of the dual active-set method
  int dependent_rows = 0;      // dual solver: rows met that depended on the held ones
  int primal_steps = 0;        // steps of the monotone fallback (0 unless it was needed)
  int factorizations = 0;
  long correction_columns = 0; // solves spent on small active-set changes
  Refinement refinement;       // dual solver: the refinement's corrections (D22); empty if not refined
  int layouts = 0;             // rows on a circle laid out for the contact: layouts solved (0: periodic splines only)
  int exchanged = 0;           // point rows added where the plate dipped between rows (rim_exchange.hpp)
  double seconds = 0;
  // With ExactOptions::measure_levels: this grid's answer read off (on the whole plate, through any
  // mirror lines), its total force (a part's times its images), whether it is certified, and
  // whether it was solved in the space carrying the kink (D31).
  std::optional<FieldMeasures> measures;
  double force = 0;
  bool certified = false, enriched = false;
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

// 1/2 w^T K w - F^T w.
double energy(const Problem& p, const VectorXd& w);

// The size of the answer: the largest finite obstacle value at a sample, or the largest nodal value
// of the free plate w_free = K^{-1} F if that is larger; 0 when both vanish. Tolerances relative to
// it do not depend on the units of length or on the obstacle's height.
double answer_scale(const Problem& p, const VectorXd& w_free);

// A bound on the round-off in a value v of an exact solve on n x n squares: u n^3 |v|. The round-off
// grows with the conditioning of the grid; the same runs with one and with two BLAS threads differ
// by at most a sixth of this bound to n = 512 (the most in the fitted q(pi/4); a three-hundredth in
// the deflections). Reports print no digit below 10 times it.
double exact_solve_roundoff(int n, double v);

}  // namespace plate
