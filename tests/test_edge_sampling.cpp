// Edge sampling and the exact solver for general constraint rows: the dual method against brute
// force and against the nodal solver, the penalty schemes against it as eps -> 0, the paper's
// invariances, the certificate where rows are dependent, the line load, and the h -> 0 order.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "active_set.hpp"
#include "contact.hpp"
#include "crosscheck.hpp"
#include "dual_active_set.hpp"
#include "dual_qp.hpp"
#include "fields.hpp"
#include "line_force.hpp"
#include "norms.hpp"
#include "paper_case.hpp"
#include "scenes.hpp"
#include "schemes.hpp"

using namespace plate;

namespace {
const Field kNoLoad = [](double, double) { return 0.0; };

// The paper's problem (obstacle height R; NaN: the paper's), sampled on the obstacle's rim.
Problem edge_problem(int n, double R = NAN, SamplingKind kind = SamplingKind::Edge) {
  return make_problem(std::isnan(R) ? paper_scene() : paper_scene(R), make_grid(n), SamplingSpec{kind});
}

ExactResult certified(Problem& p) {
  ExactResult r = solve_sequenced(p, ExactOptions{});
  EXPECT_TRUE(r.converged) << r.message;
  EXPECT_LE(r.certificate.worst(), 1e-10);
  return r;
}
ExactResult certified(Problem&& p) { return certified(p); }
}  // namespace

TEST(DualQP, MatchesBruteForceOverEveryActiveSetWithDependentRows) {
  // min 1/2 w^T K w - F^T w, S w >= phi with K random SPD (4 x 4) and 6 rows, two of them repeated:
  // G = S K^-1 S^T is singular. Brute force: the minimiser over every set of rows held as equalities
  // (least squares on the held rows), kept if feasible; the lowest energy is the answer.
  std::mt19937 rng(7);
  std::normal_distribution<double> N01;
  for (int trial = 0; trial < 40; ++trial) {
    Eigen::MatrixXd B(4, 4), S(6, 4);
    for (int i = 0; i < 16; ++i) B.data()[i] = N01(rng);
    const Eigen::MatrixXd K = B * B.transpose() + 0.5 * Eigen::MatrixXd::Identity(4, 4);
    for (int i = 0; i < 24; ++i) S.data()[i] = N01(rng);
    S.row(4) = S.row(0);
    S.row(5) = 2 * S.row(1);
    Eigen::VectorXd F(4), phi(6);
    for (int i = 0; i < 4; ++i) F[i] = N01(rng);
    for (int i = 0; i < 4; ++i) phi[i] = N01(rng);
    phi[4] = phi[0];
    phi[5] = 2 * phi[1];
    const Eigen::LLT<Eigen::MatrixXd> llt(K);
    const Eigen::VectorXd w0 = llt.solve(F);
    const Eigen::MatrixXd G = S * llt.solve(S.transpose());
    const DualQPResult d = solve_dual_qp(G, phi - S * w0, 1e-13, 1000);
    ASSERT_TRUE(d.ok) << d.message;
    const Eigen::VectorXd w = w0 + llt.solve(S.transpose() * d.mu);
    double best = INFINITY;
    Eigen::VectorXd w_best;
    for (int mask = 0; mask < 64; ++mask) {
      std::vector<int> held;
      for (int i = 0; i < 6; ++i)
        if (mask >> i & 1) held.push_back(i);
      Eigen::MatrixXd SA(held.size(), 4);
      Eigen::VectorXd pA(held.size());
      for (size_t k = 0; k < held.size(); ++k) SA.row(k) = S.row(held[k]), pA[k] = phi[held[k]];
      // KKT by the null space of SA: w = w_p + Z y, minimise over y.
      Eigen::VectorXd v = w0;
      if (!held.empty()) {
        const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(SA);
        if ((SA * cod.solve(pA) - pA).norm() > 1e-9) continue;  // inconsistent equalities
        const Eigen::VectorXd wp = cod.solve(pA);
        const Eigen::FullPivLU<Eigen::MatrixXd> lu(SA);
        const Eigen::MatrixXd Z = lu.kernel();
        if (lu.rank() == 4 || Z.cols() == 0) v = wp;
        else v = wp + Z * (Z.transpose() * K * Z).ldlt().solve(Z.transpose() * (F - K * wp));
      }
      if (((S * v - phi).array() < -1e-9).any()) continue;
      const double e = 0.5 * v.dot(K * v) - F.dot(v);
      if (e < best) best = e, w_best = v;
    }
    ASSERT_TRUE(std::isfinite(best));
    EXPECT_LE((w - w_best).norm(), 1e-9 * (1 + w_best.norm())) << "trial " << trial;
    EXPECT_GE(d.mu.minCoeff(), 0.0);
    const Eigen::VectorXd gap = S * w - phi;
    EXPECT_GE(gap.minCoeff(), -1e-10);
    for (int i = 0; i < 6; ++i) EXPECT_LE(std::abs(d.mu[i] * gap[i]), 1e-10 * (1 + d.mu.norm()));
  }
}

