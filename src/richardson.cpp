// Richardson extrapolation with an honest error bar: the limit from the last three grids, its
// uncertainty the distance to the limit the three grids before would have given. Where the order
// is not steady no extrapolation is trusted: the finest value stands, with its last increment.
#include "richardson.hpp"

#include <cmath>

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
// Eq. (D13): observed orders, and the limit where the order is steady over the last four grids.
Extrapolation extrapolate(const std::vector<double>& v, const std::vector<double>& noise, double spread) {
  Extrapolation e;
  const int m = static_cast<int>(v.size());
  auto z = [&](int k) { return noise.empty() ? 0.0 : noise[k]; };
  for (int k = 0; k + 2 < m; ++k) {
    e.orders.push_back(order(v[k], v[k + 1], v[k + 2]));
    // p = log2(d1 / d2): each increment carries the noise of its two ends.
    e.order_noise.push_back(((z(k) + z(k + 1)) / std::abs(v[k + 1] - v[k]) +
                             (z(k + 1) + z(k + 2)) / std::abs(v[k + 2] - v[k + 1])) / std::log(2.0));
  }
  const int t = static_cast<int>(e.orders.size());
  if (m >= 2) {
    e.limit = v[m - 1], e.bar = std::abs(v[m - 1] - v[m - 2]);
    e.limit_noise = z(m - 1), e.bar_noise = z(m - 1) + z(m - 2);
  }
  if (t < 2 || !std::isfinite(e.orders[t - 1]) || !std::isfinite(e.orders[t - 2])) return e;
  const double p = e.orders[t - 1], q = e.orders[t - 2];
  if (std::abs(p - q) > spread) return e;
  e.steady = true;
  e.limit = richardson(v[m - 2], v[m - 1], p);
  e.bar = std::abs(e.limit - richardson(v[m - 3], v[m - 2], q));
  // An order within the spread of 0 could be no order at all: then nothing bounds the limit.
  e.order_doubt = p - spread <= 0 ? INFINITY
                                  : std::max(std::abs(richardson(v[m - 2], v[m - 1], p - spread) - e.limit),
                                             std::abs(richardson(v[m - 2], v[m - 1], p + spread) - e.limit));
  // The limit moves with c and b, and with p through 1 / (2^p - 1).
  auto limit_noise = [&](int b, int c, double order, double order_noise) {
    const double g = std::pow(2.0, order) - 1;
    return z(c) + (z(c) + z(b)) / g + std::abs(v[c] - v[b]) * (g + 1) * std::log(2.0) / (g * g) * order_noise;
  };
  e.limit_noise = limit_noise(m - 2, m - 1, p, e.order_noise[t - 1]);
  e.bar_noise = e.limit_noise + limit_noise(m - 3, m - 2, q, e.order_noise[t - 2]);
  return e;
}
// @end richardson

double loglog_slope(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double k = static_cast<double>(x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    const double a = std::log(x[i]), b = std::log(y[i]);
    sx += a, sy += b, sxx += a * a, sxy += a * b;
  }
  return (k * sxy - sx * sy) / (k * sxx - sx * sx);
}

}  // namespace plate
