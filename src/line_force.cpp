// Reading the line load off the edge rows, and its D4 Fourier fit.
#include "line_force.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/QR>

namespace plate {

namespace {
// Least squares q(theta) ~ sum_k a_k cos(4 k theta), with no more harmonics than the points resolve.
void fit_harmonics(LineForce& f, int harmonics) {
  const int m = static_cast<int>(f.theta.size());
  harmonics = std::min(harmonics, m / 8 + 1);
  if (m == 0 || harmonics <= 0) return;
  Eigen::MatrixXd A(m, harmonics);
  Eigen::VectorXd b(m);
  for (int i = 0; i < m; ++i) {
    for (int k = 0; k < harmonics; ++k) A(i, k) = std::cos(4.0 * k * f.theta[i]);
    b[i] = f.q[i];
  }
  const Eigen::VectorXd a = A.colPivHouseholderQr().solve(b);
  f.fourier.assign(a.data(), a.data() + a.size());
}
// A spline line load is a function of the angle: its extremes lie between the knots too. Sampled at
// the listing's angles, then each closed in on by golden sections over the two steps about the best sample.
// On a symmetric scene the extreme is reached at several angles, equal but for round-off, which
// would pick one of them at random (the paper's least q came out at pi/4 or 3 pi/4 from one build
// to the next): samples within kTie of the best count as equal, and the first from theta = 0 is taken.
void refine_extremes(LineForce& f) {
  const int angles = kLineLoadAngles;
  const double step = 2 * M_PI / angles, ratio = 0.5 * (std::sqrt(5.0) - 1);
  constexpr double kTie = 1e-9;  // relative to the largest |q|: ten times the certificate's tolerance
  std::vector<double> sampled(angles);
  double largest = 0;
  for (int k = 0; k < angles; ++k) sampled[k] = line_force_value(f, k * step), largest = std::max(largest, std::abs(sampled[k]));
  for (double sign : {+1.0, -1.0}) {
    double top = -INFINITY;
    for (double q : sampled) top = std::max(top, sign * q);
    int best = 0;
    while (best + 1 < angles && !(sign * sampled[best] >= top - kTie * largest)) ++best;  // NaN samples are passed over
    double lo = (best - 1) * step, hi = (best + 1) * step;
    double a = hi - ratio * (hi - lo), b = lo + ratio * (hi - lo);
    double fa = sign * line_force_value(f, a), fb = sign * line_force_value(f, b);
    while (hi - lo > 1e-12) {
      if (fa > fb) hi = b, b = a, fb = fa, a = hi - ratio * (hi - lo), fa = sign * line_force_value(f, a);
      else lo = a, a = b, fa = fb, b = lo + ratio * (hi - lo), fb = sign * line_force_value(f, b);
    }
    const double here = sign * sampled[best];
    const double t = std::max(fa, fb) > here ? (fa > fb ? a : b) : best * step;
    const double v = sign * std::max({fa, fb, here});
    // A row's own value (summarise) may pass the closed-in one at a tied copy: the value then stays
    // the row's, and the angle, the tie's first, may lie up to kTie away in q from where it is reached.
    if (sign > 0 && v >= f.max - kTie * largest) f.max = std::max(f.max, v), f.theta_max = std::remainder(t, 2 * M_PI);
    if (sign < 0 && v <= f.min + kTie * largest) f.min = std::min(f.min, v), f.theta_min = std::remainder(t, 2 * M_PI);
  }
}

void summarise(LineForce& f) {
  f.mean = f.total / f.length;
  f.min = *std::min_element(f.q.begin(), f.q.end());
  f.max = *std::max_element(f.q.begin(), f.q.end());
}
}  // namespace

// @region line-force
// Eq. (9): the line load q on the edge; its mean is the total over the length.
LineForce line_force(const Problem& p, const VectorXd& lambda, int harmonics) {
  LineForce f;
  const Sampling& s = p.sampling;
  if (s.edge_size() == 0) return f;
  f.theta = s.edge.theta;
  f.length = s.edge.length;
  const int m = s.edge_size();
  if (s.rim_laid_out()) {
    f.spline_degree = s.edge_spline_degree;
    f.layout = s.rim;
    for (const SplineArc& a : s.rim.arcs) f.arc_coefficients.emplace_back(a.basis_count(f.spline_degree), NAN);
    int points = 0;
    for (int k = 0; k < m; ++k) {
      const RimRow& r = s.rim_rows[k];
      if (r.point()) {
        f.point_theta.push_back(s.edge.theta[k]), f.point_q.push_back(lambda[s.edge_begin + k]);
        ++points;
      } else {
        f.arc_coefficients[r.arc][r.basis] = lambda[s.edge_begin + k];
      }
    }
    bool whole = points == static_cast<int>(s.rim.points.size());
    for (const auto& c : f.arc_coefficients)
      for (double v : c) whole = whole && !std::isnan(v);
    if (!whole) throw std::invalid_argument("line_force: the rows of part of a circle (unfold them first)");
  } else if (s.edge_spline_degree > 0) {
    if (m != s.edge_knots) throw std::invalid_argument("line_force: the spline rows of part of a circle (unfold them first)");
    f.spline_degree = s.edge_spline_degree;
    f.coefficients.assign(lambda.data() + s.edge_begin, lambda.data() + s.size());
  }
  for (int k = 0; k < m; ++k) {
    const int row = s.edge_begin + k;
    // Points: the multiplier is q there. B-spline rows: q(theta_k) = sum_i lambda_i B(k - i).
    const bool point = s.edge_spline_degree == 0 || (s.rim_laid_out() && s.rim_rows[k].point());
    f.q.push_back(point ? lambda[row] : line_force_value(f, f.theta[k]));
    f.total += s.weights[row] * lambda[row];
  }
  summarise(f);
  if (f.spline_degree > 0) refine_extremes(f);
  fit_harmonics(f, harmonics);
  return f;
}
// @end line-force

LineForce line_force_from_point_forces(const std::vector<double>& theta, const std::vector<double>& force,
                                       double radius, int harmonics) {
  if (theta.size() != force.size() || theta.size() < 2 || !(radius > 0))
    throw std::invalid_argument("line_force_from_point_forces: need as many angles as forces, at least two, and r > 0");
  std::vector<size_t> order(theta.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return theta[i] < theta[j]; });
  LineForce f;
  f.length = 2 * M_PI * radius;
  const size_t m = order.size();
  for (size_t k = 0; k < m; ++k) {
    // Half the angle to each neighbour, around the circle.
    const double before = theta[order[k]] - theta[order[(k + m - 1) % m]], after = theta[order[(k + 1) % m]] - theta[order[k]];
    const double arc = radius * 0.5 * (std::remainder(before, 2 * M_PI) + std::remainder(after, 2 * M_PI));
    if (!(arc > 0)) throw std::invalid_argument("line_force_from_point_forces: two points at one angle");
    f.theta.push_back(theta[order[k]]);
    f.q.push_back(force[order[k]] / arc);
    f.total += force[order[k]];
  }
  summarise(f);
  fit_harmonics(f, harmonics);
  return f;
}

