// Assembling a Problem and validating its data before any solve.
#include "problem.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace plate {

void check_obstacle_on_boundary(const Grid& g, const Field& obstacle) {
  const int per_edge = 8;
  auto check = [&](double x, double y) {
    const double v = obstacle(x, y);
    if (!(v < 0.0)) {
      std::ostringstream m;
      if (std::isnan(v)) {
        m << "obstacle is not a number (NaN) at the boundary point (" << x << ", " << y << ")";
        throw std::invalid_argument(m.str());
      }
      m << "obstacle must be below zero on the boundary (the plate is clamped at w = 0 there), "
        << "but phi(" << x << ", " << y << ") = " << v;
      throw std::invalid_argument(m.str());
    }
  };
  for (int k = 0; k < g.nx * per_edge; ++k) {
    const double x = k * g.h / per_edge;
    check(x, 0.0);
    check(g.lx() - x, g.ly());
  }
  for (int k = 0; k < g.ny * per_edge; ++k) {
    const double y = k * g.h / per_edge;
    check(g.lx(), y);
    check(0.0, g.ly() - y);
  }
}

Problem make_problem(const Grid& g, SamplingKind kind, const Field& obstacle, const Field& load) {
  check_obstacle_on_boundary(g, obstacle);
  Problem p{g, make_sampling(g, kind), {}, {}, {}, {}};
  p.phi.resize(p.sampling.size());
  for (int i = 0; i < p.sampling.size(); ++i) {
    const double v = obstacle(p.sampling.x[i], p.sampling.y[i]);
    if (std::isnan(v) || v == INFINITY) {
      std::ostringstream m;
      m << "obstacle must be a number or -inf (no constraint), but phi(" << p.sampling.x[i] << ", "
        << p.sampling.y[i] << ") = " << v;
      throw std::invalid_argument(m.str());
    }
    p.phi[i] = v;
  }
  p.K = assemble_matrix(g, bfs_stiffness(g.h));
  p.M = sampling_mass(g, p.sampling);
  p.F = assemble_load(g, load, "load");
  return p;
}

}  // namespace plate
