// Saye's height-function quadrature for implicitly defined regions, in two dimensions and for
// bicubics (D30).
#include "implicit_quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "gauss.hpp"

namespace plate {

namespace {

using Cubic = std::array<double, 4>;

double eval_cubic(Cubic c, double u) {  // de Casteljau: stable for every u in [0, 1]
  for (int r = 1; r < 4; ++r)
    for (int k = 0; k + r < 4; ++k) c[k] = (1 - u) * c[k] + u * c[k + 1];
  return c[0];
}

// The cubic on [0, u] (left) and [u, 1] (right), each in its own local coordinate.
void split_cubic(Cubic c, double u, Cubic& left, Cubic& right) {
  left[0] = c[0];
  right[3] = c[3];
  for (int r = 1; r < 4; ++r) {
    for (int k = 0; k + r < 4; ++k) c[k] = (1 - u) * c[k] + u * c[k + 1];
    left[r] = c[0];
    right[3 - r] = c[3 - r];
  }
}

// The cubic on [a, b] within [0, 1].
Cubic sub_cubic(const Cubic& c, double a, double b) {
  Cubic left, right, unused;
  if (b < 1) split_cubic(c, b, left, unused); else left = c;
  if (a <= 0) return left;
  split_cubic(left, a / b, unused, right);
  return right;
}

bool all_positive(const double* c, int n, int stride) {
  for (int k = 0; k < n; ++k) if (!(c[k * stride] > 0)) return false;
  return true;
}
bool all_negative(const double* c, int n, int stride) {
  for (int k = 0; k < n; ++k) if (!(c[k * stride] < 0)) return false;
  return true;
}

void roots_on(const Cubic& c, double a, double b, int depth, std::vector<double>& out) {
  if (all_positive(c.data(), 4, 1) || all_negative(c.data(), 4, 1)) return;
  // A curve that lies along the line (a ray of (D31) on a grid line, say) makes the cubic vanish
  // there: it splits nothing, and halving it would go on to the depth limit on every half.
  if (c[0] == 0 && c[1] == 0 && c[2] == 0 && c[3] == 0) return;
  const Cubic d{c[1] - c[0], c[2] - c[1], c[3] - c[2], 0};
  const bool monotone = all_positive(d.data(), 3, 1) || all_negative(d.data(), 3, 1);
  if (monotone || depth >= 48) {
    if (c[0] == 0) { out.push_back(a); return; }
    if (c[3] == 0) { out.push_back(b); return; }
    if ((c[0] < 0) == (c[3] < 0)) return;  // monotone without a sign change: no root
    // Bisection to the last bit: on a monotone piece it cannot miss, and it needs no derivative.
    double lo = 0, hi = 1;
    const bool rising = c[0] < 0;
    for (int it = 0; it < 64 && hi - lo > 0; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      ((eval_cubic(c, mid) < 0) == rising ? lo : hi) = mid;
    }
    out.push_back(a + (b - a) * 0.5 * (lo + hi));
    return;
  }
  Cubic left, right;
  split_cubic(c, 0.5, left, right);
  const double m = 0.5 * (a + b);
  roots_on(left, a, m, depth + 1, out);
  roots_on(right, m, b, depth + 1, out);
}

// The coefficients of t -> p(t, s) (axis 0) at fixed s, or of s -> p(t, s) (axis 1) at fixed t.
Cubic line(const Bicubic& p, int axis, double at) {
  Cubic c;
  for (int k = 0; k < 4; ++k) {
    Cubic other;
    for (int l = 0; l < 4; ++l) other[l] = axis == 0 ? p.b[4 * k + l] : p.b[4 * l + k];
    c[k] = eval_cubic(other, at);
  }
  return c;
}

// The root of a cubic that is monotone on [0, 1], if it changes sign there.
bool monotone_root(const Cubic& c, double& root) {
  std::vector<double> r;
  roots_on(c, 0, 1, 0, r);
  if (r.empty()) return false;
  root = r.front();
  return true;
}

struct Box {
  double x0, y0, hx, hy;
};

void tensor_rule(const Box& box, const Quadrature1D& q, const std::vector<Bicubic>* test, std::vector<WeightedPoint>& out) {
  for (size_t i = 0; i < q.points.size(); ++i)
    for (size_t j = 0; j < q.points.size(); ++j) {
      const double t = q.points[i], s = q.points[j];
      if (test) {
        bool inside = true;
        for (const Bicubic& p : *test) inside = inside && p(t, s) < 0;
        if (!inside) continue;
      }
      out.push_back({box.x0 + box.hx * t, box.y0 + box.hy * s, q.weights[i] * q.weights[j] * box.hx * box.hy});
    }
}

// The heights (local coordinate along `axis`) where each function's curve meets the line at base
// coordinate u; NaN for a function whose curve does not meet it.
std::vector<double> heights(const std::vector<Bicubic>& psi, int axis, double u) {
  std::vector<double> h(psi.size(), NAN);
  for (size_t k = 0; k < psi.size(); ++k) {
    double r;
    if (monotone_root(line(psi[k], axis, u), r)) h[k] = r;
  }
  return h;
}

// @region height-rule
// Every function monotone along `axis`: integrate along lines parallel to it, split where the
// curves meet them, and across the lines by Gauss on base intervals where the set of curves met,
// and their order along the line, does not change.
void height_rule(const Box& box, const std::vector<Bicubic>& psi, int axis, const Quadrature1D& q,
                 const Quadrature1D& across, std::vector<WeightedPoint>& out) {
  const int base = 1 - axis;
  std::vector<double> breaks{0.0, 1.0};
  for (const Bicubic& p : psi)
    for (double end : {0.0, 1.0}) roots_on(line(p, base, end), 0, 1, 0, breaks);
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end(), [](double a, double b) { return b - a < 1e-15; }), breaks.end());
  // Where two curves cross inside a base interval the integrand across the lines has a kink: a
  // break there keeps each piece smooth. A crossing shows as two heights changing order between the
  // interval's ends, and is found by bisection. (Two crossings in one interval of one box, which
  // would leave the order as it was, are not looked for.)
  auto crossing = [&](double a, double b) {
    const double da = a + 1e-9 * (b - a), db = b - 1e-9 * (b - a);
    const std::vector<double> ha = heights(psi, axis, da), hb = heights(psi, axis, db);
    for (size_t k = 0; k < psi.size(); ++k)
      for (size_t l = k + 1; l < psi.size(); ++l) {
        if (std::isnan(ha[k]) || std::isnan(ha[l]) || std::isnan(hb[k]) || std::isnan(hb[l])) continue;
        const bool below = ha[k] < ha[l];
        if (below == (hb[k] < hb[l])) continue;
        double lo = da, hi = db;
        for (int it = 0; it < 60; ++it) {
          const double mid = 0.5 * (lo + hi);
          const std::vector<double> hm = heights(psi, axis, mid);
          if (std::isnan(hm[k]) || std::isnan(hm[l])) break;
          ((hm[k] < hm[l]) == below ? lo : hi) = mid;
        }
        return 0.5 * (lo + hi);
      }
    return double(NAN);
  };
  for (size_t i = 0, added = 0; i + 1 < breaks.size() && added < 4 * psi.size() * psi.size();) {
    const double c = breaks[i + 1] - breaks[i] < 1e-12 ? NAN : crossing(breaks[i], breaks[i + 1]);
    if (std::isnan(c)) { ++i; continue; }
    breaks.insert(breaks.begin() + static_cast<long>(i) + 1, c);  // then [a, c] is looked at again
    ++added;
  }
  const double len_base = axis == 1 ? box.hx : box.hy, len_height = axis == 1 ? box.hy : box.hx;
  for (size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double a = breaks[i], b = breaks[i + 1];
    if (!(b > a)) continue;
    for (size_t g = 0; g < across.points.size(); ++g) {
      const double u = a + (b - a) * across.points[g];
      const double wu = (b - a) * across.weights[g] * len_base;
      std::vector<double> cuts{0.0, 1.0};
      for (double h : heights(psi, axis, u)) if (!std::isnan(h)) cuts.push_back(h);
      std::sort(cuts.begin(), cuts.end());
      for (size_t c = 0; c + 1 < cuts.size(); ++c) {
        const double lo = cuts[c], hi = cuts[c + 1];
        if (!(hi > lo)) continue;
        const double mid = 0.5 * (lo + hi);
        bool inside = true;
        for (const Bicubic& p : psi) inside = inside && (axis == 1 ? p(u, mid) : p(mid, u)) < 0;
        if (!inside) continue;
        for (size_t k = 0; k < q.points.size(); ++k) {
          const double v = lo + (hi - lo) * q.points[k];
          const double t = axis == 1 ? u : v, s = axis == 1 ? v : u;
          out.push_back({box.x0 + box.hx * t, box.y0 + box.hy * s, wu * (hi - lo) * q.weights[k] * len_height});
        }
      }
    }
  }
}

