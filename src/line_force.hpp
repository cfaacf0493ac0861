// The contact force as what it is on the paper's cylinder: a line load q on the circle (10).
// With edge sampling the multiplier at an edge point is a force per unit length, so q(theta) is
// read off directly, and its total over the rim is the obstacle's whole push on the plate.
#pragma once
#include <cmath>
#include <functional>
#include <vector>

#include "problem.hpp"

namespace plate {

// The angles at which a line load on a circle is listed (plate --line-csv, for every model), and
// from which its extremes and its distance from another are searched, equally spaced from 0: the
// same set for every scheme, so runs compare point by point.
constexpr int kLineLoadAngles = 720;

struct LineForce {
  std::vector<double> theta, q;  // at each edge point (theta: circles only)
  double length = 0;             // of the edge curve
  double total = 0;              // sum_p W_p q_p over the edge points
  double mean = 0;               // total / length
  double min = 0, max = 0;
  double theta_min = NAN, theta_max = NAN;  // where (a spline's extremes, found between the knots)
  // Least-squares fit q(theta) ~ sum_k a_k cos(4 k theta), k = 0..harmonics-1: the harmonics the
  // square's eight symmetries allow for a function on a circle about the square's centre (fewer
  // when M points cannot tell them apart: 4 k <= M / 2).
  std::vector<double> fourier;
  // Spline rows (D12): q is the function sum_j c_j B_p((theta - theta_j) / Delta) with the knots
  // theta_j = 2 pi j / M, Delta = 2 pi / M, and c_j the rows' multipliers; theta and q above are its
  // values at the knots. Degree 0: point rows, q known at the points only.
  int spline_degree = 0;
  std::vector<double> coefficients;
  // Rows laid out for a contact (D28): q is the splines' sum on each arc of `layout`, and off the
  // arcs the value at the nearest point row. `coefficients` is then empty.
  RimLayout layout;
  std::vector<std::vector<double>> arc_coefficients;  // per arc of layout, per basis
  std::vector<double> point_theta, point_q;           // the point rows
  bool laid_out() const { return spline_degree > 0 && !layout.periodic; }
  bool empty() const { return q.empty(); }
};

// Eq. (9): the force per unit length at the edge rows of `lambda` (force densities at every
// sample). Empty when the sampling has no edge rows.
LineForce line_force(const Problem& p, const VectorXd& lambda, int harmonics = 4);

// The same from point forces F_k at angles theta_k on a circle of radius r (another code's
// multipliers at the circle's mesh vertices): q_k = F_k over the arc nearer to point k than to its
// neighbours. Throws std::invalid_argument on sizes that differ or on fewer than two points.
LineForce line_force_from_point_forces(const std::vector<double>& theta, const std::vector<double>& force,
                                       double radius, int harmonics = 4);

// Eq. (9) for samples off the circle (grid nodes, Gauss points): the force W_p lambda_p of every
// sample, gathered by its angle about the circle's centre into `bins` equal arcs and spread over
// the arc's length. A coarse force per unit length, but one that every sampling, and another code's
// point forces, can be set beside. Throws std::invalid_argument unless bins is a positive multiple
// of 8 (so that the square's symmetries map bins onto bins) and r > 0.
LineForce binned_line_force(const Problem& p, const VectorXd& lambda, const EdgeCurve& circle, int bins);

// q at the edge point nearest the angle theta (circles only). Point values scatter by about 10%
// about a smooth curve, because the finite element space cannot resolve a load at the scale of h.
double line_force_at(const LineForce& f, double theta);
// The line load at any angle: the spline's value (D12), or for point rows the nearest point's.
double line_force_value(const LineForce& f, double theta);
// The largest distance of the line load from a reference q(theta): for spline rows over `angles`
// equal angles and the knots, for point rows at the points. NaN without angles (a polygon).
double max_distance(const LineForce& f, const std::function<double(double)>& reference, int angles = kLineLoadAngles);
// The fitted (smoothed) line load sum_k a_k cos(4 k theta); NaN without a fit.
double line_force_fit(const LineForce& f, double theta);

// What a report states of a line load on a circle besides its rows, evaluated once so that a report
// only formats: q and its fit at theta = 0 and pi/4, and, for a function of the angle (spline rows,
// the rim-contact series), its values at kLineLoadAngles equal angles from 0 and the points of the
// circle where they act (the circle through p's edge points, of radius f.length / 2 pi). The table
// is empty for point rows, whose rows are listed themselves.
struct LineFigures {
  double q0 = NAN, q45 = NAN;      // line_force_value at 0 and pi/4
  double fit0 = NAN, fit45 = NAN;  // line_force_fit at 0 and pi/4
  std::vector<double> theta, x, y, q;
};
LineFigures line_figures(const Problem& p, const LineForce& f);
// The angles of the table, kLineLoadAngles equal steps from 0, and their points on the circle of
// radius r about (cx, cy); g.q is left to the caller.
void line_figures_circle(LineFigures& g, double cx, double cy, double r);

}  // namespace plate
