// Post-processing: Hermite evaluation, contact force and moments.
#include "contact.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace plate {

namespace {
// The coefficients of w on element (ex, ey): 0 for the clamped unknowns.
Vector16 coefficients_in(const Grid& g, const VectorXd& w, int ex, int ey) {
  const auto dofs = g.element_dofs(ex, ey);
  Vector16 c;
  for (int k = 0; k < 16; ++k) c[k] = dofs[k] >= 0 ? w[dofs[k]] : 0.0;
  return c;
}

PointValues evaluate_in(const Grid& g, const VectorXd& w, int ex, int ey, double t, double s) {
  const LocalBasis b = bfs_basis(t, s, g.h);
  const Vector16 c = coefficients_in(g, w, ex, ey);
  return {c.dot(b.v), c.dot(b.dx), c.dot(b.dy), c.dot(b.dxx), c.dot(b.dxy), c.dot(b.dyy)};
}

double value_in(const Grid& g, const VectorXd& w, int ex, int ey, double t, double s) {
  return coefficients_in(g, w, ex, ey).dot(bfs_values(t, s, g.h));
}

void locate_or_throw(const Grid& g, double x, double y, int& ex, int& ey, double& t, double& s, int& flips) {
  if (g.locate(x, y, ex, ey, t, s, &flips)) return;
  std::ostringstream m;
  m << "point (" << x << ", " << y << ") is outside the plate [0, " << g.whole_lx() << "] x [0, " << g.whole_ly() << "]";
  throw std::invalid_argument(m.str());
}
}  // namespace

PointValues evaluate(const Grid& g, const VectorXd& w, double x, double y) {
  int ex, ey, flips = 0;
  double t, s;
  locate_or_throw(g, x, y, ex, ey, t, s, flips);
  PointValues v = evaluate_in(g, w, ex, ey, t, s);
  // The mirror image of a symmetric plate: slopes across the line change sign, and w_xy with each.
  if (flips & 1) v.wx = -v.wx, v.wxy = -v.wxy;
  if (flips & 2) v.wy = -v.wy, v.wxy = -v.wxy;
  return v;
}

namespace {
PointValues plus(const PointValues& a, const PointValues& b) {
  return {a.w + b.w, a.wx + b.wx, a.wy + b.wy, a.wxx + b.wxx, a.wxy + b.wxy, a.wyy + b.wyy};
}
}  // namespace

PlateField::PlateField(const Problem& p, const VectorXd& w) : p_(p), w_(w) {
  const int N = p.grid.unknowns();
  if (p.kink) c_ = w.segment(N, p.kink->size()), Pc_ = p.kink_interp * c_;
  if (!p.ends.empty()) e_ = w.segment(N + p.kink_size(), static_cast<Eigen::Index>(p.ends.size()));
}

// The enrichment's share (D31) at (x, y), with its interpolant's part I read by the caller.
PointValues PlateField::share(const PointValues& I, double x, double y, const int* cell) const {
  const KinkValue k = kink_field(*p_.kink, c_, KinkValue{I.w, I.wx, I.wy, I.wxx, I.wxy, I.wyy}, x, y, cell);
  return {k.w, k.wx, k.wy, k.wxx, k.wxy, k.wyy};
}

// The ends' share at (x, y), with I_h F of `cell` (read at its local t, s) if given. Their functions
// live on the grid's part of the plate (attach_ends keeps each cut-off clear of the mirror lines),
// so a point of a mirror image is read at its image in the part, with the slopes across the line
// turned as evaluate turns them.
PointValues PlateField::ends_at(double x, double y, const int* cell, double t, double s) const {
  PointValues v{0, 0, 0, 0, 0, 0};
  if (p_.ends.empty()) return v;
  const Grid& g = p_.grid;
  int flips = 0;
  if (g.mirror_x && x > g.lx()) x = 2 * g.lx() - x, flips |= 1;
  if (g.mirror_y && y > g.ly()) y = 2 * g.ly() - y, flips |= 2;
  for (size_t f = 0; f < p_.ends.size(); ++f) {
    const EndDerivatives d = cell ? end_function_derivatives_in(p_.ends[f], p_.end_fields[f], g, cell[0], cell[1], t, s, x, y)
                                  : end_function_derivatives(p_.ends[f], p_.end_fields[f], g, x, y);
    const double c = e_[static_cast<Eigen::Index>(f)];
    v = plus(v, {c * d.w, c * d.wx, c * d.wy, c * d.wxx, c * d.wxy, c * d.wyy});
  }
  if (flips & 1) v.wx = -v.wx, v.wxy = -v.wxy;
  if (flips & 2) v.wy = -v.wy, v.wxy = -v.wxy;
  return v;
}