TEST(EdgeSampling, CircleHasTheSquaresSymmetryAndItsLength) {
  const EdgePoints e = edge_points(paper_scene().edge, 1.0 / 64);
  EXPECT_EQ(e.size() % 8, 0);
  EXPECT_NEAR(e.size(), 2 * M_PI * 0.25 * 64, 0.5 * 2 * M_PI * 0.25 * 64);  // about 2 pi r / h
  double length = 0;
  for (double w : e.weight) length += w;
  EXPECT_NEAR(length, 2 * M_PI * 0.25, 1e-14);
  // Each of the eight symmetries of the square about (0.5, 0.5) maps a point onto another one.
  for (int k = 0; k < e.size(); ++k) {
    const double x = e.x[k] - 0.5, y = e.y[k] - 0.5;
    for (auto [u, v] : {std::pair{y, x}, {-x, y}, {x, -y}, {-y, -x}, {-y, x}, {y, -x}, {-x, -y}}) {
      double nearest = INFINITY;
      for (int j = 0; j < e.size(); ++j) nearest = std::min(nearest, std::hypot(e.x[j] - 0.5 - u, e.y[j] - 0.5 - v));
      EXPECT_LE(nearest, 1e-14);
    }
  }
}

TEST(EdgeSampling, PolygonWeightsSumToItsPerimeter) {
  const EdgeCurve square = parse_edge("polygon:0.3,0.3;0.7,0.3;0.7,0.7;0.3,0.7");
  const EdgePoints e = edge_points(square, 0.03);
  double length = 0;
  for (double w : e.weight) length += w;
  EXPECT_NEAR(length, 1.6, 1e-14);
  EXPECT_NEAR(e.length, 1.6, 1e-14);
  EXPECT_NEAR(distance_to_edge(square, 0.5, 0.5), 0.2, 1e-15);
}

TEST(EdgeSampling, DualSolverAgreesWithTheNodalSolverOnNodes) {
  // Two different algorithms on the same constraints (bounds on nodal values): primal-dual active
  // sets with a bordered correction, and the dual method on G = S K^-1 S^T.
  for (int n : {8, 16}) {
    const Problem p = paper_problem(n, SamplingKind::Nodes);
    const ExactResult a = solve_exact(p, ExactOptions{});
    const ExactResult b = solve_exact_rows(p, ExactOptions{}, {});
    ASSERT_TRUE(a.converged && b.converged) << a.message << b.message;
    EXPECT_LE(max_nodal_abs(a.w - b.w), 1e-12 * max_nodal_abs(a.w)) << "n = " << n;
    EXPECT_LE((a.lambda - b.lambda).lpNorm<Eigen::Infinity>(), 1e-9 * a.lambda.lpNorm<Eigen::Infinity>());
  }
}

TEST(EdgeSampling, PenaltySchemeApproachesTheExactAnswerLinearlyInEps) {
  Problem p = edge_problem(16);
  const ExactResult exact = certified(p);
  std::vector<double> d;
  for (double eps : {1e-6, 1e-7, 1e-8}) {
    const SolveResult r = solve(p, fixed_eps_options(Scheme::Nonlinear, eps, 1e-14, 200));
    d.push_back(max_nodal_abs(r.w - exact.w));
  }
  std::printf("(3a) - exact with edge sampling: %.3e %.3e %.3e\n", d[0], d[1], d[2]);
  EXPECT_NEAR(d[0] / d[1], 10.0, 0.5);
  EXPECT_NEAR(d[1] / d[2], 10.0, 0.1);
}

TEST(EdgeSampling, SymmetricUnderTheSquareAndHomogeneousInR) {
  const ExactResult r1 = certified(edge_problem(32)), r2 = certified(edge_problem(32, 2 * paper_scene().cylinder->height));
  EXPECT_LE(max_nodal_abs(r2.w - 2 * r1.w), 1e-13 * max_nodal_abs(r2.w));
  EXPECT_LE((r2.lambda - 2 * r1.lambda).lpNorm<Eigen::Infinity>(), 1e-11 * r2.lambda.lpNorm<Eigen::Infinity>());
  EXPECT_LE(asymmetry(make_grid(32), r1.w), 1e-13 * max_nodal_abs(r1.w));
}

