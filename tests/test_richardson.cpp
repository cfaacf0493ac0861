// Richardson extrapolation (D13) on sequences whose limit is known, and the agreement rule built on it.
#include <gtest/gtest.h>

#include <cmath>

#include "crosscheck.hpp"
#include "richardson.hpp"

using namespace plate;

namespace {
// v(h) = L + C h^p + D h^(p+1) on h = 1/8, 1/16, ...
std::vector<double> sequence(double L, double C, double p, double D, int grids) {
  std::vector<double> v;
  for (int k = 0; k < grids; ++k) {
    const double h = std::pow(0.5, 3 + k);
    v.push_back(L + C * std::pow(h, p) + D * std::pow(h, p + 1));
  }
  return v;
}
}  // namespace

TEST(Richardson, FindsTheOrderAndTheLimitOfAKnownSequence) {
  const double L = 0.0976921, p = 3;
  const auto v = sequence(L, 2.0, p, -5.0, 6);
  const Extrapolation e = extrapolate(v);
  ASSERT_TRUE(e.steady);
  EXPECT_NEAR(e.orders.back(), p, 0.05);
  // The bar bounds the true error, and is not vacuous: below the finest value's own error, which
  // the limit improves on at least tenfold.
  EXPECT_LE(std::abs(e.limit - L), e.bar);
  EXPECT_LT(e.bar, std::abs(v.back() - L));
  EXPECT_LT(std::abs(e.limit - L), 0.1 * std::abs(v.back() - L));
}

TEST(Richardson, AnIrregularSequenceKeepsItsFinestValueAndLastIncrement) {
  std::vector<double> v = sequence(1.0, 1.0, 2, 0, 5);
  v[3] += 0.02;  // one grid cut differently: the increments change sign
  const Extrapolation e = extrapolate(v);
  EXPECT_FALSE(e.steady);
  EXPECT_EQ(e.limit, v.back());
  EXPECT_DOUBLE_EQ(e.bar, std::abs(v[4] - v[3]));
}

// Terms of nearby orders can give two triples the same observed order: on v = 1 + h^4 + 0.18 h^3.5
// - h^5 over h = 1/8 ... 1/64 both orders are 3.74 (as FreeFEM's force at eps = 1e-5 on the quarter
// meshes, 3.7), steady, and the limit misses 1 by about five times the bar, which compares two
// triples that share that order. Moving the order by the steady spread (order_doubt) carries it.
TEST(Richardson, TheOrdersDoubtCarriesWhatTheBarMissesWhereOrdersAgreeByChance) {
  std::vector<double> v;
  for (int k = 0; k < 4; ++k) {
    const double h = std::pow(0.5, 3 + k);
    v.push_back(1 + std::pow(h, 4) + 0.18 * std::pow(h, 3.5) - std::pow(h, 5));
  }
  const Extrapolation e = extrapolate(v);
  ASSERT_TRUE(e.steady);
  const double p = e.orders.back();
  EXPECT_NEAR(p, 3.74, 0.01);
  EXPECT_GT(std::abs(e.limit - 1), 4 * e.bar);
  EXPECT_LE(std::abs(e.limit - 1), e.bar + e.order_doubt);
  // The doubt is the limit's move with the order lowered by the spread (the larger way here).
  const double lower = v[3] + (v[3] - v[2]) / (std::pow(2.0, p - kSteadySpread) - 1);
  EXPECT_DOUBLE_EQ(e.order_doubt, std::abs(lower - e.limit));
  EXPECT_EQ(extrapolate({0, 1, 1.25, 1.28125}).order_doubt, 0);  // not steady: none
}

TEST(Richardson, OrdersThatDriftAreNotSteady) {
  // increments 1, 1/4, 1/32: orders 2 then 3, more than 0.3 apart
  const Extrapolation e = extrapolate({0, 1, 1.25, 1.28125});
  ASSERT_EQ(e.orders.size(), 2u);
  EXPECT_NEAR(e.orders[0], 2, 1e-12);
  EXPECT_NEAR(e.orders[1], 3, 1e-12);
  EXPECT_FALSE(e.steady);
}

TEST(Agreement, LimitsAgreeWithinTheSumOfTheirBarsAndNoCloser) {
  Extrapolation a, b;
  a.limit = 1.0, a.bar = 1e-6, a.steady = true;
  b.limit = 1.0 + 1.5e-6, b.bar = 1e-6, b.steady = true;
  Agreement g = compare_limits(a, b);
  EXPECT_TRUE(g.agree);
  EXPECT_TRUE(g.steady);
  EXPECT_NEAR(g.tolerance, 2e-6, 1e-18);
  b.limit = 1.0 + 2.5e-6;
  EXPECT_FALSE(compare_limits(a, b).agree);
  // A bar below the round-off of the limit counts as the round-off.
  b.bar = 0, b.bar_noise = 2e-6, b.steady = false;
  g = compare_limits(a, b);
  EXPECT_NEAR(g.tolerance, 3e-6, 1e-18);
  EXPECT_TRUE(g.agree);
  EXPECT_FALSE(g.steady);
}

// A difference that round-off can make (within ten times the limits' noise, below the digits that
// are printed) is not a disagreement; one beyond both the bars and that is.
TEST(Agreement, ADifferenceWithinRoundOffIsNotADisagreement) {
  Extrapolation a, b;
  a.limit = 1.0, a.bar = 1e-9, a.limit_noise = 1e-9, a.steady = true;
  b.limit = 1.0 + 5e-9, b.bar = 1e-12, b.limit_noise = 1e-12, b.steady = true;
  Agreement g = compare_limits(a, b);
  EXPECT_GT(g.difference, g.tolerance);
  EXPECT_TRUE(g.agree);
  EXPECT_NEAR(g.difference_noise, 1e-9 + 1e-12, 1e-24);
  b.limit = 1.0 + 2e-8;  // beyond ten times the noise and beyond the bars
  EXPECT_FALSE(compare_limits(a, b).agree);
}
