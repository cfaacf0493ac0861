// The equality-constrained step inside every active-set iteration: minimise the discrete energy
// 1/2 w^T K w - F^T w with the value unknowns of a set A of nodes held at phi. One factorisation
// of K with a set A0 decoupled serves every nearby set A1 through a small dense correction.
#pragma once
#include <unordered_map>
#include <vector>

#include "cholesky.hpp"

namespace plate {

using NodeSet = std::vector<char>;  // membership flag per interior node

// How many nodes the set holds.
inline int members(const NodeSet& s) {
  int c = 0;
  for (char v : s) c += v != 0;
  return c;
}

// Right-hand sides per block of correction solves: many at once run at BLAS-3 speed, but each
// costs a vector of the grid's size.
constexpr int kCorrectionBlock = 16;

class FixedSetSolver {
 public:
  // K, F: stiffness and load; phi: obstacle at the interior nodes. The node of value unknown 4p is p.
  // max_correction: largest |A0 xor A1| solved from A0's factor; beyond it we refactorise.
  FixedSetSolver(const SpMat& K, const VectorXd& F, const VectorXd& phi, int max_correction);

  // The minimiser with w_p = phi_p for every p in `fixed` (exactly: those entries are set, not solved).
  VectorXd solve(const NodeSet& fixed);

  int factorizations() const { return chol_.factorizations(); }
  long correction_columns() const { return correction_columns_; }

 private:
  void factorize(const NodeSet& fixed);
  void add_columns(const std::vector<int>& nodes);  // responses of A0's system, cached per node
  bool in_base(int node) const { return base_[node] != 0; }

  const SpMat& K_;
  const VectorXd& F_;
  const VectorXd& phi_;
  int max_correction_;
  Cholesky chol_;
  NodeSet base_;    // A0, the set the current factor decouples
  VectorXd w0_;     // the minimiser for A0 itself
  std::unordered_map<int, VectorXd> columns_;  // responses of A0's system to one node's change
  long correction_columns_ = 0;
};

// K with the value unknowns of the nodes in `fixed` decoupled: their rows and columns are zero
// except the diagonal, which keeps K's value. The sparsity pattern is K's, explicit zeros included,
// so the symbolic analysis of K serves every set.
SpMat decoupled(const SpMat& K, const NodeSet& fixed);

}  // namespace plate
