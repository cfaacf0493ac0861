// Clamped B-splines on arcs of a circle, the contact a solve found, and the layout of rows it calls for.
#include "rim_rows.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace plate {

namespace {
constexpr double kTwoPi = 2 * M_PI;
// theta moved into [begin, begin + 2 pi); unchanged (to the last bit) when it is there already.
double unwrap(double theta, double begin) {
  if (theta >= begin && theta - begin < kTwoPi) return theta;
  double d = std::fmod(theta - begin, kTwoPi);
  if (d < 0) d += kTwoPi;
  return begin + d;
}
}  // namespace

double SplineArc::knot(int i, int degree) const { return breaks[std::clamp(i - degree, 0, intervals())]; }

double SplineArc::widest() const {
  double w = 0;
  for (int k = 0; k < intervals(); ++k) w = std::max(w, span(k));
  return w;
}

double SplineArc::greville(int j, int degree) const {
  double s = 0;
  for (int i = j + 1; i <= j + degree; ++i) s += knot(i, degree);
  return degree > 0 ? s / degree : knot(j, degree);
}

bool SplineArc::contains(double theta) const { return unwrap(theta, begin()) <= end() + 1e-12; }

// Cox-de Boor on the clamped knots, the last span closed on the right so that the basis sums to one
// at `end` too.
double clamped_bspline(const SplineArc& a, int degree, int j, double theta) {
  double t = unwrap(theta, a.begin());
  if (t > a.end()) {
    if (t - a.end() > 1e-12) return 0;
    t = a.end();  // the end itself, to round-off
  }
  const int n = a.basis_count(degree);
  if (j < 0 || j >= n) throw std::out_of_range("clamped_bspline: no basis " + std::to_string(j));
  // Degree 0 on the spans of basis j's support, then raised one degree at a time.
  std::vector<double> N(degree + 1);
  for (int i = 0; i <= degree; ++i) {
    const double lo = a.knot(j + i, degree), hi = a.knot(j + i + 1, degree);
    const bool last = hi == a.end() && j + i + 1 >= n;  // the span that ends at `end`
    N[i] = (lo <= t && (t < hi || (last && t <= hi)) && lo < hi) ? 1.0 : 0.0;
  }
  for (int k = 1; k <= degree; ++k)
    for (int i = 0; i + k <= degree; ++i) {
      const double a0 = a.knot(j + i, degree), a1 = a.knot(j + i + k, degree);
      const double b0 = a.knot(j + i + 1, degree), b1 = a.knot(j + i + k + 1, degree);
      const double left = a1 > a0 ? (t - a0) / (a1 - a0) * N[i] : 0.0;
      const double right = b1 > b0 ? (b1 - t) / (b1 - b0) * N[i + 1] : 0.0;
      N[i] = left + right;
    }
  return N[0];
}

double clamped_bspline_integral(const SplineArc& a, int degree, int j) {
  return (a.knot(j + degree + 1, degree) - a.knot(j, degree)) / (degree + 1);
}

ContactArcs contact_arcs(const std::vector<double>& rows, const std::vector<bool>& touching,
                         const std::vector<double>& reach) {
  if (rows.size() != touching.size() || rows.size() != reach.size())
    throw std::invalid_argument("contact_arcs: one flag and one reach per row");
  struct Row {
    double theta;
    bool touching;
    double reach;
  };
  std::vector<Row> r;
  for (size_t k = 0; k < rows.size(); ++k) r.push_back({unwrap(rows[k], 0.0), touching[k], reach[k]});
  std::sort(r.begin(), r.end(), [](const Row& a, const Row& b) { return a.theta < b.theta; });
  const size_t m = r.size();
  // Each touching row's arc: half way to each neighbour, or its reach if that is farther.
  std::vector<std::pair<double, double>> iv;
  for (size_t k = 0; k < m; ++k) {
    if (!r[k].touching) continue;
    const double before = m > 1 ? 0.5 * unwrap(r[k].theta - r[(k + m - 1) % m].theta, 0.0) : M_PI;
    const double after = m > 1 ? 0.5 * unwrap(r[(k + 1) % m].theta - r[k].theta, 0.0) : M_PI;
    const double b = r[k].theta - std::max(before, r[k].reach);
    iv.emplace_back(unwrap(b, 0.0), unwrap(b, 0.0) + std::max(before, r[k].reach) + std::max(after, r[k].reach));
  }
  ContactArcs c;
  if (iv.empty()) return c;
  std::sort(iv.begin(), iv.end());
  // Merge on the line, then the last with the first across 2 pi. Two rows' arcs meet at the
  // midpoint between them, computed from each side: they join if they meet to round-off.
  const double joins = 1e-12;
  std::vector<std::pair<double, double>> merged{iv[0]};
  for (size_t k = 1; k < iv.size(); ++k) {
    if (iv[k].first <= merged.back().second + joins)
      merged.back().second = std::max(merged.back().second, iv[k].second);
    else
      merged.push_back(iv[k]);
  }
  if (merged.size() > 1 && merged.back().second + joins >= merged.front().first + kTwoPi) {
    merged.front().second = std::max(merged.front().second, merged.back().second - kTwoPi);
    merged.front().first = merged.back().first - kTwoPi;
    merged.pop_back();
  }
  for (const auto& [b, e] : merged) {
    if (e - b + joins >= kTwoPi) {
      c.whole = true;
      c.arcs.clear();
      return c;
    }
    const double nb = unwrap(b, 0.0);
    c.arcs.emplace_back(nb, nb + (e - b));
  }
  return c;
}

