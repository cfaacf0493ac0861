// Sparse Cholesky (CHOLMOD supernodal) with the ordering and symbolic analysis done once and
// reused by every numeric factorisation of a matrix with the same pattern, and with the solves'
// workspace kept between calls: a solve with k right-hand sides needs three dense blocks of
// k x unknowns, and allocating them anew for every block (as cholmod_solve does) cost more in page
// faults than the solve itself (n = 256: 1.4 million faults, 10 s of kernel time in 28 s).
#pragma once
#include <cholmod.h>

#include "sparse.hpp"

namespace plate {

class Cholesky {
 public:
  Cholesky();
  ~Cholesky();
  Cholesky(const Cholesky&) = delete;
  Cholesky& operator=(const Cholesky&) = delete;

  // Fill-reducing ordering and symbolic factorisation of A's pattern (A symmetric; its lower
  // triangle is read).
  void analyze(const SpMat& A);
  // Numeric factorisation; A must have the analysed pattern. Throws if A is not positive definite.
  void factorize(const SpMat& A);
  VectorXd solve(const VectorXd& b) const;
  // Several right-hand sides at once. The answer lives in this object's workspace: it is valid
  // until the next solve_many, and costs no allocation when the block size repeats.
  Eigen::Map<const Eigen::MatrixXd> solve_many(const Eigen::MatrixXd& B) const;
  int factorizations() const { return factorizations_; }

 private:
  struct Workspace {
    cholmod_dense *x = nullptr, *y = nullptr, *e = nullptr;
  };
  void solve_into(const double* b, int n, int columns, Workspace& ws) const;
  void free(Workspace& ws) const;

  mutable cholmod_common common_;
  cholmod_factor* factor_ = nullptr;
  mutable Workspace one_, many_;  // one right-hand side, and blocks of them: kept apart so neither resizes
  int factorizations_ = 0;
};

}  // namespace plate
