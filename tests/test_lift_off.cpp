// The default rows on scenes where the plate lifts off part of the rim (D28), h = 1/64 and 1/128:
// the plate kept out of the obstacle, the line load nonnegative, and max w beside rows at points.
// The located-ends solve on the 2 x 1 scene. (Fine grids: `make test` runs them, `make test-fast`
// does not.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "active_set.hpp"
#include "contact.hpp"
#include "extrema.hpp"
#include "line_force.hpp"
#include "located_ends.hpp"
#include "norms.hpp"
#include "rim_exchange.hpp"

using namespace plate;

namespace {
const Field kNoLoad = [](double, double) { return 0.0; };

struct LiftOff {
  double lx, ly, cx, cy;
  int n;  // cells along x for h = 1/64 (a whole number of cells across ly, and even)
};
// Three scenes where the plate lifts off part of the rim (the series refuses them): a 2 x 1 plate and
// a 1.5 x 1 plate with the cylinder at their centres, and the 1.5 x 1 plate with it off both
// centre lines.
const LiftOff kScenes[] = {{2, 1, 1, 0.5, 128}, {1.5, 1, 0.75, 0.5, 96}, {1.5, 1, 0.6, 0.45, 96}};

SceneSolution lift_off(const LiftOff& s, int n, EdgeRows rows = {}) {
  SceneSolution x = solve_exact_scene(Scene::rectangle(s.lx, s.ly).over(Cylinder{s.cx, s.cy, 0.25, 0.0625}), n,
                                      SamplingSpec{SamplingKind::Edge, rows}, ExactOptions{});
  EXPECT_TRUE(x.result.converged) << x.result.message;
  EXPECT_LE(x.result.certificate.worst(), 1e-10);
  return x;
}
}  // namespace

// The default rows on the lift-off scenes, h = 1/64 and 1/128: laid out for the contact (not
// periodic), the plate nowhere more than 1e-5 R below the rim between rows and that shrinking at
// least like h^2, the line load nonnegative, and max w within 2e-5 (relative) of rows at points.
// The spline rows alone, everywhere (the default before), dip 6e-4 R into the obstacle at
// h = 1/64 and miss the point rows by 4e-4 at h = 1/128 on the first scene. (At h = 1/32 the
// spline arcs' graded end spans are two cells wide and the dips do not yet shrink; `liftoff`
// reports them from h = 1/16 to 1/256.)
TEST(RimRows, LiftOffScenesKeepThePlateOutOfTheObstacle) {
  const double R = 0.0625;
  for (const LiftOff& s : kScenes) {
    std::vector<double> dips;
    double max_w = 0;
    for (int n : {s.n, 2 * s.n}) {
      const SceneSolution x = lift_off(s, n);
      EXPECT_FALSE(x.whole().sampling.rim.periodic) << s.lx << " " << s.cx;
      dips.push_back(dip_below_edge(x.whole(), x.result.w));
      const LineForce q = line_force(x.whole(), x.result.lambda);
      EXPECT_GE(q.min, -1e-9 * q.max);
      max_w = extremum_of_w(x.whole(), x.result.w, +1).value;
    }
    std::printf("lift-off %g x %g, centre (%g, %g): dips %.2e %.2e\n", s.lx, s.ly, s.cx, s.cy, dips[0], dips[1]);
    EXPECT_LE(dips[0], 1e-5 * R) << s.lx << " " << s.cx;
    EXPECT_LE(dips[1], dips[0] / 4) << s.lx << " " << s.cx;
    const SceneSolution points = lift_off(s, 2 * s.n, EdgeRows::points());
    EXPECT_NEAR(max_w, extremum_of_w(points.whole(), points.result.w, +1).value, 2e-5 * max_w) << s.lx << " " << s.cx;
  }
}

// The located-ends solve (located_ends.hpp) on the 2 x 1 scene, whole plate, h = 1/32, from the
// contact of the default solve: the ends settle and the answer is certified; nothing in the solve
// knows the scene's mirror lines, yet the four ends it finds are each other's mirror images; and
// max w lies beside the default's.
TEST(LocatedEnds, TheEndsOfASymmetricContactSettleSymmetrically) {
  const Scene scene = Scene::rectangle(2, 1).over(Cylinder{1, 0.5, 0.25, 0.0625});
  const int n = 64;
  const SceneSolution d = solve_exact_scene(scene, n, SamplingSpec{SamplingKind::Edge, EdgeRows{}}, ExactOptions{}, false);
  const double touch = std::max(1e-10 * max_nodal_abs(d.result.w.head(d.solved.grid.unknowns())), dip_below_edge(d.solved, d.result.w));
  const ContactArcs start = rim_contact(d.solved, d.result.w, d.result.lambda, touch);
  ASSERT_EQ(start.arcs.size(), 2u);
  const EndsSolve r = solve_located_ends(scene, n, start, ExactOptions{}, EndsOptions{});
  ASSERT_TRUE(r.result.converged);
  EXPECT_TRUE(r.settled) << r.moves << " moves";
  ASSERT_EQ(r.problem.ends.size(), 8u);  // two functions at each of four ends
  const double t = r.problem.ends[0].theta;
  EXPECT_NEAR(r.problem.ends[2].theta, M_PI - t, 1e-7);
  EXPECT_NEAR(r.problem.ends[4].theta, M_PI + t, 1e-7);
  EXPECT_NEAR(r.problem.ends[6].theta, 2 * M_PI - t, 1e-7);
  EXPECT_GT(std::abs(t - start.arcs[0].first), 1e-3);  // the ends did move from the start
  const double max_w = extremum_of_w(r.problem, r.result.w, +1).value;
  EXPECT_NEAR(max_w, extremum_of_w(d.solved, d.result.w, +1).value, 1e-4 * max_w);
}