// @end height-rule

// The axis along which every function is monotone and its curve no steeper than 1 / kSlope across
// the lines (the steeper axis wins when both qualify), or -1. Monotone alone would do for the
// construction, but a curve that turns towards the lines just outside the box makes the heights
// nearly singular across them (a square root at the turning point), and Gauss on that converges
// slowly (1e-6 relative on a circle in one square); halving such boxes keeps the turn away.
constexpr double kSlope = 0.25;
int height_axis(const std::vector<Bicubic>& psi) {
  double best = 0;
  int axis = -1;
  for (int a = 0; a < 2; ++a) {
    double least = INFINITY, across = 0;  // |slope| along the lines, and across them, bounded by coefficients
    for (const Bicubic& p : psi) {
      if (!p.monotone(a)) { least = 0; break; }
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j) {
          const double along = a == 0 ? p.b[4 * (j + 1) + i] - p.b[4 * j + i] : p.b[4 * i + j + 1] - p.b[4 * i + j];
          const double other = a == 0 ? p.b[4 * i + j + 1] - p.b[4 * i + j] : p.b[4 * (j + 1) + i] - p.b[4 * j + i];
          least = std::min(least, std::abs(along));
          across = std::max(across, std::abs(other));
        }
    }
    if (least > 0 && least >= kSlope * across && least > best) best = least, axis = a;
  }
  return axis;
}

