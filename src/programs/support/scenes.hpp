// The obstacles of the hard cases (results/hard_cases.md and tests/test_hard_cases.cpp): scenes
// the paper did not try, each with an expectation that comes from outside this code.
#pragma once
#include <cmath>
#include <vector>

#include "assemble.hpp"
#include "cholesky.hpp"
#include "grid.hpp"
#include "penalty_bound.hpp"
#include "problem.hpp"

namespace plate {

// The same value everywhere: a uniform load, or a flat support.
inline Field uniform(double v) {
  return [v](double, double) { return v; };
}


// Height `top` at the grid node nearest the centre and no constraint elsewhere: nodal sampling
// sees a single point, so the obstacle acts as a point load.
inline Field centre_spike(const Grid& g, double top) {
  const double cx = g.x((g.nx + 1) / 2), cy = g.y((g.ny + 1) / 2), half = 0.25 * g.h;
  return [=](double x, double y) { return (std::abs(x - cx) < half && std::abs(y - cy) < half) ? top : -INFINITY; };
}

// Under f = 1 the free plate (no contact) rises to w_free; an obstacle at the centre node of exactly
// that height is touched with zero force: complementarity's degenerate case.
struct JustTouching {
  Problem free_plate;
  VectorXd w_free;
  Problem touching;
};
inline JustTouching just_touching(int n) {
  const Grid g = make_grid(n);
  JustTouching s{make_problem(Scene::rectangle(1, 1).over(uniform(-1.0)).loaded(uniform(1.0)), g, SamplingSpec{SamplingKind::Nodes}), {}, {}};
  Cholesky chol;
  chol.factorize(s.free_plate.K);
  s.w_free = chol.solve(s.free_plate.F);
  s.touching = make_problem(Scene::rectangle(1, 1).over(centre_spike(g, s.w_free[centre_value_dof(g)])).loaded(uniform(1.0)), g,
                            SamplingSpec{SamplingKind::Nodes});
  return s;
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

// A complementarity problem on which the plain primal-dual iteration cycles from the empty set:
// lambda = M z + q, 0 <= z _|_ lambda >= 0, with M symmetric positive definite but not an M-matrix
// (a 3 x 3 case found by random search; the plate's own matrices gave none, see the document).
// It is put in a Problem on the 4 x 4 grid: nodes 0, 1, 2 carry M on their value unknowns,
// every other unknown is decoupled, and phi = 0, F = -q, weights 1 make z = w and lambda as above.
inline Problem cycling_problem() {
  const double M[3][3] = {{1.56, 1.14, -0.47}, {1.14, 3.51, -2.38}, {-0.47, -2.38, 1.71}};
  const double q[3] = {-0.09, -0.80, 0.58};
  Problem p = make_problem(Scene::rectangle(1, 1).over(uniform(-1.0)).loaded(uniform(0.0)), make_grid(4), SamplingSpec{SamplingKind::Nodes});
  const int n = p.grid.unknowns();
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i)
    if (i % 4 != 0 || i >= 12) t.emplace_back(i, i, 1.0);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) t.emplace_back(4 * a, 4 * b, M[a][b]);
  p.K.resize(n, n);
  p.K.setFromTriplets(t.begin(), t.end());
  p.F = VectorXd::Zero(n);
  p.phi = VectorXd::Constant(p.phi.size(), -INFINITY);
  p.sampling.weights.setOnes();
  for (int a = 0; a < 3; ++a) {
    p.F[4 * a] = -q[a];
    p.phi[a] = 0.0;
  }
  return p;
}
}  // namespace plate
