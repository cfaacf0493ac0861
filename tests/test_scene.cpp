// A scene stated one attribute at a time (scene.hpp), and the figures a report states of a line load
// (line_force.hpp, rim_contact.hpp), against values set by hand and closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "line_force.hpp"
#include "rim_contact.hpp"
#include "scene.hpp"

using namespace plate;

namespace {
// The message of the std::invalid_argument that `make` throws, or "" if it throws none.
template <class Make>
std::string refusal(Make make) {
  try {
    make();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Scene, EachAttributeIsSetByItsOwnFunctionAndTheRestKept) {
  const Scene s = Scene::rectangle(1.5, 1).over(Cylinder{0.75, 0.5, 0.25, 0.0625}).loaded(-2.0);
  EXPECT_EQ(s.lx, 1.5);
  EXPECT_EQ(s.ly, 1);
  ASSERT_TRUE(s.cylinder && s.uniform_load);
  EXPECT_EQ(*s.uniform_load, -2);
  EXPECT_EQ(s.load(0.1, 0.9), -2);
  EXPECT_EQ(s.obstacle(0.75, 0.5), 0.0625);      // on the disk
  EXPECT_TRUE(std::isinf(s.obstacle(0.1, 0.1)));  // no constraint off it
  EXPECT_EQ(s.edge.kind, EdgeCurve::Kind::Circle);
  // Another obstacle drops the cylinder and its rim; the load stays.
  const Scene e = s.over("0.01 - x*x");
  EXPECT_FALSE(e.cylinder);
  EXPECT_EQ(e.edge.kind, EdgeCurve::Kind::None);
  EXPECT_DOUBLE_EQ(e.obstacle(0.5, 0), 0.01 - 0.5 * 0.5);
  EXPECT_EQ(*e.uniform_load, -2);
  // A number as text is a uniform load too; an expression is not.
  EXPECT_EQ(*Scene::rectangle(1, 1).loaded(std::string("3")).uniform_load, 3);
  EXPECT_FALSE(Scene::rectangle(1, 1).loaded(std::string("x")).uniform_load);
  EXPECT_FALSE(Scene::rectangle(1, 1).loaded([](double x, double) { return x; }).uniform_load);
  // The rectangle alone: nothing under it, no load.
  const Scene bare = Scene::rectangle(2, 1);
  EXPECT_TRUE(std::isinf(bare.obstacle(1, 0.5)) && bare.obstacle(1, 0.5) < 0);
  EXPECT_EQ(bare.load(1, 0.5), 0);
}

TEST(Scene, RefusesWhatIsNoSceneNamingTheOption) {
  EXPECT_NE(refusal([] { Scene::rectangle(-1, 1); }).find("--lx"), std::string::npos);
  EXPECT_NE(refusal([] { Scene::rectangle(1, NAN); }).find("--ly"), std::string::npos);
  const std::string outside = refusal([] { Scene::rectangle(1, 1).over(Cylinder{0.9, 0.5, 0.25, 0.0625}); });
  EXPECT_NE(outside.find("--centre and --radius"), std::string::npos) << outside;
  EXPECT_NE(refusal([] { Scene::rectangle(1, 1).over(Cylinder{0.5, 0.5, -0.25, 0.0625}); }).find("--radius"), std::string::npos);
  EXPECT_NE(refusal([] { Scene::rectangle(1, 1).over(Cylinder{0.5, 0.5, 0.25, INFINITY}); }).find("--obstacle-height"), std::string::npos);
  EXPECT_NE(refusal([] { Scene::rectangle(1, 1).loaded(NAN); }).find("--load"), std::string::npos);
  EXPECT_NE(refusal([] { Scene::rectangle(1, 1).loaded(std::string("x +")); }).find("--load"), std::string::npos);
  EXPECT_NE(refusal([] { Scene::rectangle(1, 1).over("(("); }).find("--obstacle"), std::string::npos);
  EXPECT_EQ(refusal([] { Scene::rectangle(1, 1).over(Cylinder{0.75, 0.5, 0.25, 0.0625}); }), "");  // touching the side is inside
}

// The series' line load as a report states it: its table at kLineLoadAngles equal angles is the
// series' q there, its total the series' (D18), its extremes those of the table, and the figures'
// points lie on the rim.
TEST(LineFigures, TheSeriesLineLoadIsItsOwnQOnAFixedSetOfAngles) {
  const Scene s = Scene::rectangle(1, 1).over(Cylinder{0.45, 0.5, 0.25, 0.0625});
  const RimSeries series = solve_rim_series(s, rim_level(1));
  const LineForce f = rim_line_force(series);
  const LineFigures g = rim_line_figures(series, f);
  ASSERT_EQ(f.q.size(), static_cast<size_t>(kLineLoadAngles));
  ASSERT_EQ(g.q.size(), f.q.size());
  double lo = INFINITY, hi = -INFINITY, sum = 0;
  for (int k = 0; k < kLineLoadAngles; ++k) {
    const double t = 2 * M_PI * k / kLineLoadAngles;
    EXPECT_DOUBLE_EQ(f.theta[k], t);
    EXPECT_EQ(f.q[k], series.q(t));
    EXPECT_NEAR(std::hypot(g.x[k] - 0.45, g.y[k] - 0.5), 0.25, 1e-15);
    lo = std::min(lo, f.q[k]), hi = std::max(hi, f.q[k]), sum += f.q[k];
  }
  EXPECT_EQ(f.min, lo);
  EXPECT_EQ(f.max, hi);
  EXPECT_LT(f.min, f.max);  // off the centre, the load is not uniform
  EXPECT_NEAR(f.length, 2 * M_PI * 0.25, 1e-15);
  EXPECT_EQ(f.total, series.total_force());
  // The mean of equally spaced samples of a trigonometric series is its constant term.
  EXPECT_NEAR(sum / kLineLoadAngles, f.mean, 1e-9 * f.mean);
  EXPECT_EQ(g.q0, series.q(0));
  EXPECT_EQ(g.q45, series.q(M_PI / 4));
}
