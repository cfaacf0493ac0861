// Primal-dual active sets for bounds on nodal values, and the monotone fallback that cannot cycle.
#include "primal_dual.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <unordered_set>

#include "norms.hpp"
#include "stopwatch.hpp"

namespace plate {

namespace {

// The sizes the relative tolerances refer to; never zero, so a plate without contact divides safely.
double value_scale(const VectorXd& w) { return std::max(max_nodal_abs(w), 1e-300); }
double force_scale(const VectorXd& lambda) { return std::max(lambda.cwiseAbs().maxCoeff(), 1e-300); }

// lambda_p = (K w - F)_{value of p} / W_p on held nodes: the force the obstacle must supply there.
VectorXd multipliers(const Problem& p, const VectorXd& w, const NodeSet& held) {
  const VectorXd r = p.K * w - p.F;
  VectorXd lambda = VectorXd::Zero(p.phi.size());
  for (int q = 0; q < lambda.size(); ++q)
    if (held[q]) lambda[q] = r[4 * q] / p.sampling.weights[q];
  return lambda;
}

// How many rows two sets disagree on: the active-set change one iteration makes.
int differing(const NodeSet& a, const NodeSet& b) {
  int d = 0;
  for (size_t q = 0; q < a.size(); ++q) d += a[q] != b[q];
  return d;
}

// A 64-bit fingerprint of a node set, to notice a repeated active set without storing it.
size_t fingerprint(const NodeSet& s) {
  size_t h = 1469598103934665603ull;
  for (size_t q = 0; q < s.size(); ++q)
    if (s[q]) h = (h ^ q) * 1099511628211ull;
  return h;
}

}  // namespace

namespace {

struct Step {
  VectorXd w, lambda;
};

// @region monotone-fallback
// Holds every free node at or below phi, at phi exactly. Returns whether any was strictly below.
bool hold_touching(const Problem& p, NodeSet& W, VectorXd& w) {
  bool violated = false;
  for (int q = 0; q < p.phi.size(); ++q)
    if (!W[q] && w[4 * q] <= p.phi[q]) {
      violated = violated || w[4 * q] < p.phi[q];
      W[q] = 1;
      w[4 * q] = p.phi[q];
    }
  return violated;
}

// The monotone fallback: a primal active-set method from a feasible point. The working set W holds
// every node where w touches phi, so after a node with lambda < 0 is released the step to the next
// blocking node is positive and the energy falls strictly; no W can come back, the method ends.
bool primal_active_set(const Problem& p, FixedSetSolver& fs, NodeSet& W, Step& s, const ExactOptions& o,
                       int& steps, ExactResult& res) {
  const int nodes = static_cast<int>(p.phi.size());
  // A feasible start: hold every violated node until none is (W only grows).
  for (;;) {
    s.w = fs.solve(W);
    ++steps;
    if (!hold_touching(p, W, s.w)) break;
    if (steps >= o.max_iter) return false;
  }
  while (steps < o.max_iter) {
    // s.w minimises the energy on W and is feasible.
    s.lambda = multipliers(p, s.w, W);
    res.fallback_energies.push_back(energy(p, s.w));
    const double lmax = force_scale(s.lambda);
    int j = -1;
    for (int q = 0; q < nodes; ++q)
      if (W[q] && s.lambda[q] < -o.tol * lmax && (j < 0 || s.lambda[q] < s.lambda[j])) j = q;
    if (j < 0) return true;
    W[j] = 0;
    // Move towards the minimiser on the smaller set until a free node would cross phi.
    for (;;) {
      const VectorXd target = fs.solve(W);
      ++steps;
      const VectorXd d = target - s.w;
      double alpha = 1.0;
      for (int q = 0; q < nodes; ++q)
        if (!W[q] && d[4 * q] < 0) alpha = std::min(alpha, (p.phi[q] - s.w[4 * q]) / d[4 * q]);
      s.w += alpha * d;
      if (alpha >= 1.0) {
        s.w = target;
        break;
      }
      hold_touching(p, W, s.w);
      if (steps >= o.max_iter) return false;
    }
  }
  return false;
}
// @end monotone-fallback

}  // namespace

ExactResult solve_exact_nodes(const Problem& p, const ExactOptions& o, NodeSet initial) {
  validate(o);
  if (!p.sampling.nodal_bounds()) throw std::invalid_argument("solve_exact_nodes: the rows are not bounds on nodal values");
  const auto t0 = Clock::now();
  const int nodes = static_cast<int>(p.phi.size());
  ExactResult res;
  ExactLevel level;
  level.cells = p.grid.whole_nx();
  NodeSet A = initial.empty() ? NodeSet(nodes, 0) : std::move(initial);
  if (static_cast<int>(A.size()) != nodes) throw std::invalid_argument("initial active set has the wrong size");
  for (int q = 0; q < nodes; ++q)
    if (A[q] && !std::isfinite(p.phi[q])) A[q] = 0;  // no obstacle there: nothing to hold
  level.predicted = members(A);
  if (o.on_iterate) o.on_iterate(p.grid.whole_nx(), 0, level.predicted, 0);
  FixedSetSolver fs(p.K, p.F, p.phi, o.max_correction);
  std::unordered_set<size_t> seen{fingerprint(A)};
  Step s;
  bool done = false;
// @region primal-dual-active-set
  // (D9)-(D10): solve with A held, read lambda on A, then keep the nodes that push (lambda > 0)
  // and add the free nodes that went below phi. Stop when the set repeats itself.
  while (level.pdas_iterations < o.max_iter) {
    s.w = fs.solve(A);
    ++level.pdas_iterations;
    s.lambda = multipliers(p, s.w, A);
    const double wmax = value_scale(s.w), lmax = force_scale(s.lambda);
    NodeSet next(nodes, 0);
    for (int q = 0; q < nodes; ++q)
      next[q] = A[q] ? s.lambda[q] > -o.tol * lmax : p.phi[q] - s.w[4 * q] > o.tol * wmax;
    if (o.on_iterate) o.on_iterate(p.grid.whole_nx(), level.pdas_iterations, members(A), differing(A, next));
    if (next == A) {
      done = true;
      break;
    }
    if (!seen.insert(fingerprint(next)).second) {
      res.cycled = true;
      break;
    }
    A.swap(next);
  }
// @end primal-dual-active-set
  if (!done && o.globalise) {
    done = primal_active_set(p, fs, A, s, o, level.primal_steps, res);
  }
  res.w = std::move(s.w);
  res.lambda = std::move(s.lambda);
  res.active = std::move(A);
  res.certificate = certify(p, res.w, res.lambda);
  std::ostringstream m;
  if (!done) {
    if (res.cycled && !o.globalise)
      m << "the primal-dual active-set iteration cycled (an active set came back after " << level.pdas_iterations
        << " iterations) and globalisation is off";
    else
      m << "the active-set iterations did not finish in max-iter = " << o.max_iter << " steps";
  } else if (!(res.certificate.worst() <= o.tol)) {  // a NaN entry fails too
    m << certificate_failure(res.certificate, o.tol);
  }
  res.message = m.str();
  res.converged = res.message.empty();
  level.active = members(res.active);
  level.factorizations = fs.factorizations();
  level.correction_columns = fs.correction_columns();
  level.seconds = seconds_since(t0);
  res.levels.push_back(level);
  return res;
}

}  // namespace plate
