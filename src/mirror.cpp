// Finding a scene's mirror lines, and carrying values between the part and the whole plate.
#include "mirror.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "gauss.hpp"

namespace plate {

std::string describe(Mirrors m) {
  if (m.x && m.y) return "quarter (mirror lines x = lx/2 and y = ly/2)";
  if (m.x) return "half (mirror line x = lx/2)";
  if (m.y) return "half (mirror line y = ly/2)";
  return "whole plate";
}

namespace {

// Points found by position, to within `tol`: a hash of cells of side 4 tol, each point looked for
// in its own cell and the eight around it.
class PointIndex {
 public:
  PointIndex(const std::vector<double>& x, const std::vector<double>& y, double tol) : x_(x), y_(y), tol_(tol), cell_(4 * tol) {
    cells_.reserve(x.size());
    for (size_t k = 0; k < x.size(); ++k) cells_[key(cell(x[k]), cell(y[k]))].push_back(static_cast<int>(k));
  }
  int find(double x, double y) const {
    const long long cx = cell(x), cy = cell(y);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto it = cells_.find(key(cx + dx, cy + dy));
        if (it == cells_.end()) continue;
        for (int k : it->second)
          if (std::abs(x_[k] - x) <= tol_ && std::abs(y_[k] - y) <= tol_) return k;
      }
    return -1;
  }

 private:
  long long cell(double v) const { return static_cast<long long>(std::floor(v / cell_)); }
  static unsigned long long key(long long cx, long long cy) {
    return static_cast<unsigned long long>(cx) * 0x9E3779B97F4A7C15ull ^ static_cast<unsigned long long>(cy);
  }
  const std::vector<double>& x_;
  const std::vector<double>& y_;
  double tol_, cell_;
  std::unordered_map<unsigned long long, std::vector<int>> cells_;
};

// The reflection in one mirror line of the whole plate: x -> lx - x, or y -> ly - y.
struct Reflection {
  bool in_x;
  double lx, ly;
  double x(double px) const { return in_x ? lx - px : px; }
  double y(double py) const { return in_x ? py : ly - py; }
};

// Compares a field at points and at their images: each pair may differ by round-off of its own size
// (1e-12 of it), and what is left over by round-off of the field's largest finite size (1e-15 of
// it), so that values far larger elsewhere (an obstacle that plunges towards the corners) do not
// excuse an asymmetry where the values are small; an infinity must meet the same infinity.
struct Comparison {
  double excess = 0, size = 0;
  bool infinities_match = true;
  void add(double a, double b) {
    if (std::isinf(a) || std::isinf(b) || std::isnan(a) || std::isnan(b)) {
      infinities_match = infinities_match && a == b;
      return;
    }
    excess = std::max(excess, std::abs(a - b) - 1e-12 * std::max(std::abs(a), std::abs(b)));
    size = std::max({size, std::abs(a), std::abs(b)});
  }
  bool same() const { return infinities_match && excess <= 1e-15 * size; }
};

// Calls visit(x, y) at every node and (if `gauss`) every 4 x 4 Gauss point of the whole grid.
template <class Visit>
void for_each_point(const Grid& g, bool nodes, bool gauss, Visit visit) {
  if (nodes)
    for (int j = 0; j <= g.ny; ++j)
      for (int i = 0; i <= g.nx; ++i) visit(g.x(i), g.y(j));
  if (!gauss) return;
  const Quadrature1D q = gauss_legendre(4);
  for (int ey = 0; ey < g.ny; ++ey)
    for (int ex = 0; ex < g.nx; ++ex)
      for (double s : q.points)
        for (double t : q.points) visit(g.x(ex) + t * g.h, g.y(ey) + s * g.h);
}

bool symmetric_in(const Grid& g, const SamplingSpec& spec, const Scene& s, const Reflection& r) {
  const Field &obstacle = s.obstacle, &load = s.load;
  if ((r.in_x ? g.nx : g.ny) % 2) return false;  // the line must be a grid line
  const bool gauss = spec.kind == SamplingKind::Gauss || spec.kind == SamplingKind::EdgeGauss;
  Comparison phi, f;
  for_each_point(g, true, gauss, [&](double x, double y) { phi.add(obstacle(x, y), obstacle(r.x(x), r.y(y))); });
  for_each_point(g, false, true, [&](double x, double y) { f.add(load(x, y), load(r.x(x), r.y(y))); });
  if (has_edge(spec.kind) && !s.edge.empty()) {
    const EdgePoints e = edge_points(s.edge, g.h);
    const PointIndex index(e.x, e.y, 1e-9 * g.h);
    for (int k = 0; k < e.size(); ++k) {
      if (index.find(r.x(e.x[k]), r.y(e.y[k])) < 0) return false;  // the edge's points are not symmetric
      // The obstacle's envelope on its edge, as make_problem reads it, at the point and at its image
      // (whose inward normal is the reflected one).
      const double nx = r.in_x ? -e.nx[k] : e.nx[k], ny = r.in_x ? e.ny[k] : -e.ny[k];
      phi.add(obstacle_on_edge(obstacle, e.x[k], e.y[k], e.nx[k], e.ny[k], g.h),
              obstacle_on_edge(obstacle, r.x(e.x[k]), r.y(e.y[k]), nx, ny, g.h));
    }
  }
  return phi.same() && f.same();
}

}  // namespace

