// The plate at the end of a contact on a circle: where a plate lifts off part of a cylinder's rim
// (the lift-off scenes), its line load grows like s^(-1/2) towards each end of the contact and the
// gap beyond it closes like s^(5/2) (the lift-off section of the document). Bicubics on a fixed grid
// cannot follow that field, and where the end falls in its cell changes from grid to grid, so the
// answer swings. These are the local fields of an end and the fit that locates it from a solve: the
// pieces of an enrichment that is not yet part of `plate` (issue 39; src/programs/contact_end_study
// measures it).
//
// In coordinates fitted to the rim about an end E at angle theta_e, t = a (theta - theta_e) sigma
// along the rim into the free side and nu = r - a across it, with polar (rho, omega) in the
// (t, nu) plane (omega = 0 on the free side of the rim, +-pi on the contact side), the fields
//   F_32 = rho^(3/2) [cos(3 omega / 2) + 3 cos(omega / 2)],
//   F_52 = rho^(5/2) [cos(5 omega / 2) - 5 cos(omega / 2)]
// vanish on the contact side with their normal slope, keep the second normal derivative continuous
// across it and jump in the third (a line load; for F_52 it is -30 rho^(-1/2)): of the even
// solutions of the plate's equation on a straight rim that a load on a half-line allows, the two of
// finite energy with the lowest exponents. F_52 is
// the field of the end (gap -4 s^(5/2) on the free side); F_32, whose load s^(-3/2) is not
// integrable, is the field of an end put in the wrong place.
#pragma once
#include <functional>
#include <vector>

#include <Eigen/Dense>

#include "grid.hpp"
#include "polar.hpp"

namespace plate {

struct ContactEnd {
  double cx = 0, cy = 0, a = 0;  // the circle
  double theta = 0;              // the end
  double sigma = 1;              // +1: the plate is free for theta > theta_e; -1: for theta < theta_e
  double inner = 0, outer = 0;   // the cut-off: 1 for rho <= inner, 0 for rho >= outer
};

enum class EndField { Gap32, Gap52 };

// A field and its derivatives in x, y.
using EndDerivatives = PlaneDerivatives;

// F_32 or F_52 at (x, y), without the cut-off.
EndDerivatives end_field(const ContactEnd& e, EndField f, double x, double y);
// The cut-off chi(rho): 1 up to `inner`, the septic smoothstep (C^3) down to 0 at `outer`.
EndDerivatives end_cutoff(const ContactEnd& e, double x, double y);
// How far from the end, in a straight line, chi can be nonzero. rho measures arc length along the
// rim, so the support reaches past `outer` outside the circle: at nu = r - a, the squared distance
// is nu^2 + 4 a r sin^2(dtheta / 2) <= rho^2 + (nu / a) t^2, largest at nu = outer / sqrt(3), which
// gives outer^2 (1 + 2 outer / (3 sqrt(3) a)).
double end_reach(const ContactEnd& e);

// The function an enrichment adds, chi (F - I_h F) with I_h the grid's Hermite interpolant: F less
// what the bicubics already carry, so that only its part at the end is new. Without the subtraction
// the cut-off's steep but smooth part dominates what the bicubics miss of chi F, and the solve's
// coefficient of the function is set by the cut-off's band rather than by the end (the closing note
// of stop 61 gives the figures). Value and Laplacian at (x, y).
struct EndValue {
  double w = 0, lap = 0;
};
EndValue end_function(const ContactEnd& e, EndField f, const Grid& g, double x, double y);
// The same function with its slopes and second derivatives: what a field read at a point (moments,
// extrema) needs of it.
EndDerivatives end_function_derivatives(const ContactEnd& e, EndField f, const Grid& g, double x, double y);
// The same with I_h F that of cell (ex, ey), read at its local (t, u), the point (x, y): on a side
// of a cell each element has its own second derivatives.
EndDerivatives end_function_derivatives_in(const ContactEnd& e, EndField f, const Grid& g, int ex, int ey, double t, double u,
                                           double x, double y);

// Where the end lies, from the gap g(s) that a solve leaves at arc lengths s > 0 into the free side
// of an end put at s = 0: least squares of g on s^(3/2), s^(5/2), s^(7/2). The gap of an end at
// s = delta is A (s - delta)^(5/2) + ..., whose s^(3/2) term is -(5/2) A delta, so delta =
// -(2/5) B / A with B, A the first two coefficients: an expansion in delta / s, so a caller moves the
// end by at most a fraction of the samples' reach and fits again. Throws std::invalid_argument for fewer than
// three samples or a fit with A <= 0 (no gap that opens like an end's).
double end_shift(const std::vector<double>& s, const std::vector<double>& gap);

// The blocks the functions `fields` at `ends` (one function each) add to the plate's system on grid
// g: border(i, k) = (Lap phi_i, Lap psi_k) over the grid's unknowns i, own(k, l) = (Lap psi_k,
// Lap psi_l). Each cell near an end is cut into squares, halved towards the end (its second
// derivatives are singular there), with kEndGaussPoints^2 Gauss points on each. Where a curve
// across which the ends' functions are not smooth cuts a square (the rim, across which their
// Laplacians kink on the contact side, and the edges rho = inner, outer of each end's cut-off,
// which is only C^3 there), each side of it is integrated apart (implicit_rule): halving towards
// the rim instead left the border 2e-4 off on the 2 x 1 plate's quarter at n = 64. The kinks of
// `others` are followed too where `kinks` gives them; otherwise `cross` is integrated across them
// as a Gauss rule would be.
// `others` more functions of the space (another enrichment's, D31's) get cross(j, k) = (Lap o_j,
// Lap psi_k), with their Laplacians at (x, y) in cell (ex, ey) from `laplacians`; a `load` f gives
// load(k) = (f, psi_k).
// Gauss points each way on a square (and along the lines of implicit_rule, with two more across):
// with 8, the border and own blocks on that quarter (n = 64, 128) lie within 1.2e-7 of those with 14
// (measured apart; tests/test_contact_end.cpp holds the border and load to a rule blind to the curves).
constexpr int kEndGaussPoints = 8;
struct EndBlocks {
  Eigen::MatrixXd border, own, cross;
  Eigen::VectorXd load;
};
using OtherLaplacians = std::function<void(int ex, int ey, double x, double y, Eigen::VectorXd& out)>;
// Where the Laplacians of `others` kink: circles about (cx, cy) and lines through it at the given
// angles ((D31)'s cut-off's edges and knot rays), followed like the ends' own curves.
struct OtherKinks {
  double cx = 0, cy = 0;
  std::vector<double> radii, rays;
};
EndBlocks assemble_end_blocks(const Grid& g, const std::vector<ContactEnd>& ends, const std::vector<EndField>& fields,
                              int others = 0, const OtherLaplacians& laplacians = {},
                              const std::function<double(double, double)>* load = nullptr, const OtherKinks* kinks = nullptr);

}  // namespace plate
