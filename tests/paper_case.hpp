// The paper's experiment as a test fixture: the scene of reference/paper_numbers.csv (published.hpp:
// unit square, f = 0, the obstacle's disk and height) on a grid.
#pragma once
#include <cmath>
#include <utility>

#include "fields.hpp"
#include "published.hpp"
#include "problem.hpp"

namespace plate {

// The paper's problem at obstacle height R (NaN: the paper's).
inline Problem paper_problem(int n, SamplingKind kind, double R = NAN) {
  return make_problem(std::isnan(R) ? paper_scene() : paper_scene(R), make_grid(n), SamplingSpec{kind});
}

// A published constant of the clamped plate, from reference/plate_constants.csv.
inline double plate_constant(const std::string& key) {
  static const std::string path = std::string(PLATE_SOURCE_DIR) + "/reference/plate_constants.csv";
  static const auto numbers = read_paper_numbers(path);
  return published(numbers, key, path);
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
