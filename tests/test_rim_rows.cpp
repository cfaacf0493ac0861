// Rows on a circle fitted to the contact (D28), for scenes where the plate lifts off part of the
// rim: the clamped B-splines on an arc and their known identities, the contact read off a solve,
// and the plate on three lift-off scenes against rows at points, the layout the spline rows replace.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "active_set.hpp"
#include "contact.hpp"
#include "extrema.hpp"
#include "fields.hpp"
#include "line_force.hpp"
#include "rim_exchange.hpp"
#include "rim_rows.hpp"

using namespace plate;

namespace {
SplineArc arc(double begin, double end, double finest, double spacing) {
  SplineArc a;
  a.breaks = graded_breaks(begin, end, finest, spacing);
  return a;
}
}  // namespace

// The clamped cubic B-splines of an arc sum to one on it, are nonnegative, integrate to the arc's
// length in total, and reproduce the angle itself with their Greville abscissae as coefficients
// (Marsden's identity, degree >= 1).
TEST(RimRows, ClampedSplinesArePartitionOfUnityAndReproduceTheAngle) {
  for (const SplineArc& a : {arc(0.3, 1.9, 0.02, 0.25), arc(5.9, 7.1, 0.05, 0.2), arc(1.0, 1.07, 0.03, 0.3)}) {
    ASSERT_FALSE(a.breaks.empty());
    double integral = 0;
    for (int j = 0; j < a.basis_count(3); ++j) integral += clamped_bspline_integral(a, 3, j);
    EXPECT_NEAR(integral, a.end() - a.begin(), 1e-14);
    for (int k = 0; k <= 400; ++k) {
      const double t = a.begin() + (a.end() - a.begin()) * k / 400;
      double sum = 0, linear = 0;
      for (int j = 0; j < a.basis_count(3); ++j) {
        const double b = clamped_bspline(a, 3, j, t);
        EXPECT_GE(b, 0);
        sum += b, linear += a.greville(j, 3) * b;
      }
      EXPECT_NEAR(sum, 1, 1e-14) << t;
      EXPECT_NEAR(linear, t, 1e-13) << t;
    }
    EXPECT_EQ(clamped_bspline(a, 3, 0, a.begin() - 0.01), 0);  // off the arc
  }
}

// Graded spans: the finest at both ends, doubling towards the middle, the same from either end.
TEST(RimRows, GradedBreaksAreSymmetricAndDoubleFromTheEnds) {
  const std::vector<double> b = graded_breaks(1.0, 2.0, 0.01, 0.1);
  const size_t n = b.size();
  ASSERT_GE(n, 8u);
  EXPECT_NEAR(b[1] - b[0], 0.01, 1e-15);
  EXPECT_NEAR(b[2] - b[1], 0.02, 1e-15);
  for (size_t k = 0; k < n; ++k) EXPECT_NEAR(b[k] - 1.0, 2.0 - b[n - 1 - k], 1e-14) << k;
  for (size_t k = 0; k + 1 < n; ++k) EXPECT_LE(b[k + 1] - b[k], 0.1 * 1.5);
  EXPECT_TRUE(graded_breaks(1.0, 1.015, 0.01, 0.1).empty());  // shorter than two finest spans
}

// The contact is the union of the arcs the touching rows stand for; it joins across 2 pi, keeps
// the symmetry of its rows, and is the whole circle when every row touches.
TEST(RimRows, ContactArcsFollowTheTouchingRows) {
  std::vector<double> rows, reach(64, 0.0);
  std::vector<bool> touching;
  for (int k = 0; k < 64; ++k) rows.push_back(2 * M_PI * k / 64), touching.push_back(std::abs(std::sin(rows.back())) > 0.6);
  const ContactArcs c = contact_arcs(rows, touching, reach);
  ASSERT_FALSE(c.whole);
  ASSERT_EQ(c.arcs.size(), 2u);
  for (const auto& [b, e] : c.arcs) EXPECT_NEAR(std::fmod(0.5 * (b + e), M_PI), M_PI / 2, 1e-12);  // about pi/2 and 3 pi/2
  // Across zero: rows touching near theta = 0 make one arc, not two.
  for (int k = 0; k < 64; ++k) touching[k] = std::cos(rows[k]) > 0.5;
  const ContactArcs z = contact_arcs(rows, touching, reach);
  ASSERT_EQ(z.arcs.size(), 1u);
  EXPECT_NEAR(std::remainder(0.5 * (z.arcs[0].first + z.arcs[0].second), 2 * M_PI), 0, 1e-12);
  EXPECT_TRUE(contact_arcs(rows, std::vector<bool>(64, true), reach).whole);
  // A reach bridges rows that touch a little apart, as a plate touches a cell apart between points.
  for (int k = 0; k < 64; ++k) touching[k] = k % 2 == 0;
  EXPECT_FALSE(contact_arcs(rows, touching, reach).whole);
  EXPECT_TRUE(contact_arcs(rows, touching, std::vector<double>(64, 2 * M_PI / 64)).whole);
}

