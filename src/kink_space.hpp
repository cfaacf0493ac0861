// What the kink-carrying spaces (D31) on a circle and (D33) on a polygon's sides share: the
// cut-off's band, the enrichment's description, the cubic B-spline and the cut-off chi, and the
// blocks they add to the plate's system. kink_enrichment.hpp builds on it and dispatches a polygon's
// enrichment to side_kinks.hpp.
#pragma once
#include <vector>

#include "polar.hpp"
#include "sparse.hpp"

namespace plate {

// The cut-off chi of (D31): 1 up to kKinkFlatCells cells outside the rim (every square the rim
// cuts lies within sqrt(2) cells of it), 0 from kKinkZeroCells cells on.
constexpr double kKinkFlatCells = 1.5, kKinkZeroCells = 2.5;
// The band of chi in cells, the defaults above unless a study widens it (kink_study's stability
// section): flat must exceed sqrt(2), so that every square the rim cuts lies where chi = 1, and
// zero must exceed flat.
struct KinkBand {
  double flat = kKinkFlatCells, zero = kKinkZeroCells;
};
// Throws std::invalid_argument unless sqrt(2) < band.flat < band.zero, both finite.
void check_kink_band(const KinkBand& band);

// (D31) fits a grid whose circle is at least this many cells in radius (so no square the rim cuts
// holds its centre) and the band's zero + 1.5 cells (kKinkZeroCells + 1.5 by default) from every
// clamped edge; (D33), a polygon whose sides are at least this many cells long.
constexpr double kKinkMinRadiusCells = 2;
// The splines' knots are at most this many cells apart (kink_enrichment.hpp says when closer).
constexpr double kKinkKnotCells = 4;

// One side of a convex polygon for (D33): its splines are those of the arc length s from the first
// vertex, uniform with `spacing`, centred at s = (j - 1) spacing for j = 0 ... count - 1, so that
// they sum to 1 on the whole side; spline j is spline first + j of the enrichment.
struct KinkSide {
  double x0 = 0, y0 = 0;  // the first vertex
  double tx = 0, ty = 0;  // the unit tangent, towards the second
  double nx = 0, ny = 0;  // the unit normal out of the polygon
  double length = 0, spacing = 0;
  int first = 0, count = 0;
};

// A corner of the polygon for (D34): the biharmonic's r^2 log r about it, boxed; its function is
// spline `index` of the enrichment (after the sides').
struct KinkCorner {
  double x = 0, y = 0;
  int index = 0;
  double inner = 0, outer = 0;  // its box: the cut-off flat to inner, 0 from outer (in each coordinate)
};

struct KinkEnrichment {
  double cx = 0, cy = 0, a = 0;         // the circle of (D31)
  std::vector<KinkSide> sides;          // or the polygon of (D33), counter-clockwise
  std::vector<KinkCorner> corners;      // and its corners (D34)
  double inner = 0, outer = 0;          // chi = 1 for d <= inner, 0 for d >= outer
  double unit = 1;                      // F_k is divided by unit^3 (the cell h^3: kink_enrichment.cpp)
  int knots = 0;                        // M: periodic splines on the whole circle, centred at 2 pi j / M (or the sides' splines, then one per corner)
  std::vector<int> function_of_spline;  // spline j belongs to function function_of_spline[j]
  int functions = 0;
  int size() const { return functions; }
  bool polygon() const { return !sides.empty() || !corners.empty(); }
};

// The centred cubic B-spline of the knot spacing x, and its first two derivatives.
struct KinkSpline {
  double v = 0, d1 = 0, d2 = 0;
};
KinkSpline cubic_bspline(double x);
// A function of the distance d to the edge and its first two derivatives in d.
struct KinkRadial {
  double g = 0, g1 = 0, g2 = 0;
};
// chi(d) of (D31) and (D33), and a corner's box of (D34) in each coordinate: the quintic
// smoothstep, C^2, from 1 at inner to 0 at outer.
KinkRadial kink_cutoff(double inner, double outer, double d);

using KinkValue = PlaneDerivatives;

// The blocks an enrichment adds to the plate's system: (Lap phi_i, Lap psi_k) in the rows of the
// grid's unknowns with its transpose and (Lap psi_k, Lap psi_l) (a square matrix of all unknowns,
// zero in the grid's block), and the load (f, psi_k).
struct KinkBlocks {
  SpMat border;
  VectorXd load;
};

}  // namespace plate
