// Our side of the cross-check, and the rule that decides whether two codes agree.
#include "crosscheck.hpp"

#include <cmath>
#include <stdexcept>

#include "cholesky.hpp"
#include "contact.hpp"
#include "norms.hpp"
#include "schemes.hpp"
#include "stopwatch.hpp"

namespace plate {

CheckValues solve_ours(int n, SamplingKind kind, const Field& phi, const CrossSettings& s) {
  const auto t0 = Clock::now();
  const Grid g = make_grid(n);
  const Problem p = make_problem(g, kind, phi, [](double, double) { return 0.0; });
  SolveOptions o;
  o.scheme = Scheme::Nonlinear;
  o.tol = s.tol;
  o.eps_start = s.eps_start;
  o.eps_min = s.eps_min;
  const SolveResult r = solve(p, o);
  CheckValues v;
  v.code = std::string("bfs-") + to_string(kind);
  v.grid = std::to_string(n) + " x " + std::to_string(n);
  v.h = g.h;
  v.unknowns = g.unknowns();
  v.converged = r.converged;
  v.iterations = r.total_iterations();
  v.eps_final = r.eps;
  v.max_w = max_nodal_abs(r.w);
  v.w_rim = evaluate(g, r.w, kCheckPoints[0][0], kCheckPoints[0][1]).w;
  v.w_mid = evaluate(g, r.w, kCheckPoints[1][0], kCheckPoints[1][1]).w;
  v.w_diag = evaluate(g, r.w, kCheckPoints[2][0], kCheckPoints[2][1]).w;
  v.force = total_contact_force(p, contact_force_density(p, r.w, r.eps));
  v.seconds = seconds_since(t0);
  return v;
}

double uniform_load_centre_ours(int n) {
  const Grid g = make_grid(n);
  Cholesky c;
  c.factorize(assemble_matrix(g, bfs_stiffness(g.h)));
  return evaluate(g, c.solve(assemble_load(g, [](double, double) { return 1.0; })), 0.5, 0.5).w;
}

std::vector<double> values_of(const std::vector<CheckValues>& runs, double CheckValues::*field) {
  std::vector<double> v;
  for (const auto& r : runs) v.push_back(r.*field);
  return v;
}

double last_increment(const std::vector<double>& values) {
  if (values.size() < 2) throw std::invalid_argument("last_increment: need at least two grids");
  return std::abs(values.back() - values[values.size() - 2]);
}

double error_bound(const std::vector<double>& values) {
  const double last = last_increment(values);
  if (values.size() < 3) return last;
  return std::max(last, std::abs(values[values.size() - 2] - values[values.size() - 3]));
}

bool agree(const std::vector<double>& a, const std::vector<double>& b, double* difference, double* tolerance) {
  *difference = std::abs(a.back() - b.back());
  *tolerance = error_bound(a) + error_bound(b);
  return *difference <= *tolerance;
}

}  // namespace plate
