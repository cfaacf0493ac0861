// Eq. (D33): the kink-carrying functions across a convex polygon's sides, and their blocks.
#include "side_kinks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "bfs_element.hpp"
#include "gauss.hpp"

namespace plate {

namespace {

double dist(const KinkSide& q, double x, double y) { return (x - q.x0) * q.nx + (y - q.y0) * q.ny; }
double along(const KinkSide& q, double x, double y) { return (x - q.x0) * q.tx + (y - q.y0) * q.ty; }
// The splines' reach past the side's ends: the first is centred a spacing before the first
// vertex and spans two spacings either way.
double reach(const KinkSide& q) { return 3 * q.spacing; }

// Each spline of side q that does not vanish at arc length s, with its derivatives in s.
template <class Visit>
void for_splines(const KinkSide& q, double s, Visit visit) {
  const int j0 = static_cast<int>(std::floor(s / q.spacing)) + 1;
  for (int j = std::max(0, j0 - 1); j <= std::min(q.count - 1, j0 + 2); ++j) {
    KinkSpline b = cubic_bspline((s - (j - 1) * q.spacing) / q.spacing);
    if (b.v == 0 && b.d1 == 0 && b.d2 == 0) continue;
    b.d1 /= q.spacing, b.d2 /= q.spacing * q.spacing;
    visit(q.first + j, b);
  }
}

// @region side-kink-functions
// Eq. (D33): F = (d / unit)^3 B(s) across side q at distance d > 0 outside it, with its Cartesian
// derivatives; d and s are linear in x and y, so the chain rule needs only n and t.
KinkValue side_profile(const KinkSide& q, const KinkSpline& b, double d, double unit) {
  if (!(d > 0)) return {};
  const double t = d / unit, G = t * t * t, G1 = 3 * t * t / unit, G2 = 6 * t / (unit * unit);
  const double nx = q.nx, ny = q.ny, tx = q.tx, ty = q.ty;
  KinkValue v;
  v.w = G * b.v;
  v.wx = G1 * nx * b.v + G * b.d1 * tx;
  v.wy = G1 * ny * b.v + G * b.d1 * ty;
  v.wxx = G2 * nx * nx * b.v + 2 * G1 * b.d1 * nx * tx + G * b.d2 * tx * tx;
  v.wxy = G2 * nx * ny * b.v + G1 * b.d1 * (nx * ty + ny * tx) + G * b.d2 * tx * ty;
  v.wyy = G2 * ny * ny * b.v + 2 * G1 * b.d1 * ny * ty + G * b.d2 * ty * ty;
  return v;
}

// chi = prod_i c(d_i) of (D33) with its gradient and Hessian, by the product rule one factor at a
// time; a factor past the cut-off makes it 0.
KinkValue side_cutoff(const KinkEnrichment& e, double x, double y) {
  KinkValue c{1, 0, 0, 0, 0, 0};
  for (const KinkSide& q : e.sides) {
    const KinkRadial f = kink_cutoff(e.inner, e.outer, dist(q, x, y));
    if (f.g == 1 && f.g1 == 0 && f.g2 == 0) continue;
    if (f.g == 0 && f.g1 == 0 && f.g2 == 0) return {};
    const double fx = f.g1 * q.nx, fy = f.g1 * q.ny;
    c.wxx = c.w * f.g2 * q.nx * q.nx + f.g * c.wxx + 2 * c.wx * fx;
    c.wxy = c.w * f.g2 * q.nx * q.ny + f.g * c.wxy + c.wx * fy + c.wy * fx;
    c.wyy = c.w * f.g2 * q.ny * q.ny + f.g * c.wyy + 2 * c.wy * fy;
    c.wx = c.w * fx + f.g * c.wx, c.wy = c.w * fy + f.g * c.wy;
    c.w *= f.g;
  }
  return c;
}
// @end side-kink-functions

// @region corner-functions
// Eq. (D34): G = rho^2 log rho about corner V, rho = r / unit, with its derivatives: the biharmonic's
// fundamental solution up to a factor and a quadratic. A point load at V puts it into the plate, and
// no bicubic follows its logarithmic moments. At V the second derivatives have no limit; 0 is
// returned there.
KinkValue corner_log(const KinkEnrichment& e, const KinkCorner& V, double x, double y) {
  const double X = x - V.x, Y = y - V.y, u2 = e.unit * e.unit, r2 = X * X + Y * Y;
  if (!(r2 > 0)) return {};
  const double L = 0.5 * std::log(r2 / u2), k = 2 * L + 1;
  return {r2 * L / u2, X * k / u2, Y * k / u2, (k + 2 * X * X / r2) / u2, 2 * X * Y / (r2 * u2), (k + 2 * Y * Y / r2) / u2};
}

// D_V = b(X) b(Y) (G - I_h G) of (D34), b the cut-off of one coordinate (1 to inner, 0 from outer),
// I_h G the Hermite interpolant on the square that holds (x, y). The cut-off comes after the
// interpolant, as chi does in (D31): cut first, G b would vary within a cell, and what the grid
// cannot follow there would swamp what it cannot follow at V. D_V and its slopes and twist vanish at
// every node, so it needs no columns of the interpolant P.
KinkValue corner_difference(const KinkEnrichment& e, const KinkCorner& V, double x, double y, const int* cell = nullptr) {
  const double X = x - V.x, Y = y - V.y, h = e.unit;
  if (!(std::abs(X) < V.outer && std::abs(Y) < V.outer)) return {};
  const double ex = cell ? cell[0] : std::floor(x / h), ey = cell ? cell[1] : std::floor(y / h);
  const LocalBasis b = bfs_basis(x / h - ex, y / h - ey, h);
  KinkValue D = corner_log(e, V, x, y);
  for (int ay = 0; ay < 2; ++ay)
    for (int ax = 0; ax < 2; ++ax) {
      const KinkValue n = corner_log(e, V, (ex + ax) * h, (ey + ay) * h);
      const double comp[4] = {n.w, n.wx, n.wy, n.wxy};
      for (int c = 0; c < 4; ++c) {
        const int i = 4 * (ax + 2 * ay) + c;
        D.w -= comp[c] * b.v[i], D.wx -= comp[c] * b.dx[i], D.wy -= comp[c] * b.dy[i];
        D.wxx -= comp[c] * b.dxx[i], D.wxy -= comp[c] * b.dxy[i], D.wyy -= comp[c] * b.dyy[i];
      }
    }
  const KinkRadial bx = kink_cutoff(V.inner, V.outer, std::abs(X)), by = kink_cutoff(V.inner, V.outer, std::abs(Y));
  const double sx = X < 0 ? -1 : 1, sy = Y < 0 ? -1 : 1;
  const double B = bx.g * by.g, Bx = sx * bx.g1 * by.g, By = sy * by.g1 * bx.g;
  const double Bxx = bx.g2 * by.g, Byy = by.g2 * bx.g, Bxy = sx * sy * bx.g1 * by.g1;
  return {B * D.w,
          B * D.wx + Bx * D.w,
          B * D.wy + By * D.w,
          B * D.wxx + 2 * Bx * D.wx + Bxx * D.w,
          B * D.wxy + Bx * D.wy + By * D.wx + Bxy * D.w,
          B * D.wyy + 2 * By * D.wy + Byy * D.w};
}
// @end corner-functions

// Whether D_V of corner V can be nonzero at (x, y): within its box.
bool in_box(const KinkCorner& V, double x, double y) {
  return std::abs(x - V.x) < V.outer && std::abs(y - V.y) < V.outer;
}

void add(KinkValue& to, const KinkValue& v, double c) {
  to.w += c * v.w, to.wx += c * v.wx, to.wy += c * v.wy, to.wxx += c * v.wxx, to.wxy += c * v.wxy, to.wyy += c * v.wyy;
}

// The polygon's vertices counter-clockwise, with any vertex that lies on the straight line through
// its neighbours left out (it is no corner, and its two sides would bring the same splines twice, a
// singular system); empty, and `why` said, unless the polygon is convex and turns once round.
struct Outline {
  std::vector<double> x, y;
};
Outline convex_outline(const EdgeCurve& p, std::string& why) {
  Outline o{p.vx, p.vy};
  double area = 0;
  for (size_t i = 0; i < o.x.size(); ++i) area += o.x[i] * o.y[(i + 1) % o.x.size()] - o.x[(i + 1) % o.x.size()] * o.y[i];
  if (area < 0) std::reverse(o.x.begin(), o.x.end()), std::reverse(o.y.begin(), o.y.end());
  double scale = 0;
  for (size_t i = 0; i < o.x.size(); ++i) scale = std::max({scale, std::abs(o.x[i]), std::abs(o.y[i])});
  for (bool dropped = true; dropped && o.x.size() >= 3;) {
    dropped = false;
    for (size_t i = 0; i < o.x.size() && !dropped; ++i) {
      const size_t m = o.x.size(), a = (i + m - 1) % m, b = (i + 1) % m;
      const double ux = o.x[i] - o.x[a], uy = o.y[i] - o.y[a], vx = o.x[b] - o.x[i], vy = o.y[b] - o.y[i];
      if (std::abs(ux * vy - uy * vx) <= 1e-12 * scale * scale && ux * vx + uy * vy >= 0)
        o.x.erase(o.x.begin() + static_cast<long>(i)), o.y.erase(o.y.begin() + static_cast<long>(i)), dropped = true;
    }
  }
  double turning = 0;
  bool left = o.x.size() >= 3;
  for (size_t i = 0; i < o.x.size() && left; ++i) {
    const size_t m = o.x.size(), a = (i + m - 1) % m, b = (i + 1) % m;
    const double ux = o.x[i] - o.x[a], uy = o.y[i] - o.y[a], vx = o.x[b] - o.x[i], vy = o.y[b] - o.y[i];
    left = ux * vy - uy * vx > 0;
    turning += std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
  }
  // A star turns left at every vertex too, but twice round.
  if (!left || std::abs(turning - 2 * M_PI) > 1e-6) {
    why = "the polygon is not convex";
    return {};
  }
  return o;
}

// The sides of the outline, each with its splines (D33); `why` says what does not fit.
std::vector<KinkSide> polygon_sides(const Outline& o, double h, std::string& why) {
  std::vector<KinkSide> sides;
  const size_t m = o.x.size();
  for (size_t i = 0; i < m; ++i) {
    KinkSide q;
    q.x0 = o.x[i], q.y0 = o.y[i];
    const double dx = o.x[(i + 1) % m] - o.x[i], dy = o.y[(i + 1) % m] - o.y[i];
    q.length = std::hypot(dx, dy);
    if (!(q.length >= kKinkMinRadiusCells * h)) {
      why = "every side of the polygon must be at least " + std::to_string(static_cast<int>(kKinkMinRadiusCells)) + " cells long";
      return {};
    }
    q.tx = dx / q.length, q.ty = dy / q.length, q.nx = q.ty, q.ny = -q.tx;
    const int intervals = std::max(2, static_cast<int>(std::ceil(q.length / (kKinkKnotCells * h) - 1e-9)));
    q.spacing = q.length / intervals, q.count = intervals + 3;
    sides.push_back(q);
  }
  // A side along a grid line gets no functions: the squares meet there sharing only w and its
  // slopes, so the plain space carries a kink across it already (a cubic one on each square). Its
  // psi would only add breaks at knots that fall inside squares, and where the knots fall on grid
  // lines too it is 0 and the bordered system singular. Within 1e-6 of a cell of a grid line psi is
  // of that size, and the system about as near singular: such a side counts as on the line.
  std::vector<KinkSide> kept;
  for (KinkSide q : sides) {
    const double across = std::abs(q.tx) < 1e-12 ? q.x0 : std::abs(q.ty) < 1e-12 ? q.y0 : NAN;
    if (std::abs(across / h - std::round(across / h)) < 1e-6) continue;
    q.first = kept.empty() ? 0 : kept.back().first + kept.back().count;
    kept.push_back(q);
  }
  return kept;
}

// @region corner-boxes
// The polygon's vertices as corners of (D34), their functions numbered from `first`. A box of a few
// cells would miss, on every grid alike, the part of G - I_h G just outside it, and the error would
// keep the plain space's order with a smaller constant; a box of a fixed size lets the order rise.
// Its half-width is a quarter of the shorter side at the corner or a third of the corner's distance
// from the clamped edges, whichever is less, lengths of the scene alone; but never less than the
// band of `zero` cells, on a grid too coarse for that.
std::vector<KinkCorner> polygon_corners(const Outline& o, const Grid& g, const KinkBand& band, int first) {
  std::vector<KinkCorner> c;
  const size_t m = o.x.size();
  for (size_t i = 0; i < m; ++i) {
    const double x = o.x[i], y = o.y[i];
    const double before = std::hypot(x - o.x[(i + m - 1) % m], y - o.y[(i + m - 1) % m]);
    const double after = std::hypot(x - o.x[(i + 1) % m], y - o.y[(i + 1) % m]);
    const double room = std::min({x, y, g.whole_lx() - x, g.whole_ly() - y});
    const double outer = std::max(std::min(0.25 * std::min(before, after), room / 3), band.zero * g.h);
    c.push_back({x, y, first + static_cast<int>(i), outer * band.flat / band.zero, outer});
  }
  return c;
}
// @end corner-boxes

// Where each function can be nonzero, every node must carry unknowns: F_ij's nodes lie within the
// splines' reach along the side and outer + 1.5 cells across it (side_kink_interpolant).
std::string clearance(const Grid& g, const std::vector<KinkSide>& sides, const std::vector<KinkCorner>& corners, double outer) {
  const double margin = 0.5 * g.h;
  for (const KinkCorner& V : corners) {
    const double room = V.outer + 1.5 * g.h + margin;
    if (!(V.x > room && V.y > room && V.x < g.whole_lx() - room && V.y < g.whole_ly() - room)) {
      std::ostringstream m;
      m << "a corner's function (D34) reaches within half a cell of a clamped edge on this grid (h = " << g.h
        << "): each corner needs " << room / g.h << " cells of room";
      return m.str();
    }
  }
  for (const KinkSide& q : sides)
    for (double s : {-reach(q), q.length + reach(q)})
      for (double d : {0.0, outer + 1.5 * g.h}) {
        const double x = q.x0 + s * q.tx + d * q.nx, y = q.y0 + s * q.ty + d * q.ny;
        if (!(x > margin && y > margin && x < g.whole_lx() - margin && y < g.whole_ly() - margin)) {
          std::ostringstream m;
          m << "its functions reach within half a cell of a clamped edge on this grid (h = " << g.h
            << "): the polygon needs about " << reach(q) / g.h << " cells of room past each vertex and "
            << outer / g.h + 2 << " beyond each side";
          return m.str();
        }
      }
  return "";
}

// The spline of the whole polygon that spline J becomes in the mirror x -> 2X - x (about_x) or
// y -> 2Y - y (a side's spline, or a corner's function); -1 if there is none.
int image_of(const KinkEnrichment& e, int J, bool about_x, double X, double Y, double tol) {
  const std::vector<KinkSide>& sides = e.sides;
  for (const KinkCorner& V : e.corners)
    if (V.index == J) {
      const double px = about_x ? 2 * X - V.x : V.x, py = about_x ? V.y : 2 * Y - V.y;
      for (const KinkCorner& W : e.corners)
        if (std::abs(W.x - px) < tol && std::abs(W.y - py) < tol) return W.index;
      return -1;
    }
  const auto it = std::find_if(sides.begin(), sides.end(), [J](const KinkSide& q) { return J >= q.first && J < q.first + q.count; });
  const KinkSide& q = *it;
  const double s = (J - q.first - 1) * q.spacing;
  double px = q.x0 + s * q.tx, py = q.y0 + s * q.ty, nx = q.nx, ny = q.ny;
  if (about_x) px = 2 * X - px, nx = -nx;
  else py = 2 * Y - py, ny = -ny;
  for (const KinkSide& r : sides) {
    if (std::abs(r.nx - nx) > 1e-9 || std::abs(r.ny - ny) > 1e-9 || std::abs(dist(r, px, py)) > tol) continue;
    if (std::abs(r.spacing - q.spacing) > tol) continue;
    const double u = along(r, px, py) / r.spacing + 1;
    const int j = static_cast<int>(std::lround(u));
    if (std::abs(u - j) * r.spacing < tol && j >= 0 && j < r.count) return r.first + j;
  }
  return -1;
}

// function_of_spline and the number of functions: each mirror orbit one function; false if a
// spline has no image.
bool orbits(const Grid& g, KinkEnrichment& e) {
  const int M = e.knots;
  const double tol = 1e-9 * g.h;
  e.function_of_spline.assign(M, -1);
  e.functions = 0;
  for (int j = 0; j < M; ++j) {
    if (e.function_of_spline[j] >= 0) continue;
    std::vector<int> orbit{j};
    if (g.mirror_x) orbit.push_back(image_of(e, j, true, g.lx(), g.ly(), tol));
    if (g.mirror_y)
      for (int k : std::vector<int>(orbit)) orbit.push_back(k < 0 ? -1 : image_of(e, k, false, g.lx(), g.ly(), tol));
    if (std::find(orbit.begin(), orbit.end(), -1) != orbit.end()) return false;
    for (int k : orbit) e.function_of_spline[k] = e.functions;
    ++e.functions;
  }
  return true;
}

// The enrichment of (D33) and (D34) before the mirror orbits: the sides' splines, then the corners.
KinkEnrichment sides_enrichment(const Grid& g, const Outline& p, const std::vector<KinkSide>& sides, const KinkBand& band) {
  KinkEnrichment e;
  e.sides = sides;
  e.inner = band.flat * g.h, e.outer = band.zero * g.h, e.unit = g.h;
  const int splines = sides.empty() ? 0 : sides.back().first + sides.back().count;
  e.corners = polygon_corners(p, g, band, splines);
  e.knots = splines + static_cast<int>(e.corners.size());
  return e;
}

}  // namespace

namespace {
// The enrichment of (D33) and (D34) for polygon p on grid g, or why it does not fit.
KinkEnrichment fit_side_kinks(const Grid& g, const EdgeCurve& p, const KinkBand& band, std::string& why) {
  if (p.kind != EdgeCurve::Kind::Polygon) return why = "the edge is not a polygon", KinkEnrichment{};
  const Outline o = convex_outline(p, why);
  if (!why.empty()) return {};
  const std::vector<KinkSide> sides = polygon_sides(o, g.h, why);
  if (!why.empty()) return {};
  KinkEnrichment e = sides_enrichment(g, o, sides, band);
  if (why = clearance(g, sides, e.corners, band.zero * g.h); !why.empty()) return {};
  if (!orbits(g, e)) why = "its functions do not map onto each other across the mirror lines";
  return e;
}
}  // namespace

std::string side_kink_misfit(const Grid& g, const EdgeCurve& p, const KinkBand& band) {
  std::string why;
  fit_side_kinks(g, p, band, why);
  return why;
}

KinkEnrichment make_side_kinks(const Grid& g, const EdgeCurve& p, const KinkBand& band) {
  check_kink_band(band);
  std::string why;
  KinkEnrichment e = fit_side_kinks(g, p, band, why);
  if (!why.empty()) throw std::invalid_argument("--enrich sides: " + why);
  return e;
}

// Eq. (D33)'s F of function k, plus its corners' D_V (D34).
KinkValue side_kink_profile(const KinkEnrichment& e, int k, double x, double y) {
  KinkValue v;
  for (const KinkSide& q : e.sides) {
    const double d = dist(q, x, y);
    if (!(d > 0)) continue;
    for_splines(q, along(q, x, y), [&](int J, const KinkSpline& b) {
      if (e.function_of_spline[J] == k) add(v, side_profile(q, b, d, e.unit), 1.0);
    });
  }
  for (const KinkCorner& V : e.corners)
    if (e.function_of_spline[V.index] == k) add(v, corner_difference(e, V, x, y), 1.0);
  return v;
}

// Eq. (D33): the Hermite interpolant of each side's F (the corners' functions need none).
SpMat side_kink_interpolant(const Grid& g, const KinkEnrichment& e) {
  std::vector<Eigen::Triplet<double>> t;
  const double read = e.outer + 1.5 * g.h;  // the nodes of every square where chi is not 0
  for (int j = 0; j <= g.ny; ++j)
    for (int i = 0; i <= g.nx; ++i) {
      const double x = g.x(i), y = g.y(j);
      if (!g.is_interior(i, j) || std::any_of(e.sides.begin(), e.sides.end(), [&](const KinkSide& q) { return dist(q, x, y) >= read; })) continue;
      for (const KinkSide& q : e.sides) {
        const double d = dist(q, x, y);
        if (!(d > 0)) continue;
        for_splines(q, along(q, x, y), [&](int J, const KinkSpline& b) {
          const KinkValue v = side_profile(q, b, d, e.unit);
          const double comp[4] = {v.w, v.wx, v.wy, v.wxy};
          for (int c = 0; c < 4; ++c)
            if (const int dof = g.dof(i, j, c); dof >= 0 && comp[c] != 0) t.emplace_back(dof, e.function_of_spline[J], comp[c]);
        });
      }
    }
  SpMat P(g.unknowns(), e.size());
  P.setFromTriplets(t.begin(), t.end());
  return P;
}

// Whether some side's psi can be nonzero at (x, y): chi not 0, and within reach of a side's splines.
static bool near_sides(const KinkEnrichment& e, double x, double y) {
  bool some = false;
  for (const KinkSide& q : e.sides) {
    const double d = dist(q, x, y), s = along(q, x, y);
    if (!(d < e.outer)) return false;  // chi = 0
    some = some || (d > -e.inner && s > -reach(q) - e.inner && s < q.length + reach(q) + e.inner);
  }
  return some;
}

static bool near_corner(const KinkEnrichment& e, double x, double y) {
  return std::any_of(e.corners.begin(), e.corners.end(), [&](const KinkCorner& V) { return in_box(V, x, y); });
}

bool side_kink_near(const KinkEnrichment& e, double x, double y) { return near_sides(e, x, y) || near_corner(e, x, y); }

namespace {
// Eq. (D33): the sides' D = sum c F - I_h(sum c F) at (x, y), the interpolant's share given.
KinkValue side_difference(const KinkEnrichment& e, const VectorXd& c, const KinkValue& interpolant, double x, double y) {
  KinkValue D;
  add(D, interpolant, -1.0);
  for (const KinkSide& q : e.sides) {
    const double d = dist(q, x, y);
    if (!(d > 0)) continue;
    for_splines(q, along(q, x, y), [&](int J, const KinkSpline& b) { add(D, side_profile(q, b, d, e.unit), c[e.function_of_spline[J]]); });
  }
  return D;
}
// Eq. (D34): the corners' sum c D_V, which chi does not multiply: cut off again at the sides' band, a corner's
// function would lose, a few cells from the sides, what its box keeps for the order's sake
// (polygon_corners); measured, the order fell back to 2.
KinkValue corners_sum(const KinkEnrichment& e, const VectorXd& c, double x, double y, const int* cell = nullptr) {
  KinkValue D;
  for (const KinkCorner& V : e.corners)
    if (in_box(V, x, y)) add(D, corner_difference(e, V, x, y, cell), c[e.function_of_spline[V.index]]);
  return D;
}
}  // namespace

// psi = chi D + sum_V c_V D_V of (D33) and (D34) at (x, y), with its derivatives.
KinkValue side_kink_field(const KinkEnrichment& e, const VectorXd& c, const KinkValue& interpolant, double x, double y, const int* cell) {
  KinkValue out = near_corner(e, x, y) ? corners_sum(e, c, x, y, cell) : KinkValue{};
  if (!near_sides(e, x, y)) return out;
  const KinkValue D = side_difference(e, c, interpolant, x, y), chi = side_cutoff(e, x, y);
  out.w += chi.w * D.w;
  out.wx += chi.w * D.wx + chi.wx * D.w;
  out.wy += chi.w * D.wy + chi.wy * D.w;
  out.wxx += chi.w * D.wxx + 2 * chi.wx * D.wx + chi.wxx * D.w;
  out.wxy += chi.w * D.wxy + chi.wx * D.wy + chi.wy * D.wx + chi.wxy * D.w;
  out.wyy += chi.w * D.wyy + 2 * chi.wy * D.wy + chi.wyy * D.w;
  return out;
}

// The value alone of side_kink_field's psi, (D33) and (D34).
double side_kink_value(const KinkEnrichment& e, const VectorXd& c, double interpolant, double x, double y) {
  const double v = near_corner(e, x, y) ? corners_sum(e, c, x, y).w : 0;
  if (!near_sides(e, x, y)) return v;
  KinkValue I;
  I.w = interpolant;
  return v + side_cutoff(e, x, y).w * side_difference(e, c, I, x, y).w;
}

namespace {

using Piece = std::vector<std::array<double, 2>>;

// Each piece cut in two by the line a x + b y = c where the line crosses it.
void split(std::vector<Piece>& pieces, double a, double b, double c, double tol) {
  std::vector<Piece> out;
  for (const Piece& p : pieces) {
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& v : p) lo = std::min(lo, a * v[0] + b * v[1] - c), hi = std::max(hi, a * v[0] + b * v[1] - c);
    if (!(lo < -tol && hi > tol)) {
      out.push_back(p);
      continue;
    }
    Piece neg, pos;
    for (size_t i = 0; i < p.size(); ++i) {
      const auto &u = p[i], &w = p[(i + 1) % p.size()];
      const double fu = a * u[0] + b * u[1] - c, fw = a * w[0] + b * w[1] - c;
      if (fu <= tol) neg.push_back(u);
      if (fu >= -tol) pos.push_back(u);
      if ((fu < -tol && fw > tol) || (fu > tol && fw < -tol)) {
        const double s = fu / (fu - fw);
        const std::array<double, 2> x{u[0] + s * (w[0] - u[0]), u[1] + s * (w[1] - u[1])};
        neg.push_back(x), pos.push_back(x);
      }
    }
    if (neg.size() >= 3) out.push_back(neg);
    if (pos.size() >= 3) out.push_back(pos);
  }
  pieces = std::move(out);
}

struct Point {
  double x, y, w;
};

// @region side-kink-pieces
// The pieces of square (x0, y0) on which every function of (D33) is one polynomial, and a rule on
// each that integrates (D33)'s blocks exactly. D = F - I_h F is of degree 6 (F: 3 in d, 3 in s; the
// bicubic: 3 in x and in y), so Lap D is of degree 4; chi is of degree 5a where a of its factors are
// neither 1 nor 0, so Lap psi is of degree 5a + 4 and (Lap psi_k, Lap psi_l) of 10a + 8. A
// triangle's collapsed rule (Duffy: the Jacobian adds a degree in the collapsed direction) with
// n = 5a + 5 Gauss points each way is exact to degree 2n - 2 = 10a + 8.
// The collapsed (Duffy) rule on triangle (A, B, C), u running from A: x = A + u (B - A) + u v (C - B),
// with Jacobian u |(B - A) x (C - B)|. The Jacobian's u adds a degree in u, so n points each way are
// exact to degree 2n - 2. Graded, the u-rule is composite on [s^(k+1), s^k] towards A, for an
// integrand with a logarithm at A (D34).
void triangle_rule(const std::array<double, 2>& A, const std::array<double, 2>& B, const std::array<double, 2>& C, int n,
                   bool graded, double h, std::vector<Point>& rule) {
  const double area2 = std::abs((B[0] - A[0]) * (C[1] - A[1]) - (B[1] - A[1]) * (C[0] - A[0]));
  if (area2 < 1e-28 * h * h) return;
  const Quadrature1D g = gauss_legendre(n);
  constexpr double kRatio = 0.2;
  constexpr int kLevels = 10;
  std::vector<std::pair<double, double>> us;  // (u, weight)
  for (int level = 0; level < (graded ? kLevels + 1 : 1); ++level) {
    const double hi = graded ? std::pow(kRatio, level) : 1, lo = graded && level < kLevels ? hi * kRatio : 0;
    for (size_t a = 0; a < g.points.size(); ++a) us.push_back({lo + (hi - lo) * g.points[a], (hi - lo) * g.weights[a]});
  }
  for (const auto& [u, wu] : us)
    for (size_t b = 0; b < g.points.size(); ++b) {
      const double v = g.points[b];
      rule.push_back({A[0] + u * (B[0] - A[0]) + u * v * (C[0] - B[0]), A[1] + u * (B[1] - A[1]) + u * v * (C[1] - B[1]),
                      wu * g.weights[b] * u * area2});
    }
}

// The point of convex piece p nearest to (x, y), made one of its vertices: the fan's apex.
Piece with_nearest_first(const Piece& p, double x, double y) {
  double best = INFINITY;
  size_t edge = 0;
  std::array<double, 2> at{};
  for (size_t i = 0; i < p.size(); ++i) {
    const auto &a = p[i], &b = p[(i + 1) % p.size()];
    const double ex = b[0] - a[0], ey = b[1] - a[1], L2 = ex * ex + ey * ey;
    const double t = L2 > 0 ? std::clamp(((x - a[0]) * ex + (y - a[1]) * ey) / L2, 0.0, 1.0) : 0;
    const std::array<double, 2> q{a[0] + t * ex, a[1] + t * ey};
    const double d = std::hypot(q[0] - x, q[1] - y);
    if (d < best) best = d, edge = i, at = q;
  }
  Piece out{at};
  for (size_t k = 1; k <= p.size(); ++k) {
    const auto& v = p[(edge + k) % p.size()];
    if (std::hypot(v[0] - at[0], v[1] - at[1]) > 1e-14 * (std::abs(at[0]) + std::abs(at[1]) + 1)) out.push_back(v);
  }
  return out;
}

std::vector<Point> cell_rule(const KinkEnrichment& e, double x0, double y0, double h) {
  const auto at = [](double x, double y) { return std::array<double, 2>{x, y}; };
  std::vector<Piece> pieces(1, Piece{at(x0, y0), at(x0 + h, y0), at(x0 + h, y0 + h), at(x0, y0 + h)});
  const double tol = 1e-13 * h;
  for (const KinkSide& q : e.sides) {
    const double c = q.x0 * q.nx + q.y0 * q.ny;
    double dmax = -INFINITY, smin = INFINITY, smax = -INFINITY;
    for (double x : {x0, x0 + h})
      for (double y : {y0, y0 + h}) dmax = std::max(dmax, dist(q, x, y)), smin = std::min(smin, along(q, x, y)), smax = std::max(smax, along(q, x, y));
    split(pieces, q.nx, q.ny, c + e.inner, tol), split(pieces, q.nx, q.ny, c + e.outer, tol);
    if (!(dmax > 0)) continue;  // F of this side is 0 on the square
    split(pieces, q.nx, q.ny, c, tol);
    const double s0 = q.x0 * q.tx + q.y0 * q.ty;
    const int k_lo = std::max(-3, static_cast<int>(std::floor(smin / q.spacing))), k_hi = std::min(q.count, static_cast<int>(std::ceil(smax / q.spacing)));
    for (int k = k_lo; k <= k_hi; ++k) split(pieces, q.tx, q.ty, s0 + k * q.spacing, tol);
  }
  // A corner's box breaks at its cut-off's lines, and the lines through the corner make it a vertex
  // of every piece it touches, where the graded rule can meet its logarithm.
  for (const KinkCorner& V : e.corners)
    for (double off : {-V.outer, -V.inner, 0.0, V.inner, V.outer})
      split(pieces, 1, 0, V.x + off, tol), split(pieces, 0, 1, V.y + off, tol);
  std::vector<Point> rule;
  for (const Piece& p : pieces) {
    double cx = 0, cy = 0, size = 0;
    for (const auto& v : p) cx += v[0] / p.size(), cy += v[1] / p.size();
    for (const auto& v : p) size = std::max(size, 2 * std::hypot(v[0] - cx, v[1] - cy));
    int active = 0;
    bool zero = false;
    for (const KinkSide& q : e.sides) {
      const double d = dist(q, cx, cy);
      zero = zero || d >= e.outer;
      active += d > e.inner && d < e.outer;
    }
    const int n = 5 * active + 5;
    // Near a corner whose D_V is not 0 on the piece, a logarithm: graded from the piece's point
    // nearest the corner where the corner is within the piece's size, else Gauss.
    bool near = false;
    double gap = INFINITY;
    Piece fan;  // from the piece's point nearest the nearest corner
    for (const KinkCorner& V : e.corners)
      if (in_box(V, cx, cy)) {
        Piece from = with_nearest_first(p, V.x, V.y);
        const double d = std::hypot(from[0][0] - V.x, from[0][1] - V.y);
        if (d < gap) gap = d, near = true, fan = std::move(from);
      }
    if (zero && !near) continue;  // chi = 0 on the piece, and no corner's box
    if (near && gap < size) {
      // At the corner itself the grading meets the logarithm and the rest is smooth. From a point
      // near it the logarithm, a fraction of the piece away, slows the rule across as well: 8 points
      // left 4e-10 of a block entry there (against a polar rule about the corner), 16 do not; and
      // Gauss's 16 points ungraded moved the acute triangle's max w by 8e-9 at n = 64.
      for (size_t i = 1; i + 1 < fan.size(); ++i) triangle_rule(fan[0], fan[i], fan[i + 1], std::max(n, gap > 0 ? 16 : 8), true, h, rule);
      continue;
    }
    // Several sizes away G is smooth on the piece, and D_V small: fewer points suffice there.
    const int m = !near ? n : std::max(n, gap < 3 * size ? 12 : 8);
    for (size_t i = 1; i + 1 < p.size(); ++i) triangle_rule(p[0], p[i], p[i + 1], m, false, h, rule);
  }
  return rule;
}
// @end side-kink-pieces

// Whether a function of (D33) or (D34) can be nonzero on square (x0, y0): a corner's box meets it,
// or chi is not 0 on all of it and some side's F is not 0 at one of its points.
bool square_near(const KinkEnrichment& e, double x0, double y0, double h) {
  if (std::any_of(e.corners.begin(), e.corners.end(), [&](const KinkCorner& V) {
        return std::abs(x0 + 0.5 * h - V.x) < V.outer + h && std::abs(y0 + 0.5 * h - V.y) < V.outer + h;
      }))
    return true;
  bool some = false;
  for (const KinkSide& q : e.sides) {
    double dmin = INFINITY, dmax = -INFINITY;
    for (double x : {x0, x0 + h})
      for (double y : {y0, y0 + h}) dmin = std::min(dmin, dist(q, x, y)), dmax = std::max(dmax, dist(q, x, y));
    if (dmin >= e.outer) return false;
    some = some || dmax > 0;
  }
  return some;
}

}  // namespace

