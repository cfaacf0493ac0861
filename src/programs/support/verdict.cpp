// The one-line verdict on an extrapolation, printed under the round-off rule of format.hpp.
#include "verdict.hpp"

#include <cmath>

#include "format.hpp"

namespace plate {

std::string format_order(double p, double noise) {
  if (!std::isfinite(p)) return "-";
  const int decimals = noise > 0 ? static_cast<int>(std::floor(-std::log10(10 * noise))) : 2;
  if (decimals < 0) return "~" + fmt("%.0f", p) + " (round-off)";
  return fmt(("%." + std::to_string(std::min(decimals, 2)) + "f").c_str(), p);
}

std::string verdict(const Extrapolation& e) { return verdict(e, fmt_above(e.bar, e.bar_noise, 2)); }

std::string verdict(const Extrapolation& e, const std::string& bar) {
  const std::string limit = fmt_above(e.limit, e.limit_noise, 10, 'g');
  const size_t t = e.orders.size();
  if (e.steady) return "order " + format_order(e.orders[t - 1], e.order_noise[t - 1]) + ", limit " + limit + " +- " + bar;
  const std::string fallback = "; finest value " + limit + " +- " + bar + " (last increment)";
  if (t < 2) return "too few grids" + fallback;
  if (!std::isfinite(e.orders[t - 1]) || !std::isfinite(e.orders[t - 2]))
    return "not steady: the last increments change sign or grow" + fallback;
  // The orders stand in the table's column beside the verdict: the cell does not repeat them.
  return "not steady" + fallback;
}

std::string bar_number(const Extrapolation& e, int digits) {
  const std::string b = fmt_above(e.bar, e.bar_noise, digits);
  return without_bound(b);
}

bool bar_is_roundoff(const Extrapolation& e) { return fmt_above(e.bar, e.bar_noise, 2)[0] == '<'; }

}  // namespace plate