PointValues PlateField::enrichment_at(double x, double y) const {
  const PointValues e = ends_at(x, y, nullptr, 0, 0);
  if (!p_.kink || !kink_near(*p_.kink, x, y)) return e;
  const PointValues k = share(evaluate(p_.grid, Pc_, x, y), x, y);
  return p_.ends.empty() ? k : plus(e, k);
}

PointValues PlateField::enrichment_in(int ex, int ey, double t, double s, double x, double y) const {
  const int cell[2] = {ex, ey};
  const PointValues e = ends_at(x, y, cell, t, s);
  if (!p_.kink || !kink_near(*p_.kink, x, y)) return e;
  const PointValues k = share(evaluate_in(p_.grid, Pc_, ex, ey, t, s), x, y, cell);
  return p_.ends.empty() ? k : plus(e, k);
}

PointValues PlateField::at(double x, double y) const {
  const PointValues v = evaluate(p_.grid, w_, x, y);
  return p_.kink || !p_.ends.empty() ? plus(v, enrichment_at(x, y)) : v;
}

double PlateField::value_at(double x, double y) const {
  if (!p_.ends.empty()) return at(x, y).w;
  int ex, ey, flips = 0;
  double t, s;
  locate_or_throw(p_.grid, x, y, ex, ey, t, s, flips);
  const double v = value_in(p_.grid, w_, ex, ey, t, s);  // a mirror image's value is the point's own
  if (!p_.kink) return v;
  if (!kink_near(*p_.kink, x, y)) return v + 0.0;  // as at() adds the enrichment's zero
  return v + kink_value(*p_.kink, c_, value_in(p_.grid, Pc_, ex, ey, t, s), x, y);
}

PointValues evaluate(const Problem& p, const VectorXd& w, double x, double y) { return PlateField(p, w).at(x, y); }

// @region moments
// Moments after (9), with Kirchhoff's sign of nu.
Moments bending_moments(double wxx, double wxy, double wyy, double nu) {
  return {-(wxx + nu * wyy), -(1.0 - nu) * wxy, -(wyy + nu * wxx)};
}
// @end moments

// @region contact-force
// Eq. (9): contact force density xi = -eps^{-1} beta(w) at the sample points.
VectorXd contact_force_density(const Problem& p, const VectorXd& w, double eps) {
  return (p.phi - p.sampling.S * w).cwiseMax(0.0) / eps;
}
// @end contact-force

double total_contact_force(const Problem& p, const VectorXd& xi) { return p.sampling.weights.dot(xi); }

double constraint_violation(const Problem& p, const VectorXd& w) {
  return (p.phi - p.sampling.S * w).cwiseMax(0.0).maxCoeff();
}

// @region penalty-residual
// Eq. (2a): residual of the discrete penalised equation.
double penalty_residual(const Problem& p, const VectorXd& w, double eps) {
  const VectorXd Kw = p.K * w;
  const VectorXd xi = contact_force_density(p, w, eps);
  const VectorXd r = Kw - p.F - p.sampling.S.transpose() * p.sampling.weights.cwiseProduct(xi);
  const double scale = Kw.norm() + p.F.norm();
  return scale > 0 ? r.norm() / scale : r.norm();
}
// @end penalty-residual

// Measured against the size of the terms that cancel, not against ||K w||: on fine grids with a
// small eps those terms are 1/eps times larger than their sum, and a backward-stable solve leaves
// a residual of round-off relative to them, whatever the conditioning.
double penalty_backward_error(const Problem& p, const VectorXd& w, double eps) {
  const VectorXd xi = contact_force_density(p, w, eps);
  const VectorXd r = p.K * w - p.F - p.sampling.S.transpose() * p.sampling.weights.cwiseProduct(xi);
  const VectorXd xi_size = (p.phi.cwiseAbs() + p.sampling.S.cwiseAbs() * w.cwiseAbs()) / eps;
  const VectorXd active_size = (xi.array() > 0).select(xi_size, 0.0);
  const VectorXd size = p.K.cwiseAbs() * w.cwiseAbs() + p.F.cwiseAbs() +
                        p.sampling.S.cwiseAbs().transpose() * p.sampling.weights.cwiseProduct(active_size);
  const double scale = size.lpNorm<Eigen::Infinity>();
  return scale > 0 ? r.lpNorm<Eigen::Infinity>() / scale : r.lpNorm<Eigen::Infinity>();
}

