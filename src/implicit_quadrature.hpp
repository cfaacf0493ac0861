// Quadrature on the part of a rectangle where one or more bicubic functions are negative: the
// region {x in box : psi_k(x) < 0 for every k}, found from the functions alone (an implicitly
// defined domain). The penalty of (2) lives on the disk where w < phi; both its edges, the circle
// and the curve w = phi, cross the squares of (8) anywhere, and a Gauss rule that merely tests its
// points integrates the jump or the kink there with an error that changes sign from grid to grid.
// This rule follows the curves instead (D30), after Saye's height-function construction (SIAM J.
// Sci. Comput. 37 (2015) A993): where every function is monotone along one axis, each line
// parallel to that axis meets each curve at most once, so the integral along it splits exactly at
// those points, and across the lines an outer Gauss rule sees a smooth integrand.
#pragma once
#include <array>
#include <vector>

namespace plate {

// A polynomial of degree <= 3 in each variable on the box [0, 1]^2 of local coordinates, in the
// Bernstein basis: p(t, s) = sum_ij b[4 i + j] B_i(t) B_j(s), B_i the cubic Bernstein polynomials.
// Its coefficients bound it (p lies between the smallest and the largest), which is what the
// construction needs to know: whether the curve p = 0 can cross a box, and whether p is monotone.
struct Bicubic {
  std::array<double, 16> b{};
  double operator()(double t, double s) const;
  // The same polynomial on the sub-box [t0, t1] x [s0, s1], in that box's local coordinates.
  Bicubic restricted(double t0, double t1, double s0, double s1) const;
  // +1 (-1) if every coefficient is > 0 (< 0), so that p is on the box; 0 if it may change sign.
  int sign() const;
  // Whether p is strictly monotone along axis 0 (t) or 1 (s) on the whole box.
  bool monotone(int axis) const;
};

// The bicubic on a box of sides hx, hy that has the given value, first derivatives and mixed
// derivative (physical units) at its four corners, corner index cx + 2 cy: each cubic Hermite
// interpolant's Bernstein coefficients are its end values and one third of the end slopes inward.
// For a function that is bicubic on the box (w_h on a square of (8), or any biquadratic such as
// the circle's (x - cx)^2 + (y - cy)^2 - r^2) it is that function, exactly.
struct CornerJet {
  double f = 0, fx = 0, fy = 0, fxy = 0;
};
Bicubic bicubic_from_corners(const std::array<CornerJet, 4>& corners, double hx, double hy);
// The circle's level function (x - cx)^2 + (y - cy)^2 - r^2, negative inside, on the square
// [x0, x0 + size] x [y0, y0 + size]: biquadratic, so this bicubic is the circle exactly.
Bicubic circle_on(double cx, double cy, double r, double x0, double y0, double size);

struct WeightedPoint {
  double x = 0, y = 0, weight = 0;
};

// How many Gauss points: `along` each line of integration and on boxes the curves miss (exact for
// polynomials of degree 2 along - 1 in each variable), and `across` the lines, where the heights of
// the curves make the integrand smooth but not polynomial (its error falls geometrically with it).
struct ImplicitOrders {
  int along = 4, across = 8;
};

// A rule for the integral over {(x, y) in box : psi_k(x, y) < 0 for every k} of the box
// [x0, x0 + hx] x [y0, y0 + hy], psi_k given on the box as bicubics. A box where no axis makes every
// function monotone, and every curve gently sloped across it, is halved both ways, down to
// `max_depth` halvings; there its points are tested one by one (what is left is a few boxes
// 2^-max_depth across). The points are appended to `out`.
void implicit_rule(double x0, double y0, double hx, double hy, const std::vector<Bicubic>& psi, ImplicitOrders orders,
                   std::vector<WeightedPoint>& out, int max_depth = 12);

// The roots of a cubic in Bernstein form on [0, 1] (coefficients c[0..3]), increasing; a root of
// even multiplicity, where the cubic touches zero without crossing, need not be found. The zero
// cubic has none: a curve along the line splits nothing there.
std::vector<double> cubic_roots(const std::array<double, 4>& c);

}  // namespace plate
