// Exact discrete penalised solutions along eps_s = 10^{-s}, and their Richardson extrapolation.
#include "eps_limit.hpp"

#include <cfloat>
#include <cmath>
#include <stdexcept>

#include "norms.hpp"
#include "schemes.hpp"

namespace plate {

std::vector<VectorXd> penalised_path(const Problem& p, double eps) {
  SolveOptions o;
  o.scheme = Scheme::Nonlinear;
  o.tol = 0;  // once (3a) repeats its active set its step is exactly zero
  o.max_iter = 200;
  Cholesky chol;
  chol.analyze(p.K + p.M);  // every pattern K + S^T D S can have (spline rows reach past an element)
  VectorXd w = VectorXd::Zero(p.grid.unknowns());
  std::vector<VectorXd> path;
  for (int s = 0;; ++s) {
    const double e = 0.1 / std::pow(10.0, s);
    if (!nonlinear_scheme_level(p, e, w, chol, o).converged)
      throw std::runtime_error("the nonlinear scheme did not settle at eps = " + std::to_string(e));
    path.push_back(w);
    if (e <= eps * (1 + 1e-12)) return path;
  }
}

// @region eps-limit
EpsLimit eps_limit(const Problem& p, double eps) {
  const std::vector<VectorXd> path = penalised_path(p, eps);
  if (path.size() < 3) throw std::runtime_error("eps_limit: eps must be at most 1e-3");
  const VectorXd& w0 = path[path.size() - 1];  // eps
  const VectorXd& w1 = path[path.size() - 2];  // 10 eps
  const VectorXd& w2 = path[path.size() - 3];  // 100 eps
  EpsLimit L;
  L.eps = eps;
  L.w = w0 + (w0 - w1) / 9.0;
  L.difference = max_nodal_abs(w0 - w1);
  L.ratio = max_nodal_abs(w1 - w2) / L.difference;
  L.estimate = max_nodal_abs(L.w - (w1 + (w1 - w2) / 9.0));
  L.roundoff = solve_roundoff(p, w0, eps);
  return L;
}
// @end eps-limit

// @region solve-roundoff
// A backward-stable solve of A w = b returns the exact solution of a system perturbed by about
// u |A| |w| + u |b|; pushed through A^{-1} that perturbation is the round-off of w. An estimate of
// its size, not a bound: the perturbation's signs are taken all alike.
double solve_roundoff(const Problem& p, const VectorXd& w, double eps) {
  const VectorXd active = ((p.sampling.S * w - p.phi).array() < 0.0).cast<double>();
  const VectorXd d = active.cwiseProduct(p.sampling.weights) / eps;
  const SpMat A = p.K + weighted_gram(p.sampling.S, d, p.grid.unknowns());
  const VectorXd d_phi = (active.array() > 0).select(d.cwiseProduct(p.phi), 0.0);  // phi = -inf off the obstacle
  const VectorXd b = p.F + p.sampling.S.transpose() * d_phi;
  Cholesky chol;
  chol.factorize(A);
  const VectorXd perturbation = DBL_EPSILON * (A.cwiseAbs() * w.cwiseAbs() + b.cwiseAbs());
  return max_nodal_abs(chol.solve(perturbation));
}
// @end solve-roundoff

}  // namespace plate
