// The closed form of the disk on a flat punch (D23)-(D25), checked against the conditions that
// define it (by finite differences of w(r), not by its coefficients) and against the classical
// point-load formula it must reduce to as the punch shrinks.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "disk_punch.hpp"
#include "paper_case.hpp"

using namespace plate;

namespace {
// Radial derivatives of w from one side of r only (s = +1: r and beyond, s = -1: r and before),
// second-order one-sided differences with step d, so that a jump at r is not smeared.
double slope(const DiskPunch& p, double r, double d, int s) {
  return s * (-3 * p.deflection(r) + 4 * p.deflection(r + s * d) - p.deflection(r + 2 * s * d)) / (2 * d);
}
double curvature(const DiskPunch& p, double r, double d, int s) {
  return (2 * p.deflection(r) - 5 * p.deflection(r + s * d) + 4 * p.deflection(r + 2 * s * d) -
          p.deflection(r + 3 * s * d)) / (d * d);
}
// Lap w = w'' + w' / r by central differences, away from the rim.
double laplacian(const DiskPunch& p, double r, double d) {
  return (p.deflection(r + d) - 2 * p.deflection(r) + p.deflection(r - d)) / (d * d) +
         (p.deflection(r + d) - p.deflection(r - d)) / (2 * d * r);
}
}  // namespace

TEST(DiskPunch, MeetsTheClampedContactAndMatchingConditions) {
  for (double b : {0.1, 0.25, 0.4}) {
    const DiskPunch s{0.5, b, 0.0625};
    const double d = 1e-4;
    EXPECT_NEAR(s.deflection(s.a), 0, 1e-13 * s.R) << "b = " << b;
    EXPECT_NEAR(slope(s, s.a, d, -1), 0, 1e-6) << "b = " << b;
    EXPECT_NEAR(s.deflection(b), s.R, 1e-13 * s.R) << "b = " << b;                   // inner formula
    EXPECT_NEAR(s.deflection(b * (1 + 1e-15)), s.R, 1e-13 * s.R) << "b = " << b;     // outer formula
    // slope and curvature from either side of the rim agree (the line load jumps the shear only)
    const double in1 = slope(s, b, d, -1), out1 = slope(s, b, d, +1);
    EXPECT_NEAR(in1, out1, 1e-6 * (1 + std::abs(in1))) << "b = " << b;
    const double in2 = curvature(s, b, 1e-3, -1), out2 = curvature(s, b, 1e-3, +1);
    EXPECT_NEAR(in2, out2, 1e-3 * std::abs(in2)) << "b = " << b;
    // Lap^2 w = 0 on either side, and the shear r (Lap w)' is 0 inside and b q outside: integrating
    // Lap^2 w = q delta(r - b) over a disk about the centre. Finite differences away from the rim.
    const double h = 1e-3;
    auto shear = [&](double r) { return r * (laplacian(s, r + h, h) - laplacian(s, r - h, h)) / (2 * h); };
    for (double r : {0.5 * b, 0.8 * b}) EXPECT_NEAR(shear(r), 0, 1e-5 * b * s.line_load()) << "b = " << b << ", r = " << r;
    for (double r : {b + 0.3 * (s.a - b), b + 0.6 * (s.a - b)})
      EXPECT_NEAR(shear(r), b * s.line_load(), 1e-5 * b * s.line_load()) << "b = " << b << ", r = " << r;
  }
}

TEST(DiskPunch, BulgesAboveThePunchAndPushesOnIt) {
  // The answer of the obstacle problem only if the plate stays on or above the punch inside the
  // rim and the punch pushes (q > 0): then the contact is the rim, as assumed.
  for (double b : {0.01, 0.1, 0.25, 0.4, 0.49}) {
    const DiskPunch s{0.5, b, 0.0625};
    EXPECT_GT(s.line_load(), 0) << "b = " << b;
    for (double r = 0; r < b; r += b / 16) EXPECT_GE(s.deflection(r), s.R) << "b = " << b << ", r = " << r;
    EXPECT_GT(s.centre(), s.R) << "b = " << b;
  }
}

TEST(DiskPunch, ShrinkingThePunchGivesTheClassicalPointLoad) {
  // A clamped disk under a central point load P deflects P a^2 / (16 pi D) at its centre
  // (Timoshenko & Woinowsky-Krieger): so R / (P a^2) -> 1 / (16 pi) as b -> 0. The difference
  // shrinks as b^2 ln b, about 4e-7 relative at b / a = 1e-4.
  const double published = plate_constant("disk_point_centre");
  const DiskPunch s{1.0, 1e-4, 1.0};
  EXPECT_NEAR(s.R / (s.total_force() * s.a * s.a), published, 1e-6 * published);
  const DiskPunch wide{1.0, 0.5, 1.0};  // and a wide punch is not a point load
  EXPECT_GT(std::abs(wide.R / (wide.total_force() * wide.a * wide.a) - published), 0.1 * published);
}

TEST(DiskPunch, RefusesAPunchNoSmallerThanThePlate) {
  EXPECT_THROW((DiskPunch{0.5, 0.5, 0.0625}.centre()), std::invalid_argument);
  EXPECT_THROW((DiskPunch{0.5, -0.1, 0.0625}.centre()), std::invalid_argument);
  EXPECT_THROW((DiskPunch{0.5, 0.25, 0}.centre()), std::invalid_argument);
  EXPECT_THROW((DiskPunch{0.5, NAN, 0.0625}.centre()), std::invalid_argument);
}
