// Construction of the two samplings and of the weighted Gram matrices S^T D S.
#include "sampling.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "bfs_element.hpp"
#include "gauss.hpp"

namespace plate {

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
  Sampling s{SamplingKind::Gauss, {}, {}, VectorXd(npts), RowSpMat(npts, g.unknowns()), 0, {}};
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
Sampling grid_nodes(const Grid& g) {
  const int npts = g.interior_nodes();
  Sampling s{SamplingKind::Nodes, {}, {}, VectorXd::Constant(npts, g.h * g.h), RowSpMat(npts, g.unknowns()), 0, {}};
  s.S.reserve(npts);
  for (int j = 1; j < g.ny; ++j)
    for (int i = 1; i < g.nx; ++i) {
      const int p = g.node(i, j);
      s.x.push_back(g.x(i));
      s.y.push_back(g.y(j));
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

// @region edge-sampling
// Keeps the interior rows farther than 1e-9 h from the curve (a node on the circle would repeat an
// edge point) and appends one row per edge point: the values of the element's 16 basis functions
// there, so that (S w)_p = w_h(x_p) exactly. A point on an element side may use either element
// (w_h is C^1).
void add_edge(const Grid& g, const EdgeCurve& curve, Sampling& s) {
  const EdgePoints e = edge_points(curve, g.h);
  std::vector<int> keep;
  for (int p = 0; p < s.size(); ++p)
    if (!(distance_to_edge(curve, s.x[p], s.y[p]) <= 1e-9 * g.h)) keep.push_back(p);
  RowBuilder b(s, keep, e.size());
  std::vector<std::pair<int, double>> row;
  for (int k = 0; k < e.size(); ++k) {
    int ex, ey;
    double t, u;
    if (!g.locate(e.x[k], e.y[k], ex, ey, t, u))
      throw std::invalid_argument("--edge: the point (" + std::to_string(e.x[k]) + ", " + std::to_string(e.y[k]) +
                                  ") of the obstacle's edge is outside the plate");
    const auto dofs = g.element_dofs(ex, ey);
    const Vector16 v = bfs_basis(t, u, g.h).v;
    row.clear();
    for (int j = 0; j < 16; ++j)
      if (dofs[j] >= 0) row.emplace_back(dofs[j], v[j]);
    std::sort(row.begin(), row.end());
    b.S.startVec(b.next);
    for (const auto& [col, val] : row) b.S.insertBack(b.next, col) = val;
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

Sampling make_sampling(const Grid& g, SamplingKind kind, const EdgeCurve& edge) {
  const bool gauss = kind == SamplingKind::Gauss || kind == SamplingKind::EdgeGauss;
  Sampling s = gauss ? gauss_points(g) : grid_nodes(g);
  s.kind = kind;
  if (has_edge(kind) && !edge.empty()) add_edge(g, edge, s);
  s.edge_begin = s.size() - s.edge.size();
  return s;
}

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

}  // namespace plate
