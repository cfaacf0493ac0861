// Gauss-Legendre quadrature on [0, 1].
// The element integrals are polynomial of degree <= 6 per direction, so 4 points are exact;
// error norms use more points.
#pragma once
#include <vector>

namespace plate {

template <class T>
struct QuadratureRule {
  std::vector<T> points;   // in (0, 1), increasing
  std::vector<T> weights;  // sum to 1
};
using Quadrature1D = QuadratureRule<double>;

// n-point rule, exact for polynomials of degree 2n - 1; T is double or long double.
template <class T>
QuadratureRule<T> gauss_legendre_rule(int n);
inline Quadrature1D gauss_legendre(int n) { return gauss_legendre_rule<double>(n); }

}  // namespace plate
