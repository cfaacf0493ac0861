// The exact-constraint solver: it meets its own certificate, agrees with the penalty schemes as
// eps -> 0 at the rate the penalty predicts, keeps the paper's invariances, and its globalisation
// ends a primal-dual iteration that cycles.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "active_set.hpp"
#include "eps_limit.hpp"
#include "fields.hpp"
#include "norms.hpp"
#include "paper_case.hpp"
#include "scenes.hpp"
#include "schemes.hpp"

using namespace plate;

namespace {
const Field kNoLoad = [](double, double) { return 0.0; };

ExactResult certified(const Problem& p, ExactOptions o = {}) {
  ExactResult r = solve_exact(p, o);
  EXPECT_TRUE(r.converged) << r.message;
  EXPECT_LE(r.certificate.worst(), o.tol);
  return r;
}

}  // namespace

TEST(ExactSolver, MeetsItsCertificateOnEveryCase) {
  struct Case {
    const char* name;
    Field obstacle, load;
  };
  const std::vector<Case> cases = {
      {"paper's cylinder", paper_scene().obstacle, kNoLoad},
      {"flat support under a downward load", [](double, double) { return -1e-4; }, [](double, double) { return -1.0; }},
      {"no contact: obstacle far below", [](double, double) { return -1.0; }, [](double, double) { return -1.0; }},
      {"oscillating obstacle", [](double x, double y) { return 0.01 * std::sin(6 * M_PI * x) * std::sin(6 * M_PI * y) - 0.002; },
       kNoLoad},
  };
  for (const auto& c : cases)
    for (int n : {4, 8, 16, 32}) {
      SCOPED_TRACE(std::string(c.name) + ", n = " + std::to_string(n));
      const Problem p = make_problem(Scene::rectangle(make_grid(n).whole_lx(), make_grid(n).whole_ly()).over(c.obstacle).loaded(c.load), make_grid(n), SamplingSpec{SamplingKind::Nodes});
      const ExactResult r = certified(p);
      for (int q = 0; q < p.phi.size(); ++q) {  // the certificate's claims, checked one by one
        EXPECT_GE(r.w[4 * q], p.phi[q] - 1e-12);
        EXPECT_GE(r.lambda[q], 0.0);
        if (r.lambda[q] > 0) {
          EXPECT_EQ(r.w[4 * q], p.phi[q]);
        }
      }
    }
}

// The certificate judges an answer relative to its own size, so it must read the same at any scale
// and still fail a wrong answer there. The paper's problem on edge sampling, certified, then scaled
// by s: at s = 1e-200 and 1e200 the scaled answer keeps its certificate; a multiplier put on a row
// that does not touch fails complementarity (the raw product underflowed to 0, and overflowed to a
// NaN that std::max passed over); w = 0 fails under an obstacle of height 1e-320 (it passed against
// a floor of 1e-300); and a NaN in w or lambda fails.
TEST(Certificate, FailsAWrongAnswerAtAnyScale) {
  const Problem p = make_problem(paper_scene(), make_grid(16), SamplingSpec{SamplingKind::Edge});
  const ExactResult r = certified(p);
  const VectorXd gap = p.sampling.S * r.w - p.phi;
  int free_row = -1;  // the row furthest from touching
  for (int q = 0; q < gap.size(); ++q)
    if (std::isfinite(gap[q]) && r.lambda[q] == 0 && (free_row < 0 || gap[q] > gap[free_row])) free_row = q;
  ASSERT_GE(free_row, 0);
  ASSERT_GT(gap[free_row], 1e-3 * max_nodal_abs(r.w));
  for (double s : {1e-200, 1.0, 1e200}) {
    SCOPED_TRACE("scale " + std::to_string(std::log10(s)));
    Problem q = p;
    for (int k = 0; k < q.phi.size(); ++k) q.phi[k] *= s;  // -inf stays -inf
    q.F *= s;
    const VectorXd w = s * r.w, lambda = s * r.lambda;
    EXPECT_LE(certify(q, w, lambda).worst(), 1e-12);
    VectorXd pushed = lambda;
    pushed[free_row] = lambda.cwiseAbs().maxCoeff();
    EXPECT_GT(certify(q, w, pushed).complementarity, 1e-3);
  }
  Problem tiny = p;
  for (int k = 0; k < tiny.phi.size(); ++k) tiny.phi[k] *= 1e-320 / 0.0625;
  tiny.F *= 0;
  const VectorXd zero_w = VectorXd::Zero(r.w.size()), zero_lambda = VectorXd::Zero(r.lambda.size());
  EXPECT_GT(certify(tiny, zero_w, zero_lambda).violation, 0.5);
  for (bool in_w : {true, false}) {
    VectorXd w = r.w, lambda = r.lambda;
    (in_w ? w[7] : lambda[free_row]) = NAN;
    EXPECT_FALSE(certify(p, w, lambda).worst() <= 1e-10) << (in_w ? "NaN in w" : "NaN in lambda");
  }
}

