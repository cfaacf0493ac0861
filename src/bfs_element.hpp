// The Bogner-Fox-Schmit element on a square of side h: local basis and element matrices.
// Local unknown 4 * (ax + 2 ay) + c belongs to corner (ax, ay) and component c (w, w_x, w_y, w_xy).
#pragma once
#include <Eigen/Dense>

namespace plate {

using Matrix16 = Eigen::Matrix<double, 16, 16>;
using Vector16 = Eigen::Matrix<double, 16, 1>;

// The 16 local basis functions and their derivatives at local coordinates (t, s).
template <class T>
struct LocalBasisT {
  Eigen::Matrix<T, 16, 1> v, dx, dy, dxx, dxy, dyy;
};
using LocalBasis = LocalBasisT<double>;
LocalBasis bfs_basis(double t, double s, double h);
// Its values alone (bfs_basis(t, s, h).v, the same numbers): a read of w that needs no slope.
Vector16 bfs_values(double t, double s, double h);
// The three columns of 16 that the kink's blocks (D31) read along a ray of direction (c, sn): the
// values, the slopes along the ray (none where `slope` is null) and the Laplacians, written straight
// where they go (copied from a LocalBasis, a wide load met the narrow stores that made it, and
// stalled: writing in place made the blocks 13% faster at n = 64).
void bfs_basis_along(double t, double s, double h, double c, double sn, double* value, double* slope, double* lap);

// Element matrices, integrated exactly by 4 x 4 Gauss points.
Matrix16 bfs_stiffness(double h);  // (Lap u, Lap v) on the element
Matrix16 bfs_mass(double h);       // (u, v) on the element
// The stiffness in long double: for residuals that the assembled K's own rounding does not limit.
Eigen::Matrix<long double, 16, 16> bfs_stiffness_extended(long double h);

}  // namespace plate
