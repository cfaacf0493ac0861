// What the paper computes after the solve: w and its derivatives anywhere, the contact force (9),
// the bending moments and the contact set.
#pragma once
#include <cmath>
#include <vector>

#include "problem.hpp"

namespace plate {

struct PointValues {
  double w, wx, wy, wxx, wxy, wyy;
};

// Hermite evaluation of w_h at (x, y); throws std::invalid_argument outside the rectangle.
PointValues evaluate(const Grid& g, const VectorXd& w, double x, double y);
// The field w of p's space, to be read at many points: with the enrichment (D31), its share is
// added (a grid-only evaluation of such a field is right at the nodes alone).
class PlateField {
 public:
  PlateField(const Problem& p, const VectorXd& w);
  PointValues at(double x, double y) const;
  // w alone (at(x, y).w, the same number) for the reads that need no slope: a third of the work.
  double value_at(double x, double y) const;
  PointValues enrichment_at(double x, double y) const;  // the enrichments' share alone (zero without one)
  // The same read in element (ex, ey) of p's grid at local (t, s), the point (x, y).
  PointValues enrichment_in(int ex, int ey, double t, double s, double x, double y) const;

 private:
  PointValues share(const PointValues& interpolant, double x, double y, const int* cell = nullptr) const;
  PointValues ends_at(double x, double y, const int* cell, double t, double s) const;
  const Problem& p_;
  const VectorXd& w_;
  VectorXd c_, Pc_;  // (D31)'s coefficients, and its interpolant's
  VectorXd e_;       // the ends' coefficients
};
// One point of it.
PointValues evaluate(const Problem& p, const VectorXd& w, double x, double y);

struct Moments {
  double m11, m12, m22;
};

// Kirchhoff bending moments with D = 1: m11 = -(w11 + nu w22), m12 = -(1 - nu) w12,
// m22 = -(w22 + nu w11). (The paper's printed matrix has +nu where -nu belongs.)
Moments bending_moments(double wxx, double wxy, double wyy, double nu);
// Poisson's ratio of every report here: the paper gives none, so this is our choice.
constexpr double kPoissonRatio = 0.3;

// xi_p = -eps^{-1} beta(w)(x_p) = eps^{-1} max(phi_p - (S w)_p, 0) >= 0 at the sample points.
VectorXd contact_force_density(const Problem& p, const VectorXd& w, double eps);

// sum_p W_p xi_p: the total upward force of the obstacle on the plate.
double total_contact_force(const Problem& p, const VectorXd& xi);

// max_p (phi_p - (S w)_p)^+: how far w lies below the obstacle at the worst sample point (0 if at none).
double constraint_violation(const Problem& p, const VectorXd& w);

// Relative residual of the discrete penalised equation (2a) at w:
// ||K w - F + eps^{-1} S^T W beta(S w)|| / (||K w|| + ||F||). Zero at the exact w_eps.
double penalty_residual(const Problem& p, const VectorXd& w, double eps);

// The same residual as a backward error: ||r||_inf over the inf-norm of the sum of the magnitudes
// of its terms (|K||w| + |F| + the active penalty terms). Of the order of the unit round-off at an
// exact w_eps, on every grid: a quantity whose digits below ~1e-13 round-off alone decides.
double penalty_backward_error(const Problem& p, const VectorXd& w, double eps);

// How far the plate dips below the obstacle along its edge curve between the rows that constrain it
// (spline rows average w, point rows hold it at points): max over points h / 32 apart on the curve of
// phi - w_h, 0 if the plate is nowhere below. NaN without an edge curve.
double dip_below_edge(const Problem& p, const VectorXd& w);
// The same, with where it is deepest: the angle about the circle's centre (NaN for a polygon, or
// where the plate is nowhere below), so that a report can say which rows failed to hold it there.
struct EdgeDip {
  double depth = NAN;
  double theta = NAN;
};
EdgeDip deepest_dip_below_edge(const Problem& p, const VectorXd& w);

// Everything the paper reports "at the nodes of the grid", at all (nx+1)(ny+1) nodes.
// Second derivatives jump across element edges; at a node we average the elements around it.
// The contact force at node r is (S^T W xi)_r / h^2, the force on its value unknown per unit
// area: with nodal sampling this is xi at the node itself; with Gauss sampling, where nodes are
// not sample points, it is the force of the neighbouring points weighted by the node's basis function.
struct NodalFields {
  std::vector<double> x, y, w, wx, wy, wxx, wxy, wyy, phi, xi, m11, m12, m22;
  std::vector<bool> contact;  // xi > 0
  int size() const { return static_cast<int>(x.size()); }
};
NodalFields nodal_fields(const Problem& p, const VectorXd& w, double eps, double nu);
// The same with the force density at the sample points given (the exact solver's multipliers).
NodalFields nodal_fields(const Problem& p, const VectorXd& w, const VectorXd& xi_samples,
                         double nu);

// The nodal fields' extremes, which the report gives beside the field's own (extrema.hpp): the
// largest nodal w and where, the largest xi and |m12| at a node, and the nodes in contact.
struct NodalExtremes {
  int argmax_w = 0;
  double max_w = -INFINITY, max_xi = 0, max_abs_m12 = 0;
  std::vector<int> contact;
};
NodalExtremes nodal_extremes(const NodalFields& f);

}  // namespace plate
