// Gauss-Legendre nodes by Newton's method on P_n, so no table has to be trusted.
#include "gauss.hpp"

#include <cmath>
#include <stdexcept>

namespace plate {

Quadrature1D gauss_legendre(int n) {
  if (n < 1) throw std::invalid_argument("gauss_legendre: n must be >= 1");
  Quadrature1D q;
  q.points.resize(n);
  q.weights.resize(n);
  for (int i = 0; i < n; ++i) {
    // Chebyshev-like first guess for the i-th root of P_n on [-1, 1], descending.
    double x = std::cos(M_PI * (i + 0.75) / (n + 0.5));
    double dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;  // P_0, P_1; three-term recurrence up to P_n
      for (int k = 2; k <= n; ++k) {
        const double pk = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = pk;
      }
      const double pn = (n == 1) ? x : p1;
      const double pnm1 = (n == 1) ? 1.0 : p0;
      dp = n * (x * pn - pnm1) / (x * x - 1.0);
      const double dx = pn / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    // Map [-1, 1] -> [0, 1]: ascending order, weights halved.
    q.points[n - 1 - i] = 0.5 * (1.0 + x);
    q.weights[n - 1 - i] = 1.0 / ((1.0 - x * x) * dp * dp);
  }
  return q;
}

}  // namespace plate
