// Assembling a Problem and validating its data before any solve.
#include "problem.hpp"

#include "side_kinks.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "bfs_element.hpp"

namespace plate {

void check_obstacle_on_boundary(const Grid& g, const Field& obstacle) {
  const int per_edge = 8;
  auto check = [&](double x, double y) {
    const double v = obstacle(x, y);
    if (!(v < 0.0)) {
      std::ostringstream m;
      if (std::isnan(v)) {
        m << "--obstacle: not a number (NaN) at the boundary point (" << x << ", " << y << ")";
        throw std::invalid_argument(m.str());
      }
      m << "--obstacle: must be below zero on the boundary (the plate is clamped at w = 0 there), "
        << "but phi(" << x << ", " << y << ") = " << v;
      throw std::invalid_argument(m.str());
    }
  };
  // The clamped edges only: a mirror line is free to lift.
  for (int k = 0; k < g.nx * per_edge; ++k) {
    const double x = k * g.h / per_edge;
    check(x, 0.0);
    if (!g.mirror_y) check(g.lx() - x, g.ly());
  }
  for (int k = 0; k < g.ny * per_edge; ++k) {
    const double y = k * g.h / per_edge;
    if (!g.mirror_x) check(g.lx(), y);
    check(0.0, g.ly() - y);
  }
  if (g.mirror_x) check(g.lx(), 0.0);  // the bottom edge's far end, which the right edge's loop no longer visits
  if (g.mirror_y && !g.mirror_x) check(g.lx(), g.ly());  // the right edge's far end, which the top edge's loop no longer visits
}

double obstacle_on_edge(const Field& obstacle, double x, double y, double nx, double ny, double h) {
  const double d = 1e-9 * h;
  double v = obstacle(x, y);
  for (double side : {-1.0, 1.0}) {
    const double u = obstacle(x + side * d * nx, y + side * d * ny);
    if (std::isnan(u)) return u;
    v = std::max(v, u);
  }
  return v;
}

namespace {
// @region edge-envelope
// The obstacle on its own edge: the largest value on either side of the curve. The cylinder is
// discontinuous exactly there, and the constraint a rigid body imposes is its upper
// semicontinuous envelope (the closed disk), whatever side rounding puts the point on.
double on_edge(const Field& obstacle, const EdgePoints& e, int k, double h) {
  return obstacle_on_edge(obstacle, e.x[k], e.y[k], e.nx[k], e.ny[k], h);
}
// @end edge-envelope

// The obstacle must be a number or -inf (no constraint) wherever it is read.
void check_obstacle_value(double x, double y, double v) {
  if (std::isnan(v) || v == INFINITY) {
    std::ostringstream m;
    m << "--obstacle: must be a number or -inf (no constraint), but phi(" << x << ", " << y << ") = " << v;
    throw std::invalid_argument(m.str());
  }
}
}  // namespace

// The obstacle at every grid node must be a number (or -inf), whatever the sampling: a NaN between
// samples would otherwise pass unseen and show up in the nodal output.
void check_obstacle_at_nodes(const Grid& g, const Field& obstacle) {
  for (int j = 0; j <= g.ny; ++j)
    for (int i = 0; i <= g.nx; ++i) check_obstacle_value(g.x(i), g.y(j), obstacle(g.x(i), g.y(j)));
}

// S^T W S on every unknown of the space, the enrichment's (D31) included. For Gauss sampling this
// equals the consistent mass matrix, which we assemble by stencil instead of from 16 points per
// element.
static SpMat sampling_mass(const Problem& p) {
  const Grid& g = p.grid;
  const Sampling& s = p.sampling;
  if (s.kind == SamplingKind::Nodes || s.kind == SamplingKind::Edge) return weighted_gram(s.S, s.weights, p.unknowns());
  // The Gauss rows by stencil, the edge rows (if any) by their Gram matrix.
  VectorXd edge_only = s.weights;
  edge_only.head(s.edge_begin).setZero();
  SpMat M = assemble_matrix(g, bfs_mass(g.h));
  M.conservativeResize(p.unknowns(), p.unknowns());
  if (s.edge_size() > 0) M += weighted_gram(s.S, edge_only, p.unknowns());
  return M;
}

// With the enrichment (D31) every row gets a column per function, psi_k read at its sample. On the
// rim psi_k = -I_h F_k, so an edge row's columns are -S P; at a node psi_k vanishes, so an interior
// row's are zero. Made anew from the grid's columns each time rows are made or added.
// The ends' functions (attach_ends) get theirs read by each edge row's own quadrature: they do not
// vanish on the free part of the rim. At the nodes they vanish with their slopes.
static void fit_columns(Problem& p) {
  const int N = p.grid.unknowns(), base = N + p.kink_size();
  if (!p.kink && p.ends.empty()) return;
  const int first = p.sampling.edge_begin;
  RowSpMat SP;
  if (p.kink) SP = p.sampling.S.bottomRows(p.sampling.edge_size()).leftCols(N) * p.kink_interp;  // edge rows only
  std::vector<int> corner_functions;  // the corners' functions (D34), each once: mirror images share one
  if (p.kink)
    for (const KinkCorner& V : p.kink->corners)
      if (const int k = p.kink->function_of_spline[V.index]; std::find(corner_functions.begin(), corner_functions.end(), k) == corner_functions.end())
        corner_functions.push_back(k);
  std::vector<Eigen::Triplet<double>> t;
  for (Eigen::Index r = 0; r < p.sampling.S.outerSize(); ++r) {
    for (RowSpMat::InnerIterator it(p.sampling.S, r); it; ++it)
      if (it.col() < N) t.emplace_back(r, it.col(), it.value());
    if (r >= first && p.kink)
      for (RowSpMat::InnerIterator it(SP, r - first); it; ++it) t.emplace_back(r, N + it.col(), -it.value());
    if (r < first || (corner_functions.empty() && p.ends.empty())) continue;
    // The functions that do not vanish on the edge, read by each edge row's own points: a corner's
    // (D34), which has no columns in P, and the ends'.
    const std::vector<RowPoint> at = edge_row_points(p.grid, p.scene.edge, p.sampling, static_cast<int>(r - first));
    for (const int k : corner_functions) {
      double v = 0;
      for (const RowPoint& q : at) v += q.weight * kink_profile(*p.kink, k, q.x, q.y).w;  // D_V: psi_V itself
      if (v != 0) t.emplace_back(r, N + k, v);
    }
    for (size_t f = 0; f < p.ends.size(); ++f) {
      double v = 0;
      for (const RowPoint& q : at) v += q.weight * end_function(p.ends[f], p.end_fields[f], p.grid, q.x, q.y).w;
      if (v != 0) t.emplace_back(r, base + static_cast<int>(f), v);
    }
  }
  RowSpMat S(p.sampling.S.rows(), p.unknowns());
  S.setFromTriplets(t.begin(), t.end());
  p.sampling.S = std::move(S);
}

namespace {
// phi at the samples from `first` on.
void sample_obstacle(Problem& p, const Field& obstacle, int first) {
  p.phi.conservativeResize(p.sampling.size());
  for (int i = first; i < p.sampling.size(); ++i) {
    const int k = i - p.sampling.edge_begin;
    const double v = k >= 0 ? on_edge(obstacle, p.sampling.edge, k, p.grid.h) : obstacle(p.sampling.x[i], p.sampling.y[i]);
    check_obstacle_value(p.sampling.x[i], p.sampling.y[i], v);
    p.phi[i] = v;
  }
}
}  // namespace

Problem make_samples(const Scene& s, const Grid& g, const SamplingSpec& spec) {
  const double tol = 1e-9 * g.h;
  if (std::abs(g.whole_lx() - s.lx) > tol || std::abs(g.whole_ly() - s.ly) > tol)
    throw std::invalid_argument("the grid covers [0, " + std::to_string(g.whole_lx()) + "] x [0, " + std::to_string(g.whole_ly()) +
                                "], not the scene's rectangle [0, " + std::to_string(s.lx) + "] x [0, " + std::to_string(s.ly) + "]");
  check_obstacle_on_boundary(g, s.obstacle);
  check_obstacle_at_nodes(g, s.obstacle);
  // Without an edge curve the edge kinds keep their interior samples alone.
  Problem p{g, make_sampling(g, spec.kind, s.edge, rows_on(g, s, spec)), {}, {}, {}, {}, spec, s, {}, {}, {}, {}, {}};
  sample_obstacle(p, s.obstacle, 0);
  return p;
}

void lay_out_rim(Problem& p, const RimLayout& layout) {
  p.sampling = make_sampling(p.grid, p.spec.kind, p.scene.edge, rows_on(p.grid, p.scene, p.spec), layout);
  sample_obstacle(p, p.scene.obstacle, 0);
  fit_columns(p);
  p.M = sampling_mass(p);
}

void append_rim_points(Problem& p, const std::vector<double>& angles) {
  const int first = p.sampling.size();
  append_rim_points(p.grid, p.scene.edge, angles, p.sampling);
  sample_obstacle(p, p.scene.obstacle, first);
  fit_columns(p);
  p.M = sampling_mass(p);
}

// Edge sampling only: its interior rows are nodal values, where psi_k vanishes; a Gauss row inside
// a square the rim cuts would need psi_k at its point.
bool kink_on(const Grid& g, const Scene& s, const SamplingSpec& spec) {
  return spec.enrich.on() && spec.kind == SamplingKind::Edge && kink_fits(g, s.edge, spec.enrich.band);
}

// @region kink-rows
// With the kink carried (D31) the plate resolves the rim to order 4, and the rows' splines must too:
// their knots H then go with h, two to four cells apart (kink_knot_cells), rather than as
// h^(3/7) r^(4/7) (D12), which balanced the rows against a plate that could not follow the kink.
EdgeRows rows_on(const Grid& g, const Scene& s, const SamplingSpec& spec) {
  EdgeRows rows = spec.rows;
  if (kink_on(g, s, spec) && s.edge.kind == EdgeCurve::Kind::Circle && rows.cells == 0) rows.cells = kink_knot_cells(s.edge.r, g.h);
  return rows;
}
// @end kink-rows

void attach_kink(Problem& p, const KinkEnrichment& e) {
  // The ends' unknowns follow (D31)'s, so (D31) cannot come after them.
  if (!p.ends.empty()) throw std::logic_error("attach_kink: the problem carries the ends' functions already");
  p.kink = e;
  p.kink_interp = kink_interpolant(p.grid, e);
  fit_columns(p);
  if (p.M.size()) p.M = sampling_mass(p);
}

namespace {
// The Laplacian of each psi_j of (D31) at (x, y) in cell (ex, ey): for the cross block of the ends'
// functions with them. The interpolant's part is read off P's rows for the cell's unknowns. Only the
// functions met in the cell are formed: those P gives a node of it, and those whose splines reach
// the angle of a corner (a cell spans less than a knot spacing, so a spline that reaches into it
// reaches one of its extreme angles), found once a cell.
OtherLaplacians kink_laplacians(const Problem& p) {
  if (!p.kink) return {};
  std::array<int, 2> cell{-1, -1};
  std::vector<int> met;
  Eigen::MatrixXd Pl;  // P on the cell: its 16 unknowns by the functions met
  return [&p, cell, met, Pl](int ex, int ey, double x, double y, Eigen::VectorXd& out) mutable {
    out.setZero();
    if (!kink_near(*p.kink, x, y)) return;
    const Grid& g = p.grid;
    const KinkEnrichment& e = *p.kink;
    if (cell != std::array<int, 2>{ex, ey}) {
      cell = {ex, ey}, met.clear();
      const auto dofs = g.element_dofs(ex, ey);
      for (int j = 0; j < e.size(); ++j) {
        bool in = false;
        for (int i = 0; i < 16 && !in; ++i) in = dofs[i] >= 0 && p.kink_interp.coeff(dofs[i], j) != 0;
        for (int c = 0; c < 4 && !in; ++c) {
          const double t = std::atan2((ey + c / 2) * g.h - e.cy, (ex + c % 2) * g.h - e.cx), r = e.a + 0.5 * g.h;
          in = kink_profile(e, j, e.cx + r * std::cos(t), e.cy + r * std::sin(t)).w != 0;
        }
        if (in) met.push_back(j);
      }
      Pl.setZero(16, static_cast<Eigen::Index>(met.size()));
      for (int i = 0; i < 16; ++i)
        for (size_t m = 0; dofs[i] >= 0 && m < met.size(); ++m) Pl(i, static_cast<Eigen::Index>(m)) = p.kink_interp.coeff(dofs[i], met[m]);
    }
    const LocalBasis b = bfs_basis((x - ex * g.h) / g.h, (y - ey * g.h) / g.h, g.h);
    VectorXd unit = VectorXd::Zero(e.size());
    for (size_t m = 0; m < met.size(); ++m) {
      const auto c = Pl.col(static_cast<Eigen::Index>(m));
      const KinkValue I{c.dot(b.v), c.dot(b.dx), c.dot(b.dy), c.dot(b.dxx), c.dot(b.dxy), c.dot(b.dyy)};
      unit[met[m]] = 1;
      const KinkValue v = kink_field(e, unit, I, x, y);
      unit[met[m]] = 0;
      out[met[m]] = v.wxx + v.wyy;
    }
  };
}
}  // namespace

OtherKinks kink_curves(const KinkEnrichment& e) {
  if (e.polygon()) throw std::logic_error("kink_curves: the ends' functions are a circle's; the problem carries a polygon's (D33)");
  OtherKinks k{e.cx, e.cy, {e.a + e.inner, e.a + e.outer}, {}};
  for (int j = 0; j < e.knots; ++j) {
    const double t = std::fmod(2 * M_PI * j / e.knots, M_PI);
    if (std::none_of(k.rays.begin(), k.rays.end(), [&](double u) { return std::abs(u - t) < 1e-12; })) k.rays.push_back(t);
  }
  return k;
}

void attach_ends(Problem& p, const std::vector<ContactEnd>& ends, const std::vector<EndField>& fields) {
  if (!p.ends.empty()) throw std::logic_error("attach_ends: the problem has its ends' functions already");
  if (ends.size() != fields.size()) throw std::logic_error("attach_ends: one field per end");
  if (p.spec.kind != SamplingKind::Edge || !p.sampling.rim_laid_out())
    throw std::invalid_argument("the ends' functions need edge rows laid out for the contact (--sampling edge)");
  const Grid& g = p.grid;
  for (const ContactEnd& e : ends) {
    const double x = e.cx + e.a * std::cos(e.theta), y = e.cy + e.a * std::sin(e.theta);
    double room = std::min({x, y, g.whole_lx() - x, g.whole_ly() - y});  // the clamped edges
    if (g.mirror_x) room = std::min(room, std::abs(g.lx() - x));
    if (g.mirror_y) room = std::min(room, std::abs(g.ly() - y));
    if (room < end_reach(e)) {
      std::ostringstream m;
      m << "the cut-off of the contact's end at theta = " << e.theta << " (radius " << e.outer << " along the rim, "
        << end_reach(e) << " in the plane) reaches a clamped edge or a mirror line, " << room << " away";
      throw std::invalid_argument(m.str());
    }
  }
  const int N = g.unknowns(), Kk = p.kink_size(), base = N + Kk, k = static_cast<int>(ends.size());
  const OtherKinks kinks = p.kink ? kink_curves(*p.kink) : OtherKinks{};
  const EndBlocks b = assemble_end_blocks(g, ends, fields, Kk, kink_laplacians(p), &p.scene.load, p.kink ? &kinks : nullptr);
  std::vector<Eigen::Triplet<double>> t;
  for (int f = 0; f < k; ++f) {
    for (int i = 0; i < N; ++i)
      if (b.border(i, f) != 0) t.emplace_back(i, base + f, b.border(i, f)), t.emplace_back(base + f, i, b.border(i, f));
    for (int j = 0; j < Kk; ++j)
      if (b.cross(j, f) != 0) t.emplace_back(N + j, base + f, b.cross(j, f)), t.emplace_back(base + f, N + j, b.cross(j, f));
    for (int l = 0; l < k; ++l) t.emplace_back(base + f, base + l, b.own(f, l));
  }
  SpMat E(base + k, base + k);
  E.setFromTriplets(t.begin(), t.end());
  p.K.conservativeResize(base + k, base + k);
  p.K += E;
  if (p.enrichment_block.size() == 0) p.enrichment_block.resize(base, base);
  p.enrichment_block.conservativeResize(base + k, base + k);
  p.enrichment_block += E;
  p.F.conservativeResize(base + k);
  p.F.tail(k) = b.load;
  p.ends = ends, p.end_fields = fields;
  fit_columns(p);
  if (p.M.size()) p.M = sampling_mass(p);
}

// The largest |phi| at the samples that carry a constraint: the obstacle's size for both risks.
static double obstacle_size(const Problem& p) {
  double phi = 0;
  for (double v : p.phi)
    if (std::isfinite(v)) phi = std::max(phi, std::abs(v));
  return phi;
}

std::string overflow_risk(const Problem& p) {
  const double phi = obstacle_size(p);
  double k = 0;
  for (Eigen::Index c = 0; c < p.K.outerSize(); ++c)
    for (SpMat::InnerIterator it(p.K, c); it; ++it) k = std::max(k, std::abs(it.value()));
  if (std::isfinite(36 * k * phi)) return "";
  std::ostringstream m;
  m << "--obstacle-height (or --obstacle): the obstacle reaches |phi| = " << phi << ", where K w (36 terms of up to " << k
    << " times that) may overflow double precision; state the problem in other units";
  return m.str();
}

std::string underflow_risk(const Problem& p) {
  const double phi = obstacle_size(p);
  const double h2 = std::min(1.0, p.grid.h * p.grid.h), load = p.F.size() ? p.F.cwiseAbs().maxCoeff() : 0.0;
  std::ostringstream m;
  if (load > 0 && load < DBL_MIN) {
    m << "--load: the load vector reaches only " << load << ", below double precision's normal range (" << DBL_MIN
      << "); state the problem in other units";
    return m.str();
  }
  if (phi == 0 || phi * h2 >= DBL_MIN) return "";
  m << "--obstacle-height (or --obstacle): the obstacle reaches only |phi| = " << phi << ", where w's smallest terms (about |phi| h^2, h = "
    << p.grid.h << ") fall below double precision's normal range (" << DBL_MIN << "); state the problem in other units";
  return m.str();
}

// K widened to the border's size, plus the border, which (D31)'s blocks leave empty in K's own block:
// each of K's columns then just gains the border's rows below its own, so the sum is a copy in
// order, not the merge of K += border (half a millisecond of plate -n 64, a tenth of its blocks).
static SpMat with_border(const SpMat& K, const SpMat& border) {
  const Eigen::Index N = K.rows(), n = border.rows();
  if (n < N || border.cols() != n) throw std::logic_error("with_border: the border is smaller than K, or not square");
  SpMat sum(n, n);
  sum.reserve(K.nonZeros() + border.nonZeros());
  for (Eigen::Index j = 0; j < n; ++j) {
    sum.startVec(j);
    if (j < N)
      for (SpMat::InnerIterator it(K, j); it; ++it) sum.insertBack(it.row(), j) = it.value();
    for (SpMat::InnerIterator it(border, j); it; ++it) {
      if (j < N && it.row() < N) throw std::logic_error("with_border: the border has an entry in K's own block");
      sum.insertBack(it.row(), j) = it.value();
    }
  }
  sum.finalize();
  return sum;
}

Problem make_problem(const Scene& s, const Grid& g, const SamplingSpec& spec) {
  Problem p = make_samples(s, g, spec);
  p.K = assemble_matrix(g, bfs_stiffness(g.h));
  p.F = assemble_load(g, s.load, "--load");
  // (D31) on every grid it fits; a coarser grid of a sequence that it does not fit is plain.
  if (kink_on(g, s, spec)) {
    if (s.edge.kind == EdgeCurve::Kind::Polygon)
      attach_kink(p, make_side_kinks(g, s.edge, spec.enrich.band));
    else
      attach_kink(p, make_kink_enrichment(g, s.edge, spline_knots(s.edge.r, g.h, rows_on(g, s, spec)), spec.enrich.band));
    KinkBlocks blocks = assemble_kink_blocks(g, *p.kink, p.kink_interp, s.load);
    p.K = with_border(p.K, blocks.border);
    p.enrichment_block = std::move(blocks.border);
    p.F.conservativeResize(p.unknowns());
    p.F.tail(p.kink->size()) = blocks.load;
  }
  p.M = sampling_mass(p);
  return p;
}

}  // namespace plate
