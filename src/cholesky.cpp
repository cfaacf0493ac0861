// CHOLMOD's C interface, with every failure turned into an exception: a failed factorisation must
// never pass silently.
#include "cholesky.hpp"

#include <stdexcept>
#include <string>

namespace plate {

namespace {
// A view of A's lower triangle as CHOLMOD's symmetric sparse matrix (no copy).
cholmod_sparse view_lower(const SpMat& A) {
  if (!A.isCompressed()) throw std::invalid_argument("Cholesky: the matrix must be compressed");
  cholmod_sparse s{};
  s.nrow = A.rows();
  s.ncol = A.cols();
  s.nzmax = A.nonZeros();
  s.p = const_cast<int*>(A.outerIndexPtr());
  s.i = const_cast<int*>(A.innerIndexPtr());
  s.x = const_cast<double*>(A.valuePtr());
  s.stype = -1;  // symmetric, lower triangle stored (entries above are ignored)
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}
}  // namespace

Cholesky::Cholesky() {
  cholmod_start(&common_);
  common_.print = 0;  // CHOLMOD would print its own warnings on stdout; we report failures ourselves
  common_.supernodal = CHOLMOD_SUPERNODAL;
}

Cholesky::~Cholesky() {
  free(one_);
  free(many_);
  if (factor_) cholmod_free_factor(&factor_, &common_);
  cholmod_finish(&common_);
}

void Cholesky::free(Workspace& ws) const {
  for (cholmod_dense** d : {&ws.x, &ws.y, &ws.e})
    if (*d) cholmod_free_dense(d, &common_);
}

void Cholesky::analyze(const SpMat& A) {
  if (factor_) cholmod_free_factor(&factor_, &common_);
  cholmod_sparse a = view_lower(A);
  factor_ = cholmod_analyze(&a, &common_);
  if (!factor_ || common_.status < CHOLMOD_OK) throw std::runtime_error("CHOLMOD: symbolic analysis failed");
}

void Cholesky::factorize(const SpMat& A) {
  if (!factor_) analyze(A);
  if (static_cast<Eigen::Index>(factor_->n) != A.rows()) throw std::invalid_argument("Cholesky: the matrix is not the analysed one");
  cholmod_sparse a = view_lower(A);
  if (!cholmod_factorize(&a, factor_, &common_) || common_.status < CHOLMOD_OK)
    throw std::runtime_error("CHOLMOD: numeric factorisation failed (status " + std::to_string(common_.status) + ")");
  if (common_.status == CHOLMOD_NOT_POSDEF || factor_->minor < factor_->n)
    throw std::runtime_error("CHOLMOD: numeric factorisation failed (matrix not positive definite at column " +
                             std::to_string(factor_->minor) + " of " + std::to_string(factor_->n) + ", status " + std::to_string(common_.status) + ")");
  ++factorizations_;
}

void Cholesky::solve_into(const double* b, int n, int columns, Workspace& ws) const {
  if (!factor_ || factorizations_ == 0) throw std::logic_error("Cholesky: solve before factorize");
  if (static_cast<size_t>(n) != factor_->n) throw std::invalid_argument("Cholesky: right-hand side of the wrong size");
  cholmod_dense rhs{};
  rhs.nrow = n;
  rhs.ncol = columns;
  rhs.nzmax = static_cast<size_t>(n) * columns;
  rhs.d = n;
  rhs.x = const_cast<double*>(b);
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  // cholmod_solve2 reuses x, y and e when they already have the right size.
  if (!cholmod_solve2(CHOLMOD_A, factor_, &rhs, nullptr, &ws.x, nullptr, &ws.y, &ws.e, &common_) ||
      common_.status < CHOLMOD_OK)
    throw std::runtime_error("CHOLMOD: solve failed");
}

VectorXd Cholesky::solve(const VectorXd& b) const {
  solve_into(b.data(), static_cast<int>(b.size()), 1, one_);
  return Eigen::Map<const VectorXd>(static_cast<const double*>(one_.x->x), b.size());
}

Eigen::Map<const Eigen::MatrixXd> Cholesky::solve_many(const Eigen::MatrixXd& B) const {
  solve_into(B.data(), static_cast<int>(B.rows()), static_cast<int>(B.cols()), many_);
  return Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(many_.x->x), B.rows(), B.cols());
}

}  // namespace plate
