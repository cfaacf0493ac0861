// The paper's experiment as a test fixture: unit square, f = 0, obstacle of height R on the disk
// of radius 0.25 around the centre.
#pragma once
#include <cmath>
#include <utility>

#include "fields.hpp"
#include "published.hpp"
#include "problem.hpp"

namespace plate {
inline Problem paper_problem(int n, SamplingKind kind, double R = 0.0625) {
  return make_problem(make_grid(n), kind, cylinder(0.5, 0.5, 0.25, R), [](double, double) { return 0.0; });
}

// A published constant of the clamped plate, from reference/plate_constants.csv.
inline double plate_constant(const std::string& key) {
  static const auto numbers = read_paper_numbers(std::string(PLATE_SOURCE_DIR) + "/reference/plate_constants.csv");
  return published(numbers, key);
}

// Largest asymmetry of the nodal values over the eight symmetries of the n x n grid.
inline double asymmetry(const Grid& g, const VectorXd& w) {
  const int n = g.nx;
  double worst = 0;
  for (int j = 1; j < n; ++j)
    for (int i = 1; i < n; ++i) {
      const double v = w[g.dof(i, j, kW)];
      for (auto [a, b] : {std::pair{j, i}, {n - i, j}, {i, n - j}, {n - i, n - j}, {n - j, i}, {j, n - i}, {n - j, n - i}})
        worst = std::max(worst, std::abs(v - w[g.dof(a, b, kW)]));
    }
  return worst;
}
}  // namespace plate
