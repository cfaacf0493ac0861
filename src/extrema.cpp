// Newton's method on grad w_h = 0, and the shrinking pattern search.
#include "extrema.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "contact.hpp"

namespace plate {

Extremum pattern_maximum(const Grid& g, const std::function<double(double, double)>& f, double x0, double y0,
                         double step) {
  const double lx = g.whole_lx(), ly = g.whole_ly();
  Extremum best{f(x0, y0), x0, y0};
  for (double s = step; s > 1e-9 * std::max(lx, ly); s /= 5) {
    const double cx = best.x, cy = best.y;
    for (int i = -6; i <= 6; ++i)
      for (int j = -6; j <= 6; ++j) {
        const double x = std::clamp(cx + i * s, 0.0, lx), y = std::clamp(cy + j * s, 0.0, ly);
        if (const double v = f(x, y); v > best.value) best = {v, x, y};
      }
  }
  return best;
}

// @region newton-extremum
namespace {
// Whether a beats b as a maximum. Two places more than a cell h apart whose values lie within 1e-13
// of each other tie (a scene's symmetry gives its images values that differ by round-off alone),
// and the tie goes to the place first in the order of the grid's nodes: by its nearest node's row,
// then column (the refined places' own coordinates differ by round-off where images share a row).
// Nearer than a cell they are one place found twice, and the larger value is the closer find.
bool beats(const Extremum& a, const Extremum& b, double h) {
  const double tie = 1e-13 * std::max(std::abs(a.value), std::abs(b.value));
  if (std::abs(a.value - b.value) > tie || std::hypot(a.x - b.x, a.y - b.y) <= h) return a.value > b.value;
  const auto node = [h](const Extremum& e) { return std::make_pair(std::lround(e.y / h), std::lround(e.x / h)); };
  if (node(a) != node(b)) return node(a) < node(b);
  return a.value > b.value;
}

template <class At>
Extremum extremum_of(const Grid& g, const At& at, double sign, int starts) {
  const double lx = g.whole_lx(), ly = g.whole_ly();
  auto value = [&](double x, double y) { return sign * at(x, y).w; };
  // The best nodes of the grid. On a part (mirror lines) the rest of the plate holds its images,
  // the same values to round-off, so the part's own nodes suffice: the place found is then on the
  // part (to round-off, at a mirror line), never whichever image round-off favoured.
  std::vector<Extremum> nodes;
  for (int j = 0; j <= g.ny; ++j)
    for (int i = 0; i <= g.nx; ++i) nodes.push_back({value(i * g.h, j * g.h), i * g.h, j * g.h});
  // The first node in the nodes' order among those that tie with the best always starts a search,
  // whichever of the tied images round-off put among the `starts` best.
  double top = -INFINITY;
  for (const Extremum& n : nodes)
    if (std::isfinite(n.value)) top = std::max(top, n.value);
  const auto first = std::find_if(nodes.begin(), nodes.end(), [&](const Extremum& n) { return top - n.value <= 1e-13 * std::abs(top); });
  const std::optional<Extremum> tied = first == nodes.end() ? std::nullopt : std::optional<Extremum>(*first);  // none: no finite value
  int k = std::min<int>(starts, static_cast<int>(nodes.size()));
  std::partial_sort(nodes.begin(), nodes.begin() + k, nodes.end(),
                    [](const Extremum& a, const Extremum& b) { return a.value > b.value; });
  if (tied && std::none_of(nodes.begin(), nodes.begin() + k, [&](const Extremum& n) { return n.x == tied->x && n.y == tied->y; }))
    nodes.insert(nodes.begin(), *tied), ++k;
  Extremum best;
  for (int s = 0; s < k; ++s) {
    double x = nodes[s].x, y = nodes[s].y;
    bool settled = false;
    for (int it = 0; it < 30 && !settled; ++it) {
      const PointValues v = at(x, y);
      // Newton on grad(sign w) = 0: H d = -grad, H negative definite at a maximum of sign w.
      const double gx = sign * v.wx, gy = sign * v.wy, hxx = sign * v.wxx, hxy = sign * v.wxy, hyy = sign * v.wyy;
      const double det = hxx * hyy - hxy * hxy;
      if (!(hxx < 0 && det > 0)) break;
      const double dx = -(hyy * gx - hxy * gy) / det, dy = -(hxx * gy - hxy * gx) / det;
      if (!(std::hypot(dx, dy) <= g.h)) break;
      const double nx = x + dx, ny = y + dy;
      if (nx < 0 || nx > lx || ny < 0 || ny > ly) break;
      settled = std::hypot(dx, dy) <= 1e-13 * std::max(lx, ly);
      x = nx, y = ny;
    }
    Extremum e{value(x, y), x, y};
    // Where Newton stopped short (an indefinite Hessian near the start, a step leaving the plate),
    // the pattern finishes the search.
    if (!settled) e = pattern_maximum(g, value, e.value >= nodes[s].value ? x : nodes[s].x, e.value >= nodes[s].value ? y : nodes[s].y, g.h / 2);
    if (s == 0 || beats(e, best, g.h)) best = e;
  }
  best.value *= sign;
  return best;
}
// @end newton-extremum
}  // namespace

Extremum extremum_of_w(const Problem& p, const VectorXd& w, double sign, int starts) {
  const PlateField field(p, w);
  return extremum_of(p.grid, [&](double x, double y) { return field.at(x, y); }, sign, starts);
}

Extremum extremum_of_w(const Grid& g, const VectorXd& w, double sign, int starts) {
  return extremum_of(g, [&](double x, double y) { return evaluate(g, w, x, y); }, sign, starts);
}

FieldMeasures measure_field(const Problem& p, const VectorXd& w, double nu, const std::vector<std::pair<double, double>>& points) {
  FieldMeasures m;
  const PlateField field(p, w);
  for (const auto& [x, y] : points) m.w_at.push_back(field.value_at(x, y));
  m.max_w = extremum_of_w(p, w, +1);
  m.min_w = extremum_of_w(p, w, -1);
  // |m12| = (1 - nu) |w_xy|, continuous for these elements: from the best node (of the part, as
  // above), by the pattern.
  const auto twist = [&](double x, double y) { return std::abs(bending_moments(0, field.at(x, y).wxy, 0, nu).m12); };
  Extremum best{-1, 0, 0};
  for (int j = 0; j <= p.grid.ny; ++j)
    for (int i = 0; i <= p.grid.nx; ++i)
      if (const Extremum v{twist(i * p.grid.h, j * p.grid.h), i * p.grid.h, j * p.grid.h}; beats(v, best, p.grid.h / 2)) best = v;
  m.max_abs_m12 = pattern_maximum(p.grid, twist, best.x, best.y, p.grid.h / 2);
  return m;
}

}  // namespace plate
