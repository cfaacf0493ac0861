// Tensor-product Hermite basis and exact Gauss integration of the element matrices.
#include "bfs_element.hpp"

#include "gauss.hpp"
#include "hermite.hpp"

namespace plate {

namespace {
// Function 4 a + c (corner a, component c) is the product of 1D cubics ix(k) in x and iy(k) in y,
// each indexed 2 * end + kind: the corner's end in that direction, the component's order there.
constexpr int x_index(int a, int c) { return 2 * (a & 1) + (c & 1); }
constexpr int y_index(int a, int c) { return 2 * (a >> 1) + (c >> 1); }

// The basis in any precision: T is double, or long double for iterative refinement.
template <class T>
LocalBasisT<T> basis(T t, T s, T h) {
  const HermiteValues<T> X = hermite_physical(t, h), Y = hermite_physical(s, h);
  LocalBasisT<T> b;
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 4; ++c) {
      const int ix = x_index(a, c), iy = y_index(a, c);
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

Vector16 bfs_values(double t, double s, double h) {
  const Hermite1D X = hermite_physical(t, h), Y = hermite_physical(s, h);
  Vector16 v;
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 4; ++c) v[4 * a + c] = X.d0[x_index(a, c)] * Y.d0[y_index(a, c)];
  return v;
}

void bfs_basis_along(double t, double s, double h, double c, double sn, double* value, double* slope, double* lap) {
  // hermite_physical's eight divisions, as products with 1 / h (the same numbers where h is a power
  // of two): with its divisions the blocks took 4% longer at n = 64.
  const double ih = 1 / h, ih2 = ih * ih;
  auto physical = [&](double u) {
    Hermite1D r = hermite_cubics(u);
    for (int k = 0; k < 4; ++k) {
      const bool slope = k & 1;
      r.d0[k] *= slope ? h : 1.0;
      r.d1[k] *= slope ? 1.0 : ih;
      r.d2[k] *= slope ? ih : ih2;
    }
    return r;
  };
  const Hermite1D X = physical(t), Y = physical(s);
  for (int a = 0; a < 4; ++a)
    for (int k = 0; k < 4; ++k) {
      const int ix = x_index(a, k), iy = y_index(a, k), i = 4 * a + k;
      value[i] = X.d0[ix] * Y.d0[iy];
      lap[i] = X.d2[ix] * Y.d0[iy] + X.d0[ix] * Y.d2[iy];
    }
  if (!slope) return;
  for (int a = 0; a < 4; ++a)
    for (int k = 0; k < 4; ++k) {
      const int ix = x_index(a, k), iy = y_index(a, k);
      slope[4 * a + k] = c * (X.d1[ix] * Y.d0[iy]) + sn * (X.d0[ix] * Y.d1[iy]);
    }
}

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