TEST(EdgeSampling, LineLoadIsPositiveAllRoundWithTheSquaresSymmetry) {
  Problem p = edge_problem(64);
  const ExactResult r = certified(p);
  const LineForce f = line_force(p, r.lambda);
  const int M = static_cast<int>(f.q.size());
  ASSERT_EQ(M % 4, 0);
  EXPECT_GT(f.min, 0.0);
  for (int k = 0; k < M; ++k) {  // theta -> -theta, pi/2 - theta, theta + pi/2
    EXPECT_NEAR(f.q[k], f.q[(M - k) % M], 1e-9 * f.max);
    EXPECT_NEAR(f.q[k], f.q[(M / 4 - k + M) % M], 1e-9 * f.max);
    EXPECT_NEAR(f.q[k], f.q[(k + M / 4) % M], 1e-9 * f.max);
  }
  // With f = 0 every bit of the obstacle's push is on the rim: the line load carries it all.
  EXPECT_NEAR(f.total, total_contact_force(p, r.lambda), 1e-12 * f.total);
  EXPECT_NEAR(f.mean, f.fourier[0], 1e-12 * f.mean);  // equal arcs: the mean is the constant term
}

// Nodal sampling does not sample the rim; its force, binned by angle, must still carry the whole
// push, as a force per unit length of the circle, and keep the square's symmetries.
TEST(EdgeSampling, BinnedLineLoadOfNodalSamplingKeepsTheForceAndTheSymmetry) {
  Problem p = paper_problem(64, SamplingKind::Nodes);
  const ExactResult r = certified(p);
  const int bins = kRimBins;
  const LineForce f = binned_line_force(p, r.lambda, paper_scene().edge, bins);
  ASSERT_EQ(static_cast<int>(f.q.size()), bins);
  EXPECT_NEAR(f.total, total_contact_force(p, r.lambda), 1e-12 * f.total);
  for (int k = 0; k < bins; ++k) {
    EXPECT_NEAR(f.q[k], f.q[(bins - k) % bins], 1e-9 * f.max) << "bin " << k;
    EXPECT_NEAR(f.q[k], f.q[(k + bins / 4) % bins], 1e-9 * f.max) << "bin " << k;
  }
  EXPECT_NEAR(f.mean * 2 * M_PI * paper_scene().cylinder->radius, f.total, 1e-12 * f.total);  // a force per unit length
  EXPECT_THROW(binned_line_force(p, r.lambda, paper_scene().edge, 12), std::invalid_argument);
}

TEST(EdgeSampling, CertificateHoldsWhereTouchingRowsAreDependent) {
  // A flat support under a downward load with Gauss sampling: the plate lies on an area. On n = 6
  // more Gauss points touch than can be held independently (the rest depend on the held ones), so
  // the multipliers are not unique; the solver holds an independent set and gives the others none.
  for (const auto& [n, height] : {std::pair{6, -2e-4}, {16, -1e-4}}) {
    const Problem p = make_problem(Scene::rectangle(make_grid(n).whole_lx(), make_grid(n).whole_ly()).over(uniform(height)).loaded(uniform(-1)), make_grid(n), SamplingSpec{SamplingKind::Gauss});
    const ExactResult r = solve_exact(p, ExactOptions{});
    ASSERT_TRUE(r.converged) << r.message;
    EXPECT_LE(r.certificate.worst(), 1e-10);
    const VectorXd gap = p.sampling.S * r.w - p.phi;
    int touching = 0;
    for (int q = 0; q < gap.size(); ++q) touching += gap[q] <= 1e-10 * std::abs(height);
    std::printf("flat support, Gauss sampling, n = %d: %d points touch, %d hold, %d dependent rows met\n", n, touching,
                members(r.active), r.levels.back().dependent_rows);
    if (n != 6) continue;
    EXPECT_GT(touching, members(r.active));
    // The penalty scheme on the same samples approaches it linearly in eps, once eps is small enough
    // that its own contact set is the exact one (above that it touches more points: 48 at 1e-8).
    std::vector<double> d;
    for (double eps : {1e-9, 1e-10})
      d.push_back(max_nodal_abs(solve(p, fixed_eps_options(Scheme::Nonlinear, eps, 1e-15, 200)).w - r.w));
    std::printf("  (3a) - exact: %.3e %.3e\n", d[0], d[1]);
    EXPECT_NEAR(d[0] / d[1], 10.0, 0.5);
  }
}

