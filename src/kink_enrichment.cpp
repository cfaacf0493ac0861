// The kink-carrying functions of (D31) and their blocks of the stiffness.
#include "kink_enrichment.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "bfs_element.hpp"
#include "gauss.hpp"
#include "side_kinks.hpp"

namespace plate {

namespace {

using Spline3 = KinkSpline;
using Radial = KinkRadial;

// @region kink-functions
// Eq. (D31): the radial profile g(d) = d_+^3 (1 - d / (2a)), d = r - a, and its first two
// derivatives. The cube alone gives the third radial derivative its jump at the rim; on a circle
// the plate's equation on both sides then forces the fourth to jump by -2/a times the third (D32),
// which the second term carries, so the grid is left only the jumps from the fifth derivative on.
// Divided by unit^3 (KinkEnrichment::unit, the cell): psi_k is then of the size of a nodal basis
// function and its blocks of the size of K's. Unscaled they went like h^4 against K's h^-2, and for
// a plate of side 1e-80 they underflowed (CHOLMOD found the system not positive definite).
// In t = d / unit, so that no power of the cell is formed alone (1 / h^3 overflows below h = 1e-103).
Radial kink_radial(double d, double a, double unit) {
  if (!(d > 0)) return {};
  const double t = d / unit;
  return {t * t * t * (1 - d / (2 * a)), 3 * t * t / unit - 2 * t * t * t / a, 6 * t / (unit * unit) - 6 * t * t / (a * unit)};
}
// @end kink-functions


// The (at most four) splines that do not vanish at angle theta: their indices and values.
struct SplinesAt {
  int count = 0;
  int j[4];
  Spline3 b[4];  // derivatives with respect to theta
};
SplinesAt splines_at(const KinkEnrichment& e, double theta) {
  SplinesAt s;
  const double spacing = 2 * M_PI / e.knots;
  const int j0 = static_cast<int>(std::floor(theta / spacing));
  for (int j = j0 - 1; j <= j0 + 2; ++j) {
    const int jj = ((j % e.knots) + e.knots) % e.knots;
    // theta - jj spacing within (-pi, pi], as std::remainder by 2 pi gives it (to the bit: the
    // difference with 2 pi is exact), without its cost: four calls a ray were 4% of the blocks.
    double d = theta - jj * spacing;
    if (d > M_PI) d -= 2 * M_PI;
    else if (d < -M_PI) d += 2 * M_PI;
    Spline3 b = cubic_bspline(d / spacing);
    if (b.v == 0 && b.d1 == 0 && b.d2 == 0) continue;
    b.d1 /= spacing, b.d2 /= spacing * spacing;
    s.j[s.count] = jj, s.b[s.count] = b, ++s.count;
  }
  return s;
}

// Cartesian derivatives of F(r, theta) = g(r - a) S(theta) from its polar ones.
KinkValue cartesian(const Radial& g, const Spline3& S, double r, double c, double s) {
  return from_polar(r, c, s, g.g * S.v, g.g1 * S.v, g.g * S.d1, g.g2 * S.v, g.g1 * S.d1, g.g * S.d2);
}

void add(KinkValue& to, const KinkValue& v, double c) {
  to.w += c * v.w, to.wx += c * v.wx, to.wy += c * v.wy, to.wxx += c * v.wxx, to.wxy += c * v.wxy, to.wyy += c * v.wyy;
}

// Where the ray from (cx, cy) at angle t enters and leaves the cell [x0, x1] x [y0, y1] (slabs);
// false if it misses.
bool ray_in_cell(double cx, double cy, double t, double x0, double x1, double y0, double y1, double& r0, double& r1) {
  const double dx = std::cos(t), dy = std::sin(t);
  r0 = 0, r1 = INFINITY;
  auto slab = [&](double o, double d, double lo, double hi) {
    if (std::abs(d) < 1e-300) return o >= lo && o <= hi;
    double a = (lo - o) / d, b = (hi - o) / d;
    if (a > b) std::swap(a, b);
    r0 = std::max(r0, a), r1 = std::min(r1, b);
    return true;
  };
  if (!slab(cx, dx, x0, x1) || !slab(cy, dy, y0, y1)) return false;
  return r1 > r0;
}

// Angles at which the circle of radius rho about (cx, cy) crosses the cell's sides.
void circle_crossings(double cx, double cy, double rho, double x0, double x1, double y0, double y1, std::vector<double>& out) {
  for (double x : {x0, x1}) {
    const double dx = x - cx, h2 = rho * rho - dx * dx;
    if (h2 < 0) continue;
    for (double sg : {-1.0, 1.0}) {
      const double y = cy + sg * std::sqrt(h2);
      if (y >= y0 && y <= y1) out.push_back(std::atan2(y - cy, dx));
    }
  }
  for (double y : {y0, y1}) {
    const double dy = y - cy, h2 = rho * rho - dy * dy;
    if (h2 < 0) continue;
    for (double sg : {-1.0, 1.0}) {
      const double x = cx + sg * std::sqrt(h2);
      if (x >= x0 && x <= x1) out.push_back(std::atan2(dy, x - cx));
    }
  }
}

}  // namespace


std::string kink_misfit(const Grid& g, const EdgeCurve& c, const KinkBand& band) {
  check_kink_band(band);
  if (c.kind == EdgeCurve::Kind::Polygon) return side_kink_misfit(g, c, band);
  if (c.kind != EdgeCurve::Kind::Circle) return "the edge is neither a circle nor a polygon";
  const double clearance = std::min({c.cx - c.r, g.whole_lx() - c.cx - c.r, c.cy - c.r, g.whole_ly() - c.cy - c.r});
  // The cells where chi is not 0 reach band.zero + sqrt(2) cells past the rim; their nodes must all carry
  // unknowns. A disk two cells across its radius keeps its centre out of every cell the rim cuts.
  if (c.r >= kKinkMinRadiusCells * g.h && clearance >= (band.zero + 1.5) * g.h) return "";
  std::ostringstream m;
  m << "the circle must be at least " << kKinkMinRadiusCells << " cells in radius and " << band.zero + 1.5
    << " cells from every clamped edge on this grid (h = " << g.h << ")";
  return m.str();
}

bool kink_fits(const Grid& g, const EdgeCurve& c, const KinkBand& band) { return kink_misfit(g, c, band).empty(); }

// @region kink-knots
// The knots of (D31)'s rows. Two cells apart, the rows ask more of the plate than its trace on the
// rim can tell apart where the rim cuts the squares badly, and the line load swings from knot to
// knot there on fine grids; four cells apart it does not. A coarse grid's circle then gets too few
// knots for the load's harmonics, so the spacing closes to leave kKinkKnotsAtLeast knots round the
// circle, but no closer than kKinkKnotCellsMin cells.
double kink_knot_cells(double r, double h) {
  return std::clamp(2 * M_PI * r / (kKinkKnotsAtLeast * h), kKinkKnotCellsMin, kKinkKnotCells);
}
// @end kink-knots

KinkEnrichment make_kink_enrichment(const Grid& g, const EdgeCurve& circle, int knots, const KinkBand& band) {
  if (circle.kind != EdgeCurve::Kind::Circle) throw std::invalid_argument("--enrich ring needs a circle (a cylinder or --edge circle:)");
  if (knots < 8 || knots % 4) throw std::invalid_argument("make_kink_enrichment: the knots must be a multiple of 4, at least 8");
  if (const std::string why = kink_misfit(g, circle, band); !why.empty()) throw std::invalid_argument("--enrich ring: " + why);
  const double tol = 1e-9 * g.h;
  if ((g.mirror_x && std::abs(circle.cx - g.lx()) > tol) || (g.mirror_y && std::abs(circle.cy - g.ly()) > tol))
    throw std::logic_error("make_kink_enrichment: the circle's centre is not on the part's mirror lines");
  KinkEnrichment e;
  e.cx = circle.cx, e.cy = circle.cy, e.a = circle.r;
  e.inner = band.flat * g.h, e.outer = band.zero * g.h, e.unit = g.h;
  e.knots = knots;
  // Mirror images of spline j: about x = cx, theta -> pi - theta; about y = cy, theta -> -theta.
  const int M = e.knots;
  e.function_of_spline.assign(M, -1);
  for (int j = 0; j < M; ++j) {
    if (e.function_of_spline[j] >= 0) continue;
    std::vector<int> orbit{j};
    if (g.mirror_x) orbit.push_back(((M / 2 - j) % M + M) % M);
    if (g.mirror_y)
      for (int k : std::vector<int>(orbit)) orbit.push_back((M - k) % M);
    for (int k : orbit) e.function_of_spline[k] = e.functions;
    ++e.functions;
  }
  return e;
}

KinkValue kink_profile(const KinkEnrichment& e, int k, double x, double y) {
  if (e.polygon()) return side_kink_profile(e, k, x, y);
  KinkValue v;
  const double dx = x - e.cx, dy = y - e.cy, r = std::hypot(dx, dy);
  if (!(r > e.a)) return v;  // F_k is 0 on and inside the rim
  const Radial g = kink_radial(r - e.a, e.a, e.unit);
  const double t = std::atan2(dy, dx);
  const SplinesAt s = splines_at(e, t < 0 ? t + 2 * M_PI : t);
  for (int i = 0; i < s.count; ++i)
    if (e.function_of_spline[s.j[i]] == k) add(v, cartesian(g, s.b[i], r, dx / r, dy / r), 1.0);
  return v;
}

SpMat kink_interpolant(const Grid& g, const KinkEnrichment& e) {
  if (e.polygon()) return side_kink_interpolant(g, e);
  std::vector<Eigen::Triplet<double>> t;
  const double reach = e.a + e.outer + 1.5 * g.h;
  for (int j = 0; j <= g.ny; ++j)
    for (int i = 0; i <= g.nx; ++i) {
      if (!g.is_interior(i, j)) continue;
      const double dx = g.x(i) - e.cx, dy = g.y(j) - e.cy;
      // Most nodes lie far beyond the band: a squared distance with a margin passes them over
      // before the exact test below (std::hypot on every node of the whole plate took 0.2 ms).
      if (dx * dx + dy * dy > 1.01 * reach * reach && reach < 1e150) continue;
      const double r = std::hypot(dx, dy);
      // Only the nodes of squares where chi is not 0 are ever read: within outer + sqrt(2) cells.
      if (r - e.a >= e.outer + 1.5 * g.h) continue;
      if (!(r > e.a)) continue;
      const Radial gr = kink_radial(r - e.a, e.a, e.unit);
      const double th = std::atan2(dy, dx);
      const SplinesAt sp = splines_at(e, th < 0 ? th + 2 * M_PI : th);
      for (int s = 0; s < sp.count; ++s) {
        const KinkValue v = cartesian(gr, sp.b[s], r, dx / r, dy / r);
        const double comp[4] = {v.w, v.wx, v.wy, v.wxy};
        for (int c = 0; c < 4; ++c) {
          const int d = g.dof(i, j, c);
          if (d >= 0 && comp[c] != 0) t.emplace_back(d, e.function_of_spline[sp.j[s]], comp[c]);
        }
      }
    }
  SpMat P(g.unknowns(), e.size());
  P.setFromTriplets(t.begin(), t.end());  // images of one spline in one function add up
  return P;
}

namespace {
// One cell's quadrature points, gathered first, and the functions met in it with the interpolant's
// coefficients on the cell (Pl) that each subtracts. The blocks are then formed by matrix products
// over all the cell's points at once: point by point, as outer products, the whole problem's
// assembly took a third longer when this was measured (n = 64: 0.040 s against 0.031 s; the blocks
// alone have since become faster, as the figures below say).
struct CellBlocks {
  std::vector<int> met;
  Eigen::MatrixXd Pl;
  // Each ray: its cosine and sine, the splines there and the local index of each one's function.
  struct Ray {
    double cs, sn;
    SplinesAt sp;
    std::array<int, 4> idx;
  };
  std::vector<Ray> rays;
  std::vector<double> r, wt;  // each point: radius and weight
  std::vector<int> ray;       // and the ray it lies on
  std::vector<int> slope_row;  // and its slope's basis row, or -1 where chi is flat (cell_blocks)
  // Kept from cell to cell and only ever grown, so that no cell allocates (resized to each cell's
  // points, they cost the blocks 1.5% at n = 64).
  Eigen::MatrixXd basis, D, psi, lap_psi, weighted;
  VectorXd load;
  static Eigen::Block<Eigen::MatrixXd> first(Eigen::MatrixXd& m, Eigen::Index rows, Eigen::Index cols) {
    if (m.rows() < rows || m.cols() < cols) m.resize(std::max(rows, m.rows()), std::max(cols, m.cols()));
    return m.topLeftCorner(rows, cols);
  }
  void reset() {
    met.clear(), Pl.setZero(16, 8);
    rays.clear(), r.clear(), wt.clear(), ray.clear();
  }
  int local(int k) {
    for (size_t i = 0; i < met.size(); ++i)
      if (met[i] == k) return static_cast<int>(i);
    met.push_back(k);
    const int n = static_cast<int>(met.size());
    if (n > Pl.cols()) {
      const int old = static_cast<int>(Pl.cols());
      Pl.conservativeResize(16, 2 * n);
      Pl.rightCols(2 * n - old).setZero();
    }
    return n - 1;
  }
  void add(double radius, double weight) { r.push_back(radius), wt.push_back(weight), ray.push_back(static_cast<int>(rays.size()) - 1); }
};
}  // namespace

// @region kink-blocks
// F = g(r) S(theta) of (D31) added to D's value, radial slope (where chi is not flat) and
// Laplacian, the three that Lap psi needs; ir = 1 / r.
static void add_profile(const Radial& g, const Spline3& S, double ir, double& v, double* slope, double& lap) {
  v += g.g * S.v;
  if (slope) *slope += g.g1 * S.v;
  lap += g.g2 * S.v + ir * g.g1 * S.v + ir * ir * g.g * S.d2;
}

// Eq. (D31)'s blocks on one cell from its gathered points: Bl = (Lap phi_i, Lap psi_k) (16 x L),
// El = (Lap psi_k, Lap psi_l) (L x L) and fl = (f, psi_k), with psi = chi D and D = F - I_h F.
// Lap psi = chi Lap D + 2 chi' D_r + D Lap chi reads D's value, slope along the ray and Laplacian
// alone; where chi is flat (1, out to kKinkFlatCells cells) it is Lap D, and psi is D, so the slope
// is carried only across the cut-off. The basis rows hold every point's Laplacians first (Lap phi_i,
// read in place by the border), then its values, then the cut-off's slopes. Five Cartesian rows a
// point made the blocks alone a fifth slower (n = 64: 7.3 ms against 6.0 ms), most of it in the product
// with the interpolant; three at every point, 5% slower than this.
static void cell_blocks(const Grid& g, const KinkEnrichment& e, const Field& f, double x0, double y0, CellBlocks& cb,
                        Eigen::MatrixXd& Bl, Eigen::MatrixXd& El, VectorXd& fl) {
  const int np = static_cast<int>(cb.r.size()), L = static_cast<int>(cb.met.size());
  cb.slope_row.assign(np, -1);
  int rows = 2 * np;
  for (int p = 0; p < np; ++p)
    if (cb.r[p] - e.a > e.inner) cb.slope_row[p] = rows++;
  auto basis = CellBlocks::first(cb.basis, 16, rows);
  if (cb.load.size() < np) cb.load.resize(np);
  for (int p = 0; p < np; ++p) {
    const CellBlocks::Ray& ray = cb.rays[cb.ray[p]];
    const double x = e.cx + cb.r[p] * ray.cs, y = e.cy + cb.r[p] * ray.sn;
    const int sr = cb.slope_row[p];
    bfs_basis_along((x - x0) / g.h, (y - y0) / g.h, g.h, ray.cs, ray.sn, &basis(0, np + p), sr < 0 ? nullptr : &basis(0, sr), &basis(0, p));
    cb.load[p] = cb.wt[p] * f(x, y);
  }
  // D = F - I_h F at every point: first minus the interpolant's share, for all functions at once.
  auto D = CellBlocks::first(cb.D, rows, L);  // the basis rows' order, one column per function
  D.noalias() = -basis.transpose() * cb.Pl.leftCols(L);
  auto psi = CellBlocks::first(cb.psi, L, np), lap_psi = CellBlocks::first(cb.lap_psi, L, np);
  for (int p = 0; p < np; ++p) {
    const CellBlocks::Ray& ray = cb.rays[cb.ray[p]];
    const double r = cb.r[p];
    const int sr = cb.slope_row[p];
    if (r > e.a) {
      const Radial F = kink_radial(r - e.a, e.a, e.unit);
      for (int k = 0; k < ray.sp.count; ++k) {
        const int l = ray.idx[k];
        add_profile(F, ray.sp.b[k], 1 / r, D(np + p, l), sr < 0 ? nullptr : &D(sr, l), D(p, l));
      }
    }
    if (sr < 0) {  // chi = 1, chi' = 0 here
      for (int l = 0; l < L; ++l) psi(l, p) = D(np + p, l), lap_psi(l, p) = D(p, l);
      continue;
    }
    const Radial chi = kink_cutoff(e.inner, e.outer, r - e.a);
    const double lapchi = chi.g2 + chi.g1 / r;
    for (int l = 0; l < L; ++l)
      psi(l, p) = chi.g * D(np + p, l), lap_psi(l, p) = chi.g * D(p, l) + 2 * chi.g1 * D(sr, l) + D(np + p, l) * lapchi;
  }
  auto weighted = CellBlocks::first(cb.weighted, L, np);
  weighted.noalias() = lap_psi * Eigen::Map<const VectorXd>(cb.wt.data(), np).asDiagonal();
  Bl.noalias() = basis.leftCols(np) * weighted.transpose();  // Lap phi_i: the first np rows
  El.noalias() = weighted * lap_psi.transpose();
  fl.noalias() = psi * cb.load.head(np);
}

// Eq. (D31)'s blocks, cell by cell over the cells that reach the band where chi is not 0, in polar coordinates
// about the centre. The angle is split at the cell's corners, where the rim or either end of the
// cut-off crosses a side, and at the splines' knots; on each piece the ray's part of the cell is a
// smooth function of the angle, split again at the rim and the cut-off's ends, and the integrand is
// smooth on each part, so Gauss rules in both converge fast.
KinkBlocks assemble_kink_blocks(const Grid& g, const KinkEnrichment& e, const SpMat& interpolant, const Field& f) {
  if (e.polygon()) return assemble_side_kink_blocks(g, e, interpolant, f);
  const int N = g.unknowns();
  const double h = g.h, spacing = 2 * M_PI / e.knots, radii[3] = {e.a, e.a + e.inner, e.a + e.outer};
  // The rule on each part of a ray (kKinkRule). Inside the rim psi_k is the bicubic -I_h F_k, so
  // along a ray both Laplacians and the factor r make a polynomial of degree 9 in r, which 5 points
  // integrate exactly. Out to the cut-off's start F_k is a quartic in d whose Laplacian divides by
  // powers of r, nearly as tame: 6 points. Across the cut-off the quintic chi enters each Laplacian, and 8 points leave
  // (Lap psi_k, Lap psi_l) 2e-8 off a 16-point rule on the paper's scene at n = 64 (6 leave 1e-4).
  // In the angle a ray's ends move with it, which matters most across the cut-off's high powers of
  // r: 6 points there leave that block 3e-6 off, 8 do not; on the two inner parts 6 points leave the
  // border 9e-10 off the 16-point rule (2e-11 with 8 everywhere) for a quarter less time. (6 there
  // would let all three parts share rays, a sixth of the blocks' time, and move max w and the force
  // by at most 2e-11 at n = 32 and 4e-14 from n = 64 on; but the load (f, psi_k) then lies 4e-7 off
  // the brute-force rule of test_kink_enrichment, where 8 hold it within that rule's own error.)
  Quadrature1D qa[3], qr[3];
  for (int part = 0; part < 3; ++part) qa[part] = gauss_legendre(kKinkRule[part].angle), qr[part] = gauss_legendre(kKinkRule[part].radius);
  const RowSpMat P = interpolant;  // rows: a node's unknowns
  std::vector<Eigen::Triplet<double>> t;
  KinkBlocks out;
  out.load = VectorXd::Zero(e.size());
  std::vector<double> cuts, knot_angles;
  for (int j = 0; j < e.knots; ++j) knot_angles.push_back(std::remainder(j * spacing, 2 * M_PI));
  std::sort(knot_angles.begin(), knot_angles.end());
  CellBlocks cb;
  Eigen::MatrixXd Bl, El;
  VectorXd fl;
  for (int ey = 0; ey < g.ny; ++ey)
    for (int ex = 0; ex < g.nx; ++ex) {
      const double x0 = ex * h, x1 = x0 + h, y0 = ey * h, y1 = y0 + h;
      const double near = std::hypot(std::clamp(e.cx, x0, x1) - e.cx, std::clamp(e.cy, y0, y1) - e.cy);
      double far = 0;
      for (double x : {x0, x1})
        for (double y : {y0, y1}) far = std::max(far, std::hypot(x - e.cx, y - e.cy));
      if (far <= e.a || near >= radii[2]) continue;
      const auto dofs = g.element_dofs(ex, ey);
      cb.reset();
      for (int q = 0; q < 16; ++q)
        if (dofs[q] >= 0)
          for (RowSpMat::InnerIterator it(P, dofs[q]); it; ++it) cb.Pl(q, cb.local(static_cast<int>(it.col()))) = it.value();
      cuts.assign({-M_PI, M_PI});
      for (double x : {x0, x1})
        for (double y : {y0, y1}) cuts.push_back(std::atan2(y - e.cy, x - e.cx));
      for (double rho : radii) circle_crossings(e.cx, e.cy, rho, x0, x1, y0, y1, cuts);
      // Only the knots within the cell's angles cut it (all where it straddles theta = pi): the
      // pieces outside those angles miss the cell, and were only ever passed over.
      const auto corners = std::minmax_element(cuts.begin() + 2, cuts.begin() + 6);
      const double lo = *corners.first, hi = *corners.second;
      if (hi - lo > M_PI)
        cuts.insert(cuts.end(), knot_angles.begin(), knot_angles.end());
      else
        cuts.insert(cuts.end(), std::upper_bound(knot_angles.begin(), knot_angles.end(), lo),
                    std::lower_bound(knot_angles.begin(), knot_angles.end(), hi));
      std::sort(cuts.begin(), cuts.end());
      for (size_t c = 0; c + 1 < cuts.size(); ++c) {
        const double t0 = cuts[c], t1 = cuts[c + 1];
        double r0, r1;
        if (t1 - t0 < 1e-14 || !ray_in_cell(e.cx, e.cy, 0.5 * (t0 + t1), x0, x1, y0, y1, r0, r1) || r0 >= radii[2]) continue;
        // Parts that share an angular rule share its rays.
        for (int first = 0; first < 3; ++first) {
          if (first > 0 && kKinkRule[first].angle == kKinkRule[first - 1].angle) continue;
          for (size_t i = 0; i < qa[first].points.size(); ++i) {
            const double th = t0 + (t1 - t0) * qa[first].points[i];
            if (!ray_in_cell(e.cx, e.cy, th, x0, x1, y0, y1, r0, r1)) continue;
            const double stops[5] = {r0, std::clamp(radii[0], r0, r1), std::clamp(radii[1], r0, r1), std::clamp(radii[2], r0, r1), r1};
            bool ray_made = false;
            for (int part = first; part < 3 && kKinkRule[part].angle == kKinkRule[first].angle; ++part) {
              const double lo = stops[part], hi = stops[part + 1];
              if (!(hi > lo)) continue;
              if (!ray_made) {
                CellBlocks::Ray& ray = cb.rays.emplace_back(CellBlocks::Ray{std::cos(th), std::sin(th), splines_at(e, th < 0 ? th + 2 * M_PI : th), {}});
                for (int s = 0; s < ray.sp.count; ++s) ray.idx[s] = cb.local(e.function_of_spline[ray.sp.j[s]]);
                ray_made = true;
              }
              for (size_t k = 0; k < qr[part].points.size(); ++k) {
                const double r = lo + (hi - lo) * qr[part].points[k];
                cb.add(r, (t1 - t0) * qa[first].weights[i] * (hi - lo) * qr[part].weights[k] * r);
              }
            }
          }
        }
      }
      cell_blocks(g, e, f, x0, y0, cb, Bl, El, fl);
      for (size_t k = 0; k < cb.met.size(); ++k) {
        const int col = N + cb.met[k];
        for (int i = 0; i < 16; ++i)
          if (dofs[i] >= 0 && Bl(i, k) != 0) t.emplace_back(dofs[i], col, Bl(i, k)), t.emplace_back(col, dofs[i], Bl(i, k));
        for (size_t l = 0; l < cb.met.size(); ++l)
          if (El(k, l) != 0) t.emplace_back(col, N + cb.met[l], El(k, l));
        out.load[cb.met[k]] += fl[k];
      }
    }
  out.border.resize(N + e.size(), N + e.size());
  out.border.setFromTriplets(t.begin(), t.end());
  return out;
}
// @end kink-blocks

bool kink_near(const KinkEnrichment& e, double x, double y) {
  if (e.polygon()) return side_kink_near(e, x, y);
  // Deeper inside than any square the rim cuts (within sqrt(2) < kKinkFlatCells cells of it), and
  // beyond the cut-off, psi_k is zero. Every field read asks this, so the squared distance is
  // compared with the band's squared radii: std::hypot took 2% of `plate -n 64`. Past 1e150 the
  // squares could overflow, and hypot decides.
  const double dx = x - e.cx, dy = y - e.cy, lo = e.a - e.inner, hi = e.a + e.outer;
  if (!(std::abs(dx) < 1e150 && std::abs(dy) < 1e150 && hi < 1e150)) {
    const double d = std::hypot(dx, dy) - e.a;
    return d > -e.inner && d < e.outer;
  }
  const double s = dx * dx + dy * dy;
  return (lo <= 0 || s > lo * lo) && s < hi * hi;
}

KinkValue kink_field(const KinkEnrichment& e, const VectorXd& c, const KinkValue& interpolant, double x, double y, const int* cell) {
  if (e.polygon()) return side_kink_field(e, c, interpolant, x, y, cell);
  KinkValue out;
  if (!kink_near(e, x, y)) return out;
  const double dx = x - e.cx, dy = y - e.cy, r = std::hypot(dx, dy);
  const Radial chi = kink_cutoff(e.inner, e.outer, r - e.a);
  KinkValue D;
  add(D, interpolant, -1.0);
  const Radial F = kink_radial(r - e.a, e.a, e.unit);
  if (r > e.a) {
    const double th = std::atan2(dy, dx);
    const SplinesAt sp = splines_at(e, th < 0 ? th + 2 * M_PI : th);
    for (int i = 0; i < sp.count; ++i) add(D, cartesian(F, sp.b[i], r, dx / r, dy / r), c[e.function_of_spline[sp.j[i]]]);
  }
  out.w = chi.g * D.w, out.wx = chi.g * D.wx, out.wy = chi.g * D.wy;
  out.wxx = chi.g * D.wxx, out.wxy = chi.g * D.wxy, out.wyy = chi.g * D.wyy;
  if (chi.g1 == 0 && chi.g2 == 0) return out;  // chi flat here: no product-rule terms
  // Product rule with chi(d(x, y)): d_x = cos, d_y = sin, d_xx = sin^2 / r, d_xy = -cos sin / r, d_yy = cos^2 / r.
  const double cs = dx / r, sn = dy / r;
  const double cx = chi.g1 * cs, cy = chi.g1 * sn;
  const double cxx = chi.g2 * cs * cs + chi.g1 * sn * sn / r, cyy = chi.g2 * sn * sn + chi.g1 * cs * cs / r;
  const double cxy = chi.g2 * cs * sn - chi.g1 * cs * sn / r;
  out.wx += cx * D.w, out.wy += cy * D.w;
  out.wxx += 2 * cx * D.wx + cxx * D.w;
  out.wyy += 2 * cy * D.wy + cyy * D.w;
  out.wxy += cx * D.wy + cy * D.wx + cxy * D.w;
  return out;
}

double kink_value(const KinkEnrichment& e, const VectorXd& c, double interpolant, double x, double y) {
  if (e.polygon()) return side_kink_value(e, c, interpolant, x, y);
  if (!kink_near(e, x, y)) return 0;
  const double dx = x - e.cx, dy = y - e.cy, r = std::hypot(dx, dy);
  double D = -interpolant;
  if (r > e.a) {
    const Radial F = kink_radial(r - e.a, e.a, e.unit);
    const double th = std::atan2(dy, dx);
    const SplinesAt sp = splines_at(e, th < 0 ? th + 2 * M_PI : th);
    for (int i = 0; i < sp.count; ++i) D += c[e.function_of_spline[sp.j[i]]] * (F.g * sp.b[i].v);
  }
  return kink_cutoff(e.inner, e.outer, r - e.a).g * D;
}

KinkEnrichment unfold_kink(const KinkEnrichment& part, const VectorXd& c_part, VectorXd& c_whole) {
  KinkEnrichment e = part;
  e.functions = e.knots;
  for (int j = 0; j < e.knots; ++j) e.function_of_spline[j] = j;
  c_whole.resize(e.knots);
  for (int j = 0; j < e.knots; ++j) c_whole[j] = c_part[part.function_of_spline[j]];
  return e;
}

}  // namespace plate
