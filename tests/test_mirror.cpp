// Symmetry as a model choice (mirror.hpp): a scene with mirror lines is solved on the half or
// quarter of the plate they leave, and the answer, unfolded, is the whole plate's discrete answer.
// Each test solves both ways and compares; the whole plate is the independent side.
#include <gtest/gtest.h>

#include <cmath>

#include "active_set.hpp"
#include "contact.hpp"
#include "fields.hpp"
#include "line_force.hpp"
#include "norms.hpp"
#include "paper_case.hpp"
#include "penalty_bound.hpp"
#include "problem.hpp"

using namespace plate;

namespace {
const Field kNoLoad = [](double, double) { return 0.0; };

struct Both {
  SceneSolution whole, part;
};

// The scene solved on the whole plate and on the part its mirrors leave; both certified.
Both solve_both(const Scene& s, int n, const SamplingSpec& spec) {
  Both b{solve_exact_scene(s, n, spec, ExactOptions{}, false), solve_exact_scene(s, n, spec, ExactOptions{}, true)};
  EXPECT_TRUE(b.whole.result.converged) << b.whole.result.message;
  EXPECT_TRUE(b.part.result.converged) << b.part.result.message;
  EXPECT_FALSE(b.whole.mirrors.any());
  EXPECT_TRUE(b.part.mirrors.any());
  return b;
}

// The part's force densities in the order of the whole plate's samples, matched by position: rows
// that follow the contact are appended in the order a solve finds them, which differs between the two.
VectorXd in_whole_order(const Both& b) {
  const Sampling &s1 = b.whole.whole().sampling, &s2 = b.part.whole().sampling;
  VectorXd l(s1.size());
  for (int i = 0; i < s1.size(); ++i) {
    int found = -1;
    for (int k = 0; k < s2.size() && found < 0; ++k)
      if (std::abs(s1.x[i] - s2.x[k]) <= 1e-9 && std::abs(s1.y[i] - s2.y[k]) <= 1e-9) found = k;
    EXPECT_GE(found, 0) << "no sample of the part at (" << s1.x[i] << ", " << s1.y[i] << ")";
    l[i] = found >= 0 ? b.part.result.lambda[found] : NAN;
  }
  return l;
}

// The largest differences of w, the force densities and the total force, each relative to its size.
// `tol_force` for the forces: rows that follow the contact add points an eighth of a point spacing
// apart where the plate dips, nearly dependent rows whose multipliers the answer w fixes only to the
// conditioning of their Gram matrix (their sum too: the constant is not a clamped plate's).
void expect_same(const Both& b, double tol, double tol_force) {
  const VectorXd &w1 = b.whole.result.w, &w2 = b.part.result.w, &l1 = b.whole.result.lambda;
  ASSERT_EQ(w1.size(), w2.size());
  ASSERT_EQ(l1.size(), b.part.result.lambda.size());
  const VectorXd l2 = in_whole_order(b);
  EXPECT_LE((w1 - w2).lpNorm<Eigen::Infinity>(), tol * w1.lpNorm<Eigen::Infinity>());
  EXPECT_LE((l1 - l2).lpNorm<Eigen::Infinity>(), tol_force * l1.lpNorm<Eigen::Infinity>());
  const double f1 = total_contact_force(b.whole.whole(), l1), f2 = total_contact_force(b.part.whole(), b.part.result.lambda);
  EXPECT_NEAR(f1, f2, tol_force * std::abs(f1));
}
}  // namespace

// The paper's scene has both mirror lines: a quarter, the same answer to the refinement's precision,
// for the default edge rows, point rows and Gauss points.
TEST(Mirror, QuarterAndWholePlateGiveOneAnswerOnThePapersScene) {
  for (const SamplingSpec& spec : {SamplingSpec{SamplingKind::Edge}, SamplingSpec{SamplingKind::Edge, EdgeRows::points()},
                                   SamplingSpec{SamplingKind::Gauss}}) {
    const Both b = solve_both(paper_scene(), 64, spec);
    EXPECT_TRUE(b.part.mirrors.x && b.part.mirrors.y) << describe(b.part.mirrors);
    EXPECT_EQ(b.part.solved.grid.unknowns(), 4 * 32 * 32);
    expect_same(b, 1e-10, 1e-10);
    // Whole-plate quantities: the line load all round, by the square's symmetry.
    if (spec.kind == SamplingKind::Edge) {
      const LineForce q1 = line_force(b.whole.whole(), b.whole.result.lambda), q2 = line_force(b.part.whole(), b.part.result.lambda);
      ASSERT_EQ(q1.q.size(), q2.q.size());
      for (size_t k = 0; k < q1.q.size(); ++k) EXPECT_NEAR(q1.q[k], q2.q[k], 1e-9 * q1.max);
    }
  }
}

