// Eq. (D33): the kink of (D31) across the sides of a convex polygon. Where the plate rests on a
// straight side, its third normal derivative jumps by the line load q(s), as on the rim of a
// circle, but with no curvature the plate's equation asks no jump of the fourth (D32's -2/a is 0).
// Side i, with outward normal n_i and arc length s_i from its first vertex, gets
//   F_ij(x) = (d_i / h)_+^3 B_j(s_i),   d_i = (x - V_i) . n_i,
// B_j its cubic B-splines (KinkSide). d_i and s_i are linear, so F_ij is a polynomial on either side
// of the side's line and of each knot's normal: C^2 across both. The cut-off is the product
//   chi = prod_i c(d_i),   c the quintic step of kink_cutoff,
// which is 1 wherever every d_i <= inner (on every square a side cuts: outside a convex polygon
// the distance to it is at least each d_i), and C^2 with no other breaks; so psi_ij = chi (F_ij -
// I_h F_ij) is a polynomial on each piece of the square that the sides' lines, the knots' normals
// and the lines d_i = inner and d_i = outer cut, and (D33)'s blocks are integrated there exactly.
// The splines run on past each vertex (three knots), so a side's kink there is only approximately
// stopped: the corners, where the line load of a plate on a polygon is not smooth, limit the order.
#pragma once
#include <string>

#include "assemble.hpp"
#include "edge.hpp"
#include "grid.hpp"
#include "kink_space.hpp"
#include "sparse.hpp"

namespace plate {

// Why (D33) does not fit grid g, in words; empty where it fits: the polygon must be convex, each
// side at least kKinkMinRadiusCells cells long, every square where a function can be nonzero clear
// of the clamped edges, and, on a part, the functions must map onto each other across its mirror lines.
std::string side_kink_misfit(const Grid& g, const EdgeCurve& polygon, const KinkBand& band);

// The enrichment of (D33) for a polygon on grid g (a whole plate or a part); throws
// std::invalid_argument naming --enrich where side_kink_misfit does not pass.
KinkEnrichment make_side_kinks(const Grid& g, const EdgeCurve& polygon, const KinkBand& band = {});

// kink_enrichment.hpp's functions for a polygon's enrichment, which they call for one.
KinkValue side_kink_profile(const KinkEnrichment& e, int k, double x, double y);
SpMat side_kink_interpolant(const Grid& g, const KinkEnrichment& e);
KinkBlocks assemble_side_kink_blocks(const Grid& g, const KinkEnrichment& e, const SpMat& interpolant, const Field& f);
bool side_kink_near(const KinkEnrichment& e, double x, double y);
KinkValue side_kink_field(const KinkEnrichment& e, const VectorXd& c, const KinkValue& interpolant, double x, double y,
                          const int* cell = nullptr);
double side_kink_value(const KinkEnrichment& e, const VectorXd& c, double interpolant, double x, double y);

}  // namespace plate