// The point rows stand for the circle off the spline arcs, all of it and no more.
TEST(RimRows, PointWeightsCoverTheCircleOffTheArcs) {
  RimLayout L;
  L.periodic = false;
  L.arcs = {arc(0.5, 1.5, 0.05, 0.2), arc(3.5, 4.2, 0.05, 0.2)};
  for (int k = 0; k < 40; ++k) {
    const double t = 2 * M_PI * k / 40;
    if (!L.arcs[0].contains(t) && !L.arcs[1].contains(t)) L.points.push_back(t);
  }
  double total = 0;
  for (double w : point_weights(L, 0.25)) {
    EXPECT_GT(w, 0);
    total += w;
  }
  EXPECT_NEAR(total, 0.25 * (2 * M_PI - 1.0 - 0.7), 1e-13);
}

// On a part of the plate (mirror lines) the dip is read on the part's own stretch of the edge alone:
// it is the whole plate's dip, to round-off, and placed on the part.
TEST(RimRows, ThePartsDipIsTheWholePlatesDip) {
  const Scene lift_off = Scene::rectangle(2, 1).over(Cylinder{1, 0.5, 0.25, 0.0625});
  for (int n : {32, 64}) {
    const SceneSolution x = solve_exact_scene(lift_off, n, SamplingSpec{SamplingKind::Edge, EdgeRows{}}, ExactOptions{});
    ASSERT_TRUE(x.result.converged) << x.result.message;
    ASSERT_TRUE(x.solved.grid.mirror_x && x.solved.grid.mirror_y);
    const EdgeDip part = deepest_dip_below_edge(x.solved, x.part_w), whole = deepest_dip_below_edge(x.whole(), x.result.w);
    ASSERT_GT(whole.depth, 0);
    EXPECT_NEAR(part.depth, whole.depth, 1e-13 * 0.0625) << n;  // within the dip's own tie
    EXPECT_LE(1 + 0.25 * std::cos(part.theta), 1 + 1e-12) << n;  // on the lower-left quarter
    EXPECT_LE(0.5 + 0.25 * std::sin(part.theta), 0.5 + 1e-12) << n;
    // The whole plate's four images tie; the first along the edge from theta = 0 is named: the
    // part's, turned through pi.
    EXPECT_NEAR(whole.theta, part.theta - M_PI, 1e-12) << n;
  }
}

