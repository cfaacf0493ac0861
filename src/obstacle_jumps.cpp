// Jumps of the obstacle along the grid's lines, off its edge curve.
#include "obstacle_jumps.hpp"

#include <algorithm>
#include <cmath>

namespace plate {

namespace {
// The change of phi between two values, infinite where exactly one of them is -inf.
double change(double a, double b) {
  if (std::isinf(a) != std::isinf(b)) return INFINITY;
  return std::isinf(a) ? 0.0 : std::abs(b - a);
}

// phi on the segment from (ax, ay) to (bx, by), whose ends differ by d: whether it jumps, and where.
bool jumps_on(const Field& phi, double ax, double ay, double bx, double by, double d, ObstacleJump& j) {
  double fa = phi(ax, ay), fb = phi(bx, by);
  for (int k = 0; k < 40; ++k) {
    const double mx = 0.5 * (ax + bx), my = 0.5 * (ay + by), fm = phi(mx, my);
    if (change(fa, fm) >= change(fm, fb))
      bx = mx, by = my, fb = fm;
    else
      ax = mx, ay = my, fa = fm;
  }
  j = {0.5 * (ax + bx), 0.5 * (ay + by), d, std::isinf(fa) != std::isinf(fb), std::max(fa, fb)};
  return change(fa, fb) >= 0.25 * d;
}
}  // namespace

std::vector<ObstacleJump> obstacle_jumps(const Grid& g, const Field& phi, const EdgeCurve& edge) {
  std::vector<ObstacleJump> found;
  // Each interior line of nodes, along x (j fixed) and then along y (i fixed). The clamped edge
  // carries no constraint (w = 0 there, phi < 0).
  for (int dir = 0; dir < 2; ++dir) {
    const int lines = dir == 0 ? g.ny : g.nx, steps = dir == 0 ? g.nx : g.ny;
    std::vector<double> v(steps + 1), d(steps);
    for (int l = 1; l < lines; ++l) {
      auto at = [&](int k, double& x, double& y) { x = dir == 0 ? g.x(k) : g.x(l), y = dir == 0 ? g.y(l) : g.y(k); };
      for (int k = 0; k <= steps; ++k) {
        double x, y;
        at(k, x, y);
        v[k] = phi(x, y);
      }
      for (int k = 0; k < steps; ++k) d[k] = change(v[k], v[k + 1]);
      for (int k = 0; k < steps; ++k) {
        const double before = k > 0 ? d[k - 1] : 0.0, after = k + 1 < steps ? d[k + 1] : 0.0;
        if (!(d[k] > 0) || (std::isfinite(d[k]) && d[k] <= 4 * std::min(before, after))) continue;
        double ax, ay, bx, by;
        at(k, ax, ay);
        at(k + 1, bx, by);
        ObstacleJump j;
        if (!jumps_on(phi, ax, ay, bx, by, d[k], j)) continue;
        if (!edge.empty() && distance_to_edge(edge, j.x, j.y) <= 1e-6 * g.h) continue;
        found.push_back(j);
      }
    }
  }
  return found;
}

}  // namespace plate
