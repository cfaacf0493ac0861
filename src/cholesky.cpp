// Error checking around Eigen's CHOLMOD wrapper: a failed factorisation must never pass silently.
#include "cholesky.hpp"

#include <stdexcept>

namespace plate {

void Cholesky::analyze(const SpMat& A) {
  llt_.cholmod().print = 0;  // CHOLMOD would print its own warnings on stdout; we report failures ourselves
  llt_.analyzePattern(A);
  if (llt_.info() != Eigen::Success) throw std::runtime_error("CHOLMOD: symbolic analysis failed");
  analyzed_ = true;
}

void Cholesky::factorize(const SpMat& A) {
  if (!analyzed_) analyze(A);
  llt_.factorize(A);
  if (llt_.info() != Eigen::Success)
    throw std::runtime_error("CHOLMOD: numeric factorisation failed (matrix not positive definite?)");
  ++factorizations_;
}

VectorXd Cholesky::solve(const VectorXd& b) const {
  VectorXd x = llt_.solve(b);
  if (llt_.info() != Eigen::Success) throw std::runtime_error("CHOLMOD: solve failed");
  return x;
}

Eigen::MatrixXd Cholesky::solve_many(const Eigen::MatrixXd& B) const {
  Eigen::MatrixXd X = llt_.solve(B);
  if (llt_.info() != Eigen::Success) throw std::runtime_error("CHOLMOD: solve failed");
  return X;
}

}  // namespace plate