// Where the plate dips deepest, and which rows hold it there: on the 2 x 1 lift-off scene at
// h = 1/32 the deepest dip is phi - w_h at the angle reported; an angle on a spline arc lies as many
// cells inside it as the arc's geometry says (half its length at its middle, half a cell half a cell
// in), one off every arc lies between points, and the same angles a turn away read the same. Rows
// at points have no arcs, and the paper's scene keeps its periodic splines, which have no end.
TEST(RimRows, TheDeepestDipIsPlacedAmongTheRowsThatHoldThePlate) {
  const auto solve = [](const Scene& scene, int n, EdgeRows rows) {
    SceneSolution x = solve_exact_scene(scene, n, SamplingSpec{SamplingKind::Edge, rows}, ExactOptions{});
    EXPECT_TRUE(x.result.converged) << x.result.message;
    return x;
  };
  const Scene lift_off = Scene::rectangle(2, 1).over(Cylinder{1, 0.5, 0.25, 0.0625});
  const SceneSolution x = solve(lift_off, 64, EdgeRows{});
  const Problem& p = x.whole();
  const EdgeDip dip = deepest_dip_below_edge(p, x.result.w);
  ASSERT_GT(dip.depth, 0);
  const PlateField field(p, x.result.w);
  const auto below = [&](double t) { return 0.0625 - field.at(1 + 0.25 * std::cos(t), 0.5 + 0.25 * std::sin(t)).w; };
  EXPECT_NEAR(below(dip.theta), dip.depth, 1e-15);
  // The deepest among angles 2 pi k / 4096 (not the h/32 points' own angles): no deeper than the
  // dip by more than the h/32 spacing can miss of a smooth minimum, a small fraction of it.
  double deepest = 0;
  for (int k = 0; k < 4096; ++k) deepest = std::max(deepest, below(2 * M_PI * (k + 0.5) / 4096));
  std::printf("deepest dip %.6e, on a finer lattice %.6e\n", dip.depth, deepest);
  EXPECT_LE(deepest, 1.01 * dip.depth);
  EXPECT_GE(deepest, 0.9 * dip.depth);
  const double cell = p.grid.h / 0.25;  // a cell's angle on the circle
  ASSERT_EQ(p.sampling.rim.arcs.size(), 2u);
  for (const SplineArc& a : p.sampling.rim.arcs) {
    const double middle = 0.5 * (a.begin() + a.end());
    EXPECT_NEAR(cells_inside_spline_arc(p, middle), 0.5 * (a.end() - a.begin()) / cell, 1e-9);
    EXPECT_NEAR(cells_inside_spline_arc(p, middle + 2 * M_PI), 0.5 * (a.end() - a.begin()) / cell, 1e-9);
    EXPECT_NEAR(cells_inside_spline_arc(p, a.begin() + 0.5 * cell), 0.5, 1e-9);
    EXPECT_NEAR(cells_inside_spline_arc(p, a.end() - 0.5 * cell - 2 * M_PI), 0.5, 1e-9);
    EXPECT_TRUE(std::isnan(cells_inside_spline_arc(p, a.begin() - 0.5 * cell)));
  }
  EXPECT_TRUE(std::isnan(cells_inside_spline_arc(p, 0.0)));  // theta = 0 points along the long span, off the contact
  EXPECT_TRUE(std::isnan(cells_inside_spline_arc(p, NAN)));
  // Arcs the scene does not have: one across theta = 0 and one longer than pi.
  Problem q = p;
  q.sampling.rim.arcs.assign(2, SplineArc{});
  q.sampling.rim.arcs[0].breaks = {2 * M_PI - 0.1, 2 * M_PI, 2 * M_PI + 0.1};
  q.sampling.rim.arcs[1].breaks = {1.0, 3.0, 5.0};
  EXPECT_NEAR(cells_inside_spline_arc(q, 0.0), 0.1 / cell, 1e-9);
  EXPECT_NEAR(cells_inside_spline_arc(q, 0.05), 0.05 / cell, 1e-9);
  EXPECT_NEAR(cells_inside_spline_arc(q, 2 * M_PI - 0.08), 0.02 / cell, 1e-9);
  EXPECT_NEAR(cells_inside_spline_arc(q, 4.5), 0.5 / cell, 1e-9);
  EXPECT_NEAR(cells_inside_spline_arc(q, 3.0), 2.0 / cell, 1e-9);
  EXPECT_TRUE(std::isnan(cells_inside_spline_arc(q, 5.5)));
  const SceneSolution points = solve(lift_off, 64, EdgeRows::points());
  EXPECT_TRUE(std::isnan(cells_inside_spline_arc(points.whole(), M_PI / 2)));
  const SceneSolution paper = solve(Scene::rectangle(1, 1).over(Cylinder{0.5, 0.5, 0.25, 0.0625}), 16, EdgeRows{});
  EXPECT_TRUE(std::isinf(cells_inside_spline_arc(paper.whole(), M_PI / 2)));
  // The reports read the three kinds through rows_at alone.
  EXPECT_EQ(rows_at(cells_inside_spline_arc(points.whole(), M_PI / 2)), RowsAt::Points);
  EXPECT_EQ(rows_at(cells_inside_spline_arc(paper.whole(), M_PI / 2)), RowsAt::Periodic);
  EXPECT_EQ(rows_at(cells_inside_spline_arc(q, 3.0)), RowsAt::Arc);
  EXPECT_EQ(rows_at(cells_inside_spline_arc(q, 0.0)), RowsAt::Arc);  // the arc across theta = 0
}
