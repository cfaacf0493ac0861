// Where the constraint w >= phi is imposed: sample points x_p with positive weights W_p and the
// sparse matrix S taking the unknowns to the point values (S w)_p = w_h(x_p). The penalty term of
// (8) is then eps^{-1} S^T W beta(S w), whichever sampling is used.
#pragma once
#include <string>
#include <vector>

#include "grid.hpp"
#include "sparse.hpp"

namespace plate {

enum class SamplingKind {
  Gauss,  // 4 x 4 Gauss points per element with their weights: (8) with the L2 product, exactly
  Nodes,  // interior grid nodes with weight h^2: the trapezoid rule, constraints on nodal values
};

struct Sampling {
  SamplingKind kind;
  std::vector<double> x, y;  // the points
  VectorXd weights;          // W_p > 0
  RowSpMat S;                // points x unknowns
  int size() const { return static_cast<int>(x.size()); }
};

Sampling make_sampling(const Grid& g, SamplingKind kind);
const char* to_string(SamplingKind kind);

// S^T diag(d) S, visiting only the points with d_p != 0 (the active ones, in the schemes).
SpMat weighted_gram(const RowSpMat& S, const VectorXd& d, int unknowns);

// S^T W S. For Gauss sampling this equals the consistent mass matrix, which we assemble by
// stencil instead of from 16 points per element (a test checks the two agree).
SpMat sampling_mass(const Grid& g, const Sampling& s);

}  // namespace plate
