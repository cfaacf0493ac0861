// Where the constraint w >= phi is imposed: sample points x_p with positive weights W_p and the
// sparse matrix S taking the unknowns to the point values (S w)_p = w_h(x_p). The penalty term of
// (8) is then eps^{-1} S^T W beta(S w), whichever sampling is used.
#pragma once
#include <string>
#include <vector>

#include "edge.hpp"
#include "grid.hpp"
#include "rim_rows.hpp"
#include "sparse.hpp"

namespace plate {

// How the edge rows constrain the plate: at points about a cell apart, or averaged against
// B-splines of the angle (circles only, D12). Auto, the default, is splines on a circle where the
// plate touches the whole rim, laid out by the contact where it does not (rim_rows.hpp, D28), and
// points on a polygon.
struct EdgeRows {
  enum class Kind { Auto, Points, Splines };
  Kind kind = Kind::Auto;
  int degree = 3;    // of the splines
  double cells = 0;  // knot spacing in cells; 0: the spacing h^(3/7) r^(4/7) of (D12)
  bool splines_on(const EdgeCurve& c) const {
    return kind == Kind::Splines || (kind == Kind::Auto && c.kind == EdgeCurve::Kind::Circle);
  }
  static EdgeRows points() { return EdgeRows{Kind::Points, 0, 0}; }
  static EdgeRows splines(int degree, double cells = 0) { return EdgeRows{Kind::Splines, degree, cells}; }
};
// The number of knots (D12) on a circle of radius r: 2 pi r over the spacing, a multiple of four
// (so that the square's symmetries and the mirrors about its centre lines map knots onto knots),
// at least 8.
int spline_knots(double r, double h, const EdgeRows& rows);
// The centred cardinal B-spline of degree p, x in knot spacings (1 at 0 for the hat, p = 1).
double cardinal_bspline(int p, double x);

enum class SamplingKind {
  Gauss,      // 4 x 4 Gauss points per element with their weights: (8) with the L2 product, exactly
  Nodes,      // interior grid nodes with weight h^2: the trapezoid rule, constraints on nodal values
  Edge,       // the interior nodes, and points on the obstacle's edge weighted by arc length
  EdgeGauss,  // the Gauss points, and the edge points
};

// Rows [0, edge_begin) are the interior samples (area weights: W_p is an area); rows from
// edge_begin on lie on the obstacle's edge (W_p is a length, so a multiplier there is a force per
// unit length: the line load of (9) on the circle (10)).
struct Sampling {
  SamplingKind kind;
  std::vector<double> x, y;  // the points
  VectorXd weights;          // W_p > 0
  RowSpMat S;                // points x unknowns
  int edge_begin = 0;
  EdgePoints edge;           // the edge rows' points, normals and angles
  int edge_spline_degree = 0;  // > 0: the edge rows are B-spline averages, their points the knots
  int edge_knots = 0;          // periodic splines: knots on the whole circle (the part may hold fewer)
  RimLayout rim;               // the layout of a circle's rows (periodic unless made for a contact)
  std::vector<RimRow> rim_rows;  // with a layout that is not periodic: each edge row's place in it
  bool rim_laid_out() const { return edge_spline_degree > 0 && !rim.periodic; }
  int size() const { return static_cast<int>(x.size()); }
  int edge_size() const { return size() - edge_begin; }
  // Whether every row is a bound on one nodal value (row q on interior node q).
  bool nodal_bounds() const { return edge_size() == 0 && (kind == SamplingKind::Nodes || kind == SamplingKind::Edge); }
};

// `edge` is used by the Edge kinds only: they sample it, and drop the interior samples that lie
// on it (a node on the circle would repeat an edge point, or stand for the line as an area).
// On a circle with spline rows (rows.splines_on) each edge row is the constraint averaged against a
// B-spline of the angle; otherwise one row per point, about a cell apart.
// `layout` (a circle with spline rows only) places the rows for a contact instead of periodically.
Sampling make_sampling(const Grid& g, SamplingKind kind, const EdgeCurve& edge = {}, const EdgeRows& rows = {},
                       const RimLayout& layout = {});
// Appends a point row at each angle of `angles` on the circle `c` (those in the grid's part of the
// plate; a point on a mirror line stands for itself alone, with half its weight), adds the angles
// and their mirror images to s.rim.points, and gives every point row the weight point_weights says.
// The new rows are the last ones; the rows before them keep their order and values.
void append_rim_points(const Grid& g, const EdgeCurve& c, const std::vector<double>& angles, Sampling& s);
// The images of an angle on a circle about the centre of a part's mirror lines: itself, and
// pi - theta, -theta, pi + theta as the grid's mirrors allow.
std::vector<double> mirror_angles(const Grid& g, double theta);
const char* to_string(SamplingKind kind);
// The sampling named by to_string; throws std::invalid_argument naming --sampling otherwise.
SamplingKind sampling_kind(const std::string& name);
inline bool has_edge(SamplingKind k) { return k == SamplingKind::Edge || k == SamplingKind::EdgeGauss; }

// Where an edge row reads the plate: points and weights with (S w)_k = sum weight w_h(x, y).
struct RowPoint {
  double x, y, weight;
};
// Spline row j of `arc` on the circle c: its quadrature (D28), pieces of about a cell with four
// Gauss points each, the weights summing to one.
std::vector<RowPoint> spline_row_points(const Grid& g, const EdgeCurve& c, const SplineArc& arc, int degree, int j);
// Edge row k of s (0 for its first): its point, weight 1, or its spline's quadrature (rows laid out
// for a contact; a periodic spline row is refused with std::logic_error).
std::vector<RowPoint> edge_row_points(const Grid& g, const EdgeCurve& c, const Sampling& s, int k);

// S^T diag(d) S, visiting only the points with d_p != 0 (the active ones, in the schemes).
SpMat weighted_gram(const RowSpMat& S, const VectorXd& d, int unknowns);

}  // namespace plate
