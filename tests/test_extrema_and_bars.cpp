// Answers a user can trust on a scene of their own: extremes of the field w_h (not of its nodal
// values), and an error bar on each answer's distance from the plate's, checked against the
// rim-contact series, which needs no grid.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "error_bar.hpp"
#include "extrema.hpp"
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

// The pattern search, on a function whose peak lies off every lattice it starts from.
TEST(Extrema, PatternSearchClosesInOnAKink) {
  const Grid g = make_grid(10);
  const auto cone = [](double x, double y) { return -std::abs(x - 0.3141) - 2 * std::abs(y - 0.7071); };
  const Extremum e = pattern_maximum(g, cone, 0.3, 0.7, g.h);
  EXPECT_NEAR(e.x, 0.3141, 1e-8);
  EXPECT_NEAR(e.y, 0.7071, 1e-8);
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
  EXPECT_EQ(error_bar({1.0}).basis, "none");
}

namespace {
std::string temp_path(const std::string& name) {
  static const Scratch scratch("bars");
  return scratch.path(name);
}
nlohmann::json run_json(const std::string& args) {
  const std::string json = temp_path("run.json");
  const Captured c = run_captured(std::string(PLATE_EXE) + " -q " + args + " --json " + json);
  EXPECT_EQ(c.status, 0) << args << "\n" << c.output;
  std::ifstream in(json);
  return nlohmann::json::parse(in, nullptr, false);
}
}  // namespace

// `plate` on the paper's scene, an off-centre cylinder and a 1.25 x 1 plate with the cylinder off
// both centre lines, n = 128 (160 for the 1.25 plate): max w and the total force each carry a bar
// from the run's own grids that holds its distance from the series' answer and is at most ten times
// it; max w is the field's peak, within 1e-7 (absolute) of the series' even where it lies between
// nodes (the nodal maximum of the off-centre scene is 3.7e-6 short). The JSON says what each bound
// is about.
TEST(ErrorBar, PlateBarsHoldTheDistanceToTheSeries) {
  struct Case {
    std::string args;
    RimScene scene;
  };
  const Case cases[] = {{"-n 128", RimScene{}},
                        {"-n 128 --centre 0.45,0.5", RimScene{1, 1, 0.45, 0.5}},
                        {"-n 160 --lx 1.25 --centre 0.6,0.45", RimScene{1.25, 1, 0.6, 0.45}}};
  for (const Case& c : cases) {
    const nlohmann::json j = run_json(c.args);
    const RimAnswer series = rim_answer(c.scene, 6, false, 3);
    ASSERT_TRUE(series.premise.holds) << c.args;
    const RimPeak peak = series.finest.max_w();
    const double force = series.finest.total_force();
    EXPECT_NEAR(j["max_w"].get<double>(), peak.w, 1e-7) << c.args;
    EXPECT_NEAR(j["max_w_at"][0].get<double>(), peak.x, 1e-4) << c.args;
    for (const auto& [key, field, truth] : {std::tuple{"max w", "max_w", peak.w}, {"total contact force", "total_contact_force", force}}) {
      const double err = std::abs(j[field].get<double>() - truth), bar = j["error_bars"][key]["bar"].get<double>();
      std::printf("%s %s: error %.2e, bar %.2e (%s)\n", c.args.c_str(), key, err, bar, j["error_bars"][key]["basis"].get<std::string>().c_str());
      EXPECT_GE(bar, err) << c.args << " " << key;
      EXPECT_LE(bar, 10 * err) << c.args << " " << key;
    }
    EXPECT_NE(j["certificate_is"].get<std::string>().find("discrete"), std::string::npos);
    EXPECT_NE(j["error_bar_is"].get<std::string>().find("continuum"), std::string::npos);
  }
}

// On a scene where the plate lifts off part of the rim (no series to hold it to), the bar from the
// four grids n/8 ... n holds the distance to the answer of a grid four times finer.
TEST(ErrorBar, LiftOffBarHoldsAFinerAnswer) {
  const nlohmann::json coarse = run_json("-n 96 --lx 1.5 --centre 0.75,0.5"), fine = run_json("-n 384 --lx 1.5 --centre 0.75,0.5 --estimate off");
  const nlohmann::json& b = coarse["error_bars"]["max w"];
  EXPECT_GE(b["bar"].get<double>(), std::abs(coarse["max_w"].get<double>() - fine["max_w"].get<double>()));
  EXPECT_EQ(coarse["error_bars"]["grids"].size(), 4u);
}