// A rectangle with a centred cylinder: the two mirrors of a rectangle, not the square's eight.
TEST(Mirror, RectangleWithACentredCylinderIsSolvedOnAQuarter) {
  const Both b = solve_both(Scene::rectangle(1.5, 1.0).over(Cylinder{0.75, 0.5, 0.3, 0.05}), 48, SamplingSpec{SamplingKind::Edge});
  EXPECT_TRUE(b.part.mirrors.x && b.part.mirrors.y);
  // The plate lifts off part of the rim here: rows laid out for the contact (D28), the same layout on
  // the quarter and on the whole plate.
  EXPECT_FALSE(b.part.whole().sampling.rim.periodic);
  EXPECT_EQ(b.part.whole().sampling.size(), b.whole.whole().sampling.size());
  expect_same(b, 1e-10, 1e-8);
}

// An expression obstacle and load, symmetric in both lines, with nodal sampling (the primal-dual
// solver, not refined: agreement to its round-off on this grid) and Gauss points.
TEST(Mirror, SymmetricExpressionObstacleIsSolvedOnAQuarter) {
  const Scene scene = Scene::rectangle(1, 1).over("0.02 - 2*((x-0.5)^2 + (y-0.5)^2)").loaded("-1 - x*(1-x)");
  for (SamplingKind kind : {SamplingKind::Nodes, SamplingKind::Gauss}) {
    const Both b = solve_both(scene, 16, SamplingSpec{kind});
    EXPECT_TRUE(b.part.mirrors.x && b.part.mirrors.y) << to_string(kind);
    expect_same(b, 1e-11, 1e-11);
  }
}

// A cylinder moved along x keeps the mirror y = 1/2 only: a half. Moved off both lines: the whole plate.
TEST(Mirror, APartialSymmetryGivesAHalfAndNoneTheWholePlate) {
  const Both b = solve_both(Scene::rectangle(1, 1).over(Cylinder{0.4, 0.5, 0.25, 0.0625}), 32, SamplingSpec{SamplingKind::Edge});
  EXPECT_FALSE(b.part.mirrors.x);
  EXPECT_TRUE(b.part.mirrors.y);
  EXPECT_EQ(b.part.solved.grid.unknowns(), 4 * 31 * 16);
  expect_same(b, 1e-10, 1e-10);
  const SceneSolution off = solve_exact_scene(Scene::rectangle(1, 1).over(Cylinder{0.4, 0.55, 0.25, 0.0625}), 32, SamplingSpec{SamplingKind::Edge},
                                              ExactOptions{});
  EXPECT_FALSE(off.mirrors.any());
  EXPECT_FALSE(off.unfolded.has_value());
}

// What breaks a mirror: an odd number of cells (the line is not a grid line), a load that is not
// symmetric, an obstacle that differs from its image by more than round-off.
TEST(Mirror, MirrorsAreFoundOnlyWhereTheSceneHasThem) {
  const Scene s = paper_scene();
  const SamplingSpec edge{SamplingKind::Edge};
  EXPECT_FALSE(find_mirrors(s, make_grid(15), edge).any());
  const Mirrors tilted = find_mirrors(s.loaded("x"), make_grid(16), edge);
  EXPECT_FALSE(tilted.x);
  EXPECT_TRUE(tilted.y);
  const Field bumpy = [](double x, double y) { return 0.01 - (x - 0.5) * (x - 0.5) - (y - 0.5) * (y - 0.5) + 1e-9 * x; };
  EXPECT_FALSE(find_mirrors(Scene::rectangle(1, 1).over(bumpy).loaded(kNoLoad), make_grid(16), SamplingSpec{SamplingKind::Nodes}).x);
  const Field rounded = [](double x, double y) { return 0.01 - (x - 0.5) * (x - 0.5) - (y - 0.5) * (y - 0.5) + 1e-16 * x; };
  EXPECT_TRUE(find_mirrors(Scene::rectangle(1, 1).over(rounded).loaded(kNoLoad), make_grid(16), SamplingSpec{SamplingKind::Nodes}).x);
}

