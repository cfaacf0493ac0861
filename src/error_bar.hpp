// An error bar on an answer's distance from the plate's (the continuum), from the grids its own
// run already solved: grid sequencing solves n/8, n/4, n/2 before n, so the answer's values there
// cost no solve. A certificate bounds the distance to the discrete answer only; this estimates the
// rest, and says how.
#pragma once
#include <string>
#include <vector>

namespace plate {

struct ErrorBar {
  double value = 0;      // on the finest grid
  double bar = 0;        // estimated |value - continuum|; NaN with fewer than two grids
  bool steady = false;   // the observed order is steady (richardson.hpp) over the last four grids
  double order = 0;      // the last observed order (NaN if none)
  double limit = 0;      // Richardson's limit (steady), else the finest value
  std::string basis;     // "richardson", "last difference", "largest of the last two differences",
                         // "the same on every grid", "last difference across the spaces" or "none"
};

// Eq. (D29): values on grids h, h/2, h/4, ... (coarsest first). Steady: the finest value's
// distance to Richardson's limit plus that limit's own bar (its distance to the limit of the grids
// before): |v_h - v| <= |v_h - L| + |L - v|. Shrinking but not steady: the last difference
// |v_h - v_2h|, which bounds the error of v_h if the differences shrink at least geometrically from
// there on (nothing here can check that, so the report says "not steady"). Swinging (the last two
// differences change sign, or the last one grew, or shrank faster than kLargestOrder allows): the
// larger of the last two differences. Equal to the last bit on every grid: a bar of 0, which holds
// only if the scene fixes the value (the output says so).
ErrorBar error_bar(const std::vector<double>& values);

// The bar of a value v_h on a grid whose space the coarser grids do not share (D31 fits the finest
// grid alone): |v_h - v_2h| plus the bar of v_2h from the coarser grids' values (coarsest first,
// ending with v_2h); none if they give none. Never steady.
ErrorBar error_bar_across(double finest, const std::vector<double>& coarser);

// No space here converges faster than order 4 (bicubics, with or without the kink of D31). A last
// difference 2^6 times smaller than the one before says that two grids' values happened to land
// close, as values that cross the limit do, not that the error fell that much: on the paper's scene
// with the kink carried, max w on n = 128 and 256 differ by about 3e-12 of it, after about 8e-9 from
// 64 to 128, and both lie about 3e-11 from the series. Even a steady order above it is not believed.
constexpr double kLargestOrder = 6;

}  // namespace plate