Mirrors find_mirrors(const Scene& s, const Grid& whole, const SamplingSpec& spec) {
  if (whole.is_part()) throw std::invalid_argument("find_mirrors: the grid must be a whole plate");
  Mirrors m;
  m.x = symmetric_in(whole, spec, s, Reflection{true, whole.lx(), whole.ly()});
  m.y = symmetric_in(whole, spec, s, Reflection{false, whole.lx(), whole.ly()});
  return m;
}

Grid part_of(const Grid& whole, Mirrors m) {
  if (whole.is_part()) throw std::invalid_argument("part_of: the grid must be a whole plate");
  if ((m.x && whole.nx % 2) || (m.y && whole.ny % 2)) throw std::invalid_argument("part_of: a mirror line must be a grid line");
  Grid p = whole;
  if (m.x) p.nx /= 2, p.mirror_x = true;
  if (m.y) p.ny /= 2, p.mirror_y = true;
  return p;
}

VectorXd unfold_unknowns(const Grid& whole, const Grid& part, const VectorXd& w_part) {
  VectorXd w = VectorXd::Zero(whole.unknowns());
  for (int j = 1; j < whole.ny; ++j)
    for (int i = 1; i < whole.nx; ++i) {
      const bool fx = part.mirror_x && i > part.nx, fy = part.mirror_y && j > part.ny;
      const int pi = fx ? 2 * part.nx - i : i, pj = fy ? 2 * part.ny - j : j;
      const double sign[4] = {1.0, fx ? -1.0 : 1.0, fy ? -1.0 : 1.0, fx != fy ? -1.0 : 1.0};
      for (int c = 0; c < 4; ++c) {
        const int from = part.dof(pi, pj, c);
        w[whole.dof(i, j, c)] = from >= 0 ? sign[c] * w_part[from] : 0.0;  // pinned: zero by symmetry
      }
    }
  return w;
}

VectorXd unfold_samples(const Sampling& whole, const Sampling& part, const Grid& part_grid, const VectorXd& v) {
  const PointIndex index(part.x, part.y, 1e-9 * part_grid.h);
  VectorXd out(whole.size());
  for (int r = 0; r < whole.size(); ++r) {
    double x = whole.x[r], y = whole.y[r];
    if (part_grid.mirror_x && x > part_grid.lx()) x = 2 * part_grid.lx() - x;
    if (part_grid.mirror_y && y > part_grid.ly()) y = 2 * part_grid.ly() - y;
    const int k = index.find(x, y);
    if (k < 0)
      throw std::logic_error("unfold_samples: the image of the sample (" + std::to_string(whole.x[r]) + ", " +
                             std::to_string(whole.y[r]) + ") is not a sample of the part");
    out[r] = v[k];
  }
  return out;
}

}  // namespace plate
