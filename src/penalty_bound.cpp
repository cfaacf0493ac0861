// The penalised operator G(w) = K w - F + eps^{-1} S^T W min(S w - phi, 0) is K plus a monotone term,
// so for any w, with e = w - w_eps and r = G(w):  ||e||_K^2 <= (r, e) <= ||r||_{K^{-1}} ||e||_K.
// A nodal value is bounded by the energy norm through the discrete Green's function,
// |e_i| <= sqrt((K^{-1})_ii) ||e||_K, and (K^{-1})_ii is largest at the centre of the plate.
#include "penalty_bound.hpp"

#include <cfloat>
#include <cmath>

#include "contact.hpp"

namespace plate {

int centre_value_dof(const Grid& g) {
  if (g.unknowns() == 0) return -1;
  // On a part of the plate (mirror.hpp) the plate's centre is the node on its mirror lines. With
  // the part's weights, (K^{-1})_cc there is the whole plate's times the number of parts (four for
  // a quarter, two for a half) and ||r||_{K^{-1}} the whole's over its square root, so the bound
  // is the whole plate's.
  const int i = g.mirror_x ? g.nx : std::clamp((g.nx + 1) / 2, 1, g.nx - 1);
  const int j = g.mirror_y ? g.ny : std::clamp((g.ny + 1) / 2, 1, g.ny - 1);
  return g.dof(i, j, kW);
}

// @region penalty-bound
// Eq. (2a): the error bound max_i |w_i - w_eps,i| <= sqrt(g) ||r||_{K^{-1}}, and its round-off floor.
PenaltyBound penalty_error_bound(const Problem& p, const VectorXd& w, double eps, Cholesky& chol) {
  PenaltyBound b;
  const int N = p.grid.unknowns();
  if (N == 0) return b;
  const VectorXd xi = contact_force_density(p, w, eps);
  const VectorXd Sw = p.sampling.S * w;
  const VectorXd residual = p.K * w - p.F - p.sampling.S.transpose() * p.sampling.weights.cwiseProduct(xi);
  // What r would be from round-off alone: phi - S w loses u (|phi| + |S w|) at every active sample,
  // and eps^{-1} magnifies it; K w and F lose u times their absolute sizes.
  VectorXd lost(p.sampling.size());
  for (int q = 0; q < lost.size(); ++q)
    lost[q] = xi[q] > 0 ? p.sampling.weights[q] * (std::abs(p.phi[q]) + std::abs(Sw[q])) / eps : 0.0;
  const SpMat absK = p.K.cwiseAbs(), absS = p.sampling.S.cwiseAbs();
  const VectorXd roundoff =
      DBL_EPSILON * (absK * w.cwiseAbs() + p.F.cwiseAbs() + absS.transpose() * lost);
  chol.factorize(p.K);
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(N, 3);
  B.col(0) = residual;
  B.col(1) = roundoff;
  B(centre_value_dof(p.grid), 2) = 1.0;
  const auto X = chol.solve_many(B);
  b.green = X(centre_value_dof(p.grid), 2);
  b.residual = std::sqrt(std::max(0.0, residual.dot(X.col(0))));
  b.bound = std::sqrt(b.green) * b.residual;
  b.roundoff = std::sqrt(b.green * std::max(0.0, roundoff.dot(X.col(1))));
  return b;
}
// @end penalty-bound

}  // namespace plate
