// Gauss-Legendre nodes by Newton's method on P_n, so no table has to be trusted.
#include "gauss.hpp"

#include <cmath>
#include <stdexcept>

namespace plate {

template <class T>
QuadratureRule<T> gauss_legendre_rule(int n) {
  if (n < 1) throw std::invalid_argument("gauss_legendre: n must be >= 1");
  QuadratureRule<T> q;
  q.points.resize(n);
  q.weights.resize(n);
  for (int i = 0; i < n; ++i) {
    // Chebyshev-like first guess for the i-th root of P_n on [-1, 1], descending.
    T x = std::cos(T(M_PI) * (i + T(0.75)) / (n + T(0.5)));
    T dp = 0;
    for (int it = 0; it < 100; ++it) {
      T p0 = 1, p1 = x;  // P_0, P_1; three-term recurrence up to P_n
      for (int k = 2; k <= n; ++k) {
        const T pk = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = pk;
      }
      const T pn = (n == 1) ? x : p1;
      const T pnm1 = (n == 1) ? T(1) : p0;
      dp = n * (x * pn - pnm1) / (x * x - 1);
      const T dx = pn / dp;
      x -= dx;
      if (std::abs(dx) < T(1e-16)) break;  // Newton has already taken the step that converges
    }
    // Map [-1, 1] -> [0, 1]: ascending order, weights halved.
    q.points[n - 1 - i] = (1 + x) / 2;
    q.weights[n - 1 - i] = 1 / ((1 - x * x) * dp * dp);
  }
  return q;
}

template QuadratureRule<double> gauss_legendre_rule<double>(int);
template QuadratureRule<long double> gauss_legendre_rule<long double>(int);

}  // namespace plate
