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
  std::string basis;     // "richardson", "last difference", "largest of the last two differences" or "none"
};

// Eq. (D29): values on grids h, h/2, h/4, ... (coarsest first). Steady: the finest value's
// distance to Richardson's limit plus that limit's own bar (its distance to the limit of the grids
// before): |v_h - v| <= |v_h - L| + |L - v|. Shrinking but not steady: the last difference
// |v_h - v_2h|, which bounds the error of v_h if the differences shrink at least geometrically from
// there on (nothing here can check that, so the report says "not steady"). Swinging (the last two
// differences change sign, or the last one grew): the larger of the last two differences.
ErrorBar error_bar(const std::vector<double>& values);

}  // namespace plate
