// Construction of the two samplings and of the weighted Gram matrices S^T D S.
#include "sampling.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "bfs_element.hpp"
#include "gauss.hpp"

namespace plate {

// The centred cardinal B-spline of degree p at x (in knot spacings): 1 at x = 0 for p = 1 (the hat),
// support |x| < (p + 1) / 2, the translates summing to one.
double cardinal_bspline(int p, double x) {
  double sum = 0, binomial = 1, factorial = 1;
  for (int k = 1; k <= p; ++k) factorial *= k;
  for (int k = 0; k <= p + 1; ++k) {
    const double t = x + 0.5 * (p + 1) - k;
    if (t > 0) sum += (k % 2 ? -1 : 1) * binomial * std::pow(t, p);
    binomial = binomial * (p + 1 - k) / (k + 1);
  }
  return sum / factorial;
}


const char* to_string(SamplingKind kind) {
  switch (kind) {
    case SamplingKind::Gauss: return "gauss";
    case SamplingKind::Nodes: return "nodes";
    case SamplingKind::Edge: return "edge";
    default: return "edge-gauss";
  }
}

SamplingKind sampling_kind(const std::string& name) {
  for (SamplingKind k : {SamplingKind::Gauss, SamplingKind::Nodes, SamplingKind::Edge, SamplingKind::EdgeGauss})
    if (name == to_string(k)) return k;
  throw std::invalid_argument("--sampling must be gauss, nodes, edge or edge-gauss, got '" + name + "'");
}

namespace {

Sampling gauss_points(const Grid& g) {
  const Quadrature1D q = gauss_legendre(4);
  const int per = 16, npts = g.elements() * per;
  Sampling s{SamplingKind::Gauss, {}, {}, VectorXd(npts), RowSpMat(npts, g.unknowns()), 0, {}, 0, 0, {}, {}};
  s.x.reserve(npts);
  s.y.reserve(npts);
  s.S.reserve(static_cast<Eigen::Index>(npts) * 16);
  std::vector<std::pair<int, double>> row;
  int p = 0;
  for (int ey = 0; ey < g.ny; ++ey)
    for (int ex = 0; ex < g.nx; ++ex) {
      const auto dofs = g.element_dofs(ex, ey);
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i, ++p) {
          s.x.push_back(g.x(ex) + q.points[i] * g.h);
          s.y.push_back(g.y(ey) + q.points[j] * g.h);
          s.weights[p] = q.weights[i] * q.weights[j] * g.h * g.h;
          const Vector16 v = bfs_basis(q.points[i], q.points[j], g.h).v;
          row.clear();
          for (int k = 0; k < 16; ++k)
            if (dofs[k] >= 0) row.emplace_back(dofs[k], v[k]);
          std::sort(row.begin(), row.end());
          s.S.startVec(p);
          for (const auto& [col, val] : row) s.S.insertBack(p, col) = val;
        }
    }
  s.S.finalize();
  return s;
}

// @region nodal-sampling
// On a mirror line a node stands for itself and its image: half its area is this grid's.
Sampling grid_nodes(const Grid& g) {
  const int npts = g.interior_nodes();
  Sampling s{SamplingKind::Nodes, {}, {}, VectorXd(npts), RowSpMat(npts, g.unknowns()), 0, {}, 0, 0, {}, {}};
  s.S.reserve(npts);
  for (int j = 1; j <= g.ny; ++j)
    for (int i = 1; i <= g.nx; ++i) {
      if (!g.is_interior(i, j)) continue;
      const int p = g.node(i, j);
      s.x.push_back(g.x(i));
      s.y.push_back(g.y(j));
      s.weights[p] = g.h * g.h * (g.mirror_x && i == g.nx ? 0.5 : 1.0) * (g.mirror_y && j == g.ny ? 0.5 : 1.0);
      s.S.startVec(p);
      s.S.insertBack(p, g.dof(i, j, kW)) = 1.0;
    }
  s.S.finalize();
  return s;
}
// @end nodal-sampling

// Copies the rows `keep` of s.S (with their points and weights) into a matrix with room for
// `extra` more rows; the caller appends those.
struct RowBuilder {
  RowSpMat S;
  VectorXd weights;
  std::vector<double> x, y;
  int next = 0;
  RowBuilder(const Sampling& s, const std::vector<int>& keep, int extra)
      : S(static_cast<Eigen::Index>(keep.size()) + extra, s.S.cols()), weights(keep.size() + extra) {
    S.reserve(static_cast<Eigen::Index>(s.S.nonZeros()) + 16L * extra);
    for (int p : keep) {
      S.startVec(next);
      for (RowSpMat::InnerIterator it(s.S, p); it; ++it) S.insertBack(next, it.col()) = it.value();
      weights[next++] = s.weights[p];
      x.push_back(s.x[p]);
      y.push_back(s.y[p]);
    }
  }
};

// The row of S that gives (S w)_p = w_h(x, y): the values of the 16 basis functions of the element
// that holds (x, y), added into `row` times `scale`. A point on an element side may use either
// element (w_h is C^1).
void add_point_row(const Grid& g, double x, double y, double scale, std::map<int, double>& row) {
  int ex, ey;
  double t, u;
  if (!g.locate(x, y, ex, ey, t, u))
    throw std::invalid_argument("--edge: the point (" + std::to_string(x) + ", " + std::to_string(y) +
                                ") of the obstacle's edge is outside the plate");
  const auto dofs = g.element_dofs(ex, ey);
  const Vector16 v = bfs_basis(t, u, g.h).v;
  for (int j = 0; j < 16; ++j)
    if (dofs[j] >= 0) row[dofs[j]] += scale * v[j];
}

// @region edge-splines
// Eq. (D12): the constraint on a circle averaged against B-splines of the angle,
//   (S w)_j = (1 / Delta) int B_j(theta) w_h(x(theta)) dtheta >= phi_j,
// B_j the cardinal B-spline of degree p centred at theta_j = 2 pi j / M, Delta = 2 pi / M. The
// weight of row j is r Delta = r int B_j, so its multiplier lambda_j is a force per unit length and
// the line load is q(theta) = sum_j lambda_j B_j(theta), nonnegative where every lambda_j is. The
// knots must be farther apart than the cells, or the plate cannot tell the multipliers apart (a
// point per cell scatters by 10 %), and farther apart on finer grids, so that what the plate
// misses at the scale of h, seen at the scale of the knots, shrinks. The load's error has two parts,
// about (h / H)^3 from the plate and H^(p+1) from the splines; for cubics (p = 3) they fall together,
// like h^(12/7), when H = h^(3/7) r^(4/7), the spacing we take (r the radius: no constant is fitted).
// The integral is taken by 4 Gauss points on pieces about a cell long between the spline's breaks;
// phi_j is the obstacle at theta_j (on the paper's scene, the rim's height).
EdgePoints spline_rows(const Grid& g, const EdgeCurve& c, const EdgeRows& how, std::vector<std::map<int, double>>& rows,
                       std::vector<RimRow>& kinds) {
  const int M = spline_knots(c.r, g.h, how), degree = how.degree;
  const double delta = 2 * M_PI / M, half = 0.5 * (degree + 1);
  const int pieces = std::max(1, static_cast<int>(std::ceil(c.r * delta / g.h)));  // per knot spacing
  const Quadrature1D q = gauss_legendre(4);
  EdgePoints e;
  e.length = 2 * M_PI * c.r;
  rows.assign(M, {});
  for (int j = 0; j < M; ++j) {
    const double tj = j * delta, cj = std::cos(tj), sj = std::sin(tj);
    e.theta.push_back(tj);
    e.x.push_back(c.cx + c.r * cj), e.y.push_back(c.cy + c.r * sj);
    e.nx.push_back(-cj), e.ny.push_back(-sj);
    e.weight.push_back(c.r * delta);
    kinds.push_back({-2, j});
    for (int span = 0; span < degree + 1; ++span)  // unit spans of the support, from -half
      for (int k = 0; k < pieces; ++k)
        for (size_t i = 0; i < q.points.size(); ++i) {
          const double x = -half + span + (k + q.points[i]) / pieces, t = tj + x * delta;
          add_point_row(g, c.cx + c.r * std::cos(t), c.cy + c.r * std::sin(t),
                        cardinal_bspline(degree, x) * q.weights[i] / pieces, rows[j]);
        }
  }
  return e;
}
// @end edge-splines

}  // namespace

