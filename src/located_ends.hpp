// A solve on a circle where the plate touches arcs of the rim, with the field of each end of the
// contact carried and each end located (issue 39's step towards the lift-off default): the rows laid
// out with the spline arcs ending at the ends and points beyond them, the space widened by F_32 and
// F_52 at every end (contact_end.hpp, attach_ends), and each end moved by the fit of the gap the
// answer leaves beyond it (end_shift) until no end moves by more than `settled`. The whole plate
// only: a part would need each end's mirror images moved with it.
#pragma once
#include <vector>

#include "exact.hpp"
#include "problem.hpp"
#include "rim_rows.hpp"

namespace plate {

struct EndsOptions {
  double dense = 8;          // point rows per cell for four cells beyond each end
  double inner = 0.05;       // the ends' cut-off: 1 within `inner` of the end, 0 from `outer` on
  double outer = 0.1;
  double settled = 1e-9;     // the ends stop when none moves by more than this (an angle)
  int max_moves = 30;        // moves at most; then EndsSolve::settled is false
  EnrichSpec enrich;         // (D31) on the rim too, or not
};

struct EndsSolve {
  Problem problem;           // the last one solved: its rows, its ends
  ExactResult result;
  int moves = 0;
  bool settled = false;      // every end moved by at most EndsOptions::settled on the last solve
  // Per end of problem.ends (two functions each, so every second entry): the point rows within four
  // cells beyond it that bear load, and the cells from the end to the first of them.
  std::vector<int> pushing;
  std::vector<double> nearest_push;
};

// The rows for `contact` (arcs of the whole rim): graded splines on each arc right to its ends (no
// margin), points a cell apart off the arcs, and `dense` a cell for four cells beyond each end in
// place of the lattice's, from `skip` cells on.
void lay_out_for_ends(Problem& p, const ContactArcs& contact, double dense, double skip);

// The scene's plate on n cells, the contact starting from `contact` (arcs of the whole rim, not the
// whole rim). Throws std::invalid_argument, naming what is wrong, for a scene that is not a
// cylinder's, options out of range (0 < inner < outer, dense >= 1, settled > 0, max_moves >= 0),
// an arc shorter than four cells or a gap between arcs shorter than eight (each end's points take
// four), at the start or after a move, or a cut-off that reaches a clamped edge.
EndsSolve solve_located_ends(const Scene& scene, int n, ContactArcs contact, const ExactOptions& o, const EndsOptions& e);

}  // namespace plate
