// The certificate of an exact solve, and the small definitions every exact solver shares.
#include "exact.hpp"

#include <cfloat>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "norms.hpp"

namespace plate {

namespace {
// The highest the obstacle asks the plate to reach. Any answer that keeps above it is about that
// large somewhere (exactly, on nodal rows; a row between nodes can read a little more than the
// nodal maximum), so feasible answers keep a scale close to max |w|; an answer that lies below a
// positive obstacle everywhere (w = 0 under R = 1e-320, where the solve underflowed) is measured
// against the obstacle instead, and fails.
double obstacle_top(const VectorXd& phi) {
  double top = 0;
  for (double v : phi)
    if (std::isfinite(v)) top = std::max(top, v);
  return top;
}
// The sizes the relative tolerances refer to, or 1 where they are 0 (every entry's numerator is then
// 0 as well, unless the answer is wrong). A fixed floor such as 1e-300 would pass any answer to a
// problem smaller than it.
double or_one(double scale) { return scale > 0 ? scale : 1.0; }
double value_scale(const VectorXd& w, const VectorXd& phi) { return or_one(std::max(max_nodal_abs(w), obstacle_top(phi))); }
double force_scale(const VectorXd& lambda) { return or_one(lambda.size() ? lambda.cwiseAbs().maxCoeff() : 0.0); }
// entry = max(entry, v), where a NaN stays: a NaN in w or lambda must fail the certificate.
void raise(double& entry, double v) {
  if (!std::isnan(entry) && (std::isnan(v) || v > entry)) entry = v;
}
}  // namespace

// NaN wins: std::max passes over it, and a NaN entry would let a broken answer through.
double Certificate::worst() const {
  double m = 0;
  for (double v : {violation, negative_multiplier, complementarity, stationarity}) {
    if (std::isnan(v)) return v;
    m = std::max(m, v);
  }
  return m;
}

// @region certificate
Certificate certify(const Problem& p, const VectorXd& w, const VectorXd& lambda) {
  Certificate c;
  const double wmax = value_scale(w.head(p.grid.unknowns()), p.phi), lmax = force_scale(lambda);
  const VectorXd Sw = p.sampling.S * w;
  for (int q = 0; q < p.phi.size(); ++q) {
    const double gap = Sw[q] - p.phi[q];  // +inf where there is no obstacle
    raise(c.violation, -gap / wmax);
    raise(c.negative_multiplier, -lambda[q] / lmax);
    // Each factor scaled first: the product of the raw ones underflows to 0 (a check that cannot
    // fail) for heights below about 1e-160, and overflows to a NaN that std::max passes over above 1e150.
    if (lambda[q] != 0) raise(c.complementarity, std::abs(lambda[q] / lmax) * std::abs(gap / wmax));
  }
  // Componentwise backward error (Oettli-Prager): the smallest relative change of K, F and the
  // contact forces that makes w exact. A normwise residual would demand the impossible of a matrix
  // whose condition number grows like h^-4. Where every term of a row is itself round-off (a slope
  // that symmetry makes zero), we add ||K_i||_inf ||w||_inf to that row's scale, as Arioli, Demmel
  // and Duff do for sparse systems (SIAM J. Matrix Anal. Appl. 10, 1989).
  const VectorXd force = p.sampling.S.transpose() * p.sampling.weights.cwiseProduct(lambda);
  VectorXd r = -p.F - force, scale = p.F.cwiseAbs() + force.cwiseAbs(), row_max = VectorXd::Zero(r.size());
  VectorXd row_terms = VectorXd::Zero(r.size());
  for (Eigen::Index col = 0; col < p.K.outerSize(); ++col)
    for (SpMat::InnerIterator it(p.K, col); it; ++it) {
      r[it.row()] += it.value() * w[col];
      scale[it.row()] += std::abs(it.value() * w[col]);
      row_max[it.row()] = std::max(row_max[it.row()], std::abs(it.value()));
      row_terms[it.row()] += 1;
    }
  const double w_inf = w.size() ? w.cwiseAbs().maxCoeff() : 0.0;
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    const double normwise = row_max[i] * w_inf;
    double s = scale[i];
    if (s <= 1000 * row_terms[i] * DBL_EPSILON * normwise) s += normwise;
    // A scale that overflowed cannot tell a residual from round-off: the entry is then NaN, and fails.
    if (s > 0 || std::isnan(s)) raise(c.stationarity, std::isinf(s) ? NAN : std::abs(r[i]) / s);
  }
  return c;
}
// @end certificate

std::string certificate_failure(const Certificate& c, double tol) {
  std::ostringstream m;
  m << "the active set settled but the certificate fails: worst relative residual " << c.worst()
    << (std::isnan(c.worst()) ? " (not a number: an entry overflowed or the answer holds a NaN), tol = " : " > tol = ") << tol
    << " (violation " << c.violation << ", negative multiplier " << c.negative_multiplier << ", complementarity "
    << c.complementarity << ", stationarity " << c.stationarity << ")";
  return m.str();
}

double energy(const Problem& p, const VectorXd& w) { return 0.5 * w.dot(p.K * w) - p.F.dot(w); }

void validate(const ExactOptions& o) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument(what);
  };
  require(std::isfinite(o.tol) && o.tol > 0, "tol must be finite and > 0");
  require(o.tol >= 1e-14, "tol must be >= 1e-14: the certificate is computed in double precision");
  require(o.max_iter >= 1, "max-iter must be >= 1");
  require(o.coarsest >= 2, "coarsest must be >= 2");
  require(o.max_correction >= 0, "max-correction must be >= 0");
}

double answer_scale(const Problem& p, const VectorXd& w_free) {
  double s = max_nodal_abs(w_free.head(p.grid.unknowns()));
  for (int q = 0; q < p.phi.size(); ++q)
    if (std::isfinite(p.phi[q])) s = std::max(s, std::abs(p.phi[q]));
  return s;
}

double exact_solve_roundoff(int n, double v) {
  return DBL_EPSILON * std::pow(static_cast<double>(n), 3) * std::abs(v);
}

}  // namespace plate
