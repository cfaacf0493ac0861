// Answers a user can trust on a scene of their own: extremes of the field w_h (not of its nodal
// values), and an error bar on each answer's distance from the plate's, checked against the
// rim-contact series, which needs no grid.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "active_set.hpp"
#include "contact.hpp"
#include "error_bar.hpp"
#include "extrema.hpp"
#include "published.hpp"
#include "rim_contact.hpp"
#include "run_program.hpp"
#include "scratch.hpp"

using namespace plate;

// A quadratic is a bicubic, so the Hermite interpolant of its values and derivatives at the nodes
// is the quadratic itself on every element whose nodes all carry unknowns: its peak, between nodes,
// is known in closed form. Newton from the best node finds it to round-off; the best node misses it.
TEST(Extrema, NewtonFindsThePeakOfTheInterpolantBetweenNodes) {
  const Grid g = make_grid(8);
  const double px = 0.4, py = 0.61, top = 0.3;  // h = 1/8: the peak lies inside the element [3/8, 1/2] x [1/2, 5/8]
  VectorXd w = VectorXd::Zero(g.unknowns());
  for (int j = 1; j < g.ny; ++j)
    for (int i = 1; i < g.nx; ++i) {
      const double x = g.x(i), y = g.y(j);
      w[g.dof(i, j, kW)] = top - (x - px) * (x - px) - 2 * (y - py) * (y - py) + 0.1 * (x - px) * (y - py);
      w[g.dof(i, j, kWx)] = -2 * (x - px) + 0.1 * (y - py);
      w[g.dof(i, j, kWy)] = -4 * (y - py) + 0.1 * (x - px);
      w[g.dof(i, j, kWxy)] = 0.1;
    }
  const Extremum e = extremum_of_w(g, w, +1);
  EXPECT_NEAR(e.x, px, 1e-12);
  EXPECT_NEAR(e.y, py, 1e-12);
  EXPECT_NEAR(e.value, top, 1e-14);
  double nodal = -1;
  for (int j = 1; j < g.ny; ++j)
    for (int i = 1; i < g.nx; ++i) nodal = std::max(nodal, w[g.dof(i, j, kW)]);
  EXPECT_LT(nodal, top - 1e-4);
  // The least value of the field -w_h is the same point, found as a minimum.
  const Extremum m = extremum_of_w(g, -w, -1);
  EXPECT_NEAR(m.value, -top, 1e-14);
  EXPECT_NEAR(m.x, px, 1e-12);
}

// Where a scene's symmetry makes several places tie, the one reported does not depend on round-off:
// solved on its quarter (mirror lines) or on the whole plate, the paper's scene puts min w (four
// images, one near each corner) and max |m12| at the same place, the images' first in the order of
// the nodes (y, then x).
TEST(Extrema, ThePlaceOfATiedExtremumIsTheSameOnThePartAndTheWholePlate) {
  SamplingSpec spec{SamplingKind::Edge};
  const Scene scene = paper_scene();
  const SceneSolution part = solve_exact_scene(scene, 32, spec, ExactOptions{}, true);
  const SceneSolution whole = solve_exact_scene(scene, 32, spec, ExactOptions{}, false);
  ASSERT_TRUE(part.result.converged && whole.result.converged);
  ASSERT_TRUE(part.solved.grid.is_part() && !whole.solved.grid.is_part());
  const FieldMeasures a = measure_field(part.solved, part.part_w, 0.3, {}), b = measure_field(whole.solved, whole.part_w, 0.3, {});
  EXPECT_NEAR(a.min_w.value, b.min_w.value, 1e-12 * std::abs(a.max_w.value));
  for (const auto& [p, q] : {std::pair{a.min_w, b.min_w}, {a.max_abs_m12, b.max_abs_m12}}) {
    EXPECT_NEAR(p.x, q.x, 1e-6) << p.x << ", " << p.y << " against " << q.x << ", " << q.y;
    EXPECT_NEAR(p.y, q.y, 1e-6);
    EXPECT_LT(p.x, 0.5);  // the lower-left image
    EXPECT_LT(p.y, 0.5);
  }
}

