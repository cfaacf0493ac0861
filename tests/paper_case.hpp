// The paper's experiment as a test fixture: unit square, f = 0, obstacle of height R on the disk
// of radius 0.25 around the centre.
#pragma once
#include "fields.hpp"
#include "problem.hpp"

namespace plate {
inline Problem paper_problem(int n, SamplingKind kind, double R = 0.0625) {
  return make_problem(make_grid(n), kind, cylinder(0.5, 0.5, 0.25, R), [](double, double) { return 0.0; });
}
}  // namespace plate
