// The paper's problem solved as a linear one, on the premise that the plate touches the cylinder
// along its rim only: a line load q(theta) on the circle, a series of biharmonic functions that
// carry it, and least squares for the clamped edge and w = R on the rim. No grid, no penalty.
#pragma once
#include <complex>
#include <string>
#include <vector>

#include "contact.hpp"
#include "line_force.hpp"
#include "scene.hpp"

namespace plate {

// What the series reads of a scene: clamped rectangle [0, lx] x [0, ly], D = 1, uniform load
// f = `load` (> 0 pushes up), rigid cylinder of radius a = `radius` and height R = `height` centred
// at (cx, cy): w >= R on the closed disk, no constraint outside.
struct RimScene {
  double lx = 0, ly = 0, cx = 0, cy = 0, radius = 0, height = 0, load = 0;
};
// The series' reading of a scene. Throws std::invalid_argument naming --obstacle or --load unless
// the obstacle is a cylinder and the load uniform (the series models those alone), and as check()
// does.
RimScene rim_scene(const Scene& s);

// Throws std::invalid_argument naming the parameter unless every number is finite, lx, ly,
// radius and height are positive and the disk lies strictly inside the plate (a disk that meets
// the edge would be held at R >= 0 and at w = 0 at once).
void check(const RimScene& s);

// The symmetries a solve may use: the square's eight about a centred disk (only cos 4k theta
// survives in q), the two mirrors of a rectangle about a centred disk (cos 2k theta), or none.
enum class RimSymmetry { None, Mirrors, Square };
RimSymmetry symmetry_of(const RimScene& s);

// Truncation of the series, and the number of equations per unknown. The defaults are
// rim_level(5), where the paper's scene has settled to 1e-13.
struct RimSeriesOptions {
  int harmonics = 28;        // highest Fourier order m of q(theta)
  int degree = 56;           // highest degree of the Trefftz polynomials about the plate's centre
  int corner_terms = 3;      // clamped-corner exponents per family (symmetric, antisymmetric)
  double oversampling = 4;   // collocation equations per unknown
  bool use_symmetry = true;  // false: the general basis and the whole boundary, whatever the scene
  bool extended = false;     // assemble and solve in long double (q's last digits; w and the force do not need it)
};

// Eq. (D15): the radial profile H_m(s), s = r / a, of the field a^3 H_m(r / a) cos(m theta) whose
// bilaplacian is the line load cos(m theta) per unit length on the circle r = a and nothing else:
// H, H', H'' continuous and H''' jumping by +1 at s = 1, bounded inside, decaying outside (m >= 2).
// `inside` picks the formula of s < 1 (it may be evaluated at s = 1 to compare the two sides).
struct RadialProfile {
  double h, h1, h2, h3;  // H and its first three derivatives in s
};
RadialProfile rim_mode_profile(int m, double s, bool inside);

// Eq. (D16): exponents of the clamped right-angle corner, w ~ r^mu Phi(phi) with
// sin((mu - 1) pi / 2) = -(mu - 1) (Phi symmetric about the bisector) or +(mu - 1) (antisymmetric);
// k = 0, 1, ... in increasing real part, upper half plane. mu_0 = 3.7396 + 1.1190i (symmetric).
std::complex<double> corner_exponent(int k, bool symmetric);

// One term of the series, and where it is centred (details of the solver, kept public for tests).
struct SeriesTerm {
  enum class Kind { Power, BarPower, RimMode, Corner } kind = Kind::Power;
  int n = 0;               // Power: zeta^n; BarPower: |zeta|^2 zeta^n; RimMode: m; Corner: k of mu_k
  bool imag = false;       // the imaginary part (Power, BarPower, Corner) or sin(m theta) (RimMode)
  bool symmetric = true;   // Corner: family
  int corner = -1;         // Corner: 0..3 counterclockwise from (0, 0); -1: the sum over the four mirror images
  std::complex<double> mu; // Corner: exponent
};

// w = f p + sum_j c_j T_j: p = |x - centre|^4 / 64 (Lap^2 p = 1), T_j the terms.
struct PlateSeries {
  double lx = 1, ly = 1, cx = 0.5, cy = 0.5, radius = 0, load = 0;  // cx, cy, radius: the rim modes' circle
  std::vector<SeriesTerm> terms;
  std::vector<double> coef;
  PointValues at(double x, double y) const;  // w and its first and second derivatives
};

// One term's value and derivatives at (x, y) (tests: biharmonic, jump and corner conditions).
PointValues term_values(const PlateSeries& field, const SeriesTerm& t, double x, double y);

// Eq. (D17): the clamped plate under the uniform load alone (no obstacle): the same series
// without rim modes. Throws std::invalid_argument for non-positive or non-finite sides or load.
PlateSeries solve_clamped_plate(double lx, double ly, double load, const RimSeriesOptions& o = {});

struct RimPeak {
  double x, y, w;
};

// One solve at one truncation.
struct RimSeries {
  RimScene scene;
  RimSeriesOptions options;
  RimSymmetry symmetry = RimSymmetry::None;
  PlateSeries field;
  std::vector<double> q_cos, q_sin;  // Eq. (D18): q(theta) = sum_m q_cos[m] cos m theta + q_sin[m] sin m theta
  int unknowns = 0, equations = 0;
  // Largest misfit on check points between the collocation points, relative to R: |w| and
  // h |dw/dn| (h the half-diagonal) on the edge, |w - R| on the rim.
  double edge_residual = 0, rim_residual = 0;

