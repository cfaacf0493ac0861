// Candidate rows, their columns of G, the dense dual problem, and the check of every other row.
// Only the rows that can touch need a column (a solve with K's factor each, in blocks); rows far
// from contact are checked against the answer and join the candidates only if it violates them.
#include "dual_active_set.hpp"

#include <algorithm>
#include <cmath>

#include "dual_qp.hpp"
#include "norms.hpp"
#include "refinement.hpp"
#include "stopwatch.hpp"

namespace plate {

namespace {

// G = S_C K^{-1} S_C^T over the candidate rows, grown a block of rows at a time.
struct Schur {
  std::vector<int> rows;  // candidate rows, in the order of G
  Eigen::MatrixXd G;
  long columns = 0;       // solves spent on columns
  Eigen::MatrixXd rhs;    // S_block^T, kept zero between blocks: allocated once, not per block

  // Adds `fresh` rows: Z = K^{-1} S_fresh^T in blocks, then G's new columns S_C Z (and rows, by symmetry).
  void grow(const Problem& p, const Cholesky& chol, const std::vector<int>& fresh) {
    const int old = static_cast<int>(rows.size()), m = old + static_cast<int>(fresh.size());
    rows.insert(rows.end(), fresh.begin(), fresh.end());
    G.conservativeResize(m, m);
    for (int first = old; first < m; first += kGramBlock) {
      const int cols = std::min(kGramBlock, m - first);
      if (rhs.rows() != p.unknowns() || rhs.cols() != cols) rhs = Eigen::MatrixXd::Zero(p.unknowns(), cols);
      for (int k = 0; k < cols; ++k)
        for (RowSpMat::InnerIterator it(p.sampling.S, rows[first + k]); it; ++it) rhs(it.col(), k) = it.value();
      const auto Z = chol.solve_many(rhs);
      for (int k = 0; k < cols; ++k)
        for (RowSpMat::InnerIterator it(p.sampling.S, rows[first + k]); it; ++it) rhs(it.col(), k) = 0;
      columns += cols;
      // Rows up to this block's last: later rows get theirs when their own block comes.
      for (int i = 0; i < first + cols; ++i)
        for (int k = 0; k < cols; ++k) {
          double s = 0;
          for (RowSpMat::InnerIterator it(p.sampling.S, rows[i]); it; ++it) s += it.value() * Z(it.col(), k);
          G(i, first + k) = s;
          G(first + k, i) = s;
        }
      auto block = G.block(first, first, cols, cols);
      const Eigen::MatrixXd sym = 0.5 * (block + block.transpose());
      block = sym;
    }
  }
};

// The rows not yet in G that the answer violates, most violated first, at most `cap` of them.
std::vector<int> violated_rows(const VectorXd& gap, const NodeSet& in_schur, double slack, size_t cap) {
  std::vector<int> v;
  for (int q = 0; q < gap.size(); ++q)
    if (!in_schur[q] && gap[q] < -slack) v.push_back(q);
  std::sort(v.begin(), v.end(), [&](int a, int b) { return gap[a] < gap[b] || (gap[a] == gap[b] && a < b); });
  if (v.size() > cap) v.resize(cap);
  return v;
}

// The refinement (D22) of the answer on the rows that push.
Refinement refine_held(const Problem& p, const Cholesky& chol, const Schur& schur, VectorXd& mu, VectorXd& w) {
  std::vector<int> held, rows;  // positions in G, and their sample rows
  for (int i = 0; i < mu.size(); ++i)
    if (mu[i] > 0) held.push_back(i), rows.push_back(schur.rows[i]);
  const int m = static_cast<int>(held.size());
  Eigen::MatrixXd G_AA(m, m);
  VectorXd mu_A(m);
  for (int i = 0; i < m; ++i) {
    mu_A[i] = mu[held[i]];
    for (int k = 0; k < m; ++k) G_AA(i, k) = schur.G(held[i], held[k]);
  }
  const Refinement sizes = refine(p, chol, rows, G_AA, mu_A, w);
  for (int i = 0; i < m; ++i) mu[held[i]] = mu_A[i];
  return sizes;
}

}  // namespace

ExactResult solve_exact_rows(const Problem& p, const ExactOptions& o, const NodeSet& candidates) {
  // Without an exchange nothing is appended to p: the solve only reads it.
  return solve_exact_rows(const_cast<Problem&>(p), o, candidates, RowExchange{}, nullptr);
}

// @region rows-solver
ExactResult solve_exact_rows(Problem& p, const ExactOptions& o, const NodeSet& candidates, const RowExchange& exchange,
                             const Cholesky* factor) {
  validate(o);
  const auto t0 = Clock::now();
  int rows = p.sampling.size();
  ExactResult res;
  ExactLevel level;
  level.cells = p.grid.whole_nx();
  Cholesky own;
  if (!factor) own.factorize(p.K);
  const Cholesky& chol = factor ? *factor : own;
  const VectorXd w0 = chol.solve(p.F);  // the plate with no obstacle
  const double slack = 0.1 * o.tol * std::max(answer_scale(p, w0), 1e-300);
  NodeSet in_schur(rows, 0);
  Schur schur;
  std::vector<int> fresh;
  if (!candidates.empty()) {
    for (int q = 0; q < rows; ++q)
      if (candidates[q] && std::isfinite(p.phi[q])) fresh.push_back(q);
  } else {
    fresh = violated_rows(p.sampling.S * w0 - p.phi, in_schur, slack, rows);
  }
  const size_t cap = std::max(256, 2 * p.sampling.edge_size());  // rows added per round at most
  level.predicted = static_cast<int>(fresh.size());
  if (o.on_iterate) o.on_iterate(p.grid.whole_nx(), 0, level.predicted, 0);
  VectorXd w = w0, mu;
  for (;;) {
    if (!fresh.empty()) {
      if (level.pdas_iterations++ >= o.max_iter) {
        res.message = "the candidate rows kept growing for max-iter = " + std::to_string(o.max_iter) + " rounds";
        break;
      }
      for (int q : fresh) in_schur[q] = 1;
      schur.grow(p, chol, fresh);
      VectorXd b(schur.rows.size());
      for (size_t i = 0; i < schur.rows.size(); ++i) b[i] = p.phi[schur.rows[i]] - p.sampling.S.row(schur.rows[i]).dot(w0);
      const DualQPResult d = solve_dual_qp(schur.G, b, slack, 20 * static_cast<int>(b.size()) + 100);
      level.dual_steps += d.steps;
      level.dependent_rows += d.dependent;
      mu = d.mu;
      VectorXd force = VectorXd::Zero(p.unknowns());  // S_C^T mu
      for (size_t i = 0; i < schur.rows.size(); ++i)
        if (mu[i] != 0)
          for (RowSpMat::InnerIterator it(p.sampling.S, schur.rows[i]); it; ++it) force[it.col()] += mu[i] * it.value();
      w = w0 + chol.solve(force);
      if (!d.ok) {
        res.message = d.message;
        break;
      }
    }
    fresh = violated_rows(p.sampling.S * w - p.phi, in_schur, slack, cap);
    // The answer for these rows, refined; the refined plate may violate a row the rounded one did not.
    if (fresh.empty() && o.refine) {
      level.refinement = refine_held(p, chol, schur, mu, w);
      fresh = violated_rows(p.sampling.S * w - p.phi, in_schur, slack, cap);
    }
    // Every row holds: rows where the plate dips between them, if the problem takes them.
    if (fresh.empty() && exchange) {
      const int added = exchange(p, w, slack);
      level.exchanged += added;
      rows = p.sampling.size();
      in_schur.resize(rows, 0);
      fresh = violated_rows(p.sampling.S * w - p.phi, in_schur, slack, cap);
    }
    if (o.on_iterate && level.pdas_iterations > 0)
      o.on_iterate(p.grid.whole_nx(), level.pdas_iterations, static_cast<int>(schur.rows.size()), static_cast<int>(fresh.size()));
    if (fresh.empty()) break;
  }
  res.lambda = VectorXd::Zero(rows);  // mu is a force; lambda its density per unit area or length
  res.active = NodeSet(rows, 0);
  for (size_t i = 0; i < schur.rows.size() && i < static_cast<size_t>(mu.size()); ++i) {
    res.lambda[schur.rows[i]] = mu[i] / p.sampling.weights[schur.rows[i]];
    res.active[schur.rows[i]] = mu[i] > 0;
  }
  res.w = std::move(w);
  res.certificate = certify(p, res.w, res.lambda);
  if (res.message.empty() && !(res.certificate.worst() <= o.tol))  // a NaN entry fails too
    res.message = certificate_failure(res.certificate, o.tol);
  res.converged = res.message.empty();
  level.active = members(res.active);
  level.factorizations = own.factorizations();
  level.correction_columns = schur.columns;
  level.seconds = seconds_since(t0);
  res.levels.push_back(level);
  return res;
}
// @end rows-solver

}  // namespace plate
