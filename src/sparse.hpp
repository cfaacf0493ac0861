// Sparse matrix types shared by the solver: column-major for factorisation, row-major for the
// sampling matrix S, whose rows (sample points) are read one at a time.
#pragma once
#include <Eigen/Sparse>

namespace plate {
using SpMat = Eigen::SparseMatrix<double>;
using RowSpMat = Eigen::SparseMatrix<double, Eigen::RowMajor>;
using Eigen::VectorXd;
}  // namespace plate