// The pattern search, on a function whose peak lies off every lattice it starts from.
TEST(Extrema, PatternSearchClosesInOnAKink) {
  const Grid g = make_grid(10);
  const auto cone = [](double x, double y) { return -std::abs(x - 0.3141) - 2 * std::abs(y - 0.7071); };
  const Extremum e = pattern_maximum(g, cone, 0.3, 0.7, g.h);
  EXPECT_NEAR(e.x, 0.3141, 1e-8);
  EXPECT_NEAR(e.y, 0.7071, 1e-8);
}

// The solver measures each grid of its sequence for the error bars (ExactOptions::measure_levels):
// every grid, the coarse ones of the recursion included, and on the finest the same values as the
// whole plate's answer read afterwards. The part solved is a quarter, so a point in another quarter
// is read through the mirror lines, and the force counts the part's four images.
TEST(ErrorBar, EveryGridOfTheSequenceIsMeasuredAsTheAnswerIs) {
  const std::vector<std::pair<double, double>> points = {{0.3, 0.2}, {0.7, 0.8}};
  ExactOptions o;
  o.measure_levels = ExactOptions::LevelMeasures{kPoissonRatio, points};
  const SceneSolution x = solve_exact_scene(paper_scene(), 32, SamplingSpec{SamplingKind::Edge, EdgeRows{}}, o, true);
  ASSERT_TRUE(x.result.converged);
  ASSERT_TRUE(x.mirrors.x && x.mirrors.y);
  ASSERT_EQ(x.result.levels.size(), 3u);  // n = 8, 16, 32
  for (size_t k = 0; k < x.result.levels.size(); ++k) {
    const ExactLevel& l = x.result.levels[k];
    ASSERT_TRUE(l.measures) << "level " << k;
    EXPECT_TRUE(l.certified);
    EXPECT_EQ(l.cells, 8 << k);
    EXPECT_EQ(l.measures->w_at.size(), points.size());
  }
  const ExactLevel& fine = x.result.levels.back();
  const FieldMeasures whole = measure_field(x.whole(), x.result.w, kPoissonRatio, points);
  const double w = whole.max_w.value;
  EXPECT_NEAR(fine.measures->max_w.value, w, 1e-12 * w);
  EXPECT_NEAR(fine.measures->max_abs_m12.value, whole.max_abs_m12.value, 1e-9 * whole.max_abs_m12.value);
  EXPECT_NEAR(fine.measures->w_at[0], whole.w_at[0], 1e-12 * w);
  EXPECT_NEAR(fine.measures->w_at[1], whole.w_at[1], 1e-12 * w);
  EXPECT_NEAR(fine.measures->w_at[1], fine.measures->w_at[0], 1e-12 * w);  // mirror images on the paper's square
  const double force = total_contact_force(x.whole(), x.result.lambda);
  EXPECT_NEAR(fine.force, force, 1e-12 * force);
  EXPECT_GT(std::abs(x.result.levels.front().force - force), 1e-6 * force);  // the coarse grid's own, not a copy
}

