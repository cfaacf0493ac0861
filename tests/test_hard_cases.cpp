// Cases the paper did not try, each checked against an expectation from outside this code: the
// clamped square's published constants, the exact-constraint solver as a second algorithm, and
// what the continuum problem says (force density q under a flat support, one region per bump).
#include <gtest/gtest.h>

#include <cstdio>

#include "active_set.hpp"
#include "cholesky.hpp"
#include "eps_sweep.hpp"
#include "fields.hpp"
#include "norms.hpp"
#include "paper_case.hpp"
#include "scenes.hpp"

using namespace plate;

TEST(HardCases, PointObstacleActsAsTheClampedSquaresPointLoad) {
  // A plate lifted at its centre only is a clamped square under a central point load P, the
  // obstacle's force, so w_c / P must be the published coefficient.
  const Grid g = make_grid(64);
  const Problem p = make_problem(Scene::rectangle(g.whole_lx(), g.whole_ly()).over(centre_spike(g, 0.01)).loaded(uniform(0.0)), g, SamplingSpec{SamplingKind::Nodes});
  const ExactResult r = solve_exact(p, ExactOptions{});
  ASSERT_TRUE(r.converged) << r.message;
  const double coefficient = 0.01 / p.sampling.weights.dot(r.lambda);
  std::printf("w_c / P = %.7f (published %.5f)\n", coefficient, plate_constant("point_centre"));
  EXPECT_NEAR(coefficient, plate_constant("point_centre"), plate_constant("point_centre") * 0.01);  // three published digits
  EXPECT_EQ(members(r.active), 1);
}

TEST(HardCases, ObstacleThatJustTouchesTheFreePlateCarriesNoForce) {
  // Under an upward load the free plate's centre rises to w_free; an obstacle of exactly that
  // height at the centre is touched with zero force, the degenerate case of complementarity.
  const JustTouching s = just_touching(32);
  const Problem& p = s.touching;
  const VectorXd& w_free = s.w_free;
  const ExactResult r = solve_exact(p, ExactOptions{});
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_LE(r.certificate.worst(), 1e-10);
  EXPECT_LE((r.w - w_free).lpNorm<Eigen::Infinity>(), 1e-12 * w_free.lpNorm<Eigen::Infinity>());
  EXPECT_LE(p.sampling.weights.dot(r.lambda), 1e-10 * s.free_plate.F.lpNorm<1>());
}

TEST(HardCases, FlatSupportIsTouchedOnAnAreaWhereTheForceEqualsTheLoad) {
  // f = -q onto phi = -R. Contact starts when R falls below the free plate's sag 0.00126532 q;
  // inside the contact area w = -R, so Lap^2 w = 0 and the force density there equals q.
  const double q = 1.0, sag = plate_constant("uniform_centre") * q;
  const Grid g32 = make_grid(32);
  for (double factor : {1.01, 0.99}) {
    Problem p = make_problem(Scene::rectangle(1, 1).over(uniform(-sag * factor)).loaded(uniform(-q)), g32, SamplingSpec{SamplingKind::Nodes});
    const ExactResult r = solve_sequenced(p, ExactOptions{});
    ASSERT_TRUE(r.converged) << r.message;
    EXPECT_EQ(members(r.active) > 0, factor < 1) << "R = " << factor << " x the published sag";
  }
  int touching[2];
  for (int k : {0, 1}) {
    const Grid g = make_grid(64 << k);
    Problem p = make_problem(Scene::rectangle(1, 1).over(uniform(-5e-4)).loaded(uniform(-q)), g, SamplingSpec{SamplingKind::Nodes});
    const ExactResult r = solve_sequenced(p, ExactOptions{});
    ASSERT_TRUE(r.converged) << r.message;
    touching[k] = members(r.active);
    const double centre = r.lambda[g.node(g.nx / 2, g.ny / 2)];
    std::printf("n = %d: %d touching nodes, force density at the centre %.5f (q = %g)\n", g.nx, touching[k], centre, q);
    if (k == 1) {
      EXPECT_NEAR(centre, q, 0.01 * q);
    }
  }
  // Halving h multiplies the nodes of an area by 4 and those of a curve by 2.
  EXPECT_GT(touching[1], 3 * touching[0]);
}

