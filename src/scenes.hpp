// The obstacles of the hard cases (results/hard_cases.md and tests/test_hard_cases.cpp): scenes
// the paper did not try, each with an expectation that comes from outside this code.
#pragma once
#include <cmath>
#include <vector>

#include "assemble.hpp"
#include "grid.hpp"

namespace plate {

// Height `top` at the grid node nearest the centre and no constraint elsewhere: nodal sampling
// sees a single point, so the obstacle acts as a point load.
inline Field centre_spike(const Grid& g, double top) {
  const double cx = g.x((g.nx + 1) / 2), cy = g.y((g.ny + 1) / 2), half = 0.25 * g.h;
  return [=](double x, double y) { return (std::abs(x - cx) < half && std::abs(y - cy) < half) ? top : -INFINITY; };
}

// k x k smooth bumps with tops at height `top` over valleys at `bottom` (< top < 0): under a
// downward load the plate rests on the tops, one contact region per bump.
inline Field bumps(int k, double bottom, double top) {
  return [=](double x, double y) {
    const double s = std::sin(k * M_PI * x) * std::sin(k * M_PI * y);
    return bottom + (top - bottom) * s * s * s * s;
  };
}

// Connected groups of touching nodes (nodal sampling: sample q is interior node q, row by row),
// neighbours along the grid lines and diagonals.
inline int contact_regions(const Grid& g, const std::vector<char>& touching) {
  const int m = g.nx - 1;
  std::vector<int> label(touching.size(), 0), stack;
  int regions = 0;
  for (size_t start = 0; start < touching.size(); ++start) {
    if (!touching[start] || label[start]) continue;
    label[start] = ++regions;
    stack.push_back(static_cast<int>(start));
    while (!stack.empty()) {
      const int q = stack.back();
      stack.pop_back();
      const int i = q % m, j = q / m;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int a = i + di, b = j + dj;
          if (a < 0 || a >= m || b < 0 || b >= g.ny - 1) continue;
          const int r = b * m + a;
          if (touching[r] && !label[r]) {
            label[r] = regions;
            stack.push_back(r);
          }
        }
    }
  }
  return regions;
}

}  // namespace plate