TEST(ExactSolver, PenaltySolutionsApproachItLinearlyInEps) {
  const Problem p = paper_problem(8, SamplingKind::Nodes);
  const ExactResult exact = certified(p);
  const std::vector<VectorXd> path = penalised_path(p, 1e-8);  // eps = 1e-1 ... 1e-8
  const double d6 = max_nodal_abs(path[5] - exact.w), d7 = max_nodal_abs(path[6] - exact.w),
               d8 = max_nodal_abs(path[7] - exact.w);
  // w_eps - w = eps z + O(eps^2): each decade of eps divides the difference by ten, and the
  // departure from ten is the eps^2 term, itself ten times smaller a decade later.
  std::printf("penalty - exact: %.3e %.3e %.3e, ratios %.5f %.5f\n", d6, d7, d8, d6 / d7, d7 / d8);
  EXPECT_NEAR(d6 / d7, 10.0, 0.2);
  EXPECT_NEAR(d7 / d8, 10.0, 0.02);
  EXPECT_LT(std::abs(d7 / d8 - 10.0), std::abs(d6 / d7 - 10.0) / 5);
  // The penalty pushes the plate below the obstacle by about eps * xi: it never lies above the exact one there.
  EXPECT_GT(d8, 0.0);
  // Richardson extrapolation of the penalised solutions lands on the exact one.
  const EpsLimit limit = eps_limit(p);
  EXPECT_LE(max_nodal_abs(limit.w - exact.w), 1e-12);
}

TEST(ExactSolver, IsPositivelyHomogeneousInRAndSymmetric) {
  const ExactResult r1 = certified(paper_problem(16, SamplingKind::Nodes));
  const ExactResult r2 = certified(paper_problem(16, SamplingKind::Nodes, 2 * paper_scene().cylinder->height));
  EXPECT_LE(max_nodal_abs(r2.w - 2 * r1.w), 1e-14 * max_nodal_abs(r2.w));
  EXPECT_EQ(r1.active, r2.active);
  EXPECT_LE(asymmetry(make_grid(16), r1.w), 1e-13 * max_nodal_abs(r1.w));
}

TEST(ExactSolver, GridSequencingChangesTheWorkNotTheAnswer) {
  const Grid g = make_grid(64);
  ExactOptions cold;
  cold.nested = false;
  Problem p = make_problem(paper_scene(), g, SamplingSpec{SamplingKind::Nodes});
  const ExactResult a = solve_sequenced(p, cold), b = solve_sequenced(p, ExactOptions{});
  ASSERT_TRUE(a.converged && b.converged) << a.message << b.message;
  EXPECT_EQ(a.active, b.active);
  // Different factorisations of a matrix with condition number ~ h^-4: agreement to round-off times that.
  EXPECT_LE(max_nodal_abs(a.w - b.w), 1e-10 * max_nodal_abs(a.w));
  EXPECT_EQ(b.levels.size(), 4u);  // 8, 16, 32, 64
  EXPECT_LT(b.levels.back().pdas_iterations, a.levels.back().pdas_iterations);
}

TEST(FixedSet, CorrectionFromAnotherSetsFactorEqualsAFreshFactorisation) {
  const Problem p = paper_problem(16, SamplingKind::Nodes);
  const int nodes = static_cast<int>(p.phi.size());
  VectorXd phi = VectorXd::Zero(nodes);
  for (int q = 0; q < nodes; ++q) phi[q] = 0.01 * std::sin(q);
  NodeSet a(nodes, 0), b(nodes, 0);
  for (int q = 0; q < nodes; q += 7) a[q] = 1;
  b = a;
  for (int q = 0; q < nodes; q += 11) b[q] = !b[q];  // some held nodes released, some free ones held
  FixedSetSolver reuse(p.K, p.F, phi, 64), fresh(p.K, p.F, phi, 0);
  reuse.solve(a);
  const VectorXd w_reuse = reuse.solve(b), w_fresh = fresh.solve(b);
  EXPECT_EQ(reuse.factorizations(), 1);
  EXPECT_GT(reuse.correction_columns(), 0);
  EXPECT_LE((w_reuse - w_fresh).lpNorm<Eigen::Infinity>(), 1e-12 * w_fresh.lpNorm<Eigen::Infinity>());
  for (int q = 0; q < nodes; ++q)
    if (b[q]) {
      EXPECT_EQ(w_reuse[4 * q], phi[q]);
    }
}

TEST(ExactSolver, PlainPrimalDualIterationCyclesOnANonMMatrix) {
  const Problem p = cycling_problem();
  ASSERT_GT(Eigen::MatrixXd(p.K).selfadjointView<Eigen::Lower>().eigenvalues().minCoeff(), 0.0);
  ExactOptions plain;
  plain.globalise = false;
  const ExactResult r = solve_exact(p, plain);
  EXPECT_FALSE(r.converged);
  EXPECT_TRUE(r.cycled);
  EXPECT_NE(r.message.find("cycled"), std::string::npos) << r.message;
}

TEST(ExactSolver, GlobalisationEndsTheCycleWithFallingEnergy) {
  const Problem p = cycling_problem();
  const ExactResult r = solve_exact(p, ExactOptions{});
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_TRUE(r.cycled);
  EXPECT_GT(r.levels.back().primal_steps, 0);
  EXPECT_LE(r.certificate.worst(), 1e-10);
  ASSERT_GE(r.fallback_energies.size(), 1u);
  for (size_t k = 1; k < r.fallback_energies.size(); ++k) EXPECT_LT(r.fallback_energies[k], r.fallback_energies[k - 1]);
  // The answer is the LCP's: compare with brute force over the 8 active sets.
  double best = INFINITY;
  for (int mask = 0; mask < 8; ++mask) {
    NodeSet held(p.phi.size(), 0);
    for (int a = 0; a < 3; ++a) held[a] = (mask >> a) & 1;
    FixedSetSolver fs(p.K, p.F, p.phi, 0);
    const VectorXd w = fs.solve(held);
    bool feasible = true;
    for (int a = 0; a < 3; ++a) feasible = feasible && w[4 * a] >= -1e-14;
    if (feasible) best = std::min(best, energy(p, w));
  }
  EXPECT_NEAR(energy(p, r.w), best, 1e-14);
}
