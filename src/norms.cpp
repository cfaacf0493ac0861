#include "norms.hpp"

#include <cmath>

namespace plate {

double max_nodal_abs(const VectorXd& w) {
  // Unknowns are interleaved (w, w_x, w_y, w_xy) per node: the values are every fourth entry.
  const Eigen::Map<const VectorXd, 0, Eigen::InnerStride<4>> values(w.data(), w.size() / 4);
  return values.size() ? values.cwiseAbs().maxCoeff() : 0.0;
}

double m_norm(const Problem& p, const VectorXd& v) {
  const VectorXd sv = p.sampling.S * v;
  return std::sqrt(sv.dot(p.sampling.weights.cwiseProduct(sv)));
}

}  // namespace plate