// (D33)'s blocks: (Lap phi_i, Lap psi_k), (Lap psi_k, Lap psi_l) and (f, psi_k), square by square
// on the pieces of cell_rule.
KinkBlocks assemble_side_kink_blocks(const Grid& g, const KinkEnrichment& e, const SpMat& interpolant, const Field& f) {
  const int N = g.unknowns();
  const double h = g.h;
  const RowSpMat P = interpolant;
  std::vector<Eigen::Triplet<double>> t;
  KinkBlocks out;
  out.load = VectorXd::Zero(e.size());
  for (int ey = 0; ey < g.ny; ++ey)
    for (int ex = 0; ex < g.nx; ++ex) {
      const double x0 = ex * h, y0 = ey * h;
      if (!square_near(e, x0, y0, h)) continue;
      const std::vector<Point> rule = cell_rule(e, x0, y0, h);
      const auto dofs = g.element_dofs(ex, ey);
      std::vector<int> met;
      auto local = [&](int k) {
        const auto it = std::find(met.begin(), met.end(), k);
        if (it != met.end()) return static_cast<int>(it - met.begin());
        met.push_back(k);
        return static_cast<int>(met.size()) - 1;
      };
      std::vector<std::array<double, 3>> entries;  // (local row, function, value) of P on the square
      for (int q = 0; q < 16; ++q)
        if (dofs[q] >= 0)
          for (RowSpMat::InnerIterator it(P, dofs[q]); it; ++it) entries.push_back({double(q), double(local(static_cast<int>(it.col()))), it.value()});
      for (const Point& p : rule) {
        for (const KinkSide& q : e.sides)
          if (dist(q, p.x, p.y) > 0) for_splines(q, along(q, p.x, p.y), [&](int J, const KinkSpline&) { local(e.function_of_spline[J]); });
        for (const KinkCorner& V : e.corners)
          if (in_box(V, p.x, p.y)) local(e.function_of_spline[V.index]);
      }
      const int L = static_cast<int>(met.size());
      if (L == 0) continue;
      Eigen::MatrixXd Pl = Eigen::MatrixXd::Zero(16, L), Bl = Eigen::MatrixXd::Zero(16, L), El = Eigen::MatrixXd::Zero(L, L);
      for (const auto& en : entries) Pl(static_cast<int>(en[0]), static_cast<int>(en[1])) = en[2];
      VectorXd fl = VectorXd::Zero(L);
      for (const Point& p : rule) {
        const LocalBasis b = bfs_basis((p.x - x0) / h, (p.y - y0) / h, h);
        const Vector16 lap = b.dxx + b.dyy;
        VectorXd Dv = -Pl.transpose() * b.v, Dx = -Pl.transpose() * b.dx, Dy = -Pl.transpose() * b.dy, Dl = -Pl.transpose() * lap;
        for (const KinkSide& q : e.sides) {
          const double d = dist(q, p.x, p.y);
          if (!(d > 0)) continue;
          for_splines(q, along(q, p.x, p.y), [&](int J, const KinkSpline& s) {
            const KinkValue F = side_profile(q, s, d, e.unit);
            const int l = local(e.function_of_spline[J]);
            Dv[l] += F.w, Dx[l] += F.wx, Dy[l] += F.wy, Dl[l] += F.wxx + F.wyy;
          });
        }
        const KinkValue chi = side_cutoff(e, p.x, p.y);
        VectorXd psi = chi.w * Dv, lap_psi = chi.w * Dl + 2 * (chi.wx * Dx + chi.wy * Dy) + (chi.wxx + chi.wyy) * Dv;
        for (const KinkCorner& V : e.corners) {  // chi does not multiply them (corners_sum)
          if (!in_box(V, p.x, p.y)) continue;
          const int here[2] = {ex, ey};
          const KinkValue F = corner_difference(e, V, p.x, p.y, here);
          const int l = local(e.function_of_spline[V.index]);
          psi[l] += F.w, lap_psi[l] += F.wxx + F.wyy;
        }
        Bl.noalias() += p.w * lap * lap_psi.transpose();
        El.noalias() += p.w * lap_psi * lap_psi.transpose();
        fl += p.w * f(p.x, p.y) * psi;
      }
      for (int k = 0; k < L; ++k) {
        const int col = N + met[k];
        for (int i = 0; i < 16; ++i)
          if (dofs[i] >= 0 && Bl(i, k) != 0) t.emplace_back(dofs[i], col, Bl(i, k)), t.emplace_back(col, dofs[i], Bl(i, k));
        for (int l = 0; l < L; ++l)
          if (El(k, l) != 0) t.emplace_back(col, N + met[l], El(k, l));
        out.load[met[k]] += fl[k];
      }
    }
  out.border.resize(N + e.size(), N + e.size());
  out.border.setFromTriplets(t.begin(), t.end());
  return out;
}

}  // namespace plate
