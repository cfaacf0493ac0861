#include "eps_sweep.hpp"

#include <cmath>

#include "contact.hpp"
#include "norms.hpp"
#include "stopwatch.hpp"

namespace plate {

SweepRow sweep_row(const Problem& p, Scheme scheme, double eps, double tol, int max_iter, const VectorXd& reference) {
  SolveOptions o = fixed_eps_options(scheme, eps, tol, max_iter);
  SweepRow row;
  VectorXd last = VectorXd::Zero(p.grid.unknowns());
  o.on_iterate = [&](double, int k, const VectorXd& w) {
    if (k == 1) row.first_step = max_nodal_abs(w);
    row.steps.push_back(m_norm(p, w - last));
    last = w;
  };
  const auto t0 = Clock::now();
  const SolveResult r = solve(p, o);
  row.seconds = seconds_since(t0);
  row.scheme = scheme;
  row.eps = eps;
  row.tol = tol;
  row.stopped = r.stopped;
  row.converged = r.converged;
  row.message = r.message;
  row.iterations = r.total_iterations();
  row.factorizations = r.levels.empty() ? 0 : r.levels[0].factorizations;
  row.bound = r.bound;
  row.violation = constraint_violation(p, r.w);
  row.error = max_nodal_abs(r.w - reference);
  row.w = r.w;
  return row;
}

double predicted_linear_iterations(double first_step, double tol, double eps, double lambda1) {
  return 1.0 + std::log(first_step / tol) / std::log1p(eps * lambda1);
}

}  // namespace plate
