// The iterations (3a) and (5a) at the discrete level and the eps continuation around them.
// With S the sampling matrix and W its weights, (8) reads
//   (K + eps^{-1} S^T W S) w^{n+1} = F + eps^{-1} S^T W max(S w^n, phi),
// because s - beta(s) = max(s, phi) pointwise.
#include "schemes.hpp"

#include <cmath>
#include <vector>
#include <sstream>
#include <stdexcept>

#include "norms.hpp"
#include "stopwatch.hpp"

namespace plate {

const char* to_string(Scheme s) { return s == Scheme::Linear ? "linear" : "nonlinear"; }

int SolveResult::total_iterations() const {
  int n = 0;
  for (const auto& l : levels) n += l.iterations;
  return n;
}

namespace {

void factorize_timed(Cholesky& chol, const SpMat& A, double* seconds, double eps) {
  const auto t0 = Clock::now();
  try {
    chol.factorize(A);
  } catch (const std::runtime_error&) {
    // K + eps^-1 S^T W S is positive definite in exact arithmetic; in floating point a tiny eps
    // drowns K, and that is the user's eps, not a fault of the solver.
    std::ostringstream m;
    m << "eps = " << eps << " is too small: K + eps^-1 S^T W S is not numerically positive definite "
      << "(CHOLMOD could not factorise it); use a larger --eps, --eps-min or --eps-start";
    throw std::invalid_argument(m.str());
  }
  if (seconds) *seconds += seconds_since(t0);
}

// The last kWindow step sizes, in a ring, so a level of any length keeps only these.
constexpr int kWindow = 1000;
using StepWindow = std::vector<double>;

// One step of a level: solve, measure the step in the C-norm, report, test the first stopping rule.
// A non-finite iterate, or steps that no longer shrink at all (the last one not below the one
// kWindow steps before: slower than any contraction double precision can show), end the level at
// once with `failure` set: iterating on could only waste time.
bool step_and_check(const Cholesky& chol, const VectorXd& rhs, VectorXd& w, double eps, LevelRecord& r,
                    const SolveOptions& o, StepWindow& steps) {
  VectorXd next = chol.solve(rhs);
  r.last_step = max_nodal_abs(next - w);
  w.swap(next);
  ++r.iterations;
  if (o.on_iterate) o.on_iterate(eps, r.iterations, w);
  if (!w.allFinite()) {
    r.failure = "the iterate is not finite (NaN or inf) after " + std::to_string(r.iterations) + " steps";
    return false;
  }
  if (steps.empty()) steps.assign(kWindow, INFINITY);
  double& slot = steps[r.iterations % kWindow];  // holds the step kWindow iterations ago
  if (r.last_step > o.tol && r.iterations > kWindow && !(r.last_step < slot)) {
    std::ostringstream m;
    m << "the steps stopped shrinking: step " << r.iterations << " is " << r.last_step << ", step "
      << r.iterations - kWindow << " was " << slot;
    r.failure = m.str();
  }
  slot = r.last_step;
  return r.last_step <= o.tol;
}
// Why a run whose steps met the stopping rules is still not an answer.
std::string uncertified_message(const SolveResult& r, const SolveOptions& o) {
  std::ostringstream m;
  m << to_string(o.scheme) << " scheme: the stopping rules were met at eps = " << r.eps / o.eps_unit
    << ", but the residual of (2a) only bounds the error by " << r.bound.bound << " (plus " << r.bound.roundoff
    << " for the rounding of the bound itself) > tol = " << o.tol << ": ";
  // Blame round-off only when the bound is of the size round-off alone would give.
  if (r.bound.roundoff > 0.1 * o.tol && r.bound.bound <= 10 * r.bound.roundoff)
    m << "round-off alone allows " << r.bound.roundoff << " at this eps (eps^-1 magnifies the rounding of w - phi); "
      << "use a larger --eps-min or --eps, or a larger --tol";
  else
    m << "the iteration stopped before it solved (2a)"
      << (o.scheme == Scheme::Linear ? " (the linear scheme's steps shrink only by 1/(1 + eps lambda_1h) each, so a "
                                       "small step is not a small error); use --scheme nonlinear or a smaller --tol"
                                     : "; use a smaller --tol");
  return m.str();
}
}  // namespace

// @region linear-scheme
// Eq. (5a): linear scheme, one factorisation per eps.
LevelRecord linear_scheme_level(const Problem& p, double eps, VectorXd& w, Cholesky& chol, const SolveOptions& o,
                                double* seconds_factorize) {
  LevelRecord r;
  r.eps = eps;
  const SpMat A = p.K + (1.0 / eps) * p.M;
  factorize_timed(chol, A, seconds_factorize, eps / o.eps_unit);
  r.factorizations = 1;
  const VectorXd scaled_w = p.sampling.weights / eps;
  StepWindow steps;
  while (r.iterations < o.max_iter && r.failure.empty()) {
    const VectorXd lifted = (p.sampling.S * w).cwiseMax(p.phi);  // w - beta(w) = max(w, phi)
    const VectorXd rhs = p.F + p.sampling.S.transpose() * scaled_w.cwiseProduct(lifted);
    if (step_and_check(chol, rhs, w, eps, r, o, steps)) {
      r.converged = true;
      break;
    }
  }
  return r;
}
// @end linear-scheme

// @region nonlinear-scheme
// Eq. (3a): nonlinear scheme, refactorised when the active set K(w^n) changes.
LevelRecord nonlinear_scheme_level(const Problem& p, double eps, VectorXd& w, Cholesky& chol,
                                   const SolveOptions& o, double* seconds_factorize) {
  LevelRecord r;
  r.eps = eps;
  const int npts = p.sampling.size();
  Eigen::Matrix<bool, Eigen::Dynamic, 1> active, previous;
  VectorXd d(npts), d_phi(npts);
  StepWindow steps;
  while (r.iterations < o.max_iter && r.failure.empty()) {
    active = ((p.sampling.S * w) - p.phi).array() < 0.0;  // K(w^n) = 1 where w^n < phi
    if (r.iterations == 0 || active != previous) {
      for (int i = 0; i < npts; ++i) {
        d[i] = active[i] ? p.sampling.weights[i] / eps : 0.0;
        d_phi[i] = active[i] ? d[i] * p.phi[i] : 0.0;  // phi is finite wherever it can be active
      }
      // The symbolic analysis of K + M (in solve) serves every factorisation.
      const SpMat A = p.K + weighted_gram(p.sampling.S, d, p.grid.unknowns());
      factorize_timed(chol, A, seconds_factorize, eps / o.eps_unit);
      ++r.factorizations;
      previous = active;
    }
    const VectorXd rhs = p.F + p.sampling.S.transpose() * d_phi;
    if (step_and_check(chol, rhs, w, eps, r, o, steps)) {
      r.converged = true;
      break;
    }
  }
  return r;
}
// @end nonlinear-scheme

SolveOptions fixed_eps_options(Scheme scheme, double eps, double tol, int max_iter) {
  SolveOptions o;
  o.scheme = scheme;
  o.continuation = false;
  o.eps_start = eps;
  o.tol = tol;
  o.max_iter = max_iter;
  return o;
}

void validate(const SolveOptions& o) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument(what);
  };
  require(std::isfinite(o.tol) && o.tol > 0, "tol must be finite and > 0");
  require(o.max_iter >= 1, "max-iter must be >= 1");
  require(std::isfinite(o.eps_start) && o.eps_start > 0, "eps must be finite and > 0");
  require(std::isfinite(o.eps_min) && o.eps_min > 0, "eps-min must be finite and > 0");
  require(!o.continuation || o.eps_min <= o.eps_start, "eps-min must not exceed the starting eps");
}

