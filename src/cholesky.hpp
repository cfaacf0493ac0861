// Sparse Cholesky (CHOLMOD supernodal, through Eigen) with the ordering and symbolic analysis
// done once and reused by every numeric factorisation of a matrix with the same pattern.
#pragma once
#include <Eigen/CholmodSupport>

#include "sparse.hpp"

namespace plate {

class Cholesky {
 public:
  // Fill-reducing ordering and symbolic factorisation of A's pattern.
  void analyze(const SpMat& A);
  // Numeric factorisation; A must have the analysed pattern. Throws if A is not positive definite.
  void factorize(const SpMat& A);
  VectorXd solve(const VectorXd& b) const;
  Eigen::MatrixXd solve_many(const Eigen::MatrixXd& B) const;  // several right-hand sides at once
  int factorizations() const { return factorizations_; }

 private:
  Eigen::CholmodSupernodalLLT<SpMat> llt_;
  bool analyzed_ = false;
  int factorizations_ = 0;
};

}  // namespace plate
