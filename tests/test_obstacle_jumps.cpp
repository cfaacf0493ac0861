// The jumps of an obstacle along the grid's lines (obstacle_jumps.hpp): found where phi jumps or its
// support ends, to the bisection's precision, and nowhere a continuous phi only bends or steepens.
#include <gtest/gtest.h>

#include <cmath>

#include "obstacle_jumps.hpp"

using namespace plate;

namespace {
Grid unit_grid(int n) {
  Grid g;
  g.nx = g.ny = n;
  g.h = 1.0 / n;
  return g;
}
}  // namespace

TEST(ObstacleJumps, TheEndOfASupportIsFoundOnItsCurveAndNotWhereAnEdgeCarriesIt) {
  const Grid g = unit_grid(32);
  const Field disk = [](double x, double y) { return std::hypot(x - 0.5, y - 0.45) <= 0.23 ? 0.05 : -INFINITY; };
  const std::vector<ObstacleJump> found = obstacle_jumps(g, disk, {});
  // Every line of nodes that crosses the circle crosses it twice: about 4 * 2 * 0.23 / h sides.
  EXPECT_GT(found.size(), 50u);
  for (const ObstacleJump& j : found) {
    EXPECT_NEAR(std::hypot(j.x - 0.5, j.y - 0.45), 0.23, 1e-9) << j.x << ", " << j.y;
    EXPECT_TRUE(std::isinf(j.size));
    EXPECT_EQ(j.upper, 0.05);
  }
  EXPECT_TRUE(obstacle_jumps(g, disk, circle_edge(0.5, 0.45, 0.23)).empty());
  // An edge elsewhere leaves them.
  EXPECT_EQ(obstacle_jumps(g, disk, circle_edge(0.5, 0.45, 0.1)).size(), found.size());
}

TEST(ObstacleJumps, AFiniteJumpIsFoundAndAContinuousObstacleHasNone) {
  const Grid g = unit_grid(16);
  const std::vector<ObstacleJump> step = obstacle_jumps(g, [](double x, double) { return x < 0.53 ? -0.01 : -0.03; }, {});
  ASSERT_EQ(step.size(), 15u);  // one on each interior line of nodes along x
  for (const ObstacleJump& j : step) {
    EXPECT_NEAR(j.x, 0.53, 1e-9);
    EXPECT_NEAR(j.size, 0.02, 1e-15);
    EXPECT_EQ(j.upper, -0.01);
  }
  const Field smooth = [](double x, double y) { return 0.05 - 2 * ((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5)); };
  const Field kink = [](double x, double y) { return -0.01 - std::abs(x - 0.47) - 3 * std::abs(y - 0.52); };
  // Continuous and steep inside one side of a cell, which is then looked at and cleared by bisection.
  const Field steep = [](double x, double) { return -1 + 0.5 * std::tanh(200 * (x - 0.53)); };
  EXPECT_TRUE(obstacle_jumps(g, smooth, {}).empty());
  EXPECT_TRUE(obstacle_jumps(g, kink, {}).empty());
  EXPECT_TRUE(obstacle_jumps(g, steep, {}).empty());
}

// Jumps in two neighbouring sides (a ridge narrower than a cell), and a jump at a node whose value
// lies between the two sides', are each found.
TEST(ObstacleJumps, ARidgeNarrowerThanACellAndAJumpAtANodeAreFound) {
  const Grid g = unit_grid(16);
  const Field ridge = [](double x, double y) { return (std::abs(x - 0.5) < 0.05 ? 0.06 * std::sin(M_PI * y) : 0.0) - 0.01; };
  const std::vector<ObstacleJump> r = obstacle_jumps(g, ridge, {});
  ASSERT_EQ(r.size(), 2u * 15);  // both sides of the ridge on each interior line along x
  for (const ObstacleJump& j : r) EXPECT_NEAR(std::abs(j.x - 0.5), 0.05, 1e-9);
  const Field step = [](double x, double) { return -0.02 + 0.01 * ((x > 0.5) - (x < 0.5)); };  // -0.02 at x = 0.5 itself
  const std::vector<ObstacleJump> s = obstacle_jumps(g, step, {});
  ASSERT_EQ(s.size(), 2u * 15);  // from the side on each hand of the node, on each interior line
  for (const ObstacleJump& j : s) EXPECT_NEAR(j.x, 0.5, 1e-9);
}
