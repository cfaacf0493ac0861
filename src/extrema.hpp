// The extremes of the finite-element fields over the plate, not over the nodes: a peak off the grid
// lines lies between nodes, where the largest nodal value falls short of it by about h^2 times the
// curvature. w_h is C^1 and a cubic in each variable inside each element, so at an interior extremum
// its gradient vanishes: Newton's method on grad w_h = 0 from the best node finds it, with the
// Hessian of the element it is in. Fields with no second derivative at hand (the twisting moment,
// continuous but with a gradient that jumps across element sides) are searched by a pattern of
// points that shrinks onto the extremum.
#pragma once
#include <functional>
#include <utility>
#include <vector>

#include "grid.hpp"
#include "problem.hpp"
#include "sparse.hpp"

namespace plate {

struct Extremum {
  double value = 0, x = 0, y = 0;
};

// The largest value of `sign` w_h (sign +1: max w, -1: min w) on the rectangle of the whole plate
// p holds (its field with the enrichment (D31), if any), from the `starts` best nodes: Newton on grad w_h = 0, each step at most a cell, falling
// back to the pattern search where the Hessian is not definite or a step goes outside; the best point
// found is returned with its value of w_h (not of sign w_h).
Extremum extremum_of_w(const Problem& p, const VectorXd& w, double sign, int starts = 3);
// The same for a field of the grid's functions alone.
Extremum extremum_of_w(const Grid& g, const VectorXd& w, double sign, int starts = 3);

// The largest value of f on the whole plate from (x0, y0) by rounds of a 13 x 13 pattern about the
// best point so far, each round's spacing a fifth of the last, from `step` down to 1e-9 of the plate.
Extremum pattern_maximum(const Grid& g, const std::function<double(double, double)>& f, double x0, double y0,
                         double step);

// What a report reads off an answer w_h, measured once: max w and min w (above), max |m12| (the
// twisting moment with Poisson's ratio nu, by the pattern from its best node), and w_h at `points`.
// On the part of the plate that mirror lines leave, w_h is read on the whole plate through them.
struct FieldMeasures {
  Extremum max_w, min_w, max_abs_m12;
  std::vector<double> w_at;  // at the points, in order
};
FieldMeasures measure_field(const Problem& p, const VectorXd& w, double nu, const std::vector<std::pair<double, double>>& points);

}  // namespace plate
