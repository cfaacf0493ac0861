// The `plate` program's outputs: the nodal fields as CSV and the summary as JSON.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "active_set.hpp"
#include "contact.hpp"
#include "error_bar.hpp"
#include "extrema.hpp"
#include "line_force.hpp"
#include "obstacle_jumps.hpp"
#include "schemes.hpp"

namespace plate {

struct RimAnswer;  // rim_contact.hpp

// What one run of `plate` reports, whichever model solved it: the grid's (problem, result, nodes
// and the fields after them) or the rim-contact series' (series; rim_report.hpp writes it).
struct Report {
  std::vector<std::pair<std::string, std::string>> config;  // the options the model echoed (plate's echo)
  double nu = kPoissonRatio;
  bool converged = false;               // the model's verdict, which every output states
  std::string message;                  // why not
  const RimAnswer* series = nullptr;    // --scheme semi-analytic: the series' answer, and no grid
  const Problem* problem = nullptr;
  const SolveResult* result = nullptr;
  const NodalFields* nodes = nullptr;
  VectorXd xi;                                    // contact force density at the sample points
  LineForce line;                                 // the line load on the edge (edge sampling; the series': on its rim)
  LineFigures line_figures;                       // its values a report states (line_force.hpp)
  const Certificate* certificate = nullptr;       // the exact solver's; null for the penalty schemes
  double certificate_tol = 0;
  std::vector<std::pair<double, double>> points;  // where the user asked for w
  double lambda1h = -1;                           // < 0: not computed
  double sharp_factor = NAN, paper_rho = NAN;     // with lambda1h: the contraction per iteration at the final eps
  double penalty_residual = NAN;                  // the penalty schemes': the residual of (2a)
  double seconds_assemble = 0, seconds_total = 0;
  double eps_unit = 1;  // eps is printed divided by this, in the user's unit (plate: lx^4)
  std::string model = "whole plate";  // the part of the plate solved (mirror.hpp)
  int model_unknowns = 0;             // its unknowns; 0: the whole grid's
  std::string space = "Bogner-Fox-Schmit";  // the finite-element space (with the enrichment D31, if any)
  std::vector<double> refinement;     // the exact solve's refinement steps, each correction's relative size
  double refinement_undone = 0;       // its first correction, when the next did not confirm it (then undone)
  double dip_below_edge = NAN;        // max of phi - w along the edge curve (NaN: no edge)
  double dip_theta = NAN;             // where it is deepest, on a circle (NaN: a polygon, or no dip)
  double dip_cells = NAN;             // the rows there: cells inside a spline arc; inf periodic; NaN points
  // Jumps of the obstacle with no edge rows there (obstacle_jumps.hpp) that the plate comes near.
  std::vector<ObstacleJump> jumps;
  // The extremes of the finite-element fields over the plate and w_h at `points` (extrema.hpp), or
  // the series' peak and w at `points`, measured by the program before it reports; the nodal ones
  // are read off `nodes`.
  FieldMeasures measures;
  NodalExtremes nodal;        // of *nodes
  double total_force = NAN;   // the contact force, summed over the sample rows
  double violation = NAN;     // max over the rows of phi - S w, 0 if none lies below
  // How the rows on a circle were laid out (D28): spline arcs, point rows, those added by exchange, layouts tried.
  int rim_arcs = -1, rim_points = 0, rim_exchanged = 0, rim_layouts = 0;
  // Error bars on the distance to the plate's answer (error_bar.hpp), from the grids `bar_grids` of
  // the run's sequence; empty with the reason in `bar_note` when there are none.
  std::vector<std::pair<std::string, ErrorBar>> bars;
  std::vector<int> bar_grids;
  std::string bar_grids_note;  // why coarser grids of the sequence were left out, if they were
  std::string bar_note;
};
std::string nodal_csv(const NodalFields& f);
std::string line_force_csv(const Problem& p, const LineForce& f, const LineFigures& g);
std::string summary_json(const Report& r);
std::string summary_text(const Report& r);
std::string error_bars_text(const Report& r);  // the lines of summary_text that give the error bars

}  // namespace plate
