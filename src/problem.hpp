// One discrete obstacle problem: the grid, the sampling of the constraint, the obstacle at the
// sample points, and the assembled stiffness, mass and load. Built once, solved many times.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "assemble.hpp"
#include "contact_end.hpp"
#include "kink_enrichment.hpp"
#include "sampling.hpp"
#include "scene.hpp"

namespace plate {

// Which sampling; the Edge kinds sample the scene's edge curve, with rows at points or averaged
// against B-splines.
struct SamplingSpec {
  SamplingKind kind = SamplingKind::Nodes;
  EdgeRows rows;  // edge rows at points, or averaged against B-splines (make_sampling)
  EnrichSpec enrich;  // the space widened by (D31) on the scene's circle, or not
  SamplingSpec() = default;
  SamplingSpec(SamplingKind k, EdgeRows r = {}) : kind(k), rows(r) {}
};

struct Problem {
  Grid grid;          // covers the scene's rectangle, or the part of it that its mirror lines leave
  Sampling sampling;
  VectorXd phi;  // obstacle at the sample points; -inf where there is no constraint
  SpMat K;       // (Lap u, Lap v)
  SpMat M;       // S^T W S
  VectorXd F;    // (f, u)
  SamplingSpec spec;  // how `sampling` was made, so a coarser grid can be sampled alike
  Scene scene;        // what the problem discretises
  // The functions (D31) adds after the grid's unknowns, the interpolant they subtract, and the part
  // of K they bring (their border and their own block), kept apart for residuals in extended
  // precision. None: the plain space.
  std::optional<KinkEnrichment> kink;
  SpMat kink_interp;
  SpMat enrichment_block;  // every enrichment's part of K: (D31)'s, then the ends'
  // The functions of the contacts' ends (contact_end.hpp), one per entry, after (D31)'s: none until
  // attach_ends gives them.
  std::vector<ContactEnd> ends;
  std::vector<EndField> end_fields;
  int kink_size() const { return kink ? kink->size() : 0; }
  // Unknowns of the space: the grid's, then (D31)'s, then the ends'.
  int unknowns() const { return grid.unknowns() + kink_size() + static_cast<int>(ends.size()); }
};

// The scene on the grid g (the whole rectangle, or a part of it: mirror.hpp), sampled as `spec`
// says. Throws std::invalid_argument (naming "obstacle" or "load") for NaN or +inf values, for an
// obstacle that is not below zero on the boundary (then no clamped plate can satisfy w >= phi), and
// for a grid that does not cover the scene's rectangle.
Problem make_problem(const Scene& s, const Grid& g, const SamplingSpec& spec);

// Why p's solve may have failed by overflow, or "" if it cannot have: an obstacle so high that K w
// overflows turns every later step to inf or NaN, and the solver then reports a failure of another
// kind (the cylinder with R = 1e307 at n = 64: "the constraints cannot all hold"). A row of K has 36
// terms (a node and its eight neighbours, four unknowns each), each up to max |K| max |phi|. The
// bound is pessimistic, so plate asks it only after a solve that failed, and then names the obstacle
// whatever the failure was: above about 1e301 / n^2 nothing else is worth suspecting. (The load is
// not bounded here: a converged answer with an output that is not finite is refused on its own.)
std::string overflow_risk(const Problem& p);
// Why p's solve may have failed by underflow, or "": an obstacle so low that w's smallest terms
// (a twist times h^2, about |phi| h^2) fall below double precision's normal range, 2.2e-308, where
// digits are lost (the cylinder with R = 1e-320 at n = 64 solved to w = 0, which the certificate now
// refuses), or a load vector that small. Asked only after a failed solve, like overflow_risk.
std::string underflow_risk(const Problem& p);
// The grid, its sampling and the obstacle at the samples, without K, M and F: what the reports of
// a solve on part of the plate read on the whole (mirror.hpp). Validates as make_problem does.
Problem make_samples(const Scene& s, const Grid& g, const SamplingSpec& spec);

// Whether the space on grid g is widened by (D31): asked for, edge sampling (not edge-gauss), and a
// circle it fits.
bool kink_on(const Grid& g, const Scene& s, const SamplingSpec& spec);
// The edge rows grid g gets: spec.rows, with splines kink_knot_cells apart where (D31) is on and no
// spacing was asked for.
EdgeRows rows_on(const Grid& g, const Scene& s, const SamplingSpec& spec);

// Gives p the enrichment e (D31): its interpolant, and a column of S for each of its functions
// (their values on the rim, -I_h F_k). K and F are left as they are.
void attach_kink(Problem& p, const KinkEnrichment& e);

// Gives p the functions chi (F - I_h F) of `fields` at `ends` (contact_end.hpp), after (D31)'s: K
// bordered by their blocks (with (D31)'s functions too), F by their load, and a column of S each
// (their values at the point rows, their averages on the spline rows). Edge sampling with rows laid
// out for the contact only; throws std::invalid_argument where an end's cut-off reaches a clamped
// edge or a mirror line (its images would be other functions), and std::logic_error if p has ends.
void attach_ends(Problem& p, const std::vector<ContactEnd>& ends, const std::vector<EndField>& fields);
// Where (D31)'s Laplacians kink, for the ends' cross block to follow: its cut-off's edges and the
// rays of its knots (each line once, for a knot and the one opposite).
OtherKinks kink_curves(const KinkEnrichment& e);

// The rows on p's circle laid out anew for a contact (rim_rows.hpp, D28): the sampling and the
// obstacle at its samples remade; K and F kept; M remade.
void lay_out_rim(Problem& p, const RimLayout& layout);
// Point rows appended at `angles` of p's circle (sampling.hpp's append_rim_points), the obstacle
// read at each, M remade.
void append_rim_points(Problem& p, const std::vector<double>& angles);

// The obstacle at a point (x, y) of its edge curve with normal (nx, ny): the largest value on the
// curve and a hair's breadth (1e-9 h) to either side, its upper semicontinuous envelope there.
double obstacle_on_edge(const Field& obstacle, double x, double y, double nx, double ny, double h);

// Samples phi along the clamped edges (every node and 8 points per cell edge) and throws
// std::invalid_argument if phi >= 0 or NaN at any of them. A mirror edge is not checked.
void check_obstacle_on_boundary(const Grid& g, const Field& obstacle);

}  // namespace plate