TEST(HardCases, SixteenBumpsGiveSixteenContactRegions) {
  // A heavy load on 4 x 4 bumps (tops at -0.01, valleys at -1): the plate rests on every top and
  // nowhere else. The penalty scheme (3a), a second algorithm, must find the same.
  const Grid g = make_grid(64);
  const Problem p = make_problem(Scene::rectangle(g.whole_lx(), g.whole_ly()).over(bumps(4, -1.0, -0.01)).loaded(uniform(-1000.0)), g, SamplingSpec{SamplingKind::Nodes});
  const ExactResult r = solve_exact(p, ExactOptions{});
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_EQ(contact_regions(g, r.active), 16);
  // sin(4 pi x) and sin(4 pi (1 - x)) differ in the last bit, and K (condition ~ n^4) magnifies that.
  EXPECT_LE(asymmetry(g, r.w), 1e-10 * max_nodal_abs(r.w));
  const double eps = 1e-10, largest = r.lambda.maxCoeff();
  const SweepRow penalty = sweep_row(p, Scheme::Nonlinear, eps, 1e-8, 100, r.w);
  ASSERT_TRUE(penalty.converged) << penalty.message;
  std::printf("(3a) at eps = %g: %.2e from the exact solution; eps max(lambda) = %.2e\n", eps, penalty.error,
              eps * largest);
  // The penalised plate sinks into each top by eps xi, and the plate follows: O(eps max lambda).
  EXPECT_LE(penalty.error, 2 * eps * largest);
}

TEST(HardCases, EveryEpsGivesACertifiedAnswerOrSaysWhyNot) {
  // The paper's problem (n = 16, nodal sampling) at each eps alone, 1e-2 ... 1e-14, both schemes.
  const Problem p = paper_problem(16, SamplingKind::Nodes);
  const ExactResult exact = solve_exact(p, ExactOptions{});
  ASSERT_TRUE(exact.converged);
  const double tol = 1e-8, lambda1 = plate_constant("lambda1");
  // The penalty error is linear in eps: its constant, from a certified run where it dominates.
  const SweepRow mid = sweep_row(p, Scheme::Nonlinear, 1e-8, tol, 100, exact.w);
  ASSERT_TRUE(mid.converged) << mid.message;
  const double slope = mid.error / 1e-8;
  for (Scheme s : {Scheme::Nonlinear, Scheme::Linear})
    for (int e = 2; e <= 14; ++e) {
      const double eps = std::pow(10.0, -e);
      const int cap = 20000;
      const SweepRow row = sweep_row(p, s, eps, tol, cap, exact.w);
      SCOPED_TRACE(std::string(to_string(s)) + " eps = 1e-" + std::to_string(e));
      if (row.converged) {
        // Certified within tol of w_eps, which is within slope * eps of the exact solution.
        EXPECT_LE(row.bound.bound + row.bound.roundoff, tol);
        EXPECT_LE(row.error, tol + 1.5 * slope * eps);
      } else {
        EXPECT_FALSE(row.message.empty());
      }
      if (s == Scheme::Nonlinear) {
        // Certified until the round-off of eps^-1 (w - phi) alone, which grows like 1/eps, exceeds tol.
        if (row.bound.roundoff < 0.1 * tol && row.bound.bound < 0.5 * tol) {
          EXPECT_TRUE(row.converged) << row.message;
        }
        if (row.bound.roundoff > tol) {
          EXPECT_FALSE(row.converged) << "a bound below its own round-off floor certifies nothing";
        }
        if (row.bound.roundoff > 10 * tol) {
          EXPECT_NE(row.message.find("round-off"), std::string::npos) << row.message;
        }
      } else {
        // Theorem 2: no slower than its contraction 1/(1 + eps lambda1) predicts (contact can only
        // make it faster). Below eps ~ 1e-12 it stops after two steps, frozen: the bound catches that.
        const double predicted = predicted_linear_iterations(row.first_step, tol, eps, lambda1);
        if (row.iterations < cap) {
          EXPECT_LE(row.iterations, 2 * predicted);
        }
      }
    }
}