std::vector<double> graded_breaks(double begin, double end, double finest, double spacing) {
  const double length = end - begin;
  if (!(length >= 2 * finest)) return {};
  // Spans from one end: finest, 2 finest, ... while below spacing and while both ends' spans fit;
  // `reach` holds their partial sums.
  std::vector<double> reach;
  double used = 0;
  for (double s = finest; s < spacing && 2 * (used + s) <= length; s *= 2) reach.push_back(used += s);
  const double middle = length - 2 * used;
  // No wider than `spacing` (the plate's dip between rows grows with the span): as many equal spans
  // as that takes, none if the graded runs nearly meet.
  const int equal = middle < 0.5 * spacing ? 0 : static_cast<int>(std::ceil(middle / spacing - 1e-9));
  std::vector<double> b{begin};
  for (double c : reach) b.push_back(begin + c);
  // The middle in equal spans; if it is narrower than half a spacing, the two graded runs meet at
  // the arc's midpoint instead.
  if (equal == 0 && !reach.empty()) b.back() = 0.5 * (begin + end);
  for (int k = 1; k < equal; ++k) b.push_back(begin + used + middle * k / equal);
  for (size_t k = reach.size(); k-- > 0;)
    if (!(equal == 0 && k + 1 == reach.size())) b.push_back(end - reach[k]);
  b.push_back(end);
  return b;
}

RimLayout layout_for(const ContactArcs& contact, double margin, double finest, double spacing,
                     const std::vector<double>& lattice, double snap) {
  RimLayout L;
  if (contact.whole) return L;  // periodic
  L.periodic = false;
  for (const auto& [b, e] : contact.arcs) {
    const double begin = std::round((b + margin) / snap) * snap, end = std::round((e - margin) / snap) * snap;
    const double start = unwrap(begin, 0.0);
    SplineArc a;
    a.breaks = graded_breaks(start, start + (end - begin), finest, spacing);
    if (!a.breaks.empty()) L.arcs.push_back(a);
  }
  for (double t : lattice) {
    bool on_arc = false;  // or at its end, to round-off: the end's spline row is there already
    for (const SplineArc& a : L.arcs) on_arc = on_arc || a.contains(t) || std::abs(std::remainder(t - a.begin(), kTwoPi)) < 1e-9 ||
                                       std::abs(std::remainder(t - a.end(), kTwoPi)) < 1e-9;
    if (!on_arc) L.points.push_back(unwrap(t, 0.0));
  }
  return L;
}

std::vector<double> point_weights(const RimLayout& layout, double r) {
  // Every point and arc end on the circle, in order; each gap between neighbours goes half to each
  // point at its ends, or all of it to a point whose neighbour is an arc's end, and none of it to
  // anyone if it lies on an arc (the splines there stand for it).
  struct Mark {
    double theta;
    int point;  // index into points, or -1 for an arc's end
  };
  std::vector<Mark> marks;
  for (size_t k = 0; k < layout.points.size(); ++k) marks.push_back({unwrap(layout.points[k], 0.0), static_cast<int>(k)});
  for (const SplineArc& a : layout.arcs) {
    marks.push_back({unwrap(a.begin(), 0.0), -1});
    marks.push_back({unwrap(a.end(), 0.0), -1});
  }
  std::sort(marks.begin(), marks.end(), [](const Mark& a, const Mark& b) { return a.theta < b.theta; });
  std::vector<double> w(layout.points.size(), 0.0);
  const size_t m = marks.size();
  if (m == 1 && marks[0].point >= 0) {
    w[marks[0].point] = kTwoPi * r;
    return w;
  }
  for (size_t k = 0; k < m; ++k) {
    const Mark& a = marks[k];
    const Mark& b = marks[(k + 1) % m];
    const double gap = unwrap(b.theta - a.theta, 0.0);
    bool on_arc = false;
    for (const SplineArc& arc : layout.arcs) on_arc = on_arc || arc.contains(a.theta + 0.5 * gap);
    if (on_arc) continue;
    const double share = a.point >= 0 && b.point >= 0 ? 0.5 : 1.0;
    if (a.point >= 0) w[a.point] += r * share * gap;
    if (b.point >= 0) w[b.point] += r * share * gap;
  }
  return w;
}

bool arcs_inside(const RimLayout& layout, const ContactArcs& contact, double clearance) {
  if (layout.periodic) return contact.whole;
  for (const SplineArc& a : layout.arcs) {
    if (contact.whole) continue;
    bool inside = false;
    for (const auto& [b, e] : contact.arcs) {
      const double begin = unwrap(a.begin(), b);  // the arc's start measured from the contact's
      inside = inside || (begin - b >= clearance && begin + (a.end() - a.begin()) <= e - clearance);
    }
    if (!inside) return false;
  }
  return true;
}

}  // namespace plate
