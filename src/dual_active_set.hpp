// The exact constraint for any sampling: w minimises 1/2 w^T K w - F^T w subject to S w >= phi,
// whatever the rows of S are (Gauss points, points on the obstacle's edge, nodes, or a mix).
// One factorisation of K; the rows that may touch get a column of G = S K^{-1} S^T each, and the
// small dense dual problem on them is solved by the dual active-set method (D20).
#pragma once
#include <functional>

#include "cholesky.hpp"
#include "exact.hpp"

namespace plate {

// Columns of G per block of solves with the one factor of K. Measured: per column, 32-64
// right-hand sides at once cost a fifth of a single one.
constexpr int kGramBlock = 32;

// `candidates` (one flag per sample row; empty: none) are the rows predicted to touch, for
// instance by the solution on a coarser grid. Rows found violated later join them.
ExactResult solve_exact_rows(const Problem& p, const ExactOptions& o, const NodeSet& candidates);

// Rows a solve adds to its problem as it goes. Called whenever the rows it has are all satisfied, it
// appends to p the rows that the answer w violates between them by more than `slack` (an exchange
// method for a constraint on a whole curve, rim_exchange.hpp) and returns how many; the rows before
// them stay as they were.
using RowExchange = std::function<int(Problem& p, const VectorXd& w, double slack)>;
// The same with an exchange, and with K's factor given (null: factorised here).
ExactResult solve_exact_rows(Problem& p, const ExactOptions& o, const NodeSet& candidates, const RowExchange& exchange,
                             const Cholesky* factor);

}  // namespace plate
