// The mirror symmetries of a scene, and the part of the plate that carries them.
//
// When the rectangle, the obstacle (with its edge) and the load are unchanged by the reflection
// x -> lx - x, so is the answer: the discrete energy is strictly convex and the constraints form a
// convex set, so the minimiser is unique and equals its own mirror image. A symmetric plate is
// fixed by its left half, where its energy is half the whole's, and a constraint row holds exactly
// when its image does. So the half [0, lx/2] x [0, ly], clamped where the plate is clamped and with
// w_x = w_xy = 0 on the line x = lx/2 (a symmetric C^1 plate has no slope across it), solves the
// whole plate's discrete problem: its rows are one per pair of images, a row on the line (its own
// image) keeping half its weight. The same holds for y -> ly - y, and for both: a quarter.
#pragma once
#include <string>

#include "problem.hpp"

namespace plate {

struct Mirrors {
  bool x = false;  // about x = lx / 2
  bool y = false;  // about y = ly / 2
  bool any() const { return x || y; }
};
// "whole plate", "half (mirror line x = lx/2)", "half (mirror line y = ly/2)" or "quarter (...)".
std::string describe(Mirrors m);

// The mirrors of the scene on the whole grid `whole`: a mirror line must be a grid line (an even
// number of cells across), the edge points of the sampling must map onto edge points, and the
// obstacle at every node, Gauss point and edge point, and the load at every Gauss point (where F
// samples it), must equal their values at the mirror images to 1e-12 of each pair's own size
// (plus 1e-15 of the field's largest, for values near zero).
Mirrors find_mirrors(const Scene& s, const Grid& whole, const SamplingSpec& spec);

// The part of `whole` that the mirrors leave: half the cells across each mirror line, the line its
// mirror edge.
Grid part_of(const Grid& whole, Mirrors m);

// The whole plate's unknowns from the part's: each node takes its image's values, with the slope
// across a mirror line (and w_xy) changing sign.
VectorXd unfold_unknowns(const Grid& whole, const Grid& part, const VectorXd& w_part);

// A value per sample of the whole plate from one per sample of the part: each sample takes the
// value of the part's sample at its mirror image. Throws std::logic_error if an image is not a
// sample of the part (the two samplings would not be one problem).
VectorXd unfold_samples(const Sampling& whole, const Sampling& part, const Grid& part_grid, const VectorXd& v);

}  // namespace plate