LineForce binned_line_force(const Problem& p, const VectorXd& lambda, const EdgeCurve& circle, int bins) {
  if (bins < 8 || bins % 8 != 0 || !(circle.r > 0))
    throw std::invalid_argument("binned_line_force: need a multiple of 8 bins and r > 0");
  std::vector<double> theta(bins), force(bins, 0.0);
  const double width = 2 * M_PI / bins;
  // Bins centred on 0, width, 2 width, ...: with bins a multiple of 8, the square's symmetries map
  // bins onto bins, and theta = 0 and pi/4 are bin centres.
  for (int b = 0; b < bins; ++b) theta[b] = b * width;
  for (int s = 0; s < p.sampling.size(); ++s) {
    if (!(lambda[s] > 0)) continue;
    const double angle = std::atan2(p.sampling.y[s] - circle.cy, p.sampling.x[s] - circle.cx);
    const int b = static_cast<int>(std::lround(angle / width));
    force[((b % bins) + bins) % bins] += p.sampling.weights[s] * lambda[s];
  }
  return line_force_from_point_forces(theta, force, circle.r);
}

double line_force_value(const LineForce& f, double theta) {
  if (f.spline_degree == 0) return line_force_at(f, theta);
  if (f.laid_out()) {
    for (size_t a = 0; a < f.layout.arcs.size(); ++a)
      if (f.layout.arcs[a].contains(theta)) {
        double q = 0;
        for (size_t j = 0; j < f.arc_coefficients[a].size(); ++j)
          q += f.arc_coefficients[a][j] * clamped_bspline(f.layout.arcs[a], f.spline_degree, static_cast<int>(j), theta);
        return q;
      }
    int best = -1;
    double dist = INFINITY;
    for (size_t i = 0; i < f.point_theta.size(); ++i) {
      const double d = std::abs(std::remainder(f.point_theta[i] - theta, 2 * M_PI));
      if (d < dist) dist = d, best = static_cast<int>(i);
    }
    return best < 0 ? 0.0 : f.point_q[best];
  }
  const int m = static_cast<int>(f.coefficients.size()), p = f.spline_degree;
  const double u = theta / (2 * M_PI / m);  // in knot spacings
  const int first = static_cast<int>(std::floor(u - 0.5 * (p + 1)));
  double q = 0;
  for (int j = first; j <= first + p + 2; ++j) q += f.coefficients[((j % m) + m) % m] * cardinal_bspline(p, u - j);
  return q;
}

double max_distance(const LineForce& f, const std::function<double(double)>& reference, int angles) {
  if (f.theta.size() != f.q.size() || f.q.empty()) return NAN;
  double d = 0;
  for (size_t k = 0; k < f.q.size(); ++k) d = std::max(d, std::abs(f.q[k] - reference(f.theta[k])));
  for (int k = 0; f.spline_degree > 0 && k < angles; ++k) {
    const double t = 2 * M_PI * k / angles;
    d = std::max(d, std::abs(line_force_value(f, t) - reference(t)));
  }
  return d;
}

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

LineFigures line_figures(const Problem& p, const LineForce& f) {
  LineFigures g;
  if (f.theta.empty()) return g;
  g.q0 = line_force_value(f, 0), g.q45 = line_force_value(f, M_PI / 4);
  g.fit0 = line_force_fit(f, 0), g.fit45 = line_force_fit(f, M_PI / 4);
  if (f.spline_degree == 0) return g;
  const double r = f.length / (2 * M_PI);
  line_figures_circle(g, p.sampling.edge.x[0] - r * std::cos(f.theta[0]), p.sampling.edge.y[0] - r * std::sin(f.theta[0]), r);
  for (double t : g.theta) g.q.push_back(line_force_value(f, t));
  return g;
}

void line_figures_circle(LineFigures& g, double cx, double cy, double r) {
  g.theta.clear(), g.x.clear(), g.y.clear();
  for (int k = 0; k < kLineLoadAngles; ++k) {
    const double t = 2 * M_PI * k / kLineLoadAngles;
    g.theta.push_back(t), g.x.push_back(cx + r * std::cos(t)), g.y.push_back(cy + r * std::sin(t));
  }
}

}  // namespace plate
