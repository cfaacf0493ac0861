// Eq. (D31): functions that carry the kink a line load on a circle puts into the plate. Where the
// plate rests on the rim r = a, its third normal derivative jumps by the line load q(theta); a
// bicubic cut by the circle cannot follow that, and the whole plate pays for it at order 3. The
// space is widened by
//   psi_k = chi (F_k - I_h F_k),   F_k(r, theta) = (r - a)_+^3 (1 - (r - a) / (2a)) B_k(theta) / h^3,
// B_k the periodic cubic B-splines of the angle, I_h the grid's Hermite interpolant (nodal values,
// slopes and twist), chi(d) a cut-off of the distance d = r - a: by default 1 up to 1.5 cells outside
// the rim, 0 from 2.5 cells on (KinkBand). F_k is C^2 with its third radial derivative jumping by 6 B_k / h^3 at the rim, so
// psi_k is in H^2 (the space stays conforming) and carries the jump; its fourth jumps by -2/a times
// that, as the plate's equation on either side of a circle demands (D32). Subtracting I_h F_k makes
// psi_k vanish with its slopes and twist at every node: the grid's unknowns stay the nodal values of
// the whole field, and psi_k is small wherever F_k is smooth, so the enlarged system stays about as
// well conditioned as K (the stable GFEM of Babuska and Banerjee, CMAME 201-204, 2012; measured in
// results/kink.md). The cut-off keeps
// each psi_k on a few cells about the rim, where the part that is not small lives. A part of the
// plate (mirror.hpp) gets the sums of each spline with its mirror images, so every function is
// symmetric as the solution is.
#pragma once
#include <string>
#include <vector>

#include "assemble.hpp"
#include "edge.hpp"
#include "grid.hpp"
#include "kink_space.hpp"
#include "sparse.hpp"

namespace plate {

// The edge rows' knot spacing where (D31) is on (problem.cpp's rows_on): kKinkKnotCells cells, or
// closer where that leaves fewer than kKinkKnotsAtLeast knots round the circle, but never closer
// than kKinkKnotCellsMin cells.
constexpr double kKinkKnotCellsMin = 2;
constexpr int kKinkKnotsAtLeast = 32;
// Gauss points of the polar rule of the blocks on each part of a ray: inside the rim, from the rim
// to the cut-off's start, and across the cut-off (kink_enrichment.cpp says why these counts).
struct KinkRulePoints {
  int angle, radius;
};
constexpr KinkRulePoints kKinkRule[3] = {{6, 5}, {6, 6}, {8, 8}};

// How the space is widened: not at all, with (D31) on the scene's circle, or with (D33) across the
// sides of its convex polygon.
struct EnrichSpec {
  enum class Kind { None, Ring, Sides };
  Kind kind = Kind::None;
  KinkBand band;
  bool on() const { return kind != Kind::None; }
};

// Whether (D31) (or (D33), for a polygon: side_kinks.hpp) fits grid g: the circle at least two cells in radius, and every square where chi is
// not 0 clear of the clamped edges (band.zero + 1.5 cells from the rim). A coarser grid of a
// sequence that fails this is solved in the plain space.
bool kink_fits(const Grid& g, const EdgeCurve& circle, const KinkBand& band = {});
// The rows' knot spacing in cells, with (D31) on a circle of radius r on cells of side h.
double kink_knot_cells(double r, double h);
// Why (D31) does not fit grid g, in words; empty where it fits.
std::string kink_misfit(const Grid& g, const EdgeCurve& circle, const KinkBand& band = {});

// The enrichment of (D31) for a circle on grid g (a whole plate or a part), with the `knots` of the
// edge rows' splines; throws std::invalid_argument naming --enrich if the curve is not a circle or
// (D31) does not fit, or std::invalid_argument for a band that breaks KinkBand's rules.
KinkEnrichment make_kink_enrichment(const Grid& g, const EdgeCurve& circle, int knots, const KinkBand& band = {});

// F_k of (D31) at (x, y): value and derivatives (before the interpolant is subtracted); for a
// corner of (D34), D_V, which has none to subtract (side_kinks.cpp).
KinkValue kink_profile(const KinkEnrichment& e, int k, double x, double y);

// The Hermite interpolant of each F_k: P(i, k) = unknown i of F_k at its node (N x functions).
SpMat kink_interpolant(const Grid& g, const KinkEnrichment& e);

// The blocks (D31) adds to the plate's system, integrated in polar coordinates on each cell near the
// rim, split wherever the integrand is not smooth: (Lap phi_i, Lap psi_k) in the rows of the grid's
// unknowns with its transpose and (Lap psi_k, Lap psi_l) (a square matrix of all unknowns, zero in
// the grid's block), and the load (f, psi_k).
KinkBlocks assemble_kink_blocks(const Grid& g, const KinkEnrichment& e, const SpMat& interpolant, const Field& f);

// Whether psi_k can be nonzero at (x, y): a square the rim cuts, or the band where chi is not 0.
bool kink_near(const KinkEnrichment& e, double x, double y);
// sum_k c_k psi_k at (x, y), given `interpolant`, the value and derivatives there of the grid's
// functions with coefficients P c (the interpolant of sum_k c_k F_k, which the caller reads from the
// grid: contact.hpp's PlateField, across mirror lines too): the enrichment's share of the field.
// `cell` (ex, ey), where given, is the square whose polynomials are read: at a node or on a cell side
// the second derivatives of a corner's function (D34) differ from square to square, as the grid's do.
KinkValue kink_field(const KinkEnrichment& e, const VectorXd& c, const KinkValue& interpolant, double x, double y,
                     const int* cell = nullptr);
// Its value alone (kink_field's w, the same number), given the interpolant's value there.
double kink_value(const KinkEnrichment& e, const VectorXd& c, double interpolant, double x, double y);

// The enrichment of a part (mirror.hpp) on the whole plate: every spline its own function, its
// coefficient that of the part's function it belongs to.
KinkEnrichment unfold_kink(const KinkEnrichment& part, const VectorXd& c_part, VectorXd& c_whole);

}  // namespace plate
