// Exact solves (exact.hpp) where every row bounds one nodal value (nodal sampling, and edge sampling
// with no edge): primal-dual active sets, a semismooth Newton method (D9)-(D10), with a monotone
// primal active-set fallback that cannot cycle, both on one factorisation of K reused for nearby
// sets (fixed_set.hpp).
#pragma once
#include "exact.hpp"

namespace plate {

// One grid, from the starting active set `initial` (one flag per node; empty: none). Throws
// std::invalid_argument unless p.sampling.nodal_bounds().
ExactResult solve_exact_nodes(const Problem& p, const ExactOptions& o, NodeSet initial = {});

}  // namespace plate
