// Inverse iteration for lambda_1h and the two contraction factors.
#include "contraction.hpp"

#include <cmath>
#include <stdexcept>

#include "cholesky.hpp"
#include "norms.hpp"
#include "schemes.hpp"

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

// @region contraction-factors
double sharp_contraction(double lambda1h, double eps) { return 1.0 / (1.0 + eps * lambda1h); }

// Eq. (6): the paper's contraction factor, kept to compare with the sharp one.
double paper_rho(double c, double eps) { return (1.0 + c * eps) / ((1.0 + 2.0 * c * eps) * (1.0 + eps / c)); }
// @end contraction-factors

std::vector<double> linear_step_norms(const Problem& p, double eps, int iterations, VectorXd* last_iterate,
                                      std::vector<double>* energies) {
  std::vector<double> steps;
  VectorXd last = VectorXd::Zero(p.grid.unknowns());
  // tol is never met: the level stops on max_iter and we read the steps. The level alone, not
  // solve(), which would end with an error bound nobody reads here.
  SolveOptions o = fixed_eps_options(Scheme::Linear, eps, 1e-300, iterations);
  o.on_iterate = [&](double, int, const VectorXd& w) {
    const VectorXd e = w - last;
    steps.push_back(m_norm(p, e));
    if (energies) energies->push_back(e.dot(p.K * e) + steps.back() * steps.back() / eps);
    last = w;
  };
  Cholesky chol;
  chol.analyze(p.K + p.M);  // every pattern K + S^T D S can have (spline rows reach past an element)
  VectorXd w = VectorXd::Zero(p.grid.unknowns());
  linear_scheme_level(p, eps, w, chol, o);
  if (last_iterate) *last_iterate = w;
  return steps;
}

// On a fixed contact set (5a) is affine, w -> A^{-1} (F + S^T W eps^{-1} max(S w, phi)) with
// A = K + eps^{-1} M, so two runs differ by d -> A^{-1} S^T W eps^{-1} P S d, P keeping the
// samples off the contact set. Its largest factor is found on a difference rescaled every step:
// the steps of a run fall into round-off, a rescaled difference never does.
double settled_factor(const Problem& p, double eps, const VectorXd& w, int max_iter) {
  const VectorXd free = ((p.sampling.S * w - p.phi).array() >= 0.0).cast<double>();
  const VectorXd d_free = free.cwiseProduct(p.sampling.weights) / eps;
  Cholesky chol;
  chol.factorize(p.K + (1.0 / eps) * p.M);
  VectorXd d = VectorXd::Zero(p.grid.unknowns());
  for (Eigen::Index i = 0; i < d.size(); i += 4) d[i] = 1.0;  // one sign: overlaps the slowest mode
  d /= m_norm(p, d);
  double factor = 0;
  for (int k = 0; k < max_iter; ++k) {
    d = chol.solve(p.sampling.S.transpose() * d_free.cwiseProduct(p.sampling.S * d));
    const double next = m_norm(p, d);
    if (!(next > 0)) return 0.0;  // every sample in contact: the difference dies in one step
    d /= next;
    if (std::abs(next - factor) <= 1e-15 * next) return next;
    factor = next;
  }
  return factor;
}

double asymptotic_factor(const std::vector<double>& s) {
  if (s.size() < 2) throw std::invalid_argument("asymptotic_factor: need two steps");
  size_t k = 1;
  while (k + 1 < s.size() && s[k] > 1e-7 * s[0]) ++k;
  return s[k] / s[k - 1];
}

double slowest_factor(const std::vector<double>& s, double settled) {
  double worst = settled;
  for (size_t k = 1; k < s.size(); ++k)
    if (s[k] > 1e-6 * s[0]) worst = std::max(worst, s[k] / s[k - 1]);
  return worst;
}

}  // namespace plate
