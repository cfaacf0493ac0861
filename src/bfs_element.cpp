// Tensor-product Hermite basis and exact Gauss integration of the element matrices.
#include "bfs_element.hpp"

#include "gauss.hpp"
#include "hermite.hpp"

namespace plate {

namespace {
// The basis in any precision: T is double, or long double for iterative refinement.
template <class T>
LocalBasisT<T> basis(T t, T s, T h) {
  const HermiteValues<T> X = hermite_physical(t, h), Y = hermite_physical(s, h);
  LocalBasisT<T> b;
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 4; ++c) {
      // 1D index 2 * end + kind: the corner's end in each direction, the component's order.
      const int ix = 2 * (a & 1) + (c & 1), iy = 2 * (a >> 1) + (c >> 1);
      const int k = 4 * a + c;
      b.v[k] = X.d0[ix] * Y.d0[iy];
      b.dx[k] = X.d1[ix] * Y.d0[iy];
      b.dy[k] = X.d0[ix] * Y.d1[iy];
      b.dxx[k] = X.d2[ix] * Y.d0[iy];
      b.dxy[k] = X.d1[ix] * Y.d1[iy];
      b.dyy[k] = X.d0[ix] * Y.d2[iy];
    }
  return b;
}

// Sum over the 4 x 4 Gauss points of weight * g g^T, g chosen from the basis.
template <class T, class Pick>
Eigen::Matrix<T, 16, 16> integrate_gram(T h, Pick pick) {
  const QuadratureRule<T> q = gauss_legendre_rule<T>(4);
  Eigen::Matrix<T, 16, 16> m = Eigen::Matrix<T, 16, 16>::Zero();
  for (size_t i = 0; i < q.points.size(); ++i)
    for (size_t j = 0; j < q.points.size(); ++j) {
      const Eigen::Matrix<T, 16, 1> g = pick(basis(q.points[i], q.points[j], h));
      m += (q.weights[i] * q.weights[j] * h * h) * g * g.transpose();
    }
  return m;
}
}  // namespace

LocalBasis bfs_basis(double t, double s, double h) { return basis(t, s, h); }

// @region bfs-stiffness
// Eq. (8), first term: the element matrix of (Lap u_h, Lap v_h).
template <class T>
Eigen::Matrix<T, 16, 16> bfs_stiffness_in(T h) {
  return integrate_gram(h, [](const LocalBasisT<T>& b) -> Eigen::Matrix<T, 16, 1> { return b.dxx + b.dyy; });
}
Matrix16 bfs_stiffness(double h) { return bfs_stiffness_in(h); }
// @end bfs-stiffness

Eigen::Matrix<long double, 16, 16> bfs_stiffness_extended(long double h) { return bfs_stiffness_in(h); }

Matrix16 bfs_mass(double h) {
  return integrate_gram(h, [](const LocalBasis& b) -> Vector16 { return b.v; });
}

}  // namespace plate