// A point of the whole plate is evaluated on the part by reflection, slopes across the line
// changing sign: the unfolded plate and the part agree everywhere.
TEST(Mirror, EvaluationBeyondTheMirrorLineReflects) {
  const SceneSolution x = solve_exact_scene(paper_scene(), 32, SamplingSpec{SamplingKind::Edge}, ExactOptions{});
  ASSERT_TRUE(x.mirrors.x && x.mirrors.y);
  for (const auto& [px, py] : {std::pair{0.7, 0.3}, {0.2, 0.9}, {0.81, 0.77}, {0.5, 0.6}}) {
    const PointValues a = evaluate(x.whole().grid, x.result.w, px, py), b = evaluate(x.solved.grid, x.part_w, px, py);
    for (auto [u, v] : {std::pair{a.w, b.w}, {a.wx, b.wx}, {a.wy, b.wy}, {a.wxx, b.wxx}, {a.wxy, b.wxy}, {a.wyy, b.wyy}})
      EXPECT_NEAR(u, v, 1e-12 * (1 + std::abs(u))) << px << ", " << py;
  }
}

// The penalty schemes' error bound (D26) on a quarter is the whole plate's: the same discrete
// problem, so the same bound on the same (symmetric) iterate. Its two factors scale apart, the
// Green's function at the centre by four and the residual's norm by one half, so a bound read at the
// wrong node of the quarter, or with the wrong weights, shows here.
TEST(Mirror, PenaltyErrorBoundOnTheQuarterIsTheWholePlates) {
  const Scene s = paper_scene();
  const Grid whole = make_grid(16), quarter = part_of(whole, Mirrors{true, true});
  for (const SamplingKind kind : {SamplingKind::Nodes, SamplingKind::Gauss}) {
    const Problem pw = make_problem(s, whole, SamplingSpec{kind}), pq = make_problem(s, quarter, SamplingSpec{kind});
    Cholesky cw, cq;
    cw.analyze(pw.K);
    cq.analyze(pq.K);
    // A symmetric iterate that violates the constraint: the plate lifted less than the obstacle.
    const auto lifted = [&](const Grid& g) {
      VectorXd v = VectorXd::Zero(g.unknowns());
      for (int i = 0; i <= g.nx; ++i)
        for (int j = 0; j <= g.ny; ++j)
          if (const int d = g.dof(i, j, kW); d >= 0) v[d] = 0.5 * s.cylinder->height;
      return v;
    };
    const VectorXd w = lifted(pw.grid), wq = lifted(pq.grid);
    const PenaltyBound bw = penalty_error_bound(pw, w, 1e-4, cw), bq = penalty_error_bound(pq, wq, 1e-4, cq);
    EXPECT_NEAR(bq.green, 4 * bw.green, 1e-10 * bq.green);
    EXPECT_NEAR(bq.residual, 0.5 * bw.residual, 1e-10 * bw.residual);
    EXPECT_NEAR(bq.bound, bw.bound, 1e-10 * bw.bound);
  }
}

// An obstacle that plunges far below the plate towards its corners must not make an asymmetry
// near the contact look like round-off: each pair of images is compared at its own size.
TEST(Mirror, AnAsymmetryIsSeenWhereTheObstacleIsSmallEvenIfItIsLargeElsewhere) {
  const Field deep = [](double x, double y) {
    const double r2 = (x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5);
    return 0.06 - 1000 * r2 * r2 + (r2 < 0.01 ? 1e-10 * x : 0.0);
  };
  EXPECT_FALSE(find_mirrors(Scene::rectangle(1, 1).over(deep).loaded(kNoLoad), make_grid(16), SamplingSpec{SamplingKind::Nodes}).x);
  const Field deep_symmetric = [](double x, double y) {
    const double r2 = (x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5);
    return 0.06 - 1000 * r2 * r2;
  };
  const Mirrors both = find_mirrors(Scene::rectangle(1, 1).over(deep_symmetric).loaded(kNoLoad), make_grid(16), SamplingSpec{SamplingKind::Nodes});
  EXPECT_TRUE(both.x && both.y);
}
