// Construction of the two samplings and of the weighted Gram matrices S^T D S.
#include "sampling.hpp"

#include <algorithm>
#include <utility>

#include "assemble.hpp"
#include "bfs_element.hpp"
#include "gauss.hpp"

namespace plate {

const char* to_string(SamplingKind kind) { return kind == SamplingKind::Gauss ? "gauss" : "nodes"; }

namespace {

Sampling gauss_points(const Grid& g) {
  const Quadrature1D q = gauss_legendre(4);
  const int per = 16, npts = g.elements() * per;
  Sampling s{SamplingKind::Gauss, {}, {}, VectorXd(npts), RowSpMat(npts, g.unknowns())};
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
  Sampling s{SamplingKind::Nodes, {}, {}, VectorXd::Constant(npts, g.h * g.h), RowSpMat(npts, g.unknowns())};
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

}  // namespace

Sampling make_sampling(const Grid& g, SamplingKind kind) {
  return kind == SamplingKind::Gauss ? gauss_points(g) : grid_nodes(g);
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

SpMat sampling_mass(const Grid& g, const Sampling& s) {
  if (s.kind == SamplingKind::Gauss) return assemble_matrix(g, bfs_mass(g.h));
  return weighted_gram(s.S, s.weights, g.unknowns());
}

}  // namespace plate
