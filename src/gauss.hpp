// Gauss-Legendre quadrature on [0, 1].
// The element integrals are polynomial of degree <= 6 per direction, so 4 points are exact;
// error norms use more points.
#pragma once
#include <vector>

namespace plate {

struct Quadrature1D {
  std::vector<double> points;   // in (0, 1), increasing
  std::vector<double> weights;  // sum to 1
};

// n-point rule, exact for polynomials of degree 2n - 1.
Quadrature1D gauss_legendre(int n);

}  // namespace plate
