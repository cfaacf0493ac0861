// The rows on a circle fitted to the contact a solve finds (D28, rim_rows.hpp), and the constraint
// held on the whole rim off the spline arcs: after a solve, every point of the rim where the plate
// dips below the obstacle between rows gets a row of its own (an exchange method for a constraint on
// a curve), until the plate dips nowhere there.
#pragma once
#include <cmath>
#include <vector>

#include "problem.hpp"
#include "rim_rows.hpp"

namespace plate {

// Whether p's rows on its circle are the default (auto) splines, which a solve lays out by the contact.
bool rim_follows_contact(const Problem& p);

// The contact of a solve (w, and lambda a force density per sample row) on the whole circle
// (contact_arcs): the edge rows that push or touch (lie within `touch` of the obstacle: the solver
// leaves a row that holds to round-off without a multiplier), with their mirror images.
ContactArcs rim_contact(const Problem& p, const VectorXd& w, const VectorXd& lambda, double touch);

// The layout for that contact on p's grid: splines on each contact arc shrunk by two cells at each
// end, in spans of two cells at its ends doubling up to the spacing of (D12) (graded_breaks); the
// points of edge_points a cell apart everywhere else.
RimLayout rim_layout_for(const Problem& p, const ContactArcs& contact);

// Points a cell apart round the whole circle, no splines: the layout that always suits a contact.
RimLayout rim_points_only(const Problem& p);

// Whether p's layout suits the solve's contact: every spline row in contact (as rim_contact says),
// and, unless the splines are periodic, every spline arc at least a cell inside a contact arc.
bool rim_layout_fits(const Problem& p, const VectorXd& w, const VectorXd& lambda, double touch);

// The angles, on the part of the circle p's grid holds and off its spline arcs, of the local minima
// of w_h - phi over a lattice of angles (eight to each spacing of edge_points) that lie more than
// `slack` below the obstacle, each where no point row is yet. A solve that adds these until there
// are none ends with w_h >= phi at every lattice point off the arcs, whatever order it added them in.
std::vector<double> rim_dips(const Problem& p, const VectorXd& w, double slack);

// Which of p's rows hold the plate at angle theta on its circle, for a report of where it dips: on
// a spline arc, how far inside it in cells (the distance to the arc's nearer end over h / r);
// infinity on periodic splines, which have no end; NaN off every arc, where point rows hold it.
double cells_inside_spline_arc(const Problem& p, double theta);

// Which kind of rows a value of cells_inside_spline_arc names, the one reading of its code.
enum class RowsAt { Points, Periodic, Arc };
inline RowsAt rows_at(double cells_inside) {
  return std::isnan(cells_inside) ? RowsAt::Points : std::isinf(cells_inside) ? RowsAt::Periodic : RowsAt::Arc;
}

}  // namespace plate