// @region rim-layout-rows
// The quadrature of (D28)'s spline rows: four Gauss points on pieces of about a cell.
std::vector<RowPoint> spline_row_points(const Grid& g, const EdgeCurve& c, const SplineArc& arc, int degree, int j) {
  const Quadrature1D q = gauss_legendre(4);
  const double delta = clamped_bspline_integral(arc, degree, j);
  std::vector<RowPoint> out;
  for (int span = j; span <= j + degree; ++span) {
    const double lo = arc.knot(span, degree), hi = arc.knot(span + 1, degree);
    // About a cell each; the same count for a span and its mirror image, which may differ by rounding.
    const int pieces = std::max(1, static_cast<int>(std::ceil(c.r * (hi - lo) / g.h - 1e-9)));
    for (int k = 0; hi > lo && k < pieces; ++k)
      for (size_t i = 0; i < q.points.size(); ++i) {
        const double t = lo + (hi - lo) * (k + q.points[i]) / pieces;
        out.push_back({c.cx + c.r * std::cos(t), c.cy + c.r * std::sin(t), clamped_bspline(arc, degree, j, t) * (hi - lo) * q.weights[i] / pieces / delta});
      }
  }
  return out;
}

// Eq. (D28): the rows of a layout made for the contact. On each spline arc the constraint averaged
// against its clamped B-splines B_j, (S w)_j = (1 / Delta_j) int B_j(theta) w_h(x(theta)) dtheta with
// Delta_j = int B_j, weight r Delta_j, placed at the basis' Greville angle; elsewhere a row at each
// point, weighted by the arc it stands for.
static EdgePoints laid_out_rows(const Grid& g, const EdgeCurve& c, const EdgeRows& how, const RimLayout& L,
                                std::vector<std::map<int, double>>& rows, std::vector<RimRow>& kinds) {
  const int degree = how.degree;
  EdgePoints e;
  e.length = 2 * M_PI * c.r;
  auto place = [&](double t, double weight) {
    e.theta.push_back(t);
    e.x.push_back(c.cx + c.r * std::cos(t)), e.y.push_back(c.cy + c.r * std::sin(t));
    e.nx.push_back(-std::cos(t)), e.ny.push_back(-std::sin(t));
    e.weight.push_back(weight);
  };
  for (size_t a = 0; a < L.arcs.size(); ++a) {
    const SplineArc& arc = L.arcs[a];
    for (int j = 0; j < arc.basis_count(degree); ++j) {
      const double delta = clamped_bspline_integral(arc, degree, j);
      place(arc.greville(j, degree), c.r * delta);
      kinds.push_back({static_cast<int>(a), j});
      rows.emplace_back();
      for (const RowPoint& p : spline_row_points(g, c, arc, degree, j)) add_point_row(g, p.x, p.y, p.weight, rows.back());
    }
  }
  const std::vector<double> weights = point_weights(L, c.r);
  for (size_t k = 0; k < L.points.size(); ++k) {
    place(L.points[k], weights[k]);
    kinds.push_back({-1, static_cast<int>(k)});
    rows.emplace_back();
    add_point_row(g, e.x.back(), e.y.back(), 1.0, rows.back());
  }
  return e;
}
// @end rim-layout-rows

