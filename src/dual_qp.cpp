// Goldfarb-Idnani on the Schur complement G. From mu = 0 (the unconstrained plate) it adds the
// most violated row p and raises mu_p while the rows already held keep their gap at zero; if a
// held multiplier reaches zero first, that row is dropped and the step goes on. Every step
// raises the dual objective, so no active set comes back and the method ends (Goldfarb and
// Idnani, Math. Program. 27, 1983). G_AA stays positive definite because a row that depends on
// the held ones is never added: it only moves the multipliers (a pure dual step).
#include "dual_qp.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace plate {

namespace {

// L L^T = G_AA, grown by a row and shrunk by Givens rotations.
struct ActiveCholesky {
  Eigen::MatrixXd L;
  int n = 0;
  explicit ActiveCholesky(int capacity) : L(capacity, capacity) {}
  Eigen::VectorXd forward(const Eigen::VectorXd& v) const {
    return L.topLeftCorner(n, n).triangularView<Eigen::Lower>().solve(v);
  }
  Eigen::VectorXd backward(const Eigen::VectorXd& v) const {
    return L.topLeftCorner(n, n).transpose().triangularView<Eigen::Upper>().solve(v);
  }
  void append(const Eigen::VectorXd& l, double d) {
    L.row(n).head(n) = l.transpose();
    L(n, n) = d;
    ++n;
  }
  // Deletes row and column k of G_AA: drop row k of L, then rotate column pairs (j, j+1) to
  // clear the entry above the diagonal that the shift left behind.
  void remove(int k) {
    for (int i = k; i + 1 < n; ++i) L.row(i).head(n) = L.row(i + 1).head(n);
    --n;
    for (int j = k; j < n; ++j) {
      const double a = L(j, j), b = L(j, j + 1), r = std::hypot(a, b);
      const double c = a / r, s = b / r;
      for (int i = j; i < n; ++i) {
        const double x = L(i, j), y = L(i, j + 1);
        L(i, j) = c * x + s * y;
        L(i, j + 1) = -s * x + c * y;
      }
    }
  }
};

int most_violated(const Eigen::VectorXd& gap, const std::vector<char>& in_active, double tol) {
  int p = -1;
  for (int i = 0; i < gap.size(); ++i)
    if (!in_active[i] && gap[i] < -tol && (p < 0 || gap[i] < gap[p])) p = i;
  return p;
}

}  // namespace

// @region dual-active-set
// Eq. (D20): Goldfarb-Idnani's dual active-set method on G = S K^{-1} S^T.
DualQPResult solve_dual_qp(const Eigen::MatrixXd& G, const Eigen::VectorXd& b, double tol, int max_steps) {
  const int m = static_cast<int>(b.size());
  DualQPResult r;
  r.mu = Eigen::VectorXd::Zero(m);
  r.gap = -b;
  std::vector<char> in_active(m, 0);
  ActiveCholesky chol(m);
  for (int p = most_violated(r.gap, in_active, tol); p >= 0; p = most_violated(r.gap, in_active, tol)) {
    for (;;) {  // raise mu_p until row p is held or a held multiplier reaches zero
      if (++r.steps > max_steps) {
        r.message = "the dual active-set method did not finish in " + std::to_string(max_steps) + " steps";
        return r;
      }
      const int n = chol.n;
      Eigen::VectorXd g_ap(n);
      for (int i = 0; i < n; ++i) g_ap[i] = G(r.active[i], p);
      const Eigen::VectorXd l = chol.forward(g_ap);
      const Eigen::VectorXd dir = chol.backward(l);  // held multipliers fall by t * dir
      const double d2 = G(p, p) - l.squaredNorm();   // how far row p is from the held rows' span
      const bool dependent = d2 <= 1e-11 * G(p, p);
      r.dependent += dependent;
      const double t_full = dependent ? INFINITY : -r.gap[p] / d2;
      double t_drop = INFINITY;
      int k = -1;
      for (int i = 0; i < n; ++i)
        if (dir[i] > 0 && r.mu[r.active[i]] / dir[i] < t_drop) t_drop = r.mu[r.active[i]] / dir[i], k = i;
      if (!std::isfinite(t_full) && !std::isfinite(t_drop)) {
        r.message = "the constraints cannot all hold: no plate in the discrete space lies above phi at every sample";
        return r;
      }
      const double t = std::min(t_full, t_drop);
      Eigen::VectorXd change = G.col(p);  // the gaps move along G(:, p) - G(:, A) dir
      for (int i = 0; i < n; ++i) {
        change -= dir[i] * G.col(r.active[i]);
        r.mu[r.active[i]] -= t * dir[i];
      }
      r.mu[p] += t;
      r.gap += t * change;
      if (t_drop < t_full) {  // row k lets go: it leaves the active set, and row p tries again
        r.mu[r.active[k]] = 0;
        in_active[r.active[k]] = 0;
        r.active.erase(r.active.begin() + k);
        chol.remove(k);
        continue;
      }
      chol.append(l, std::sqrt(d2));
      r.active.push_back(p);
      in_active[p] = 1;
      for (int i : r.active) r.gap[i] = 0;  // held rows touch exactly; round-off says otherwise
      break;
    }
  }
  r.ok = true;
  return r;
}
// @end dual-active-set

}  // namespace plate
