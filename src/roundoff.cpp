#include "roundoff.hpp"

#include <cfloat>
#include <cmath>
#include <stdexcept>

#include "contact.hpp"

namespace plate {

SolutionRoundoff::SolutionRoundoff(const Problem& p, const VectorXd& w, const VectorXd& lambda) : p_(p) {
  // Its perturbations live on the grid's unknowns; an enriched solve is refined instead (D22).
  if (p.kink || !p.ends.empty()) throw std::logic_error("SolutionRoundoff takes the plain space: the problem carries the kink (D31) or the ends' functions");
  const VectorXd force = p.sampling.S.transpose() * p.sampling.weights.cwiseProduct(lambda);
  VectorXd r = p.K * w - p.F - force;
  scale_ = p.F.cwiseAbs() + force.cwiseAbs();
  for (Eigen::Index col = 0; col < p.K.outerSize(); ++col)
    for (SpMat::InnerIterator it(p.K, col); it; ++it) scale_[it.row()] += std::abs(it.value() * w[col]);
  residual_abs_ = r.cwiseAbs();
  chol_.analyze(p.K);
  chol_.factorize(p.K);
}

namespace {
// @region exact-roundoff
// The residual carried through K^{-1}, its terms of random sign:
// sqrt(sum_i z_i^2 (r_i^2 + u^2 scale_i^2)).
double through_inverse(const VectorXd& z, const VectorXd& residual_abs, const VectorXd& scale) {
  return std::sqrt(z.cwiseProduct(residual_abs).squaredNorm() +
                   DBL_EPSILON * DBL_EPSILON * z.cwiseProduct(scale).squaredNorm());
}
// @end exact-roundoff
}  // namespace

std::vector<double> SolutionRoundoff::of(const Eigen::MatrixXd& g) const {
  const auto z = chol_.solve_many(g);
  std::vector<double> out;
  for (Eigen::Index c = 0; c < z.cols(); ++c) out.push_back(through_inverse(z.col(c), residual_abs_, scale_));
  return out;
}

namespace {
// The coefficients of a linear output of w_h at (x, y): the values of the basis functions there.
VectorXd coefficients_at(const Grid& g, double x, double y, double PointValues::*what) {
  VectorXd c = VectorXd::Zero(g.unknowns()), e = VectorXd::Zero(g.unknowns());
  int ex, ey;
  double t, s;
  if (!g.locate(x, y, ex, ey, t, s)) throw std::invalid_argument("a point outside the plate has no round-off estimate");
  for (int dof : g.element_dofs(ex, ey)) {
    if (dof < 0) continue;
    e[dof] = 1;
    c[dof] = evaluate(g, e, x, y).*what;
    e[dof] = 0;
  }
  return c;
}
}  // namespace

VectorXd SolutionRoundoff::point_value(double x, double y) const { return coefficients_at(p_.grid, x, y, &PointValues::w); }
VectorXd SolutionRoundoff::point_twist(double x, double y) const { return coefficients_at(p_.grid, x, y, &PointValues::wxy); }

VectorXd SolutionRoundoff::unknown(int dof) const {
  VectorXd e = VectorXd::Zero(p_.grid.unknowns());
  e[dof] = 1;
  return e;
}

}  // namespace plate