namespace {

// Whether a point of the whole plate lies in the grid's part, and the share of its weight the part
// keeps: half on a mirror line, where it stands for itself alone.
bool in_part(const Grid& g, double& x, double& y, double& share) {
  const double on_line = 1e-9 * g.h;
  share = 1;
  if (g.mirror_x && x > g.lx() + on_line) return false;
  if (g.mirror_y && y > g.ly() + on_line) return false;
  if (g.mirror_x && std::abs(x - g.lx()) <= on_line) x = g.lx(), share *= 0.5;
  if (g.mirror_y && std::abs(y - g.ly()) <= on_line) y = g.ly(), share *= 0.5;
  return true;
}

// @region edge-sampling
// Keeps the interior rows farther than 1e-9 h from the curve (a node on the circle would repeat an
// edge point) and appends one row per edge point: the values of the element's 16 basis functions
// there, so that (S w)_p = w_h(x_p) exactly. A point on an element side may use either element
// (w_h is C^1). On the part of a symmetric plate only the points of the part are kept (those of
// the whole curve, so the part and the whole plate solve one discrete problem), and a point on a
// mirror line, which stands for itself alone, keeps half its weight.
void add_edge(const Grid& g, const EdgeCurve& curve, const EdgeRows& how, const RimLayout& layout, Sampling& s) {
  std::vector<std::map<int, double>> rows;
  std::vector<RimRow> kinds;
  EdgePoints whole;
  if (how.splines_on(curve) && !layout.periodic) {
    whole = laid_out_rows(g, curve, how, layout, rows, kinds);
    s.edge_spline_degree = how.degree;
    s.rim = layout;
  } else if (how.splines_on(curve)) {  // make_sampling has checked that the curve is a circle
    whole = spline_rows(g, curve, how, rows, kinds);
    s.edge_spline_degree = how.degree;
    s.edge_knots = whole.size();
  } else {
    whole = edge_points(curve, g.h);
    rows.resize(whole.size());
    for (int k = 0; k < whole.size(); ++k) add_point_row(g, whole.x[k], whole.y[k], 1.0, rows[k]);
  }
  EdgePoints e;
  std::vector<int> kept;
  for (int k = 0; k < whole.size(); ++k) {
    double x = whole.x[k], y = whole.y[k], share = 1;
    if (!in_part(g, x, y, share)) continue;
    kept.push_back(k);
    if (!kinds.empty()) s.rim_rows.push_back(kinds[k]);
    e.x.push_back(x), e.y.push_back(y);
    e.nx.push_back(whole.nx[k]), e.ny.push_back(whole.ny[k]);
    if (!whole.theta.empty()) e.theta.push_back(whole.theta[k]);
    e.weight.push_back(share * whole.weight[k]);
    e.length += e.weight.back();
  }
  std::vector<int> keep;
  for (int p = 0; p < s.size(); ++p)
    if (!(distance_to_edge(curve, s.x[p], s.y[p]) <= 1e-9 * g.h)) keep.push_back(p);
  RowBuilder b(s, keep, e.size());
  for (int k = 0; k < e.size(); ++k) {
    b.S.startVec(b.next);
    for (const auto& [col, val] : rows[kept[k]]) b.S.insertBack(b.next, col) = val;  // a std::map: columns in order
    b.weights[b.next++] = e.weight[k];
    b.x.push_back(e.x[k]);
    b.y.push_back(e.y[k]);
  }
  b.S.finalize();
  s.S = std::move(b.S);
  s.weights = std::move(b.weights);
  s.x = std::move(b.x);
  s.y = std::move(b.y);
  s.edge = e;
}
// @end edge-sampling

}  // namespace