EdgeDip deepest_dip_below_edge(const Problem& p, const VectorXd& w) {
  const Field& obstacle = p.scene.obstacle;
  if (!has_edge(p.spec.kind) || p.scene.edge.empty()) return {};
  const EdgePoints e = edge_points(p.scene.edge, p.grid.h / 32);
  EdgeDip dip{0, NAN};
  const PlateField field(p, w);
  // On a part (mirror.hpp) the plate beyond a mirror line is the image of the part's own, so only
  // the edge's points on the part are read: a quarter of them on the paper's scene.
  const Grid& g = p.grid;
  const double beyond_x = g.lx() + 1e-12 * g.whole_lx(), beyond_y = g.ly() + 1e-12 * g.whole_ly();
  // A scene's symmetry gives its images dips that differ by round-off of w alone: two places more
  // than a cell apart within 1e-13 of phi tie, and the first along the edge keeps the place, so
  // that every build names the same one (extrema.cpp does the same for the field's extremes).
  double at_x = 0, at_y = 0;
  for (int k = 0; k < e.size(); ++k) {
    if ((g.mirror_x && e.x[k] > beyond_x) || (g.mirror_y && e.y[k] > beyond_y)) continue;
    const double phi = obstacle_on_edge(obstacle, e.x[k], e.y[k], e.nx[k], e.ny[k], p.grid.h);
    const double below = std::isfinite(phi) ? phi - field.value_at(e.x[k], e.y[k]) : 0.0;
    if (!(below > dip.depth)) continue;
    const bool first = dip.depth == 0, near = std::hypot(e.x[k] - at_x, e.y[k] - at_y) <= g.h;
    if (first || near || below - dip.depth > 1e-13 * std::abs(phi))
      dip = {below, e.theta.empty() ? NAN : e.theta[k]}, at_x = e.x[k], at_y = e.y[k];
  }
  return dip;
}

double dip_below_edge(const Problem& p, const VectorXd& w) { return deepest_dip_below_edge(p, w).depth; }

NodalFields nodal_fields(const Problem& p, const VectorXd& w, double eps, double nu) {
  return nodal_fields(p, w, contact_force_density(p, w, eps), nu);
}

NodalFields nodal_fields(const Problem& p, const VectorXd& w, const VectorXd& xi_samples, double nu) {
  const Field& obstacle = p.scene.obstacle;
  const Grid& g = p.grid;
  const VectorXd force = p.sampling.S.transpose() * p.sampling.weights.cwiseProduct(xi_samples);
  const PlateField field(p, w);
  NodalFields f;
  for (int j = 0; j <= g.ny; ++j)
    for (int i = 0; i <= g.nx; ++i) {
      PointValues avg{0, 0, 0, 0, 0, 0};
      int count = 0;
      for (int ey = std::max(0, j - 1); ey <= std::min(g.ny - 1, j); ++ey)
        for (int ex = std::max(0, i - 1); ex <= std::min(g.nx - 1, i); ++ex) {
          // With (D31), each element's own share: its curvatures jump across the sides as the grid's do.
          const PointValues v = plus(evaluate_in(g, w, ex, ey, i - ex, j - ey),
                                     field.enrichment_in(ex, ey, i - ex, j - ey, g.x(i), g.y(j)));
          avg = {avg.w + v.w, avg.wx + v.wx, avg.wy + v.wy, avg.wxx + v.wxx, avg.wxy + v.wxy, avg.wyy + v.wyy};
          ++count;
        }
      const double k = 1.0 / count;
      const double x = g.x(i), y = g.y(j), phi = obstacle(x, y);
      const double value = avg.w * k;
      const double xi = g.is_interior(i, j) ? force[g.dof(i, j, kW)] / (g.h * g.h) : 0.0;
      const Moments m = bending_moments(avg.wxx * k, avg.wxy * k, avg.wyy * k, nu);
      f.x.push_back(x);
      f.y.push_back(y);
      f.w.push_back(value);
      f.wx.push_back(avg.wx * k);
      f.wy.push_back(avg.wy * k);
      f.wxx.push_back(avg.wxx * k);
      f.wxy.push_back(avg.wxy * k);
      f.wyy.push_back(avg.wyy * k);
      f.phi.push_back(phi);
      f.xi.push_back(xi);
      f.m11.push_back(m.m11);
      f.m12.push_back(m.m12);
      f.m22.push_back(m.m22);
      f.contact.push_back(xi > 0);
    }
  return f;
}

NodalExtremes nodal_extremes(const NodalFields& f) {
  NodalExtremes e;
  for (int k = 0; k < f.size(); ++k) {
    if (f.w[k] > e.max_w) e.max_w = f.w[k], e.argmax_w = k;
    e.max_xi = std::max(e.max_xi, f.xi[k]);
    e.max_abs_m12 = std::max(e.max_abs_m12, std::abs(f.m12[k]));
    if (f.contact[k]) e.contact.push_back(k);
  }
  return e;
}

}  // namespace plate
