// What (D31) and (D33) share: the cubic B-spline, the cut-off, the band's rules.
#include "kink_space.hpp"

#include <cmath>
#include <stdexcept>

namespace plate {

// The centred cubic B-spline of the knot spacing x and its first two derivatives.
KinkSpline cubic_bspline(double x) {
  const double a = std::abs(x), sg = x < 0 ? -1.0 : 1.0;
  if (a >= 2) return {};
  if (a >= 1) {
    const double t = 2 - a;
    return {t * t * t / 6, -sg * t * t / 2, t};
  }
  return {2.0 / 3 - a * a + a * a * a / 2, -2 * x + 1.5 * x * a, -2 + 3 * a};
}

// @region kink-cutoff
// chi(d) and its first two derivatives: the quintic smoothstep, C^2, from 1 at inner to 0 at outer.
KinkRadial kink_cutoff(double inner, double outer, double d) {
  if (d <= inner) return {1, 0, 0};
  if (d >= outer) return {};
  const double L = outer - inner, u = (d - inner) / L, u2 = u * u;
  return {1 - u2 * u * (10 - 15 * u + 6 * u2), -30 * u2 * (1 - 2 * u + u2) / L, -60 * u * (1 - 3 * u + 2 * u2) / (L * L)};
}
// @end kink-cutoff

// Not finite, or not ordered: refused before any comparison that a NaN would pass.
void check_kink_band(const KinkBand& band) {
  if (!(band.flat > std::sqrt(2.0) && band.zero > band.flat && std::isfinite(band.zero)))
    throw std::invalid_argument("the cut-off's band of (D31) must have sqrt(2) < flat < zero cells, both finite");
}

}  // namespace plate
