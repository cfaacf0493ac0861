// The two schemes solve the same penalised problem (2); the penalty's violation is O(eps);
// the continuation and its failures behave as documented.
#include <gtest/gtest.h>

#include <cstdio>

#include "contact.hpp"
#include "contraction.hpp"
#include "norms.hpp"
#include "paper_case.hpp"
#include "schemes.hpp"

using namespace plate;

namespace {
SolveResult at_eps(const Problem& p, Scheme s, double eps, double tol = 1e-14, int max_iter = 100000) {
  return solve(p, fixed_eps_options(s, eps, tol, max_iter));
}
double violation(const Problem& p, const VectorXd& w) { return (p.phi - p.sampling.S * w).cwiseMax(0.0).maxCoeff(); }
}  // namespace

TEST(Schemes, LinearAndNonlinearReachTheSamePenalisedSolution) {
  for (SamplingKind kind : {SamplingKind::Gauss, SamplingKind::Nodes})
    for (double eps : {1e-3, 1e-4}) {
      const Problem p = paper_problem(8, kind);
      const SolveResult lin = at_eps(p, Scheme::Linear, eps), non = at_eps(p, Scheme::Nonlinear, eps);
      ASSERT_TRUE(lin.stopped && non.stopped);  // tol 1e-14: steps to round-off, below what the bound certifies
      const double diff = max_nodal_abs(lin.w - non.w);
      std::printf("  %s eps = %g: linear %d iterations, nonlinear %d (%d factorisations), max difference %.2e\n",
                  to_string(kind), eps, lin.total_iterations(), non.total_iterations(),
                  non.levels[0].factorizations, diff);
      EXPECT_LT(diff, 1e-12);
      // w_eps solves (2a): its residual vanishes to round-off.
      EXPECT_LT(penalty_residual(p, non.w, eps), 1e-12);
      // The nonlinear scheme stops when the active set repeats: a handful of steps, not hundreds.
      EXPECT_LE(non.total_iterations(), 10);
      EXPECT_LE(non.levels[0].factorizations, non.total_iterations());
    }
}

TEST(Schemes, ConstraintViolationShrinksLikeEps) {
  for (SamplingKind kind : {SamplingKind::Gauss, SamplingKind::Nodes}) {
    const Problem p = paper_problem(8, kind);
    std::vector<double> v;
    // Asymptotically violation = eps max xi with xi -> its (finite, discrete) limit. The regime starts
    // once the penalty is much stiffer than the plate and the active set has settled: on h = 1/8 the
    // ratio is within 1% of 10 from eps = 1e-7 with nodal sampling but only from eps = 1e-8 with Gauss
    // points (more points share the rim). We check from eps = 1e-9 on, for both.
    for (int s = 3; s <= 11; ++s) v.push_back(violation(p, at_eps(p, Scheme::Nonlinear, std::pow(10.0, -s)).w));
    for (size_t k = 1; k < v.size(); ++k) {
      std::printf("  %s: eps 1e-%zu: violation %.3e, ratio to the previous %.4f\n", to_string(kind), k + 3, v[k],
                  v[k - 1] / v[k]);
      if (k + 3 >= 9) {
        EXPECT_NEAR(v[k - 1] / v[k], 10.0, 0.05);
      }
    }
  }
}

TEST(Schemes, StoppedLinearIterateIsWithinTheAPosterioriBound) {
  // Contraction q in the M-norm gives ||w^n - w_eps||_M <= q / (1 - q) ||w^n - w^{n-1}||_M.
  const Problem p = paper_problem(8, SamplingKind::Nodes);
  const double eps = 1e-4, q = sharp_contraction(smallest_eigenpair(p.K, p.M).lambda, eps);
  const VectorXd exact = at_eps(p, Scheme::Nonlinear, eps).w;
  VectorXd previous = VectorXd::Zero(p.grid.unknowns());
  SolveOptions o;
  o.continuation = false;
  o.eps_start = eps;
  o.tol = 1e-300;
  o.max_iter = 60;
  o.on_iterate = [&](double, int n, const VectorXd& w) {
    const double bound = q / (1 - q) * m_norm(p, w - previous), error = m_norm(p, w - exact);
    EXPECT_LE(error, bound * (1 + 1e-9) + 1e-15) << "iteration " << n;
    previous = w;
  };
  solve(p, o);
}

TEST(Schemes, ReachingTheIterationCapIsAReportedFailure) {
  const Problem p = paper_problem(4, SamplingKind::Gauss);
  const SolveResult r = at_eps(p, Scheme::Linear, 1e-5, 1e-12, 3);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.total_iterations(), 3);
  EXPECT_NE(r.message.find("did not converge"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("max-iter"), std::string::npos) << r.message;
}

TEST(Schemes, ContinuationVisitsPowersOfTenAndStopsOnTheLevelRule) {
  const Problem p = paper_problem(4, SamplingKind::Nodes);
  SolveOptions o;
  o.scheme = Scheme::Nonlinear;
  o.tol = 1e-6;
  const SolveResult r = solve(p, o);
  ASSERT_TRUE(r.converged) << r.message;
  for (size_t s = 0; s < r.levels.size(); ++s) EXPECT_EQ(r.levels[s].eps, 0.1 / std::pow(10.0, s));
  EXPECT_LE(r.levels.back().level_change, o.tol);
  for (size_t s = 1; s + 1 < r.levels.size(); ++s) EXPECT_GT(r.levels[s].level_change, o.tol);

  o.eps_min = 1e-3;  // too early for tol: a failure, said so
  const SolveResult f = solve(p, o);
  EXPECT_FALSE(f.converged);
  EXPECT_NE(f.message.find("eps continuation did not converge"), std::string::npos) << f.message;
}
