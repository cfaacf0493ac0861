// Where an obstacle jumps with no edge curve there to carry its rows. A jump sampled at nodes alone
// moves the discrete contact line by up to a cell, unevenly from grid to grid, so the answer
// converges like h with steps that no error bar from the grids (D29) can follow: a cylinder written
// as an expression, with no --edge, is 4.5e-4 off at n = 64 with a bar of 1.2e-4.
#pragma once
#include <vector>

#include "assemble.hpp"
#include "edge.hpp"
#include "grid.hpp"

namespace plate {

struct ObstacleJump {
  double x = 0, y = 0;  // where on a grid line, to about 1e-12 h
  double size = 0;      // |phi| across it (infinite where one side is -inf: no constraint there)
  double upper = 0;     // phi on its higher side
};

// The jumps of phi along the lines of g (its nodes' rows and columns) farther than two cells from
// `edge` (every jump if it is empty). A side of a cell is looked at if phi is -inf at one end only,
// or if its change is four times either neighbouring side's; it holds a jump if, halved forty times
// towards the larger change, a quarter of the change is still there (a smooth phi's would be about
// 1e-12 of it).
std::vector<ObstacleJump> obstacle_jumps(const Grid& g, const Field& phi, const EdgeCurve& edge);

}  // namespace plate
