// A0's factor solves a nearby set A1 exactly: a node newly held contributes an unknown force s_q at
// its value unknown, a node released contributes an unknown value shift u_r, and
//   w = w0 + sum_q s_q y_q + sum_r u_r z_r
// with y_q, z_r solves with A0's factor. The |A0 xor A1| conditions (w_q = phi_q on new nodes,
// (K w - F)_r = 0 on released ones) form a small dense system: a bordered (capacitance) solve.
#include "fixed_set.hpp"

#include <algorithm>
#include <stdexcept>

#include <Eigen/LU>

namespace plate {

SpMat decoupled(const SpMat& K, const NodeSet& fixed) {
  SpMat A = K;
  auto held = [&](Eigen::Index dof) { return dof % 4 == 0 && fixed[dof / 4]; };
  for (Eigen::Index col = 0; col < A.outerSize(); ++col)
    for (SpMat::InnerIterator it(A, col); it; ++it)
      if (it.row() != col && (held(it.row()) || held(col))) it.valueRef() = 0.0;
  return A;
}

FixedSetSolver::FixedSetSolver(const SpMat& K, const VectorXd& F, const VectorXd& phi, int max_correction)
    : K_(K), F_(F), phi_(phi), max_correction_(max_correction) {
  if (4 * phi.size() != K.rows()) throw std::invalid_argument("FixedSetSolver: phi must have one value per node");
}

void FixedSetSolver::factorize(const NodeSet& fixed) {
  base_ = fixed;
  chol_.factorize(decoupled(K_, fixed));
  // Right-hand side of A0's system: the load, minus what the held values push into the free rows.
  VectorXd b = F_;
  for (int p = 0; p < phi_.size(); ++p) {
    if (!fixed[p]) continue;
    for (SpMat::InnerIterator it(K_, 4 * p); it; ++it)
      if (it.row() != 4 * p) b[it.row()] -= it.value() * phi_[p];
  }
  for (int p = 0; p < phi_.size(); ++p)
    if (fixed[p]) b[4 * p] = K_.coeff(4 * p, 4 * p) * phi_[p];
  w0_ = chol_.solve(b);
  columns_.clear();
}

void FixedSetSolver::add_columns(const std::vector<int>& nodes) {
  std::vector<int> missing;
  for (int q : nodes)
    if (!columns_.count(q)) missing.push_back(q);
  for (size_t first = 0; first < missing.size(); first += kCorrectionBlock) {
    const int cols = static_cast<int>(std::min<size_t>(kCorrectionBlock, missing.size() - first));
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(K_.rows(), cols);
    for (int k = 0; k < cols; ++k) {
      const int node = missing[first + k], dof = 4 * node;
      if (!in_base(node)) {
        rhs(dof, k) = 1.0;  // a unit force on the value unknown
      } else {
        // Raise the held value by one: free rows feel -K(:, dof); the held row says "value = 1".
        for (SpMat::InnerIterator it(K_, dof); it; ++it)
          if (!(it.row() % 4 == 0 && in_base(static_cast<int>(it.row() / 4)))) rhs(it.row(), k) = -it.value();
        rhs(dof, k) = K_.coeff(dof, dof);
      }
    }
    const auto sol = chol_.solve_many(rhs);
    for (int k = 0; k < cols; ++k) columns_.emplace(missing[first + k], sol.col(k));
    correction_columns_ += cols;
  }
}

// @region bordered-correction
VectorXd FixedSetSolver::solve(const NodeSet& fixed) {
  std::vector<int> changed;
  if (!base_.empty())
    for (int p = 0; p < static_cast<int>(fixed.size()); ++p)
      if (fixed[p] != base_[p]) changed.push_back(p);
  if (base_.empty() || static_cast<int>(changed.size()) > max_correction_) {
    factorize(fixed);
    changed.clear();
  }
  VectorXd w = w0_;
  const int m = static_cast<int>(changed.size());
  if (m > 0) {
    add_columns(changed);
    std::vector<const VectorXd*> cols;
    for (int q : changed) cols.push_back(&columns_.at(q));
    Eigen::MatrixXd C(m, m);
    VectorXd rhs(m);
    for (int i = 0; i < m; ++i) {
      const int dof = 4 * changed[i];
      if (!in_base(changed[i])) {  // newly held: w_q = phi_q
        for (int k = 0; k < m; ++k) C(i, k) = (*cols[k])[dof];
        rhs[i] = phi_[changed[i]] - w0_[dof];
      } else {  // released: (K w - F)_r = 0
        auto k_row_dot = [&](const VectorXd& v) {
          double s = 0;
          for (SpMat::InnerIterator it(K_, dof); it; ++it) s += it.value() * v[it.row()];  // K symmetric
          return s;
        };
        for (int k = 0; k < m; ++k) C(i, k) = k_row_dot(*cols[k]);
        rhs[i] = F_[dof] - k_row_dot(w0_);
      }
    }
    const VectorXd x = C.fullPivLu().solve(rhs);
    for (int k = 0; k < m; ++k) w += x[k] * (*cols[k]);
  }
  for (int p = 0; p < static_cast<int>(fixed.size()); ++p)
    if (fixed[p]) w[4 * p] = phi_[p];
  return w;
}
// @end bordered-correction

}  // namespace plate
