// The exact solver as a user calls it (exact.hpp states the problem): the hand-off to the solver
// the rows call for (primal_dual.hpp for bounds on nodal values, dual_active_set.hpp for any other
// rows), grid sequencing, rows on a circle laid out for the contact (D28), and a scene solved on the
// part of the plate its mirror lines leave.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "exact.hpp"
#include "mirror.hpp"

namespace plate {

// One grid, from the starting active set `initial` (one flag per sample row; empty: none).
ExactResult solve_exact(const Problem& p, const ExactOptions& o, NodeSet initial = {});

// Grid sequencing: solve the problem's scene on the grid with nx / 2 cells first (while nx is even
// and above o.coarsest) and start from the active set its solution predicts. Default rows on a
// circle follow the contact (rim_exchange.hpp, D28): p's sampling and obstacle samples are then
// those the answer was found with, which the result's lambda and active refer to.
ExactResult solve_sequenced(Problem& p, const ExactOptions& o);

// A scene solved exactly on the part of the plate its mirror lines leave (mirror.hpp), or whole when
// it has none or `use_mirrors` is false. The answer is the whole plate's either way: `result.w` and
// `result.lambda` (and `active`) live on whole().grid and whole().sampling; the certificate and the
// levels are those of the problem solved, `solved`, with the part's own w and lambda beside it.
struct SceneSolution {
  Mirrors mirrors;
  Problem solved;                   // the part (or the whole plate), with K, M and F
  std::optional<Problem> unfolded;  // the whole plate's grid, sampling and obstacle, when a part was solved
  ExactResult result;               // on the whole plate
  VectorXd part_w, part_lambda;     // the solve's own, on `solved` (the same as result's when whole)
  const Problem& whole() const { return unfolded ? *unfolded : solved; }
};
// n: cells along x of the whole plate; `mirrors` as find_mirrors found them for that grid (none: whole).
SceneSolution solve_exact_scene(const Scene& s, int n, const SamplingSpec& spec, const ExactOptions& o, Mirrors mirrors);
// The same, finding the scene's mirror lines itself (none when use_mirrors is false).
SceneSolution solve_exact_scene(const Scene& s, int n, const SamplingSpec& spec, const ExactOptions& o, bool use_mirrors = true);


}  // namespace plate
