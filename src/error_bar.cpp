// The error bar from the run's own grids.
#include "error_bar.hpp"

#include <algorithm>
#include <cmath>

#include "richardson.hpp"

namespace plate {

// @region error-bar
// Eq. (D29): the finest value with a bar on its distance from the continuum.
ErrorBar error_bar(const std::vector<double>& values) {
  ErrorBar b;
  if (values.empty()) return b;
  b.value = b.limit = values.back();
  b.bar = b.order = NAN;
  b.basis = "none";
  if (values.size() < 2) return b;
  if (std::all_of(values.begin(), values.end(), [&](double v) { return v == values.back(); })) {
    // To the last bit on every grid, as a value the scene fixes is (w at a clamped corner, no force
    // where nothing touches): no change to measure. The grids cannot tell that from a feature that
    // every one of them misses (a spike of obstacle between nodes), so the bar of 0 is marked.
    b.bar = 0;
    b.basis = "the same on every grid";
    return b;
  }
  const Extrapolation e = extrapolate(values);
  if (!e.orders.empty()) b.order = e.orders.back();
  const bool believable = b.order <= kLargestOrder;  // false for NaN: they swing, or are too few
  b.steady = e.steady && believable;
  if (b.steady) {
    b.limit = e.limit;
    b.bar = std::abs(b.value - e.limit) + e.bar;
    b.basis = "richardson";
  } else if (values.size() >= 3 && !believable) {
    // The increments change sign or grow, or the last is too small to be convergence: the values
    // swing rather than settle, and the larger of the last two swings is the scale of the finest
    // value's error.
    const size_t m = values.size();
    b.bar = std::max(std::abs(values[m - 1] - values[m - 2]), std::abs(values[m - 2] - values[m - 3]));
    b.basis = "largest of the last two differences";
  } else {
    b.bar = std::abs(values[values.size() - 1] - values[values.size() - 2]);
    b.basis = "last difference";
  }
  return b;
}
// @end error-bar

// @region error-bar-across
// Eq. (D29) across two spaces: the finest grid in one, the coarser ones in the other (the kink
// functions of (D31) fit the finest grid alone). v_h's distance to the plate's answer is at most
// |v_h - v_2h| + |v_2h - v|, and the second is the coarser space's own bar.
ErrorBar error_bar_across(double finest, const std::vector<double>& coarser) {
  std::vector<double> all = coarser;
  all.push_back(finest);
  if (const ErrorBar same = error_bar(all); same.basis == "the same on every grid") return same;
  const ErrorBar below = error_bar(coarser);
  ErrorBar b;
  b.value = b.limit = finest;
  b.order = NAN;
  b.bar = below.basis == "none" ? NAN : std::abs(finest - coarser.back()) + below.bar;
  b.basis = below.basis == "none" ? "none" : "last difference across the spaces";
  return b;
}
// @end error-bar-across

}  // namespace plate
