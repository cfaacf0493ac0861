// The penalty over the true disk, square by square (D30).
#include "penalty_integral.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "bfs_element.hpp"
#include "cholesky.hpp"
#include "norms.hpp"
#include "refinement.hpp"

namespace plate {

namespace {

const Cylinder& cylinder_of(const Problem& p) {
  if (!p.scene.cylinder) throw std::invalid_argument("the penalty over the true disk needs a cylinder obstacle");
  return *p.scene.cylinder;
}

// w_h - shift on square (ex, ey) as a bicubic: its value and derivatives at the corners are
// unknowns of (8) (zero on a clamped edge).
Bicubic field_on(const Grid& g, const std::array<int, 16>& dofs, const VectorXd& w, double shift) {
  std::array<CornerJet, 4> c;
  for (int a = 0; a < 4; ++a) {
    auto value = [&](int comp) { return dofs[4 * a + comp] >= 0 ? w[dofs[4 * a + comp]] : 0.0; };
    c[a] = {value(kW) - shift, value(kWx), value(kWy), value(kWxy)};
  }
  return bicubic_from_corners(c, g.h, g.h);
}

// Calls f with each square's unknowns and the points of its part of the region.
void for_each_square(const Problem& p, const VectorXd* w, ImplicitOrders orders,
                     const std::function<void(const std::array<int, 16>&, double, double, const std::vector<WeightedPoint>&)>& f) {
  const Cylinder& d = cylinder_of(p);
  const Grid& g = p.grid;
  std::vector<WeightedPoint> pts;
  for (int ey = 0; ey < g.ny; ++ey)
    for (int ex = 0; ex < g.nx; ++ex) {
      const double x0 = g.x(ex), y0 = g.y(ey);
      // A square the circle's disk cannot reach: its nearest point is farther than the radius.
      const double nx = std::clamp(d.cx, x0, x0 + g.h) - d.cx, ny = std::clamp(d.cy, y0, y0 + g.h) - d.cy;
      if (nx * nx + ny * ny > d.radius * d.radius) continue;
      const std::array<int, 16> dofs = g.element_dofs(ex, ey);
      std::vector<Bicubic> psi{circle_on(d.cx, d.cy, d.radius, x0, y0, g.h)};
      if (w) psi.push_back(field_on(g, dofs, *w, d.height));
      pts.clear();
      implicit_rule(x0, y0, g.h, g.h, psi, orders, pts);
      if (!pts.empty()) f(dofs, x0, y0, pts);
    }
}

}  // namespace

PenaltyRule penalty_rule(const Problem& p, const VectorXd* w, ImplicitOrders orders) {
  PenaltyRule r;
  std::vector<Eigen::Triplet<double>> t;
  std::vector<double> weights;
  const double h = p.grid.h;
  for_each_square(p, w, orders, [&](const std::array<int, 16>& dofs, double x0, double y0, const std::vector<WeightedPoint>& pts) {
    for (const WeightedPoint& q : pts) {
      const int row = static_cast<int>(weights.size());
      const Vector16 v = bfs_basis((q.x - x0) / h, (q.y - y0) / h, h).v;
      for (int k = 0; k < 16; ++k)
        if (dofs[k] >= 0) t.emplace_back(row, dofs[k], v[k]);
      r.x.push_back(q.x), r.y.push_back(q.y), weights.push_back(q.weight);
    }
  });
  r.weights = Eigen::Map<const VectorXd>(weights.data(), static_cast<Eigen::Index>(weights.size()));
  r.S.resize(static_cast<Eigen::Index>(weights.size()), p.grid.unknowns());
  r.S.setFromTriplets(t.begin(), t.end());
  return r;
}

// Corrections below this fraction of w that stop shrinking are round-off.
constexpr double kRoundoffStep = 1e-12;

// @region penalised-newton
PenalisedSolve solve_penalised_exactly(const Problem& p, double eps, VectorXd w, double tol, int max_iter,
                                       ImplicitOrders orders) {
  if (!(eps > 0) || !std::isfinite(eps)) throw std::invalid_argument("eps must be finite and > 0");
  const double height = cylinder_of(p).height, h = p.grid.h;
  // Every matrix below has the pattern of K and of every square the disk reaches (explicit zeros
  // where the region misses a square), so one symbolic analysis serves each factorisation.
  SpMat base;
  {
    std::vector<Eigen::Triplet<double>> t;
    for_each_square(p, nullptr, {1, 1}, [&](const std::array<int, 16>& dofs, double, double, const std::vector<WeightedPoint>&) {
      for (int i : dofs)
        for (int j : dofs)
          if (i >= 0 && j >= 0) t.emplace_back(i, j, 0.0);
    });
    base.resize(p.K.rows(), p.K.cols());
    base.setFromTriplets(t.begin(), t.end());
    base += p.K;
  }
  Cholesky chol;
  chol.analyze(base);
  PenalisedSolve s;
  const VectorXd none = VectorXd::Zero(p.sampling.size());
  while (s.iterations < max_iter) {
    // (3a) at w^n as a correction: (K + eps^-1 int_D v v^T) dw = F + eps^-1 int_D (phi - w^n) v - K w^n,
    // D the part of the disk where w^n < phi. The right side is the residual of (2a), with K w^n
    // in long double element by element (D21) and each square's penalty summed in long double: in
    // double the rounding of K alone would leave w some u cond(K) off, 1e-8 relative at n = 512
    // (measured).
    std::vector<Eigen::Triplet<double>> t;
    VectorXd r = extended_residual(p, w, none);
    for_each_square(p, &w, orders, [&](const std::array<int, 16>& dofs, double x0, double y0, const std::vector<WeightedPoint>& pts) {
      Matrix16 G = Matrix16::Zero();
      Eigen::Matrix<long double, 16, 1> b = Eigen::Matrix<long double, 16, 1>::Zero();
      for (const WeightedPoint& q : pts) {
        const Vector16 v = bfs_basis((q.x - x0) / h, (q.y - y0) / h, h).v;
        G.noalias() += (q.weight / eps) * v * v.transpose();
        long double gap = height;
        for (int k = 0; k < 16; ++k)
          if (dofs[k] >= 0) gap -= static_cast<long double>(v[k]) * w[dofs[k]];
        b += (static_cast<long double>(q.weight) / eps * gap) * v.cast<long double>();
      }
      for (int i = 0; i < 16; ++i) {
        if (dofs[i] < 0) continue;
        r[dofs[i]] += static_cast<double>(b[i]);
        for (int j = 0; j < 16; ++j)
          if (dofs[j] >= 0) t.emplace_back(dofs[i], dofs[j], G(i, j));
      }
    });
    SpMat A(p.K.rows(), p.K.cols());
    A.setFromTriplets(t.begin(), t.end());
    A += base;
    chol.factorize(A);
    const VectorXd dw = chol.solve(r);
    if (!dw.allFinite()) break;
    const double previous = s.last_step;
    s.last_step = max_nodal_abs(dw);
    w += dw;
    ++s.iterations;
    const double scale = std::max(max_nodal_abs(w), 1e-300);
    // Newton's corrections shrink quadratically until round-off stops them: one that no longer falls
    // by a factor 4, once below kRoundoffStep of w, is round-off, and w is as good as it gets.
    if (s.last_step <= tol * scale || (s.iterations > 2 && s.last_step > previous / 4 && s.last_step <= kRoundoffStep * scale)) {
      s.converged = true;
      break;
    }
  }
  s.w = std::move(w);
  return s;
}
// @end penalised-newton

std::vector<VectorXd> penalised_path_exactly(const Problem& p, const std::vector<double>& eps, ImplicitOrders orders) {
  std::vector<VectorXd> path;
  VectorXd w = VectorXd::Zero(p.grid.unknowns());
  for (size_t k = 0; k < eps.size(); ++k) {
    if (k > 0 && !(eps[k] < eps[k - 1])) throw std::invalid_argument("penalised_path_exactly: eps must decrease");
    // The decades above eps[k] that the path has not visited yet, then eps[k] itself.
    const double from = k == 0 ? 0.1 : eps[k - 1] / 10;
    for (double e = from; e > eps[k] * (1 + 1e-9); e /= 10) w = solve_penalised_exactly(p, e, w, 1e-14, 60, orders).w;
    const PenalisedSolve s = solve_penalised_exactly(p, eps[k], w, 1e-14, 60, orders);
    if (!s.converged)
      throw std::runtime_error("Newton's method on the penalised problem did not converge at eps = " + std::to_string(eps[k]) +
                               " (last correction " + std::to_string(s.last_step) + ")");
    w = s.w;
    path.push_back(w);
  }
  return path;
}

double penalised_force(const Problem& p, const PenaltyRule& rule, const VectorXd& w, double eps) {
  return (rule.weights.array() * (cylinder_of(p).height - (rule.S * w).array())).sum() / eps;
}

}  // namespace plate
