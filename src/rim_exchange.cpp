// The contact read off a solve, the layout it calls for, and the exchange of rows where the plate dips.
#include "rim_exchange.hpp"

#include <algorithm>
#include <cmath>

#include "contact.hpp"

namespace plate {

namespace {
// The knot spacing of (D12) on p's circle, as an angle.
double knot_angle(const Problem& p) { return 2 * M_PI / spline_knots(p.scene.edge.r, p.grid.h, rows_on(p.grid, p.scene, p.spec)); }
double cell_angle(const Problem& p) { return p.grid.h / p.scene.edge.r; }
// The lattice of the exchange: eight steps to each spacing of the points of edge_points.
double exchange_step(size_t points) { return 2 * M_PI / (8.0 * points); }
}  // namespace

bool rim_follows_contact(const Problem& p) {
  return p.spec.rows.kind == EdgeRows::Kind::Auto && has_edge(p.spec.kind) &&
         p.scene.edge.kind == EdgeCurve::Kind::Circle && p.sampling.edge_spline_degree > 0;
}

namespace {
bool in_contact(const Problem& p, const VectorXd& Sw, const VectorXd& lambda, double touch, int row) {
  return lambda[row] > 0 || Sw[row] - p.phi[row] <= touch;
}
}  // namespace

ContactArcs rim_contact(const Problem& p, const VectorXd& w, const VectorXd& lambda, double touch) {
  const Sampling& s = p.sampling;
  const VectorXd Sw = s.S * w;
  std::vector<double> at, reach;
  std::vector<bool> touching;
  for (int k = 0; k < s.edge_size(); ++k) {
    const bool t = in_contact(p, Sw, lambda, touch, s.edge_begin + k);
    // The plate touches at points about a cell apart between point rows (only there can its cubics
    // meet the obstacle): a point row's contact reaches a cell to each side, so such points join up.
    const double d = !s.rim_rows.empty() && s.rim_rows[k].point() ? cell_angle(p) : 0.0;
    for (double a : mirror_angles(p.grid, s.edge.theta[k])) at.push_back(a), touching.push_back(t), reach.push_back(d);
  }
  return contact_arcs(at, touching, reach);
}

RimLayout rim_layout_for(const Problem& p, const ContactArcs& contact) {
  const double cell = cell_angle(p);
  const std::vector<double> lattice = edge_points(p.scene.edge, p.grid.h).theta;
  return layout_for(contact, 2 * cell, 2 * cell, knot_angle(p), lattice, exchange_step(lattice.size()));
}

RimLayout rim_points_only(const Problem& p) {
  const std::vector<double> lattice = edge_points(p.scene.edge, p.grid.h).theta;
  return layout_for(ContactArcs{}, 0, 0, knot_angle(p), lattice, exchange_step(lattice.size()));
}

bool rim_layout_fits(const Problem& p, const VectorXd& w, const VectorXd& lambda, double touch) {
  const Sampling& s = p.sampling;
  const VectorXd Sw = s.S * w;
  for (int k = 0; k < s.edge_size(); ++k)
    if (!s.rim_rows[k].point() && !in_contact(p, Sw, lambda, touch, s.edge_begin + k)) return false;
  return s.rim.periodic || arcs_inside(s.rim, rim_contact(p, w, lambda, touch), cell_angle(p));
}

double cells_inside_spline_arc(const Problem& p, double theta) {
  const Sampling& s = p.sampling;
  if (!(s.edge_spline_degree > 0) || !std::isfinite(theta)) return NAN;
  if (s.rim.periodic) return INFINITY;
  for (const SplineArc& a : s.rim.arcs)
    if (a.contains(theta)) {
      double along = std::fmod(theta - a.begin(), 2 * M_PI);  // an arc may be longer than pi
      if (along < 0) along += 2 * M_PI;
      return std::max(0.0, std::min(along, a.end() - a.begin() - along)) / cell_angle(p);
    }
  return NAN;
}

// @region rim-dips
std::vector<double> rim_dips(const Problem& p, const VectorXd& w, double slack) {
  const Field& obstacle = p.scene.obstacle;
  const Grid& g = p.grid;
  const EdgeCurve& c = p.scene.edge;
  const Sampling& s = p.sampling;
  const PlateField field(p, w);
  auto point = [&](double t, double& x, double& y) { x = c.cx + c.r * std::cos(t), y = c.cy + c.r * std::sin(t); };
  auto gap = [&](double t) {
    double x, y;
    point(t, x, y);
    return field.value_at(x, y) - obstacle_on_edge(obstacle, x, y, -std::cos(t), -std::sin(t), g.h);
  };
  auto free_here = [&](double t) {  // on the grid's part and off every spline arc
    double x, y;
    point(t, x, y);
    const double tol = 1e-9 * g.h;
    if ((g.mirror_x && x > g.lx() + tol) || (g.mirror_y && y > g.ly() + tol)) return false;
    for (const SplineArc& a : s.rim.arcs)
      if (a.contains(t)) return false;
    return true;
  };
  // The lattice: eight points between neighbouring points of edge_points, the same for every mirror
  // image and for every path the exchange takes, so that the rows a solve ends with do not depend on
  // the order it found them in, and the part of a symmetric plate and the whole add the same ones.
  const double dt = exchange_step(edge_points(c, g.h).theta.size());
  const int steps = static_cast<int>(std::lround(2 * M_PI / dt));
  std::vector<double> values(steps);
  for (int k = 0; k < steps; ++k) values[k] = free_here(k * dt) ? gap(k * dt) : INFINITY;
  std::vector<bool> held(steps, false);
  for (int r = 0; r < s.edge_size(); ++r)
    if (s.rim_rows[r].point()) {
      const long k = std::lround(s.edge.theta[r] / dt);
      if (std::abs(s.edge.theta[r] - k * dt) <= 1e-12) held[((k % steps) + steps) % steps] = true;
    }
  std::vector<double> found;
  for (int k = 0; k < steps; ++k) {
    const double v = values[k];
    if (held[k] || !(v < -slack) || v > values[(k + steps - 1) % steps] || v > values[(k + 1) % steps]) continue;
    found.push_back(k * dt);
  }
  return found;
}
// @end rim-dips

}  // namespace plate
