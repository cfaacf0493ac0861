// Inverse iteration for lambda_1h and the two contraction factors.
#include "contraction.hpp"

#include <cmath>
#include <stdexcept>

#include "cholesky.hpp"

namespace plate {

Eigenpair smallest_eigenpair(const SpMat& K, const SpMat& M, double rtol, int max_iter) {
  Cholesky chol;
  chol.factorize(K);
  Eigenpair e;
  // Start from the nodal values all one: the first mode is of one sign, so they overlap.
  e.v = VectorXd::Zero(K.rows());
  for (Eigen::Index i = 0; i < e.v.size(); i += 4) e.v[i] = 1.0;
  double previous = INFINITY;
  for (e.iterations = 1; e.iterations <= max_iter; ++e.iterations) {
    e.v = chol.solve(M * e.v);
    const double mnorm2 = e.v.dot(M * e.v);
    if (!(mnorm2 > 0)) throw std::runtime_error("smallest_eigenpair: iterate has no component seen by M");
    e.v /= std::sqrt(mnorm2);
    e.lambda = e.v.dot(K * e.v);
    if (std::abs(e.lambda - previous) <= rtol * e.lambda) return e;
    previous = e.lambda;
  }
  throw std::runtime_error("smallest_eigenpair: inverse iteration did not converge");
}

double sharp_contraction(double lambda1h, double eps) { return 1.0 / (1.0 + eps * lambda1h); }

// Eq. (6): the paper's contraction factor, kept to compare with the sharp one.
double paper_rho(double c, double eps) { return (1.0 + c * eps) / ((1.0 + 2.0 * c * eps) * (1.0 + eps / c)); }

}  // namespace plate
