// Our side of the cross-check, and the rule that decides whether two codes agree.
#include "crosscheck.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "active_set.hpp"
#include "cholesky.hpp"
#include "contact.hpp"
#include "line_force.hpp"
#include "norms.hpp"
#include "roundoff.hpp"
#include "stopwatch.hpp"

namespace plate {

CheckValues solve_ours(const Scene& s, int n, const SamplingSpec& spec) {
  const EdgeCurve& rim = s.edge;
  const double radius = rim.r;
  const auto t0 = Clock::now();
  const SceneSolution scene = solve_exact_scene(s, n, spec, ExactOptions{});
  const Problem& p = scene.whole();
  const ExactResult& x = scene.result;
  CheckValues v;
  v.code = std::string("bfs-") + to_string(spec.kind);
  v.grid = std::to_string(n) + " x " + std::to_string(n);
  v.cells = n;
  v.h = p.grid.h;
  v.unknowns = p.grid.unknowns();
  v.certified = x.converged;
  for (const ExactLevel& l : x.levels) v.iterations += l.pdas_iterations;
  v.max_w = max_nodal_abs(x.w);
  for (const CheckPoint& c : kCheckPoints) v.w_at.push_back(evaluate(p, x.w, c.x, c.y).w);
  // Round-off of the problem solved (the part, when mirrors were used), at the whole plate's points.
  const SolutionRoundoff roundoff(scene.solved, scene.part_w, scene.part_lambda);
  const Grid& g = p.grid;
  Eigen::MatrixXd outputs(scene.solved.grid.unknowns(), 1 + std::size(kCheckPoints));
  int top = 0;  // the unknown of max |w|: a nodal value
  for (int i = 0; i < g.unknowns(); i += 4)
    if (std::abs(x.w[i]) > std::abs(x.w[top])) top = i;
  const int node = top / 4, i_top = node % (g.nx - 1) + 1, j_top = node / (g.nx - 1) + 1;
  outputs.col(0) = roundoff.point_value(g.x(i_top), g.y(j_top));
  for (size_t k = 0; k < std::size(kCheckPoints); ++k) outputs.col(1 + k) = roundoff.point_value(kCheckPoints[k].x, kCheckPoints[k].y);
  v.noise_w = roundoff.of(outputs);
  // A refined answer is the same on every machine to its last correction, far below the estimate
  // above for the unrefined solve (the same rule as the continuum study's).
  require_not_undone(x.levels.back().refinement, "crosscheck");
  if (const Refinement& refined = x.levels.back().refinement; !refined.w.empty()) {
    for (double& noise : v.noise_w) noise = refined.noise_w(x.w);
    v.force_floor = refined.relative_noise_mu();
  }
  v.force = total_contact_force(p, x.lambda);
  v.mean_line = v.force / (2 * M_PI * radius);  // with f = 0 the whole push is on the rim
  v.line = line_force(p, x.lambda);
  // The spline's own values; point rows scatter, so theirs come from the cos 4k theta fit (NaN without edge rows).
  const bool spline = v.line.spline_degree > 0;
  v.q0 = spline ? line_force_value(v.line, 0) : line_force_fit(v.line, 0);
  v.q45 = spline ? line_force_value(v.line, M_PI / 4) : line_force_fit(v.line, M_PI / 4);
  if (v.line.empty()) v.line = binned_line_force(p, x.lambda, rim, kRimBins);
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

std::vector<double> values_at(const std::vector<CheckValues>& runs, int point) {
  std::vector<double> v;
  for (const auto& r : runs) v.push_back(r.w_at.at(point));
  return v;
}

// @region agreement
// Two limits agree within the sum of their error bars, each at least what round-off can move. A
// difference within ten times the limits' round-off (where fmt_above stops printing digits) is not
// resolved, and is no evidence that they differ: a rebuild can move it that far.
Agreement compare_limits(const Extrapolation& a, const Extrapolation& b) {
  Agreement g;
  g.difference = std::abs(a.limit - b.limit);
  g.tolerance = std::max(a.bar, a.bar_noise) + std::max(b.bar, b.bar_noise);
  g.difference_noise = a.limit_noise + b.limit_noise;
  g.tolerance_noise = a.bar_noise + b.bar_noise;
  g.agree = g.difference <= g.tolerance || g.difference < 10 * g.difference_noise;
  g.steady = a.steady && b.steady;
  return g;
}
// @end agreement

double last_increment(const std::vector<double>& values) {
  if (values.size() < 2) throw std::invalid_argument("last_increment: need at least two grids");
  return std::abs(values.back() - values[values.size() - 2]);
}

}  // namespace plate
