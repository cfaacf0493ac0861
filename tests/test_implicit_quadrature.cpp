// The rule on implicitly defined regions (D30) against closed forms: the disk's area and moments,
// the region under a cubic, and, for the two together, an independent one-dimensional integral.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <functional>

#include "implicit_quadrature.hpp"
#include "mirror.hpp"
#include "paper_case.hpp"
#include "penalty_integral.hpp"

namespace plate {
namespace {

// A cubic in power form a0 + a1 u + a2 u^2 + a3 u^3 in Bernstein form.
std::array<double, 4> bernstein(double a0, double a1, double a2, double a3) {
  return {a0, a0 + a1 / 3, a0 + 2 * a1 / 3 + a2 / 3, a0 + a1 + a2 + a3};
}

TEST(CubicRoots, FindsEachRootOfThreeAndNoneOfACubicThatStaysPositive) {
  // (u - 0.2)(u - 0.5)(u - 0.9) = u^3 - 1.6 u^2 + 0.73 u - 0.09
  const std::vector<double> r = cubic_roots(bernstein(-0.09, 0.73, -1.6, 1));
  ASSERT_EQ(r.size(), 3u);
  EXPECT_NEAR(r[0], 0.2, 1e-15);
  EXPECT_NEAR(r[1], 0.5, 1e-15);
  EXPECT_NEAR(r[2], 0.9, 1e-15);
  EXPECT_TRUE(cubic_roots(bernstein(0.02, -0.2, 1, 0)).empty());  // u^2 - 0.2 u + 0.02 >= 0.01
  EXPECT_TRUE(cubic_roots(bernstein(1, 1, 1, 1)).empty());
}

// Each square of an n x n grid on the unit square, the functions given by their corner jets.
using Jet = std::function<CornerJet(double, double)>;
std::vector<WeightedPoint> rule_on_grid(int n, const std::vector<Jet>& fields, ImplicitOrders orders) {
  std::vector<WeightedPoint> pts;
  const double h = 1.0 / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      std::vector<Bicubic> psi;
      for (const Jet& f : fields) {
        std::array<CornerJet, 4> c;
        for (int k = 0; k < 4; ++k) c[k] = f((i + (k & 1)) * h, (j + (k >> 1)) * h);
        psi.push_back(bicubic_from_corners(c, h, h));
      }
      implicit_rule(i * h, j * h, h, h, psi, orders, pts);
    }
  return pts;
}
double integrate(const std::vector<WeightedPoint>& pts, const std::function<double(double, double)>& g) {
  long double s = 0;
  for (const WeightedPoint& p : pts) s += p.weight * g(p.x, p.y);
  return static_cast<double>(s);
}

constexpr double cx = 0.43, cy = 0.57, r = 0.3;
CornerJet circle(double x, double y) { return {(x - cx) * (x - cx) + (y - cy) * (y - cy) - r * r, 2 * (x - cx), 2 * (y - cy), 0}; }
double g(double x) { return 0.3 + 0.2 * x + 0.1 * x * x - 0.15 * x * x * x; }
CornerJet below_cubic(double x, double y) { return {y - g(x), -(0.2 + 0.2 * x - 0.45 * x * x), 1, 0}; }

TEST(ImplicitRule, TheDiskHasItsAreaAndSecondMomentOnGridsThatCutItAnywhere) {
  for (int n : {8, 17, 64}) {
    const std::vector<WeightedPoint> pts = rule_on_grid(n, {circle}, {4, 10});
    const double area = M_PI * r * r;
    EXPECT_NEAR(integrate(pts, [](double, double) { return 1.0; }) / area, 1, 1e-13) << n;
    // int_disk x^2 = pi r^2 cx^2 + pi r^4 / 4
    EXPECT_NEAR(integrate(pts, [](double x, double) { return x * x; }) / (area * cx * cx + M_PI * std::pow(r, 4) / 4), 1, 1e-13) << n;
  }
}

TEST(ImplicitRule, AcrossTheLinesTheErrorFallsGeometricallyWithTheNumberOfPoints) {
  // A circle in three squares: the heights are square roots, smooth but not polynomial.
  double previous = 1;
  for (int across : {4, 8, 12, 16}) {
    const std::vector<WeightedPoint> pts = rule_on_grid(3, {circle}, {4, across});
    const double error = std::abs(integrate(pts, [](double, double) { return 1.0; }) / (M_PI * r * r) - 1);
    EXPECT_LT(error, previous / 50) << across;
    previous = std::max(error, 1e-15);
  }
  EXPECT_LT(previous, 1e-13);
}

TEST(ImplicitRule, TheRegionUnderACubicIsIntegratedExactlyAlongItsLines) {
  // int_0^1 g = 0.3 + 0.1 + 0.1 / 3 - 0.15 / 4, and int y^6 over {y < g} = int g^7 / 7, a
  // polynomial of degree 21 across the lines: 11 points on each line and across them are exact.
  const double area = 0.3 + 0.1 + 0.1 / 3 - 0.0375;
  std::vector<WeightedPoint> ref;  // the tensor rule on the unit square: the y-integral of 1 is 1
  implicit_rule(0, 0, 1, 1, {}, {30, 30}, ref);
  double g7 = 0;
  for (const WeightedPoint& p : ref) g7 += p.weight * std::pow(g(p.x), 7) / 7;
  for (int n : {1, 4, 16}) {
    const std::vector<WeightedPoint> pts = rule_on_grid(n, {below_cubic}, {11, 11});
    EXPECT_NEAR(integrate(pts, [](double, double) { return 1.0; }) / area, 1, 1e-15) << n;
    EXPECT_NEAR(integrate(pts, [](double, double y) { return std::pow(y, 6); }) / g7, 1, 1e-14) << n;
  }
}

// The area of {inside the disk, below the cubic} by one integral in theta, x = cx + r sin theta,
// of the length of the vertical chord below the cubic: smooth between the angles where the cubic
// meets the circle, which are found by bisection and made breaks of an adaptive Simpson rule.
double chord_length(double theta) {
  const double x = cx + r * std::sin(theta), half = r * std::cos(theta);
  return std::max(0.0, std::min(g(x), cy + half) - (cy - half)) * r * std::cos(theta);
}
double simpson(double a, double b, double fa, double fm, double fb, double whole, int depth) {
  const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  const double flm = chord_length(lm), frm = chord_length(rm);
  const double left = (m - a) / 6 * (fa + 4 * flm + fm), right = (b - m) / 6 * (fm + 4 * frm + fb);
  if (depth > 40 || std::abs(left + right - whole) < 1e-16) return left + right + (left + right - whole) / 15;
  return simpson(a, m, fa, flm, fm, left, depth + 1) + simpson(m, b, fm, frm, fb, right, depth + 1);
}

TEST(ImplicitRule, TheDiskBelowACubicAgreesWithAnIndependentIntegralInTheAngle) {
  std::vector<double> breaks{-M_PI / 2, M_PI / 2};
  auto gap = [](double th, int side) {  // the cubic above the circle's lower (side 0) or upper (1) point
    const double x = cx + r * std::sin(th), half = r * std::cos(th);
    return g(x) - (side ? cy + half : cy - half);
  };
  const int steps = 4000;
  for (int side : {0, 1})
    for (int k = 0; k < steps; ++k) {
      double a = -M_PI / 2 + M_PI * k / steps, b = a + M_PI / steps;
      if ((gap(a, side) < 0) == (gap(b, side) < 0)) continue;
      for (int it = 0; it < 80; ++it) {
        const double m = 0.5 * (a + b);
        ((gap(m, side) < 0) == (gap(a, side) < 0) ? a : b) = m;
      }
      breaks.push_back(0.5 * (a + b));
    }
  std::sort(breaks.begin(), breaks.end());
  ASSERT_GE(breaks.size(), 4u) << "the cubic must cross the circle for this test to mean something";
  double reference = 0;
  for (size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double a = breaks[i], b = breaks[i + 1], m = 0.5 * (a + b);
    const double fa = chord_length(a), fm = chord_length(m), fb = chord_length(b);
    reference += simpson(a, b, fa, fm, fb, (b - a) / 6 * (fa + 4 * fm + fb), 0);
  }
  for (int n : {8, 32}) {
    const std::vector<WeightedPoint> pts = rule_on_grid(n, {circle, below_cubic}, {4, 10});
    EXPECT_NEAR(integrate(pts, [](double, double) { return 1.0; }) / reference, 1, 1e-12) << n;
  }
}

TEST(ImplicitRule, ABoxOutsideGivesNoPointAndABoxInsideTheTensorRule) {
  std::vector<WeightedPoint> pts;
  implicit_rule(0.9, 0.9, 0.1, 0.1, {bicubic_from_corners({circle(0.9, 0.9), circle(1, 0.9), circle(0.9, 1), circle(1, 1)}, 0.1, 0.1)}, {4, 8}, pts);
  EXPECT_TRUE(pts.empty());
  implicit_rule(0.4, 0.5, 0.1, 0.1, {bicubic_from_corners({circle(0.4, 0.5), circle(0.5, 0.5), circle(0.4, 0.6), circle(0.5, 0.6)}, 0.1, 0.1)}, {4, 8}, pts);
  EXPECT_EQ(pts.size(), 16u);
  EXPECT_THROW(implicit_rule(0, 0, -1, 1, {}, {4, 8}, pts), std::invalid_argument);
  EXPECT_THROW(implicit_rule(0, 0, 1, 1, {}, {0, 8}, pts), std::invalid_argument);
}

// A curve along a line the rule halves on (a ray of (D31) along a grid line) vanishes on that line:
// it splits nothing there, and the rule must not go on halving it (it did, towards 2^48 pieces, and
// ran out of memory). The region left of x = 1/2, the first halving, in a disk about (1/2, 1/2) is
// half the disk. Where the line meets the circle's top and bottom no axis makes both monotone, so
// the rule halves down to its depth limit there and tests points one by one: the area is right to
// within the boxes left at that depth, 4^-12 each, a few about each of the two crossings.
TEST(ImplicitRule, ACurveAlongALineOfTheRuleSplitsNothingThere) {
  std::vector<WeightedPoint> pts;
  const double a = 0.3;
  const std::array<CornerJet, 4> line{CornerJet{-0.5, 1, 0, 0}, CornerJet{0.5, 1, 0, 0}, CornerJet{-0.5, 1, 0, 0}, CornerJet{0.5, 1, 0, 0}};
  implicit_rule(0, 0, 1, 1, {bicubic_from_corners(line, 1, 1), circle_on(0.5, 0.5, a, 0, 0, 1)}, {4, 16}, pts, 12);
  EXPECT_NEAR(integrate(pts, [](double, double) { return 1.0; }), M_PI * a * a / 2, 2 * 4 * std::pow(4.0, -12));
  EXPECT_LT(pts.size(), 100000u);
}

// The circle's level function is biquadratic, so its bicubic on a square is the function itself,
// off the square's corners too; checked against the formula at points of an off-centre square.
TEST(ImplicitRule, TheCirclesBicubicIsItsLevelFunctionExactly) {
  const double x0 = 0.31, y0 = 0.62, size = 0.07;
  const Bicubic p = circle_on(cx, cy, r, x0, y0, size);
  for (double t : {0.0, 0.13, 0.5, 0.91})
    for (double s : {0.0, 0.37, 0.77, 1.0}) EXPECT_NEAR(p(t, s), circle(x0 + t * size, y0 + s * size).f, 1e-15) << t << " " << s;
}

}  // namespace
}  // namespace plate