int spline_knots(double r, double h, const EdgeRows& how) {
  const double spacing = how.cells > 0 ? how.cells * h : std::pow(h, 3.0 / 7) * std::pow(r, 4.0 / 7);
  return std::max(8, 4 * static_cast<int>(std::lround(2 * M_PI * r / spacing / 4)));
}

Sampling make_sampling(const Grid& g, SamplingKind kind, const EdgeCurve& edge, const EdgeRows& how, const RimLayout& layout) {
  if (how.kind == EdgeRows::Kind::Splines) {
    if (how.degree < 1 || how.degree > 5) throw std::invalid_argument("--edge-rows: the spline degree must be 1 ... 5");
    if (!(how.cells >= 0 && std::isfinite(how.cells)))
      throw std::invalid_argument("--edge-rows: the knot spacing in cells must be finite and >= 0 (0: the automatic spacing)");
    if (!(has_edge(kind) && edge.kind == EdgeCurve::Kind::Circle))
      throw std::invalid_argument("--edge-rows spline needs edge sampling of a circle");
  }
  const bool gauss = kind == SamplingKind::Gauss || kind == SamplingKind::EdgeGauss;
  Sampling s = gauss ? gauss_points(g) : grid_nodes(g);
  s.kind = kind;
  if (!layout.periodic && !(how.splines_on(edge) && edge.kind == EdgeCurve::Kind::Circle && has_edge(kind)))
    throw std::invalid_argument("make_sampling: a rim layout needs spline rows on a circle");
  if (has_edge(kind) && !edge.empty()) add_edge(g, edge, how, layout, s);
  s.edge_begin = s.size() - s.edge.size();
  return s;
}

