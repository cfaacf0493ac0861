// The claims the table of the document rests on: the eps -> 0 reference is trustworthy (the
// penalty error is linear in eps and the limit satisfies the constraint), and the paper's
// stopping rule stops the linear scheme far from the solution while (3a) gets close.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "eps_limit.hpp"
#include "norms.hpp"
#include "paper_case.hpp"
#include "published.hpp"
#include "schemes.hpp"

using namespace plate;

TEST(EpsLimit, PenaltyErrorIsLinearInEpsAndTheLimitIsFeasible) {
  for (int n : {4, 8})
    for (SamplingKind kind : {SamplingKind::Gauss, SamplingKind::Nodes}) {
      const Problem p = paper_problem(n, kind);
      const EpsLimit L = eps_limit(p);
      const VectorXd gap = p.sampling.S * L.w - p.phi;  // >= 0 at an admissible point
      const double violation = std::max(0.0, -gap.minCoeff());
      std::printf("  n = %d %s: eps-ratio %.6f, estimate %.2e, violation %.2e\n", n, to_string(kind), L.ratio,
                  L.estimate, violation);
      EXPECT_NEAR(L.ratio, 10.0, 0.05);  // w_eps - w = eps z + O(eps^2)
      EXPECT_LT(L.estimate, 1e-9);
      // The limit meets the constraint up to the extrapolation's own error.
      EXPECT_LT(violation, 1e-9);
    }
}

TEST(EpsLimit, DecreasingPenaltyApproachesTheLimitLinearly) {
  // Independent of the extrapolation: the exact w_eps at eps = 1e-6 and 1e-7 are 10 times
  // closer to the limit for each decade.
  const Problem p = paper_problem(8, SamplingKind::Nodes);
  const EpsLimit L = eps_limit(p);
  const auto path = penalised_path(p, 1e-7);
  const double e6 = max_nodal_abs(path[path.size() - 2] - L.w), e7 = max_nodal_abs(path.back() - L.w);
  std::printf("  ||w_eps - w||_C: eps = 1e-6: %.3e, 1e-7: %.3e\n", e6, e7);
  EXPECT_NEAR(e6 / e7, 10.0, 0.1);
}

TEST(PaperTable, TheStoppingRuleLeavesErrorsFarAboveTheTolerance) {
  const auto table = read_paper_table(std::string(PLATE_SOURCE_DIR) + "/reference/paper_table.csv");
  const Problem p = paper_problem(4, SamplingKind::Nodes);
  const EpsLimit L = eps_limit(p);
  for (const auto& row : table) {
    SolveOptions lin, newton;
    lin.tol = newton.tol = row.tolerance;
    newton.scheme = Scheme::Nonlinear;
    const SolveResult a = solve(p, lin), b = solve(p, newton);
    const double ea = max_nodal_abs(a.w - L.w), eb = max_nodal_abs(b.w - L.w);
    std::printf("  OS %.3g: linear %d iterations (paper %d), error %.2e; nonlinear %d, error %.2e\n",
                row.tolerance, a.total_iterations(), row.iterations, ea, b.total_iterations(), eb);
    ASSERT_TRUE(a.stopped && b.converged) << b.message;
    EXPECT_GT(ea, 10 * row.tolerance);  // the paper's rule certifies far less than it seems to
    EXPECT_FALSE(a.converged);          // and the error bound from the residual of (2a) says so
    EXPECT_LT(eb, row.tolerance);       // (3a) solves each level exactly: its error is O(eps)
    EXPECT_LT(eb, 1e-2 * ea);
    // Nodal sampling gives counts of the paper's size (its quantities are "at the nodes").
    EXPECT_GT(a.total_iterations(), row.iterations / 2);
    EXPECT_LT(a.total_iterations(), row.iterations * 2);
  }
}

