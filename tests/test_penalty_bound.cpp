// The a posteriori bound that decides whether a penalty run is an answer: it must hold (never below
// the true distance to w_eps), be sharp enough to be useful, and rest on the right Green's function.
#include <gtest/gtest.h>

#include <cstdio>

#include "norms.hpp"
#include "paper_case.hpp"
#include "penalty_bound.hpp"
#include "schemes.hpp"

using namespace plate;

TEST(PenaltyBound, HoldsAndIsWithinAFactorOfTheTrueErrorAlongTheLinearScheme) {
  for (SamplingKind kind : {SamplingKind::Gauss, SamplingKind::Nodes}) {
    const Problem p = paper_problem(8, kind);
    const double eps = 1e-5;  // contraction 1/(1 + eps lambda_1h) ~ 0.987: slow, errors stay visible
    const VectorXd w_eps = solve(p, fixed_eps_options(Scheme::Nonlinear, eps, 1e-14)).w;  // exact per active set
    std::vector<VectorXd> iterates;
    SolveOptions o = fixed_eps_options(Scheme::Linear, eps, 1e-300, 200);  // run all 200 steps
    o.on_iterate = [&](double, int k, const VectorXd& w) {
      if (k == 2 || k == 10 || k == 50 || k == 200) iterates.push_back(w);
    };
    solve(p, o);
    ASSERT_EQ(iterates.size(), 4u);
    Cholesky chol;
    chol.analyze(p.K);
    for (const VectorXd& w : iterates) {
      const double truth = max_nodal_abs(w - w_eps);
      const PenaltyBound b = penalty_error_bound(p, w, eps, chol);
      std::printf("  %s: true error %.3e, bound %.3e (ratio %.1f), round-off floor %.1e\n", to_string(kind), truth,
                  b.bound, b.bound / truth, b.roundoff);
      EXPECT_GE(b.bound, truth);
      EXPECT_LE(b.bound, 100 * truth);
    }
  }
}

TEST(PenaltyBound, GreensFunctionPeaksAtTheCentreAndIsThePointLoadCoefficient) {
  // (K^{-1})_ii is the deflection at node i under a unit point load there: largest at the centre,
  // where Timoshenko & Woinowsky-Krieger give 0.00560 a^2 / D for the clamped square.
  for (auto [nx, lx] : {std::pair{8, 1.0}, {12, 1.5}}) {
    const Grid g = make_grid(nx, lx, 1.0);
    const Problem p = make_problem(Scene::rectangle(g.whole_lx(), g.whole_ly()).over([](double, double) { return -1.0; }).loaded([](double, double) { return 0.0; }), g, SamplingSpec{SamplingKind::Nodes});
    Cholesky chol;
    chol.factorize(p.K);
    const Eigen::MatrixXd inverse = chol.solve_many(Eigen::MatrixXd::Identity(g.unknowns(), g.unknowns()));
    double largest = 0;
    for (int q = 0; q < g.unknowns(); q += 4) largest = std::max(largest, inverse(q, q));
    EXPECT_DOUBLE_EQ(largest, inverse(centre_value_dof(g), centre_value_dof(g))) << "lx = " << lx;
  }
  const Problem square = make_problem(Scene::rectangle(1, 1).over([](double, double) { return -1.0; }).loaded([](double, double) { return 0.0; }), make_grid(64), SamplingSpec{SamplingKind::Nodes});
  Cholesky chol;
  chol.analyze(square.K);
  const PenaltyBound b = penalty_error_bound(square, VectorXd::Zero(square.grid.unknowns()), 1.0, chol);
  const double published_point = plate_constant("point_centre");
  std::printf("  (K^-1)_cc = %.7f at n = 64 (published %.5f)\n", b.green, published_point);
  EXPECT_NEAR(b.green, published_point, published_point * 0.01);
}
