// Cases the paper did not try, each checked against an expectation from outside this code:
// a point obstacle against the clamped square's point-load coefficient, and an obstacle that just
// touches the free plate (contact with zero force).
#include <gtest/gtest.h>

#include "active_set.hpp"
#include "cholesky.hpp"
#include "fields.hpp"

using namespace plate;

namespace {
// An obstacle at the centre node only (nodal sampling sees nothing else): height `top` there.
Field centre_point(int n, double top) {
  const double half = 0.25 / n;
  return [=](double x, double y) { return (std::abs(x - 0.5) < half && std::abs(y - 0.5) < half) ? top : -INFINITY; };
}
}  // namespace

TEST(HardCases, PointObstacleActsAsTheClampedSquaresPointLoad) {
  // A plate lifted at its centre only is a clamped square under a central point load P, the
  // obstacle's force: Timoshenko & Woinowsky-Krieger (Theory of Plates and Shells, 2nd ed., table of
  // clamped rectangular plates under a central load) give w_c = 0.00560 P a^2 / D.
  const int n = 64;
  const Problem p = make_problem(make_grid(n), SamplingKind::Nodes, centre_point(n, 0.01), [](double, double) { return 0.0; });
  const ExactResult r = solve_exact(p, ExactOptions{});
  ASSERT_TRUE(r.converged) << r.message;
  const double P = p.sampling.weights.dot(r.lambda);
  const double coefficient = 0.01 / P;
  std::printf("w_c / P = %.7f (published 0.00560)\n", coefficient);
  EXPECT_NEAR(coefficient, 0.00560, 0.00560 * 0.01);  // three published digits; the mesh error is well below 1%
  int touching = 0;
  for (int q = 0; q < r.lambda.size(); ++q) touching += r.lambda[q] > 0;
  EXPECT_EQ(touching, 1);
}

TEST(HardCases, ObstacleThatJustTouchesTheFreePlateCarriesNoForce) {
  // Under an upward load the free plate's centre rises to w_free; an obstacle of exactly that
  // height at the centre is touched with zero force, the degenerate case of complementarity.
  const int n = 32;
  const Field up = [](double, double) { return 1.0; };
  const Problem free_plate = make_problem(make_grid(n), SamplingKind::Nodes, [](double, double) { return -1.0; }, up);
  Cholesky chol;
  chol.factorize(free_plate.K);
  const VectorXd w_free = chol.solve(free_plate.F);
  const Grid& g = free_plate.grid;
  const double top = w_free[g.dof(n / 2, n / 2, kW)];
  const Problem p = make_problem(g, SamplingKind::Nodes, centre_point(n, top), up);
  const ExactResult r = solve_exact(p, ExactOptions{});
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_LE(r.certificate.worst(), 1e-10);
  EXPECT_LE((r.w - w_free).lpNorm<Eigen::Infinity>(), 1e-12 * w_free.lpNorm<Eigen::Infinity>());
  EXPECT_LE(p.sampling.weights.dot(r.lambda), 1e-10 * free_plate.F.lpNorm<1>());
}