std::vector<double> mirror_angles(const Grid& g, double theta) {
  std::vector<double> a{theta};
  if (g.mirror_x) a.push_back(M_PI - theta);
  if (g.mirror_y) a.push_back(-theta);
  if (g.mirror_x && g.mirror_y) a.push_back(M_PI + theta);
  for (double& t : a) t = std::fmod(std::fmod(t, 2 * M_PI) + 2 * M_PI, 2 * M_PI);
  // An angle on a mirror line is its own image: keep it once.
  std::vector<double> distinct;
  for (double t : a) {
    bool seen = false;
    for (double u : distinct) seen = seen || std::abs(std::remainder(t - u, 2 * M_PI)) <= 1e-12;
    if (!seen) distinct.push_back(t);
  }
  return distinct;
}

// @region rim-exchange-rows
void append_rim_points(const Grid& g, const EdgeCurve& c, const std::vector<double>& angles, Sampling& s) {
  if (!s.rim_laid_out()) throw std::logic_error("append_rim_points: the sampling has no rim layout");
  const int old = s.size();
  std::vector<std::pair<int, std::map<int, double>>> fresh;  // layout index, row
  std::vector<double> shares;
  for (double theta : angles) {
    double x = c.cx + c.r * std::cos(theta), y = c.cy + c.r * std::sin(theta), share = 1;
    const int index = static_cast<int>(s.rim.points.size());
    for (double t : mirror_angles(g, theta)) s.rim.points.push_back(t);
    if (!in_part(g, x, y, share)) continue;
    std::map<int, double> row;
    add_point_row(g, x, y, 1.0, row);
    fresh.emplace_back(index, std::move(row));
    shares.push_back(share);
    s.x.push_back(x), s.y.push_back(y);
    s.edge.x.push_back(x), s.edge.y.push_back(y), s.edge.theta.push_back(theta);
    s.edge.nx.push_back(-std::cos(theta)), s.edge.ny.push_back(-std::sin(theta));
    s.edge.weight.push_back(0);  // set below
    s.rim_rows.push_back({-1, index});
  }
  RowSpMat S(old + static_cast<Eigen::Index>(fresh.size()), s.S.cols());
  S.reserve(s.S.nonZeros() + 16 * static_cast<Eigen::Index>(fresh.size()));
  for (int r = 0; r < old; ++r) {
    S.startVec(r);
    for (RowSpMat::InnerIterator it(s.S, r); it; ++it) S.insertBack(r, it.col()) = it.value();
  }
  for (size_t k = 0; k < fresh.size(); ++k) {
    S.startVec(old + static_cast<int>(k));
    for (const auto& [col, val] : fresh[k].second) S.insertBack(old + static_cast<int>(k), col) = val;
  }
  S.finalize();
  s.S = std::move(S);
  // Every point row's weight from the new layout: a new point shortens its neighbours' arcs.
  const std::vector<double> w = point_weights(s.rim, c.r);
  s.weights.conservativeResize(s.size());
  double length = 0;
  for (int k = 0; k < s.edge_size(); ++k) {
    const RimRow& row = s.rim_rows[k];
    if (row.point()) {
      double x = s.edge.x[k], y = s.edge.y[k], share = 1;
      in_part(g, x, y, share);
      s.edge.weight[k] = share * w[row.basis];
      s.weights[s.edge_begin + k] = s.edge.weight[k];
    }
    length += s.edge.weight[k];
  }
  s.edge.length = length;
}
// @end rim-exchange-rows

SpMat weighted_gram(const RowSpMat& S, const VectorXd& d, int unknowns) {
  std::vector<Eigen::Triplet<double>> t;
  for (Eigen::Index p = 0; p < S.rows(); ++p) {
    if (d[p] == 0.0) continue;
    for (RowSpMat::InnerIterator a(S, p); a; ++a)
      for (RowSpMat::InnerIterator b(S, p); b; ++b) t.emplace_back(a.col(), b.col(), d[p] * a.value() * b.value());
  }
  SpMat G(unknowns, unknowns);
  G.setFromTriplets(t.begin(), t.end());
  return G;
}

std::vector<RowPoint> edge_row_points(const Grid& g, const EdgeCurve& c, const Sampling& s, int k) {
  if (s.edge_spline_degree == 0 || (s.rim_laid_out() && s.rim_rows[k].point()))
    return {{s.x[s.edge_begin + k], s.y[s.edge_begin + k], 1.0}};
  if (!s.rim_laid_out()) throw std::logic_error("edge_row_points: periodic spline rows are not read point by point here");
  const RimRow& row = s.rim_rows[k];
  return spline_row_points(g, c, s.rim.arcs[row.arc], s.edge_spline_degree, row.basis);
}

}  // namespace plate
