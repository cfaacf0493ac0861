// `plate`'s error bars on the user's scene (D29), run as a user runs the program: against the
// rim-contact series on the scenes it solves, and against a finer grid on one it refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "published.hpp"
#include "rim_contact.hpp"
#include "run_program.hpp"
#include "scratch.hpp"

using namespace plate;

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
// both centre lines: max w and the total force each carry a bar from the run's own grids that holds
// its distance from the series' answer; max w is the field's peak, within 1e-7 (absolute) of the
// series' even where it lies between nodes (the nodal maximum of the off-centre scene is 3.7e-6
// short). The JSON says what each bound is about. In the plain space (n = 128, 160 for the 1.25
// plate) every bar is at most ten times the error. With the kink carried (D31, the default) the
// values converge at order 4, where a last difference is some 15 times the error: a bar from
// Richardson (n = 256, 320, whose four grids all carry the kink) must be within ten times it, and
// every other bar must hold the error.
TEST(ErrorBar, PlateBarsHoldTheDistanceToTheSeries) {
  struct Case {
    std::string args;
    Scene scene;
  };
  const Scene off_centre = Scene::rectangle(1, 1).over(Cylinder{0.45, 0.5, 0.25, 0.0625});
  const Scene oblong = Scene::rectangle(1.25, 1).over(Cylinder{0.6, 0.45, 0.25, 0.0625});
  const Case cases[] = {{"-n 128 --enrich none", paper_scene()},
                        {"-n 128 --enrich none --centre 0.45,0.5", off_centre},
                        {"-n 160 --enrich none --lx 1.25 --centre 0.6,0.45", oblong},
                        {"-n 256", paper_scene()},
                        {"-n 256 --centre 0.45,0.5", off_centre},
                        {"-n 320 --lx 1.25 --centre 0.6,0.45", oblong}};
  for (const Case& c : cases) {
    const nlohmann::json j = run_json(c.args);
    const bool plain = c.args.find("--enrich none") != std::string::npos;
    EXPECT_EQ(j["model"]["space"].get<std::string>().find("(D31)") == std::string::npos, plain) << c.args;
    const RimAnswer series = rim_answer(c.scene, 6, false, 3);
    ASSERT_TRUE(series.premise.holds) << c.args;
    const RimPeak peak = series.finest.max_w();
    const double force = series.finest.total_force();
    EXPECT_NEAR(j["max_w"].get<double>(), peak.w, 1e-7) << c.args;
    EXPECT_NEAR(j["max_w_at"][0].get<double>(), peak.x, 1e-4) << c.args;
    for (const auto& [key, field, truth] : {std::tuple{"max w", "max_w", peak.w}, {"total contact force", "total_contact_force", force}}) {
      const double err = std::abs(j[field].get<double>() - truth), bar = j["error_bars"][key]["bar"].get<double>();
      const std::string basis = j["error_bars"][key]["basis"].get<std::string>();
      std::printf("%s %s: error %.2e, bar %.2e (%s)\n", c.args.c_str(), key, err, bar, basis.c_str());
      EXPECT_GE(bar, err) << c.args << " " << key;
      if (plain || basis == "richardson") {
        EXPECT_LE(bar, 10 * err) << c.args << " " << key;
      }
    }
    EXPECT_NE(j["certificate_is"].get<std::string>().find("discrete"), std::string::npos);
    EXPECT_NE(j["error_bar_is"].get<std::string>().find("continuum"), std::string::npos);
  }
}

// On a scene where the plate lifts off part of the rim (no series to hold it to), the bar from the
// four grids n/8 ... n holds the distance to the answer of a grid twice finer (n = 24 is the first
// grid the kink-carrying space (D31) fits on this plate, so the four grids end at 192).
TEST(ErrorBar, LiftOffBarHoldsAFinerAnswer) {
  const nlohmann::json coarse = run_json("-n 192 --lx 1.5 --centre 0.75,0.5"), fine = run_json("-n 384 --lx 1.5 --centre 0.75,0.5 --estimate off");
  const nlohmann::json& b = coarse["error_bars"]["max w"];
  EXPECT_GE(b["bar"].get<double>(), std::abs(coarse["max_w"].get<double>() - fine["max_w"].get<double>()));
  EXPECT_EQ(coarse["error_bars"]["grids"].size(), 4u);
}

// With the cylinder 0.05 from the clamped edge, the kink functions (D31) fit n = 128 but none of the
// coarser grids (they need four cells there), so n = 128 is the only grid of its space. Its bar is
// then its step from n = 64 plus the bar of n = 64 from the plain grids 8 ... 64. There the plate
// lifts off part of the rim and the series refuses the scene, so the bar must hold the distance to
// n = 256's answer (which has n = 128 in its space), widened by that answer's own bar; the JSON says
// how it was found.
TEST(ErrorBar, AGridAloneInItsSpaceTakesItsBarFromTheCoarserSpace) {
  const nlohmann::json j = run_json("-n 128 --centre 0.3,0.5"), fine = run_json("-n 256 --centre 0.3,0.5");
  ASSERT_NE(j["model"]["space"].get<std::string>().find("(D31)"), std::string::npos) << j.dump();
  EXPECT_EQ(j["error_bars"]["grids"].size(), 5u) << j["error_bars"].dump();
  EXPECT_NE(j["error_bars"]["grids_note"].get<std::string>().find("n = 128 carries the kink"), std::string::npos);
  for (const auto& [key, field] : {std::pair{"max w", "max_w"}, {"total contact force", "total_contact_force"}}) {
    const nlohmann::json& b = j["error_bars"][key];
    EXPECT_EQ(b["basis"], "last difference across the spaces") << key;
    EXPECT_FALSE(b["steady"].get<bool>()) << key;
    const nlohmann::json& f = fine["error_bars"][key];
    ASSERT_NE(f["basis"], "last difference across the spaces") << key;  // n = 256 has n = 128 in its space
    const double apart = std::abs(j[field].get<double>() - fine[field].get<double>()) + f["bar"].get<double>();
    std::printf("%s: n = 128 to n = 256 and its bar %.2e, n = 128's bar %.2e\n", key, apart, b["bar"].get<double>());
    EXPECT_GE(b["bar"].get<double>(), apart) << key;
  }
}
