// Richardson extrapolation with an honest error bar: the limit from the last three grids, its
// uncertainty the distance to the limit the three grids before would have given. Where the order
// is not steady no extrapolation is trusted: the finest value stands, with its last increment.
#include "richardson.hpp"

#include <cmath>

#include "format.hpp"

namespace plate {

namespace {
double order(double a, double b, double c) {
  const double d1 = b - a, d2 = c - b;
  if (!(d1 * d2 > 0) || std::abs(d2) >= std::abs(d1)) return NAN;
  return std::log2(d1 / d2);
}
double richardson(double b, double c, double p) { return c + (c - b) / (std::pow(2.0, p) - 1); }
}  // namespace

// @region richardson
// Eq. (D16): observed orders, and the limit where the order is steady over the last four grids.
Extrapolation extrapolate(const std::vector<double>& v, double spread) {
  Extrapolation e;
  const int m = static_cast<int>(v.size());
  for (int k = 0; k + 2 < m; ++k) e.orders.push_back(order(v[k], v[k + 1], v[k + 2]));
  const int t = static_cast<int>(e.orders.size());
  if (m >= 2) e.limit = v[m - 1], e.bar = std::abs(v[m - 1] - v[m - 2]);
  const std::string fallback = "; finest value " + fmt("%.10g", e.limit) + " +- " + fmt("%.1e", e.bar) + " (last increment)";
  if (t < 2 || !std::isfinite(e.orders[t - 1]) || !std::isfinite(e.orders[t - 2])) {
    e.verdict = (t < 2 ? "too few grids" : "not steady: the last increments change sign or grow") + fallback;
    return e;
  }
  const double p = e.orders[t - 1], q = e.orders[t - 2];
  if (std::abs(p - q) > spread) {
    e.verdict = "not steady: the last two orders are " + fmt("%.2f", q) + " and " + fmt("%.2f", p) + fallback;
    return e;
  }
  e.steady = true;
  e.limit = richardson(v[m - 2], v[m - 1], p);
  e.bar = std::abs(e.limit - richardson(v[m - 3], v[m - 2], q));
  e.verdict = "order " + fmt("%.2f", p) + ", limit " + fmt("%.10g", e.limit) + " +- " + fmt("%.1e", e.bar);
  return e;
}
// @end richardson

}  // namespace plate
