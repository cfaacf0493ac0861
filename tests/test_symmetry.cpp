// Exact invariances of the paper's problem: positive homogeneity in R (f = 0) and the eight
// symmetries of the square. Both hold for the penalised and discrete problems too.
#include <gtest/gtest.h>

#include "norms.hpp"
#include "paper_case.hpp"
#include "schemes.hpp"

using namespace plate;

namespace {
VectorXd penalised(const Problem& p, double eps = 1e-6) {
  // tol below what the error bound can certify: we want the steps to stop changing w at all.
  const SolveResult r = solve(p, fixed_eps_options(Scheme::Nonlinear, eps, 1e-15));
  EXPECT_TRUE(r.stopped) << r.message;
  return r.w;
}
}  // namespace

TEST(Invariance, DeflectionIsPositivelyHomogeneousInR) {
  for (SamplingKind kind : {SamplingKind::Gauss, SamplingKind::Nodes}) {
    const VectorXd w1 = penalised(paper_problem(8, kind));
    const VectorXd w2 = penalised(paper_problem(8, kind, 2 * paper_scene().cylinder->height));
    const VectorXd w3 = penalised(paper_problem(8, kind, 3 * paper_scene().cylinder->height));
    // Doubling is exact in binary floating point, so the whole computation doubles exactly.
    EXPECT_LE(max_nodal_abs(w2 - 2 * w1), 1e-15 * max_nodal_abs(w2)) << to_string(kind);
    EXPECT_LE(max_nodal_abs(w3 - 3 * w1), 1e-13 * max_nodal_abs(w3)) << to_string(kind);
  }
}

TEST(Invariance, DeflectionHasTheEightSymmetriesOfTheSquare) {
  for (SamplingKind kind : {SamplingKind::Gauss, SamplingKind::Nodes}) {
    const Problem p = paper_problem(8, kind);
    const VectorXd w = penalised(p);
    EXPECT_LE(asymmetry(p.grid, w), 1e-13 * max_nodal_abs(w)) << to_string(kind);
  }
  // The check sees asymmetry when there is some: a load f = x tilts the plate.
  const Grid g = make_grid(8);
  const Problem tilted = make_problem(Scene::rectangle(g.whole_lx(), g.whole_ly()).over(paper_scene().obstacle).loaded([](double x, double) { return 10 * x; }), g, SamplingSpec{SamplingKind::Nodes});
  const VectorXd w = penalised(tilted);
  EXPECT_GT(asymmetry(g, w), 1e-6 * max_nodal_abs(w));
}
