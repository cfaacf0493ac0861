// Element-by-element residuals in long double, and the refinement they drive.
#include "refinement.hpp"

#include <cfloat>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

#include "bfs_element.hpp"

namespace plate {

using Extended = long double;

// @region extended-residual
// Eq. (D21): the residual with K never assembled: each element's K_e w_e in long double.
VectorXd extended_residual(const Problem& p, const VectorXd& w, const VectorXd& mu) {
  const Grid& g = p.grid;
  const Eigen::Matrix<Extended, 16, 16> Ke = bfs_stiffness_extended(static_cast<Extended>(g.h));
  std::vector<Extended> r(p.F.data(), p.F.data() + p.F.size());
  for (int q = 0; q < mu.size(); ++q)
    if (mu[q] != 0)
      for (RowSpMat::InnerIterator it(p.sampling.S, q); it; ++it) r[it.col()] += static_cast<Extended>(it.value()) * mu[q];
  Eigen::Matrix<Extended, 16, 1> we;
  for (int ey = 0; ey < g.ny; ++ey)
    for (int ex = 0; ex < g.nx; ++ex) {
      const auto dofs = g.element_dofs(ex, ey);
      for (int k = 0; k < 16; ++k) we[k] = dofs[k] >= 0 ? static_cast<Extended>(w[dofs[k]]) : 0;
      const Eigen::Matrix<Extended, 16, 1> f = Ke * we;
      for (int k = 0; k < 16; ++k)
        if (dofs[k] >= 0) r[dofs[k]] -= f[k];
    }
  // The enrichments' borders and blocks ((D31)'s and the ends'), whose entries are the problem's as assembled.
  for (Eigen::Index col = 0; col < p.enrichment_block.outerSize(); ++col)
    for (SpMat::InnerIterator it(p.enrichment_block, col); it; ++it)
      r[it.row()] -= static_cast<Extended>(it.value()) * static_cast<Extended>(w[col]);
  VectorXd out(r.size());
  for (size_t i = 0; i < r.size(); ++i) out[i] = static_cast<double>(r[i]);
  return out;
}
// @end extended-residual

VectorXd extended_gap(const Problem& p, const VectorXd& w, const std::vector<int>& rows) {
  VectorXd gap(rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    Extended s = p.phi[rows[i]];
    for (RowSpMat::InnerIterator it(p.sampling.S, rows[i]); it; ++it) s -= static_cast<Extended>(it.value()) * w[it.col()];
    gap[i] = static_cast<double>(s);
  }
  return gap;
}

// @region refinement
// Eq. (D22): with the residuals in long double (D21), the double factor of K and a factor of G_AA,
//   z = K^{-1} r_w,   G_AA dmu = r_A - S_A z,   dw = z + K^{-1} S_A^T dmu.
// Each step shrinks the error by about u cond(K) (some 1e-5 on n = 512).
Refinement refine(const Problem& p, const Cholesky& chol, const std::vector<int>& rows, const Eigen::MatrixXd& G_AA,
                  VectorXd& mu, VectorXd& w) {
  const int m = static_cast<int>(rows.size());
  const Eigen::LDLT<Eigen::MatrixXd> factor(G_AA);
  const RowSpMat& S = p.sampling.S;
  Refinement sizes;
  const VectorXd w_start = w, mu_start = mu;
  auto undo = [&] { w = w_start, mu = mu_start, sizes = {}; };
  for (int step = 0; step < 8; ++step) {
    VectorXd force_at_rows = VectorXd::Zero(p.sampling.size());
    for (int i = 0; i < m; ++i) force_at_rows[rows[i]] = mu[i];
    const VectorXd z = chol.solve(extended_residual(p, w, force_at_rows));
    VectorXd dw = z, dmu;
    if (m > 0) {
      VectorXd rhs = extended_gap(p, w, rows);
      for (int i = 0; i < m; ++i) rhs[i] -= S.row(rows[i]).dot(z);
      dmu = factor.solve(rhs);
      VectorXd push = VectorXd::Zero(p.unknowns());  // S_A^T dmu
      for (int i = 0; i < m; ++i)
        for (RowSpMat::InnerIterator it(S, rows[i]); it; ++it) push[it.col()] += dmu[i] * it.value();
      dw += chol.solve(push);
    }
    const double size = dw.lpNorm<Eigen::Infinity>() / std::max(w.lpNorm<Eigen::Infinity>(), 1e-300);
    const double size_mu = m > 0 ? dmu.lpNorm<Eigen::Infinity>() / std::max(mu.lpNorm<Eigen::Infinity>(), 1e-300) : 0.0;
    const bool shrinking = sizes.w.empty() || size < sizes.w.back();
    const double largest = std::max(size, size_mu);
    const double first = sizes.w.empty() ? 0.0 : std::max(sizes.w[0], sizes.mu[0]);
    const bool confirming = step == 1 && first >= kRefineLargestFirst;
    // A first correction of kRefineLargestFirst or more is the double solve's own round-off on an
    // ill-conditioned grid, or noise that a near-singular G_AA amplifies; only the second tells
    // them apart, and if it does not confirm the first, the whole refinement is undone (an empty
    // record: callers fall back to the unrefined solve's round-off, and `undone` says why). On the
    // 2 x 1 plate at h = 1/1024 the first correction is 6e-3 and the second 3e-8: refusing the first
    // by its size alone left max w 2e-6 and the force 2e-5 off, under a certificate of 1e-15.
    if (confirming && !(largest <= kRefineContraction * first)) {
      undo();
      sizes.undone = first;
      break;
    }
    // Past that, a correction of kRefineLargestFirst or more (or not finite) is noise, not round-off
    // being removed: it is not applied, and the steps before it stand.
    if (!std::isfinite(largest) || (step > 0 && !confirming && largest >= kRefineLargestFirst)) break;
    sizes.w.push_back(size), sizes.mu.push_back(size_mu);
    if (!shrinking) break;  // the residual's own round-off: this correction is noise, not applied
    w += dw;
    if (m > 0) mu += dmu;
    // Done when w's correction is down to round-off; not after a first correction still to be confirmed.
    if (size <= 4 * DBL_EPSILON && !(step == 0 && largest >= kRefineLargestFirst)) break;
  }
  return sizes;
}
// @end refinement

void require_not_undone(const Refinement& r, const std::string& what) {
  if (r.undone > 0) {
    std::ostringstream m;
    m << what << ": the refinement (D22) was undone (its first correction, " << r.undone
      << " of the answer, was not confirmed by the next), so the answer's round-off is unknown";
    throw std::runtime_error(m.str());
  }
}

VectorXd solve_refined(const Problem& p, const Cholesky& chol, Refinement* record) {
  VectorXd w = chol.solve(p.F), none;
  const Refinement sizes = refine(p, chol, {}, Eigen::MatrixXd(), none, w);
  if (record) *record = sizes;
  return w;
}

}  // namespace plate