void rule_on(const Box& box, const std::vector<Bicubic>& psi_in, const Quadrature1D& q, const Quadrature1D& across,
             int depth, int max_depth, std::vector<WeightedPoint>& out) {
  std::vector<Bicubic> psi;
  for (const Bicubic& p : psi_in) {
    const int s = p.sign();
    if (s > 0) return;  // outside on the whole box
    if (s == 0) psi.push_back(p);
  }
  if (psi.empty()) return tensor_rule(box, q, nullptr, out);
  const int axis = height_axis(psi);
  if (axis >= 0) return height_rule(box, psi, axis, q, across, out);
  if (depth >= max_depth) return tensor_rule(box, q, &psi, out);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      std::vector<Bicubic> sub;
      for (const Bicubic& p : psi) sub.push_back(p.restricted(0.5 * i, 0.5 * (i + 1), 0.5 * j, 0.5 * (j + 1)));
      rule_on({box.x0 + 0.5 * i * box.hx, box.y0 + 0.5 * j * box.hy, 0.5 * box.hx, 0.5 * box.hy}, sub, q, across,
              depth + 1, max_depth, out);
    }
}

}  // namespace

double Bicubic::operator()(double t, double s) const {
  Cubic c;
  for (int i = 0; i < 4; ++i) c[i] = eval_cubic({b[4 * i], b[4 * i + 1], b[4 * i + 2], b[4 * i + 3]}, s);
  return eval_cubic(c, t);
}

Bicubic Bicubic::restricted(double t0, double t1, double s0, double s1) const {
  Bicubic r;
  for (int j = 0; j < 4; ++j) {
    const Cubic c = sub_cubic({b[j], b[4 + j], b[8 + j], b[12 + j]}, t0, t1);
    for (int i = 0; i < 4; ++i) r.b[4 * i + j] = c[i];
  }
  for (int i = 0; i < 4; ++i) {
    const Cubic c = sub_cubic({r.b[4 * i], r.b[4 * i + 1], r.b[4 * i + 2], r.b[4 * i + 3]}, s0, s1);
    for (int j = 0; j < 4; ++j) r.b[4 * i + j] = c[j];
  }
  return r;
}

int Bicubic::sign() const {
  if (all_positive(b.data(), 16, 1)) return 1;
  if (all_negative(b.data(), 16, 1)) return -1;
  return 0;
}

bool Bicubic::monotone(int axis) const {
  bool up = true, down = true;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) {
      const double d = axis == 0 ? b[4 * (j + 1) + i] - b[4 * j + i] : b[4 * i + j + 1] - b[4 * i + j];
      up = up && d > 0;
      down = down && d < 0;
    }
  return up || down;
}

// @region bicubic-from-corners
Bicubic bicubic_from_corners(const std::array<CornerJet, 4>& corners, double hx, double hy) {
  Bicubic p;
  for (int cy = 0; cy < 2; ++cy)
    for (int cx = 0; cx < 2; ++cx) {
      const CornerJet& c = corners[cx + 2 * cy];
      const double sx = cx ? -1 : 1, sy = cy ? -1 : 1;  // inward
      const int i = 3 * cx, j = 3 * cy, in = cx ? 2 : 1, jn = cy ? 2 : 1;
      p.b[4 * i + j] = c.f;
      p.b[4 * in + j] = c.f + sx * hx * c.fx / 3;
      p.b[4 * i + jn] = c.f + sy * hy * c.fy / 3;
      p.b[4 * in + jn] = c.f + sx * hx * c.fx / 3 + sy * hy * c.fy / 3 + sx * sy * hx * hy * c.fxy / 9;
    }
  return p;
}
// @end bicubic-from-corners

Bicubic circle_on(double cx, double cy, double r, double x0, double y0, double size) {
  std::array<CornerJet, 4> c;
  for (int k = 0; k < 4; ++k) {
    const double x = x0 + (k & 1) * size - cx, y = y0 + (k >> 1) * size - cy;
    c[k] = {x * x + y * y - r * r, 2 * x, 2 * y, 0};
  }
  return bicubic_from_corners(c, size, size);
}

void implicit_rule(double x0, double y0, double hx, double hy, const std::vector<Bicubic>& psi, ImplicitOrders orders,
                   std::vector<WeightedPoint>& out, int max_depth) {
  if (!(hx > 0 && hy > 0)) throw std::invalid_argument("implicit_rule: the box must have positive sides");
  if (orders.along < 1 || orders.across < 1) throw std::invalid_argument("implicit_rule: the orders must be >= 1");
  rule_on({x0, y0, hx, hy}, psi, gauss_legendre(orders.along), gauss_legendre(orders.across), 0, max_depth, out);
}

std::vector<double> cubic_roots(const std::array<double, 4>& c) {
  std::vector<double> r;
  roots_on(c, 0, 1, 0, r);
  std::sort(r.begin(), r.end());
  r.erase(std::unique(r.begin(), r.end(), [](double a, double b) { return b - a < 1e-15; }), r.end());
  return r;
}

}  // namespace plate