  PointValues at(double x, double y) const { return field.at(x, y); }
  double w(double x, double y) const { return field.at(x, y).w; }
  Moments moments(double x, double y, double nu = kPoissonRatio) const;
  double q(double theta) const;  // line load at polar angle theta about the disk's centre
  double total_force() const;    // Eq. (D18): 2 pi a q_cos[0]
  RimPeak max_w() const;         // grid search, then Newton on the gradient
  RimPeak max_w_from(double x, double y) const;  // Newton (or uphill steps) from (x, y)
};

// Eq. (D17): Lap^2 w = f + q delta_rim, clamped, w = R on the rim; q and w from one least-squares
// solve. Throws std::invalid_argument for a bad scene or options.
RimSeries solve_rim_series(const Scene& s, const RimSeriesOptions& o = {});

// Eq. (D14): the premise that makes the series the obstacle problem's solution: the cylinder
// pushes everywhere on the rim (q >= 0) and the plate stays on or above it inside (w >= R).
// Sampled at `angles` angles and on a polar grid of the disk (rings down to 1e-3 a inside the rim);
// `tolerance` is relative (to max q and to R).
struct RimPremise {
  bool holds = false;
  double min_q = 0, theta_min_q = 0;
  double min_w_minus_R = 0, x_min = 0, y_min = 0;  // over the disk, excluding the rim itself
  std::string why;
};
RimPremise check_premise(const RimSeries& s, int angles = kLineLoadAngles, double tolerance = 1e-9);

// The truncation of level l = 0, 1, ...: harmonics 8 + 4l, degree 16 + 8l, corner terms 1 + l / 2.
RimSeriesOptions rim_level(int level, bool extended = false);

struct RimConvergenceRow {
  int level, harmonics, degree, corner_terms, unknowns;
  double max_w, x_max, y_max, total_force, q0, q45;  // q0 = q(0), q45 = q(pi / 4)
  double edge_residual, rim_residual;
};

// Solves at levels 0..levels-1. A bar is the change from the previous level, but never below the
// round-off floor 1000 u |value|; `settled` says each bar is below the change before it (or at the
// floor): the changes shrink geometrically, so the last one bounds the error of the finest level.
struct RimAnswer {
  RimSeries finest;
  RimPremise premise;
  std::vector<RimConvergenceRow> rows;
  double bar_max_w = 0, bar_force = 0, bar_q0 = 0, bar_q45 = 0;
  bool settled = false;
};
// `first`: the coarsest level solved (at least three levels are kept, for a bar that shrank). An
// answer in double whose premise holds but that has not settled is solved again in long double.
RimAnswer rim_answer(const Scene& s, int levels = 6, bool extended = false, int first = 0);

// The series' line load as a report of the grid schemes states one (line_force.hpp): its values at
// kLineLoadAngles equal angles from 0, the rim's length, the total (D18), the mean q_cos[0], and the
// extremes over those angles.
LineForce rim_line_force(const RimSeries& s);
// q at 0 and pi/4, and f's table (rim_line_force's) with its points on the rim (no fit: the series
// is the function).
LineFigures rim_line_figures(const RimSeries& s, const LineForce& f);

// max |m12| over the plate (Fig. 2's quantity, off the grid): on a lattice of (k + 1)^2 points, then
// on finer lattices about the best one.
double rim_max_abs_m12(const RimSeries& s, double nu, int k = 100);

}  // namespace plate