namespace plate {
namespace {

// The penalty's rule on a plate (penalty_integral.hpp): with no field it covers the disk, on the
// whole plate and on the quarter the mirror lines leave; with w = 0 < R the region is the disk again;
// with the field far above the obstacle it is empty. The paper's disk has radius 1/4 and lies on no
// grid line's tangent, so each grid's squares cut it differently.
TEST(PenaltyRule, CoversTheDiskOnTheWholePlateAndTheQuarterAndNothingWhereTheFieldIsAbove) {
  const Scene s = paper_scene();
  const double r = s.cylinder->radius, disk = M_PI * r * r;
  for (int n : {16, 40, 64}) {
    const Problem whole = make_problem(s, make_grid(n), SamplingSpec{SamplingKind::Gauss});
    EXPECT_NEAR(penalty_rule(whole, nullptr).weights.sum(), disk, 1e-13) << n;
    const VectorXd zero = VectorXd::Zero(whole.grid.unknowns());
    EXPECT_NEAR(penalty_rule(whole, &zero).weights.sum(), disk, 1e-13) << n;
    // 2 R at every node with unknowns, zero slopes: the field is 2 R on every square no clamped edge
    // touches, which includes every square the disk reaches, so no point of the disk lies below R.
    VectorXd high = VectorXd::Zero(whole.grid.unknowns());
    for (Eigen::Index k = 0; k < high.size(); k += 4) high[k] = 2 * s.cylinder->height;
    EXPECT_EQ(penalty_rule(whole, &high).weights.size(), 0) << n;
    const SamplingSpec spec{SamplingKind::Gauss};
    const Grid g = make_grid(n);
    const Problem quarter = make_problem(s, part_of(g, find_mirrors(s, g, spec)), spec);
    EXPECT_NEAR(penalty_rule(quarter, nullptr).weights.sum(), disk / 4, 1e-13) << n;
  }
}

}  // namespace
}  // namespace plate
