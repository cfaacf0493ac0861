// The fields of a contact's end (contact_end.hpp): their derivatives against finite differences,
// the conditions on the contact side that make them fields of a plate resting on a rim, the line
// load of F_52 against its closed form, the enrichment's vanishing at the nodes, and the fit that
// locates an end recovering a shift put into a gap by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact_end.hpp"

using namespace plate;

namespace {
// The 2 x 1 lift-off scene's end in the lower half (the quarter's), free for smaller angles.
ContactEnd scene_end() { return {1, 0.5, 0.25, M_PI + 0.98, -1, 0.05, 0.1}; }
double end_x(const ContactEnd& e) { return e.cx + e.a * std::cos(e.theta); }
double end_y(const ContactEnd& e) { return e.cy + e.a * std::sin(e.theta); }
}  // namespace

TEST(ContactEnd, DerivativesMatchFiniteDifferences) {
  const ContactEnd e = scene_end();
  for (EndField f : {EndField::Gap32, EndField::Gap52})
    for (double angle : {0.3, 1.7, 2.6, -1.2, -2.8})
      for (double rho : {0.004, 0.02, 0.07}) {
        const double x = end_x(e) + rho * std::cos(angle), y = end_y(e) + rho * std::sin(angle), d = 1e-3 * rho;
        const EndDerivatives v = end_field(e, f, x, y);
        // Fourth-order central differences, in x (dx = 1) or y (dx = 0).
        auto diff = [&](auto get, int dx) {
          auto at = [&](double k) { return get(end_field(e, f, x + dx * k * d, y + (1 - dx) * k * d)); };
          return (-at(2) + 8 * at(1) - 8 * at(-1) + at(-2)) / (12 * d);
        };
        auto w = [](const EndDerivatives& u) { return u.w; };
        auto wx = [](const EndDerivatives& u) { return u.wx; };
        const double slope = std::abs(v.wx) + std::abs(v.wy), scale = std::abs(v.wxx) + std::abs(v.wyy) + std::abs(v.wxy);
        EXPECT_NEAR(v.wx, diff(w, 1), 1e-8 * slope);
        EXPECT_NEAR(v.wy, diff(w, 0), 1e-8 * slope);
        EXPECT_NEAR(v.wxx, diff(wx, 1), 1e-8 * scale);
        EXPECT_NEAR(v.wxy, diff(wx, 0), 1e-8 * scale);
        const EndDerivatives X = end_cutoff(e, x, y);
        auto c = [&](double px, double py) { return end_cutoff(e, px, py).w; };
        const double h = 1e-5;
        EXPECT_NEAR(X.wxx + X.wyy, (c(x + h, y) + c(x - h, y) + c(x, y + h) + c(x, y - h) - 4 * c(x, y)) / (h * h),
                    1e-3 * (1 + std::abs(X.wxx) + std::abs(X.wyy)));
      }
}

// On the contact side (theta beyond the end, on the rim) each field vanishes with its normal slope,
// and its second normal derivative is the same from both sides: the plate is one piece resting on
// the rim. Across the free side of the rim it is smooth.
TEST(ContactEnd, VanishesWithItsSlopeWhereThePlateTouches) {
  const ContactEnd e = scene_end();
  for (EndField f : {EndField::Gap32, EndField::Gap52})
    for (double s : {0.003, 0.02, 0.06}) {
      const double th = e.theta + s / e.a;  // the contact side (sigma = -1)
      const double nx = std::cos(th), ny = std::sin(th), x = e.cx + e.a * nx, y = e.cy + e.a * ny;
      const EndDerivatives v = end_field(e, f, x, y);
      const double size = std::pow(s, f == EndField::Gap32 ? 1.5 : 2.5);
      EXPECT_LT(std::abs(v.w), 1e-12 * size);
      EXPECT_LT(std::abs(v.wx * nx + v.wy * ny), 1e-10 * size / s);
      auto nn = [&](double d) {
        const EndDerivatives u = end_field(e, f, x + d * nx, y + d * ny);
        return u.wxx * nx * nx + 2 * u.wxy * nx * ny + u.wyy * ny * ny;
      };
      EXPECT_NEAR(nn(1e-12), nn(-1e-12), 1e-6 * size / (s * s));
    }
}

