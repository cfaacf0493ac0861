// The paper's iterations for the penalised problem (2): the nonlinear scheme (3a) and the linear
// scheme (5a), discretised by (8), with the continuation eps_s = 10^{-s} and the two stopping rules.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "cholesky.hpp"
#include "penalty_bound.hpp"
#include "problem.hpp"

namespace plate {

enum class Scheme { Linear, Nonlinear };
const char* to_string(Scheme s);

struct SolveOptions {
  Scheme scheme = Scheme::Linear;
  double tol = 1e-6;         // OS: both stopping rules, max norm over nodal values of w
  int max_iter = 100000;     // per eps level; reaching it is a failure
  double eps_start = 1e-1;   // eps_s = eps_start * 10^{-(s - s0)}
  double eps_min = 1e-12;    // continuation fails if successive levels are not within tol by here
  bool continuation = true;  // false: one level at eps_start
  double eps_unit = 1.0;     // messages give eps divided by this: the caller's unit (plate: lx^4)
  // Called after every iteration with the eps level and the new iterate.
  std::function<void(double eps, int iteration, const VectorXd& w)> on_iterate;
};

struct LevelRecord {
  double eps = 0;
  int iterations = 0;
  int factorizations = 0;
  double last_step = 0;        // ||w^{n+1} - w^n||_C at the end of the level
  double level_change = -1;    // ||w^{eps_s} - w^{eps_{s-1}}||_C; -1 on the first level
  bool converged = false;
  std::string failure;         // why the level stopped early: a non-finite iterate, or steps that stopped shrinking
};

struct SolveResult {
  VectorXd w;
  double eps = 0;  // eps of the last level
  std::vector<LevelRecord> levels;
  bool stopped = false;    // the paper's stopping rules were met
  PenaltyBound bound;      // how far w can be from w_eps, from the residual of (2a)
  bool converged = false;  // stopped, and the bound is within tol: the answer is certified
  std::string message;     // why not, when not converged
  double seconds_factorize = 0, seconds_iterate = 0, seconds_bound = 0;
  int total_iterations() const;
};

// Runs one eps level from the starting guess w (overwritten with the last iterate).
LevelRecord linear_scheme_level(const Problem& p, double eps, VectorXd& w, Cholesky& chol, const SolveOptions& o,
                                double* seconds_factorize = nullptr);
LevelRecord nonlinear_scheme_level(const Problem& p, double eps, VectorXd& w, Cholesky& chol, const SolveOptions& o,
                                   double* seconds_factorize = nullptr);

// The full method: starting guess w = 0, eps levels eps_start, eps_start/10, ... until successive
// levels agree within tol. Then the last iterate is certified: converged only if it is provably
// within tol of w_eps at the last eps (penalty_error_bound). Never throws for non-convergence:
// the result says converged = false and why.
SolveResult solve(const Problem& p, const SolveOptions& o);

// Options for `scheme` at `eps` alone (no continuation), stopping at tol or after max_iter steps.
SolveOptions fixed_eps_options(Scheme scheme, double eps, double tol, int max_iter = SolveOptions{}.max_iter);

// Throws std::invalid_argument naming the option if an option is out of range.
void validate(const SolveOptions& o);

}  // namespace plate
