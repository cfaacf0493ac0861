// Reading the line load off the edge rows, and its D4 Fourier fit.
#include "line_force.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/QR>

namespace plate {

// @region line-force
// Eq. (9): the line load q on the edge; its mean is the total over the length.
LineForce line_force(const Problem& p, const VectorXd& lambda, int harmonics) {
  LineForce f;
  const Sampling& s = p.sampling;
  if (s.edge_size() == 0) return f;
  f.theta = s.edge.theta;
  f.length = s.edge.length;
  for (int k = 0; k < s.edge_size(); ++k) {
    const int row = s.edge_begin + k;
    f.q.push_back(lambda[row]);
    f.total += s.weights[row] * lambda[row];
  }
  f.mean = f.total / f.length;
  f.min = *std::min_element(f.q.begin(), f.q.end());
  f.max = *std::max_element(f.q.begin(), f.q.end());
  const int m = static_cast<int>(f.theta.size());
  harmonics = std::min(harmonics, m / 8 + 1);
  if (m > 0 && harmonics > 0) {
    Eigen::MatrixXd A(m, harmonics);
    Eigen::VectorXd b(m);
    for (int i = 0; i < m; ++i) {
      for (int k = 0; k < harmonics; ++k) A(i, k) = std::cos(4.0 * k * f.theta[i]);
      b[i] = f.q[i];
    }
    const Eigen::VectorXd a = A.colPivHouseholderQr().solve(b);
    f.fourier.assign(a.data(), a.data() + a.size());
  }
  return f;
}
// @end line-force

double line_force_fit(const LineForce& f, double theta) {
  if (f.fourier.empty()) return NAN;
  double q = 0;
  for (size_t k = 0; k < f.fourier.size(); ++k) q += f.fourier[k] * std::cos(4.0 * k * theta);
  return q;
}

double line_force_at(const LineForce& f, double theta) {
  int best = -1;
  double dist = INFINITY;
  for (size_t i = 0; i < f.theta.size(); ++i) {
    const double d = std::abs(std::remainder(f.theta[i] - theta, 2 * M_PI));
    if (d < dist) dist = d, best = static_cast<int>(i);
  }
  return best < 0 ? NAN : f.q[best];
}

}  // namespace plate
