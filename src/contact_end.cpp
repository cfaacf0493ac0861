// The fields of a contact's end, the fit that locates it, and their blocks of the stiffness.
#include "contact_end.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "bfs_element.hpp"
#include "gauss.hpp"
#include "implicit_quadrature.hpp"

namespace plate {

namespace {

// The rim-fitted coordinates of (x, y): t along the rim into the free side, nu = r - a.
struct Fitted {
  double r, theta, t, nu, rho;
};
Fitted fitted(const ContactEnd& e, double x, double y) {
  Fitted f;
  const double dx = x - e.cx, dy = y - e.cy;
  f.r = std::hypot(dx, dy), f.theta = std::atan2(dy, dx);
  f.t = e.a * std::remainder(f.theta - e.theta, 2 * M_PI) * e.sigma;
  f.nu = f.r - e.a;
  f.rho = std::hypot(f.t, f.nu);
  return f;
}

// A function of (t, nu), given its derivatives there, in x and y: d/dr = d/dnu, d/dtheta = sigma a d/dt.
EndDerivatives from_fitted(const ContactEnd& e, const Fitted& p, double v, double Ft, double Fn, double Ftt, double Ftn, double Fnn) {
  const double sa = e.sigma * e.a;
  return from_polar(p.r, std::cos(p.theta), std::sin(p.theta), v, Fn, sa * Ft, Fnn, sa * Ftn, e.a * e.a * Ftt);
}

}  // namespace

EndDerivatives end_field(const ContactEnd& e, EndField which, double x, double y) {
  const Fitted p = fitted(e, x, y);
  if (p.rho == 0) return {};
  // rho^lambda G(omega), G = cos(lambda omega) + B cos(omega / 2): B = 3 for lambda = 3/2 and -5 for
  // 5/2 make the normal slope vanish on the contact side (G'(pi) = 0), so the field is C^2 across it.
  const double lam = which == EndField::Gap32 ? 1.5 : 2.5, B = which == EndField::Gap32 ? 3.0 : -5.0;
  const double om = std::atan2(p.nu, p.t), c = std::cos(om), s = std::sin(om), rho = p.rho;
  const double G = std::cos(lam * om) + B * std::cos(om / 2);
  const double G1 = -lam * std::sin(lam * om) - 0.5 * B * std::sin(om / 2);
  const double G2 = -lam * lam * std::cos(lam * om) - 0.25 * B * std::cos(om / 2);
  const double rl = std::pow(rho, lam);
  // The derivatives in (t, nu) from those in (rho, omega), then in (x, y) from those in (t, nu).
  const PlaneDerivatives d = from_polar(rho, c, s, rl * G, lam * rl / rho * G, rl * G1, lam * (lam - 1) * rl / (rho * rho) * G,
                                        lam * rl / rho * G1, rl * G2);
  return from_fitted(e, p, d.w, d.wx, d.wy, d.wxx, d.wxy, d.wyy);
}

EndDerivatives end_cutoff(const ContactEnd& e, double x, double y) {
  const Fitted p = fitted(e, x, y);
  EndDerivatives o;
  if (p.rho >= e.outer) return o;
  o.w = 1;
  if (p.rho <= e.inner) return o;
  const double L = e.outer - e.inner, u = (p.rho - e.inner) / L, u2 = u * u, v = 1 - u;
  const double X = 1 - u2 * u2 * (35 - 84 * u + 70 * u2 - 20 * u2 * u);
  const double X1 = -140 * u2 * u * v * v * v / L, X2 = -420 * u2 * v * v * (1 - 2 * u) / (L * L);
  const double c = p.t / p.rho, s = p.nu / p.rho;
  return from_fitted(e, p, X, X1 * c, X1 * s, X2 * c * c + X1 * s * s / p.rho, (X2 - X1 / p.rho) * c * s,
                     X2 * s * s + X1 * c * c / p.rho);
}

double end_reach(const ContactEnd& e) { return e.outer * std::sqrt(1 + 2 * e.outer / (3 * std::sqrt(3.0) * e.a)); }

namespace {
// The 16 unknowns of I_h F on cell (ex, ey): each corner's value, slopes and twist of F.
std::array<double, 16> interpolant_unknowns(const ContactEnd& e, EndField which, const Grid& g, int ex, int ey) {
  std::array<double, 16> u{};
  for (int ay = 0; ay < 2; ++ay)
    for (int ax = 0; ax < 2; ++ax) {
      const EndDerivatives n = end_field(e, which, (ex + ax) * g.h, (ey + ay) * g.h);
      const double dof[4] = {n.w, n.wx, n.wy, n.wxy};
      for (int c = 0; c < 4; ++c) u[4 * (ax + 2 * ay) + c] = dof[c];
    }
  return u;
}

// chi (F - I_h F) at (x, y), given chi there (X, not 0), the cell's basis b there and I_h F's
// unknowns u on the cell.
EndValue end_function_in_cell(const ContactEnd& e, EndField which, const EndDerivatives& X, const std::array<double, 16>& u,
                              const LocalBasis& b, double x, double y) {
  const EndDerivatives F = end_field(e, which, x, y);
  EndDerivatives I;
  for (int j = 0; j < 16; ++j) {
    I.w += u[j] * b.v[j], I.wx += u[j] * b.dx[j], I.wy += u[j] * b.dy[j];
    I.wxx += u[j] * b.dxx[j], I.wyy += u[j] * b.dyy[j];
  }
  const double d = F.w - I.w, dx = F.wx - I.wx, dy = F.wy - I.wy, lap = F.wxx + F.wyy - I.wxx - I.wyy;
  return {X.w * d, X.w * lap + 2 * (X.wx * dx + X.wy * dy) + d * (X.wxx + X.wyy)};
}
}  // namespace

namespace {
// The cell of (x, y) and the basis there; throws std::invalid_argument off the grid.
struct CellAt {
  int ex, ey;
  LocalBasis b;
};
CellAt cell_at(const Grid& g, double x, double y) {
  int ex, ey;
  double t, u;
  if (!g.locate(x, y, ex, ey, t, u)) throw std::invalid_argument("end_function: the point is outside the grid");
  return {ex, ey, bfs_basis(t, u, g.h)};
}
}  // namespace

// Its value and Laplacian as the blocks form them (end_function_in_cell), which the test of the
// derivatives holds against the product rule below.
EndValue end_function(const ContactEnd& e, EndField which, const Grid& g, double x, double y) {
  const EndDerivatives X = end_cutoff(e, x, y);
  if (X.w == 0) return {};
  const CellAt c = cell_at(g, x, y);
  return end_function_in_cell(e, which, X, interpolant_unknowns(e, which, g, c.ex, c.ey), c.b, x, y);
}

namespace {
// chi (F - I_h F) and its derivatives at (x, y), with I_h F that of cell (ex, ey), b its basis there.
EndDerivatives derivatives_in(const ContactEnd& e, EndField which, const Grid& g, const EndDerivatives& X, int ex, int ey,
                              const LocalBasis& b, double x, double y) {
  const std::array<double, 16> c = interpolant_unknowns(e, which, g, ex, ey);
  EndDerivatives D = end_field(e, which, x, y);  // then D = F - I_h F
  for (int j = 0; j < 16; ++j) {
    D.w -= c[j] * b.v[j], D.wx -= c[j] * b.dx[j], D.wy -= c[j] * b.dy[j];
    D.wxx -= c[j] * b.dxx[j], D.wxy -= c[j] * b.dxy[j], D.wyy -= c[j] * b.dyy[j];
  }
  // The product rule for chi D.
  return {X.w * D.w,
          X.w * D.wx + X.wx * D.w,
          X.w * D.wy + X.wy * D.w,
          X.w * D.wxx + 2 * X.wx * D.wx + X.wxx * D.w,
          X.w * D.wxy + X.wx * D.wy + X.wy * D.wx + X.wxy * D.w,
          X.w * D.wyy + 2 * X.wy * D.wy + X.wyy * D.w};
}
}  // namespace

EndDerivatives end_function_derivatives(const ContactEnd& e, EndField which, const Grid& g, double x, double y) {
  const EndDerivatives X = end_cutoff(e, x, y);
  if (X.w == 0) return {};
  const CellAt c = cell_at(g, x, y);
  return derivatives_in(e, which, g, X, c.ex, c.ey, c.b, x, y);
}

EndDerivatives end_function_derivatives_in(const ContactEnd& e, EndField which, const Grid& g, int ex, int ey, double t, double u,
                                           double x, double y) {
  const EndDerivatives X = end_cutoff(e, x, y);
  if (X.w == 0) return {};
  return derivatives_in(e, which, g, X, ex, ey, bfs_basis(t, u, g.h), x, y);
}

double end_shift(const std::vector<double>& s, const std::vector<double>& gap) {
  if (s.size() != gap.size() || s.size() < 3) throw std::invalid_argument("end_shift: three or more samples, one gap each");
  Eigen::MatrixXd A(s.size(), 3);
  Eigen::VectorXd b(s.size());
  for (size_t i = 0; i < s.size(); ++i) {
    A(i, 0) = std::pow(s[i], 1.5), A(i, 1) = std::pow(s[i], 2.5), A(i, 2) = std::pow(s[i], 3.5);
    b[i] = gap[i];
  }
  const Eigen::VectorXd c = A.colPivHouseholderQr().solve(b);
  if (!(c[1] > 0)) throw std::invalid_argument("end_shift: the gap does not open like an end's (its s^(5/2) term is not positive)");
  return -0.4 * c[0] / c[1];
}

namespace {
// The line through (cx, cy) at angle theta, linear and so exact.
Bicubic line_on(double cx, double cy, double theta, double sx, double sy, double size) {
  std::array<CornerJet, 4> c;
  const double nx = -std::sin(theta), ny = std::cos(theta);
  for (int k = 0; k < 4; ++k) c[k] = {nx * (sx + (k & 1) * size - cx) + ny * (sy + (k >> 1) * size - cy), nx, ny, 0};
  return bicubic_from_corners(c, size, size);
}
// rho^2 - c^2 on the same square, rho^2 = t^2 + nu^2 of the end's fitted coordinates: its bicubic
// Hermite interpolant from the corners, which follows the curve rho = c to the interpolant's order
// (the edge is a smooth curve and a square is at most a cell across, so the two stay close).
Bicubic cutoff_circle_on(const ContactEnd& e, double c, double sx, double sy, double size) {
  std::array<CornerJet, 4> jets;
  for (int k = 0; k < 4; ++k) {
    const double x = sx + (k & 1) * size, y = sy + (k >> 1) * size, X = x - e.cx, Y = y - e.cy;
    const double r2 = X * X + Y * Y, r = std::sqrt(r2), sa = e.sigma * e.a;
    // The fitted coordinates end at the centre; a square there has rho >= a - sqrt(2) h, beyond
    // every cut-off edge while outer < a - sqrt(2) h, so it is taken as uncut.
    if (!(r2 > 0)) return Bicubic{{1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1}};
    const double t = e.a * std::remainder(std::atan2(Y, X) - e.theta, 2 * M_PI) * e.sigma, nu = r - e.a;
    const double tx = -sa * Y / r2, ty = sa * X / r2, txy = sa * (Y * Y - X * X) / (r2 * r2);
    const double nx = X / r, ny = Y / r, nxy = -X * Y / (r2 * r);
    jets[k] = {t * t + nu * nu - c * c, 2 * (t * tx + nu * nx), 2 * (t * ty + nu * ny),
               2 * (tx * ty + t * txy + nx * ny + nu * nxy)};
  }
  return bicubic_from_corners(jets, size, size);
}

// The curves across which the ends' functions are not smooth: each rim (their Laplacians kink
// across its contact side; (D31)'s across all of it) and the edges of each end's cut-off, where it
// is only C^3; each once, though an end appears once per field.
struct EndCurves {
  std::vector<ContactEnd> rims, centres;
};
EndCurves end_curves(const std::vector<ContactEnd>& ends) {
  EndCurves c;
  for (const ContactEnd& e : ends) {
    auto on_rim = [&](const ContactEnd& o) { return o.cx == e.cx && o.cy == e.cy && o.a == e.a; };
    if (std::none_of(c.rims.begin(), c.rims.end(), on_rim)) c.rims.push_back(e);
    if (std::none_of(c.centres.begin(), c.centres.end(), [&](const ContactEnd& o) {
          return on_rim(o) && o.theta == e.theta && o.inner == e.inner && o.outer == e.outer;
        }))
      c.centres.push_back(e);
  }
  return c;
}

// Those of `curves`, and of the other functions' `kinks`, that cut the square.
std::vector<Bicubic> cutting_curves(const EndCurves& curves, const OtherKinks* kinks, double sx, double sy, double size) {
  std::vector<Bicubic> out;
  auto add = [&](const Bicubic& b) {
    if (b.sign() == 0) out.push_back(b);
  };
  if (kinks) {
    for (double r : kinks->radii) add(circle_on(kinks->cx, kinks->cy, r, sx, sy, size));
    for (double t : kinks->rays) add(line_on(kinks->cx, kinks->cy, t, sx, sy, size));
  }
  for (const ContactEnd& e : curves.rims) add(circle_on(e.cx, e.cy, e.a, sx, sy, size));
  for (const ContactEnd& e : curves.centres)
    for (double c : {e.inner, e.outer}) add(cutoff_circle_on(e, c, sx, sy, size));
  return out;
}
}  // namespace

EndBlocks assemble_end_blocks(const Grid& g, const std::vector<ContactEnd>& ends, const std::vector<EndField>& fields,
                              int others, const OtherLaplacians& laplacians, const std::function<double(double, double)>* load,
                              const OtherKinks* kinks) {
  if (ends.size() != fields.size()) throw std::invalid_argument("assemble_end_blocks: one field per end");
  if (others > 0 && !laplacians) throw std::invalid_argument("assemble_end_blocks: other functions without their Laplacians");
  // The cut-off's curves are followed in the fitted coordinates, which end at the circle's centre:
  // cutoff_circle_on takes a square there as uncut, right only while outer < a - sqrt(2) h. Past
  // that the centre's squares are misread, and a node at the centre makes the blocks NaN (the
  // end's field divides by r).
  for (const ContactEnd& e : ends) {
    const double widest = e.a - std::sqrt(2.0) * g.h;
    if (e.inner > 0 && e.outer > e.inner && e.outer < widest) continue;
    std::ostringstream m;
    m << "assemble_end_blocks: the end's cut-off (inner " << e.inner << ", outer " << e.outer
      << ") must have 0 < inner < outer < a - sqrt(2) h = " << widest;
    throw std::invalid_argument(m.str());
  }
  const int k = static_cast<int>(ends.size()), N = g.unknowns();
  EndBlocks out{Eigen::MatrixXd::Zero(N, k), Eigen::MatrixXd::Zero(k, k), Eigen::MatrixXd::Zero(others, k), Eigen::VectorXd::Zero(k)};
  Eigen::VectorXd olap(others);
  const Quadrature1D q = gauss_legendre(kEndGaussPoints);
  // Halvings towards an end, where the integrand of the functions' own block grows like 1/rho: the
  // square left after 30 holds a share of about 2^-30 of the cell's, which the Gauss rule on it
  // still takes in part.
  const int to_end = 30;
  auto distance = [](double px, double py, double sx, double sy, double size) {
    return std::hypot(std::max({sx - px, 0.0, px - sx - size}), std::max({sy - py, 0.0, py - sy - size}));
  };
  std::vector<double> px, py;  // the ends' points
  for (const ContactEnd& e : ends) px.push_back(e.cx + e.a * std::cos(e.theta)), py.push_back(e.cy + e.a * std::sin(e.theta));
  std::vector<double> lap(k);
  std::vector<EndDerivatives> cut(k);
  std::vector<std::array<double, 16>> interpolants(k);
  std::vector<WeightedPoint> pts;
  const EndCurves curves = end_curves(ends);
  for (int ey = 0; ey < g.ny; ++ey)
    for (int ex = 0; ex < g.nx; ++ex) {
      const double x0 = ex * g.h, y0 = ey * g.h;
      bool near = false;
      for (int f = 0; f < k; ++f) near = near || distance(px[f], py[f], x0, y0, g.h) < ends[f].outer * 1.2 + g.h;
      if (!near) continue;
      const auto dofs = g.element_dofs(ex, ey);
      for (int f = 0; f < k; ++f) interpolants[f] = interpolant_unknowns(ends[f], fields[f], g, ex, ey);
      auto add_point = [&](double x, double y, double wq) {
        bool any = false;
        for (int f = 0; f < k; ++f) any = (cut[f] = end_cutoff(ends[f], x, y)).w != 0 || any;
        if (!any) return;
        const LocalBasis b = bfs_basis((x - x0) / g.h, (y - y0) / g.h, g.h);
        const double fxy = load ? (*load)(x, y) : 0.0;
        for (int f = 0; f < k; ++f) {
          const EndValue v = cut[f].w == 0 ? EndValue{} : end_function_in_cell(ends[f], fields[f], cut[f], interpolants[f], b, x, y);
          lap[f] = v.lap;
          out.load[f] += wq * fxy * v.w;
        }
        for (int i = 0; i < 16; ++i)
          if (dofs[i] >= 0)
            for (int f = 0; f < k; ++f) out.border(dofs[i], f) += wq * (b.dxx[i] + b.dyy[i]) * lap[f];
        for (int f = 0; f < k; ++f)
          for (int l = 0; l < k; ++l) out.own(f, l) += wq * lap[f] * lap[l];
        if (others == 0) return;
        laplacians(ex, ey, x, y, olap);
        for (int j = 0; j < others; ++j)
          if (olap[j] != 0)
            for (int f = 0; f < k; ++f) out.cross(j, f) += wq * olap[j] * lap[f];
      };
      auto square = [&](auto&& self, double sx, double sy, double size, int depth) -> void {
        bool split = false;
        for (int f = 0; f < k; ++f) split = split || (depth < to_end && distance(px[f], py[f], sx, sy, size) < size);
        if (split) {
          const double h2 = size / 2;
          self(self, sx, sy, h2, depth + 1), self(self, sx + h2, sy, h2, depth + 1);
          self(self, sx, sy + h2, h2, depth + 1), self(self, sx + h2, sy + h2, h2, depth + 1);
          return;
        }
        // Each side of every curve across which the integrand kinks, taken apart where the curves
        // cut the square (implicit_quadrature.hpp); the square whole where none does.
        const std::vector<Bicubic> cutting = cutting_curves(curves, kinks, sx, sy, size);
        if (cutting.empty()) {
          for (size_t i = 0; i < q.points.size(); ++i)
            for (size_t j = 0; j < q.points.size(); ++j)
              add_point(sx + size * q.points[i], sy + size * q.points[j], size * size * q.weights[i] * q.weights[j]);
          return;
        }
        for (unsigned sides = 0; sides < (1u << cutting.size()); ++sides) {
          std::vector<Bicubic> psi = cutting;
          for (size_t c = 0; c < cutting.size(); ++c)
            if ((sides >> c) & 1)
              for (double& v : psi[c].b) v = -v;
          pts.clear();
          implicit_rule(sx, sy, size, size, psi, ImplicitOrders{kEndGaussPoints, kEndGaussPoints + 2}, pts);
          for (const WeightedPoint& p : pts) add_point(p.x, p.y, p.weight);
        }
      };
      square(square, x0, y0, g.h, 0);
    }
  return out;
}

}  // namespace plate
