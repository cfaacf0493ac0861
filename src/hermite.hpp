// The 1D cubic Hermite basis on [0, 1]: the building block of the Bogner-Fox-Schmit element.
// g(end, kind) is 1 in value (kind 0) or slope (kind 1) at `end` and 0 in the other three.
#pragma once
#include <array>

namespace plate {

// Value and first two derivatives (with respect to t) of the four Hermite cubics at t.
// Order: [end 0 value, end 0 slope, end 1 value, end 1 slope]. T is double, or long double for
// the residuals of iterative refinement.
template <class T>
struct HermiteValues {
  std::array<T, 4> d0, d1, d2;
};
using Hermite1D = HermiteValues<double>;

// @region hermite-cubics
template <class T>
HermiteValues<T> hermite_cubics(T t) {
  const T t2 = t * t, t3 = t2 * t;
  HermiteValues<T> h;
  h.d0 = {1 - 3 * t2 + 2 * t3, t - 2 * t2 + t3, 3 * t2 - 2 * t3, -t2 + t3};
  h.d1 = {-6 * t + 6 * t2, 1 - 4 * t + 3 * t2, 6 * t - 6 * t2, -2 * t + 3 * t2};
  h.d2 = {-6 + 12 * t, -4 + 6 * t, 6 - 12 * t, -2 + 6 * t};
  return h;
}
// @end hermite-cubics

// Physical basis on a cell of width h: the slope functions carry a factor h so that their
// x-derivative is 1 at their node, and each x-derivative divides by h.
template <class T>
HermiteValues<T> hermite_physical(T t, T h) {
  HermiteValues<T> r = hermite_cubics(t);
  for (int k : {1, 3}) {
    r.d0[k] *= h;
    r.d1[k] *= h;
    r.d2[k] *= h;
  }
  for (int k = 0; k < 4; ++k) {
    r.d1[k] /= h;
    r.d2[k] /= h * h;
  }
  return r;
}

}  // namespace plate
