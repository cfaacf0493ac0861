// Where an obstacle jumps with no edge rows there. A jump sampled at nodes alone moves the discrete
// contact line by up to a cell, unevenly from grid to grid, so the answer converges like h with
// steps that no error bar from the grids (D29) can follow: a cylinder written as an expression, with
// no --edge, is 4.5e-4 off at n = 64 with a bar of 1.2e-4 (the series gives 0.0680667842).
#pragma once
#include <vector>

#include "assemble.hpp"
#include "edge.hpp"
#include "grid.hpp"

namespace plate {

struct ObstacleJump {
  double x = 0, y = 0;  // where on a grid line, to about 1e-12 h
  double size = 0;      // the change of phi along the cell's side that holds it
  bool ends = false;    // phi is -inf on one side (the obstacle's support ends there)
  double upper = 0;     // phi on its higher side
};

// The jumps of phi along the interior lines of g (its nodes' rows and columns off the clamped
// edge) that do not lie on `edge` (within 1e-6 h; every jump if it is empty). A side of a cell is
// looked at if phi is -inf at one end only, or if its change is four times that of a neighbouring
// side (the lesser, so that jumps in two neighbouring sides are both looked at); it holds a jump if,
// halved forty times towards the larger change, a quarter of the change is still there (a
// continuous phi's would be about 1e-12 of it). At most 2 (n + 1)^2 + 40 per side looked at
// evaluations of phi. A feature that lies between the lines stays unseen.
std::vector<ObstacleJump> obstacle_jumps(const Grid& g, const Field& phi, const EdgeCurve& edge);

}  // namespace plate