// The bar on a sequence with a known limit: steady (v + C h^3 + D h^4), the bar holds the finest
// value's error and is at most ten times it; not steady, the last difference, marked so.
TEST(ErrorBar, HoldsTheErrorOfASteadySequenceAndSaysWhenItIsNotSteady) {
  std::vector<double> v;
  for (int k = 0; k < 4; ++k) {
    const double h = std::pow(0.5, k + 3);
    v.push_back(1 + 0.7 * h * h * h + 2.0 * h * h * h * h);
  }
  const ErrorBar b = error_bar(v);
  EXPECT_EQ(b.basis, "richardson");
  EXPECT_TRUE(b.steady);
  const double err = std::abs(v.back() - 1);
  EXPECT_GE(b.bar, err);
  EXPECT_LE(b.bar, 10 * err);
  EXPECT_NEAR(b.order, 3, 0.2);
  const ErrorBar shrinking = error_bar({1.0, 1.1, 1.15, 1.16});  // orders 1 and 2.3: not steady
  EXPECT_EQ(shrinking.basis, "last difference");
  EXPECT_FALSE(shrinking.steady);
  EXPECT_NEAR(shrinking.bar, 0.01, 1e-12);
  const ErrorBar swinging = error_bar({1.0, 1.1, 1.05, 1.07});  // the last increments change sign
  EXPECT_EQ(swinging.basis, "largest of the last two differences");
  EXPECT_NEAR(swinging.bar, 0.05, 1e-12);
  // Values that cross their limit 1 between the last two grids: errors -8e-3, 3e-5, 3.3e-5 (the
  // shape of max w with the kink carried on n = 64, 128, 256). The last difference, 3e-6, is 2700
  // times smaller than the one before, faster than anything converges here, and would not hold the
  // error of 3.3e-5: the larger of the last two differences does.
  const std::vector<double> crossing{1 - 4e-2, 1 - 8e-3, 1 + 3e-5, 1 + 3.3e-5};
  const ErrorBar crossed = error_bar(crossing);
  EXPECT_EQ(crossed.basis, "largest of the last two differences");
  EXPECT_GE(crossed.bar, 3.3e-5);
  EXPECT_NEAR(crossed.bar, 8.03e-3, 1e-12);
  // Even a steady order of 7 is beyond any space here, so Richardson's bar is not taken from it.
  std::vector<double> seventh;
  for (int k = 0; k < 4; ++k) seventh.push_back(1 + std::pow(0.5, 7 * (k + 1)));
  const ErrorBar fast = error_bar(seventh);
  EXPECT_EQ(fast.basis, "largest of the last two differences");
  EXPECT_FALSE(fast.steady);
  EXPECT_NEAR(fast.order, 7, 1e-6);
  EXPECT_EQ(error_bar({1.0}).basis, "none");
}

// A value the scene fixes (w at a clamped corner, a force of 0 where nothing touches) is the same to
// the last bit on every grid. It has nothing to estimate and does not swing; one bit apart it is
// judged like any other sequence.
TEST(ErrorBar, AValueEqualOnEveryGridHasNoBarAndIsNotCalledSwinging) {
  const ErrorBar same = error_bar({0.0, 0.0, 0.0, 0.0});
  EXPECT_EQ(same.basis, "the same on every grid");
  EXPECT_EQ(same.bar, 0.0);
  EXPECT_FALSE(same.steady);
  EXPECT_EQ(error_bar({0.0625, 0.0625}).basis, "the same on every grid");
  const double next = std::nextafter(0.0625, 1.0);
  const ErrorBar apart = error_bar({0.0625, 0.0625, 0.0625, next});
  EXPECT_NE(apart.basis, "the same on every grid");
  EXPECT_GT(apart.bar, 0.0);
}

// Across two spaces the bar is the triangle inequality: the finest value's step from the grid before
// plus that grid's own bar from the coarser space's sequence; none where that sequence gives none,
// and a value the same on every grid of both is marked as such.
TEST(ErrorBar, AcrossTwoSpacesTheStepIsAddedToTheCoarserBar) {
  // Increments 0.1, 0.05, 0.01 (orders 1 and 2.3, not steady): the coarser bar is the last, 0.01.
  const std::vector<double> coarser{1.0, 1.1, 1.15, 1.16};
  const ErrorBar b = error_bar_across(1.1605, coarser);
  EXPECT_EQ(b.basis, "last difference across the spaces");
  EXPECT_FALSE(b.steady);
  EXPECT_EQ(b.value, 1.1605);
  EXPECT_NEAR(b.bar, 0.0005 + 0.01, 1e-12);
  EXPECT_EQ(error_bar_across(0.0, {0.0, 0.0, 0.0}).basis, "the same on every grid");
  EXPECT_NE(error_bar_across(1e-300, {0.0, 0.0, 0.0}).basis, "the same on every grid");
  EXPECT_EQ(error_bar_across(1.0, {1.1}).basis, "none");
  EXPECT_TRUE(std::isnan(error_bar_across(1.0, {1.1}).bar));
}
