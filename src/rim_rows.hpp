// The rows on a circle laid out by the contact they meet (D28). Where the plate touches the rim all
// along an arc, the constraint is averaged against cubic B-splines of the angle there (D12: a line
// load that converges point by point). Where the contact ends, the line load grows like the inverse
// square root of the distance to the end and the gap closes like its 5/2 power; a spline straddling
// that end holds the plate to R on average only, so the plate dips through the obstacle on one side
// and lifts off too soon on the other. There, and where the plate is free, the constraint is held at
// points a cell apart, and at every point between them where the plate would dip (an exchange
// method for the constraint on the whole curve), so the end of the contact is found at the grid's
// own resolution.
#pragma once
#include <utility>
#include <vector>

namespace plate {

// An arc of the circle (angles, breaks[0] < ... < breaks.back() <= breaks[0] + 2 pi) carrying the
// clamped B-splines of the angle of one degree on the knot spans between its breaks: the first and
// last breaks repeated degree + 1 times.
struct SplineArc {
  std::vector<double> breaks;
  double begin() const { return breaks.front(); }
  double end() const { return breaks.back(); }
  int intervals() const { return static_cast<int>(breaks.size()) - 1; }
  double span(int k) const { return breaks[k + 1] - breaks[k]; }
  double widest() const;                     // the widest span
  double knot(int i, int degree) const;      // i = 0 ... intervals + 2 degree
  int basis_count(int degree) const { return intervals() + degree; }
  double greville(int j, int degree) const;  // the mean of the inner knots of basis j: where its row sits
  bool contains(double theta) const;         // theta taken modulo 2 pi; the ends to 1e-12
};

// The value at theta of basis j (0 ... basis_count - 1) of the arc; 0 off its support. Cox-de Boor.
double clamped_bspline(const SplineArc& a, int degree, int j, double theta);
// The integral of basis j over its support, in radians: (t_{j+p+1} - t_j) / (p + 1).
double clamped_bspline_integral(const SplineArc& a, int degree, int j);

// Where the rows on a circle go. Periodic: uniform periodic splines round the whole circle (D12),
// the layout of a plate that touches the whole rim. Otherwise: clamped splines on `arcs`, and one
// row at each angle of `points`, which lie off the arcs.
struct RimLayout {
  bool periodic = true;
  std::vector<SplineArc> arcs;
  std::vector<double> points;  // angles in [0, 2 pi)
};

// An edge row's place in a layout: basis `basis` of arc `arc`, or a point (arc = -1) of index
// `basis` in RimLayout::points; for periodic splines arc = -2 and basis is the knot.
struct RimRow {
  int arc = -2, basis = 0;
  bool point() const { return arc == -1; }
};

// The arcs where a solve found contact. Each row stands for the arc nearer to it than to the rows
// beside it, or at least `reach` (an angle) to each side; the contact is the union of the arcs of
// the rows in contact (angles of the whole circle, every row with its mirror images). `whole` when
// that is the whole circle.
struct ContactArcs {
  bool whole = false;
  std::vector<std::pair<double, double>> arcs;  // begin < end, begin in [0, 2 pi)
};
ContactArcs contact_arcs(const std::vector<double>& rows, const std::vector<bool>& touching,
                         const std::vector<double>& reach);

// The breaks of an arc from `begin` to `end`: spans of `finest` at both ends, doubling towards the
// middle up to `spacing`, and equal spans of at most `spacing` between (angles). The line load grows
// like s^(-1/2) at a contact's end, and spans graded so keep its error as small there as elsewhere.
// Symmetric: the breaks from the other end are the same. Empty if the arc is shorter than 2 finest.
std::vector<double> graded_breaks(double begin, double end, double finest, double spacing);

// The layout for a contact: splines on each contact arc shrunk by `margin` at both ends, on
// graded_breaks(finest, spacing), where at least two finest spans are left; one point at each angle
// of `lattice` off those arcs. Each arc's ends are moved to the nearest multiple of `snap` (> 0), so
// that contacts equal to round-off give one layout, and the mirror images of an arc are arcs of
// the layout exactly. A whole-circle contact gives the periodic layout.
RimLayout layout_for(const ContactArcs& contact, double margin, double finest, double spacing,
                     const std::vector<double>& lattice, double snap);

// The arc length each point row stands for (radius r): half the way to each neighbouring point,
// all the way to the end of a neighbouring spline arc, round the whole circle. One per point.
std::vector<double> point_weights(const RimLayout& layout, double r);

// Whether the splines of `layout` lie where a solve found contact: every arc inside a contact arc,
// with at least `clearance` (angle) of contact beyond each of its ends.
bool arcs_inside(const RimLayout& layout, const ContactArcs& contact, double clearance);

}  // namespace plate