SolveResult solve(const Problem& p, const SolveOptions& o) {
  validate(o);
  // The penalty schemes, their bounds and rates are written for the grid's space alone.
  if (p.kink || !p.ends.empty()) throw std::logic_error("the penalty schemes take the plain space: the problem carries the kink (D31) or the ends' functions");
  SolveResult res;
  res.w = VectorXd::Zero(p.grid.unknowns());  // starting guess w^{eps,0} = 0
  const auto t_start = Clock::now();
  Cholesky chol;
  // K + S^T W S has every pattern K + S^T D S can have: spline rows (D12) couple unknowns of
  // elements that share no node, so K's own pattern would not do.
  chol.analyze(p.K + p.M);
  res.seconds_factorize += seconds_since(t_start);
  VectorXd previous_level;
// @region continuation
  for (int s = 0;; ++s) {
    // Divide by an exact power of ten rather than repeatedly by 10, so eps_s has no drift.
    const double eps = o.eps_start / std::pow(10.0, s);
    LevelRecord r = (o.scheme == Scheme::Linear)
                        ? linear_scheme_level(p, eps, res.w, chol, o, &res.seconds_factorize)
                        : nonlinear_scheme_level(p, eps, res.w, chol, o, &res.seconds_factorize);
    res.eps = eps;
    if (previous_level.size()) r.level_change = max_nodal_abs(res.w - previous_level);
    res.levels.push_back(r);
    std::ostringstream m;
    if (!r.converged && !r.failure.empty()) {
      m << to_string(o.scheme) << " scheme did not converge at eps = " << eps / o.eps_unit << ": " << r.failure;
      res.message = m.str();
      break;
    }
    if (!r.converged) {
      m << to_string(o.scheme) << " scheme did not converge at eps = " << eps / o.eps_unit << ": " << o.max_iter
        << " iterations (max-iter) left a step of " << r.last_step << " > tol = " << o.tol;
      res.message = m.str();
      break;
    }
    if (!o.continuation || (r.level_change >= 0 && r.level_change <= o.tol)) {
      res.stopped = true;
      break;
    }
    if (eps / 10.0 < o.eps_min * (1 - 1e-12)) {
      m << "eps continuation did not converge: at eps-min = " << o.eps_min / o.eps_unit
        << " successive eps levels still differ by " << r.level_change << " > tol = " << o.tol;
      res.message = m.str();
      break;
    }
    previous_level = res.w;
  }
// @end continuation
  res.seconds_iterate = seconds_since(t_start) - res.seconds_factorize;
  const auto t_bound = Clock::now();
  res.bound = penalty_error_bound(p, res.w, res.eps, chol);
  res.seconds_bound = seconds_since(t_bound);
  // The bound is computed in floating point and can be off by about its round-off floor (D27), which
  // is an estimate, not a bound: certify only when the two together stay within tol.
  res.converged = res.stopped && res.bound.bound + res.bound.roundoff <= o.tol;
  if (res.stopped && !res.converged) res.message = uncertified_message(res, o);
  return res;
}

}  // namespace plate