// F_52's third normal derivative jumps across the contact side by -30 s^(-1/2) (the line load of an
// end, which grows like the inverse square root of the distance to it): -2 G'''(pi) with
// G''' = (125/8) sin(5 w / 2) - (5/8) sin(w / 2), worked by hand. One-sided differences of the second
// normal derivative, far from the end where the rim's curvature barely bends the field.
TEST(ContactEnd, TheEndsFieldCarriesALoadThatGrowsLikeTheInverseSquareRoot) {
  const ContactEnd e = scene_end();
  for (double s : {0.0005, 0.002}) {
    const double th = e.theta + s / e.a, nx = std::cos(th), ny = std::sin(th), x = e.cx + e.a * nx, y = e.cy + e.a * ny;
    auto nn = [&](double d) {
      const EndDerivatives u = end_field(e, EndField::Gap52, x + d * nx, y + d * ny);
      return u.wxx * nx * nx + 2 * u.wxy * nx * ny + u.wyy * ny * ny;
    };
    const double d = 1e-3 * s;
    const double jump = (nn(d) - nn(1e-12)) / d - (nn(-1e-12) - nn(-d)) / d;
    EXPECT_NEAR(jump * std::sqrt(s), -30.0, 0.3);
  }
}

// chi (F - I_h F) is zero at every node with its slopes: the grid's unknowns stay the nodal values
// of the whole field. Between nodes it is not zero where F is not a bicubic.
TEST(ContactEnd, TheEnrichmentVanishesAtTheNodes) {
  const ContactEnd e = scene_end();
  const Grid g = make_grid(64, 1.0, 0.5);
  double between = 0;
  for (int j = 10; j < 25; ++j)
    for (int i = 45; i < 64; ++i) {
      EXPECT_LT(std::abs(end_function(e, EndField::Gap52, g, i * g.h, j * g.h).w), 1e-15);
      between = std::max(between, std::abs(end_function(e, EndField::Gap52, g, (i + 0.5) * g.h, (j + 0.5) * g.h).w));
    }
  EXPECT_GT(between, 1e-8);
}

// The fit as a solve would use it: the end put at e, the gap sampled beyond it, e moved by the shift
// the fit finds (at most an eighth of the samples' reach: the expansion holds where the shift is
// small against s), again. On a gap with the next term of an end's expansion it settles on the end.
TEST(ContactEnd, TheFitFindsAnEndPutOffByHand) {
  for (double end : {-0.004, 0.0, 0.003}) {
    auto gap = [&](double x) { return x > end ? 0.34 * std::pow(x - end, 2.5) - 1.5 * std::pow(x - end, 3.5) : 0.0; };
    double e = end == 0 ? 0.002 : 0.0;
    for (int k = 0; k < 12; ++k) {
      std::vector<double> s, g;
      for (int i = 0; i < 60; ++i) {
        const double si = 0.001 + 0.02 * i / 59.0;
        if (gap(e + si) > 0) s.push_back(si), g.push_back(gap(e + si));
      }
      e += std::clamp(end_shift(s, g), -0.0025, 0.0025);
    }
    EXPECT_NEAR(e, end, 1e-7) << "end " << end;
  }
  EXPECT_THROW(end_shift({0.01, 0.02}, {1e-6, 2e-6}), std::invalid_argument);
  std::vector<double> s, below;  // a plate that dips below the rim beyond the end
  for (double si : {0.01, 0.02, 0.03, 0.04}) s.push_back(si), below.push_back(-std::pow(si, 2.5));
  EXPECT_THROW(end_shift(s, below), std::invalid_argument);
}
