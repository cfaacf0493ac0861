// Formatting of the outputs. The summary and the CSVs carry 10 significant digits, for a reader;
// the grid schemes' JSON carries every digit of the double (the series' JSON, rim_report.cpp, 15),
// for a program that compares answers (the kink space's max w is within 1e-10 of the series, where
// ten digits would round the error away). JSON has no infinity, so an absent obstacle (-inf) is
// written as null.
#include "summary.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

#include "format.hpp"
#include "rim_exchange.hpp"

namespace plate {

namespace {
// Ten digits for a reader: about what the finest answers here are certain to (the JSON has every digit).
std::string summary_value(double v) { return std::isfinite(v) ? fmt_digits(v, 10) : "null"; }
std::string csv_num(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char b[32];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}
}  // namespace

std::string nodal_csv(const NodalFields& f) {
  std::ostringstream o;
  o << "# plate: nodal fields; w and derivatives (second ones averaged over the elements at the node),\n"
       "# obstacle phi (-inf: none), contact force density xi = eps^-1 max(phi - w, 0), moments (D = 1)\n"
       "x,y,w,w_x,w_y,w_xx,w_xy,w_yy,phi,xi,m11,m12,m22,contact\n";
  for (int k = 0; k < f.size(); ++k)
    o << csv_num(f.x[k]) << ',' << csv_num(f.y[k]) << ',' << csv_num(f.w[k]) << ',' << csv_num(f.wx[k]) << ','
      << csv_num(f.wy[k]) << ',' << csv_num(f.wxx[k]) << ',' << csv_num(f.wxy[k]) << ',' << csv_num(f.wyy[k]) << ','
      << csv_num(f.phi[k]) << ',' << csv_num(f.xi[k]) << ',' << csv_num(f.m11[k]) << ',' << csv_num(f.m12[k])
      << ',' << csv_num(f.m22[k]) << ',' << (f.contact[k] ? 1 : 0) << '\n';
  return o.str();
}

std::string line_force_csv(const Problem& p, const LineForce& f, const LineFigures& g) {
  std::ostringstream o;
  if (f.spline_degree > 0) {  // a function of the angle (D12): its values at fixed angles, comparable across grids
    o << "# plate: the contact force per unit length q on the rim, the spline of the edge rows' multipliers (degree "
      << f.spline_degree << ", ";
    if (f.laid_out()) {  // (D28): splines on the contact arcs, points elsewhere; a row is one or the other
      o << f.q.size() - f.point_theta.size() << " bases on " << f.layout.arcs.size() << " arcs; off them the nearest of " << f.point_theta.size()
        << " point rows)";
    } else {
      o << f.coefficients.size() << " knots)";
    }
    o << ", at " << g.theta.size() << " equally spaced angles theta about the circle's centre\n"
         "theta,x,y,q\n";
    for (size_t k = 0; k < g.theta.size(); ++k)
      o << csv_num(g.theta[k]) << ',' << csv_num(g.x[k]) << ',' << csv_num(g.y[k]) << ',' << csv_num(g.q[k]) << '\n';
    return o.str();
  }
  o << "# plate: the contact force per unit length q at the points on the obstacle's edge (theta: angle about\n"
       "# the circle's centre, empty for a polygon), and the weight (arc length) each point stands for\n"
       "theta,x,y,weight,q\n";
  for (size_t k = 0; k < f.q.size(); ++k) {
    const int row = p.sampling.edge_begin + static_cast<int>(k);
    o << (f.theta.empty() ? std::string() : csv_num(f.theta[k])) << ',' << csv_num(p.sampling.x[row]) << ','
      << csv_num(p.sampling.y[row]) << ',' << csv_num(p.sampling.weights[row]) << ',' << csv_num(f.q[k]) << '\n';
  }
  return o.str();
}

namespace {
using Json = nlohmann::ordered_json;  // keys in the order written, as a reader expects them

// The double itself (nlohmann writes a form that reads back to it exactly); JSON has no infinity
// or NaN, so those become null.
Json number(double v) {
  if (!std::isfinite(v)) return nullptr;
  return v;
}

Json numbers(const std::vector<double>& v) {
  Json a = Json::array();
  for (double x : v) a.push_back(number(x));
  return a;
}

// The rows between which the plate dips deepest (Report::dip_cells). Off the arcs a stretch may lie
// between an arc's end row and a point row: both count as held point by point there.
std::string dip_rows(const Report& r) {
  switch (rows_at(r.dip_cells)) {
    case RowsAt::Points: return "off the spline arcs, among point rows";
    case RowsAt::Periodic: return "on the periodic spline rows";
    case RowsAt::Arc: return "on a spline arc";
  }
  return "";
}

// What the line load's rows are: the knots of periodic splines (D12), splines on the contact arcs
// and points off them (D28), or points.
std::string rows_are(const LineForce& f) {
  if (f.laid_out()) return "spline bases on the contact arcs and points off them";
  return f.spline_degree > 0 ? "spline knots" : "points";
}

Json line_force_json(const LineForce& f, const LineFigures& g) {
  if (f.empty()) return nullptr;
  Json j = {{"rows", f.q.size()}, {"rows_are", rows_are(f)},
            {"length", number(f.length)}, {"total", number(f.total)},
            {"mean", number(f.mean)}, {"min", number(f.min)}, {"max", number(f.max)},
            {"theta_min", number(f.theta_min)}, {"theta_max", number(f.theta_max)}};
  if (!f.theta.empty()) {
    j["q_fit_theta_0"] = number(g.fit0);
    j["q_fit_theta_pi_4"] = number(g.fit45);
    j["q_theta_0"] = number(g.q0);  // the spline's value, or the nearest point's
    j["q_theta_pi_4"] = number(g.q45);
  }
  j["fourier_cos_4k_theta"] = numbers(f.fourier);
  j["theta"] = numbers(f.theta);
  j["q"] = numbers(f.q);
  return j;
}

Json levels_json(const SolveResult& s, double eps_unit) {
  Json a = Json::array();
  for (const LevelRecord& l : s.levels)
    a.push_back({{"eps", number(l.eps / eps_unit)}, {"iterations", l.iterations}, {"factorizations", l.factorizations},
                 {"last_step", number(l.last_step)}, {"level_change", l.level_change < 0 ? Json(nullptr) : number(l.level_change)},
                 {"converged", l.converged}});
  return a;
}

// The exact solver's certificate, or the penalty run's residual and error bound.
void check_json(Json& j, const Report& r) {
  const SolveResult& s = *r.result;
  if (r.certificate) {
    const Certificate& c = *r.certificate;
    j["certificate"] = {{"violation", number(c.violation)}, {"negative_multiplier", number(c.negative_multiplier)},
                        {"complementarity", number(c.complementarity)}, {"stationarity", number(c.stationarity)},
                        {"tol", number(r.certificate_tol)}};
    j["penalty_residual"] = nullptr;
    j["residual_ok"] = c.worst() <= r.certificate_tol;
  } else {
    j["penalty_residual"] = number(r.penalty_residual);
    j["error_bound"] = {{"bound", number(s.bound.bound)}, {"roundoff", number(s.bound.roundoff)},
                        {"green_centre", number(s.bound.green)}};
    j["residual_ok"] = s.converged;
  }
}
Json error_bars_json(const Report& r) {
  Json j = {{"grids", r.bar_grids}, {"note", r.bar_note}, {"grids_note", r.bar_grids_note}};
  for (const auto& [name, b] : r.bars)
    j[name] = {{"value", number(b.value)}, {"bar", number(b.bar)}, {"basis", b.basis}, {"steady", b.steady},
               {"order", number(b.order)}, {"limit", number(b.limit)}};
  return j;
}

// The largest error bar on a value of w (max w, min w, w at a point), or -1 if there is none. The
// plate's own answer keeps above the obstacle, so a dip below it between rows is a distance of w_h
// from that answer: a dip beyond every such bar puts w_h farther from the answer somewhere than any
// bar puts a value of w, which suggests that the rows resolve the constraint more coarsely than the
// bars suggest (--edge-rows spline:3,50 at n = 64 dips 5e-4 with a bar of 4e-8 on max w, which is
// 1e-4 off).
double largest_w_bar(const Report& r) {
  double largest = -1;
  for (const auto& [name, b] : r.bars)
    if ((name == "max w" || name == "min w" || name.rfind("w(", 0) == 0) && std::isfinite(b.bar)) largest = std::max(largest, b.bar);
  return largest;
}
bool dip_beyond_bars(const Report& r) {
  const double largest = largest_w_bar(r);
  return std::isfinite(r.dip_below_edge) && largest >= 0 && r.dip_below_edge > largest;
}
}  // namespace

std::string error_bars_text(const Report& r) {
  std::ostringstream o;
  if (r.bars.empty()) {
    if (!r.bar_note.empty()) o << "error bar (continuum): none: " << r.bar_note << "\n";
    return o.str();
  }
  o << "error bars (continuum: the distance to the plate's answer, estimated from the grids n =";
  for (size_t k = 0; k < r.bar_grids.size(); ++k) o << (k ? ", " : " ") << r.bar_grids[k];
  o << " of this run's sequence" << (r.bar_grids_note.empty() ? "" : "; " + r.bar_grids_note) << "):\n";
  for (const auto& [name, b] : r.bars) {
    o << "  " << name << " = " << summary_value(b.value) << " +- " << fmt("%.2g", b.bar) << "  (";
    if (b.basis == "richardson") o << "Richardson, order " << fmt("%.2f", b.order) << ", steady";
    else if (b.basis == "last difference")
      o << "NOT STEADY: the last difference" << (std::isfinite(b.order) ? ", order " + fmt("%.2f", b.order) : std::string(", one grid before"));
    else if (b.basis == "the same on every grid")
      o << "the same value on every grid: 0 holds only if the scene fixes it, which no grid can tell from a feature they all miss";
    else if (b.basis == "last difference across the spaces") o << "NOT STEADY: the step from the grid before, plus that grid's own bar";
    else if (b.basis != "none") o << "NOT STEADY: the values swing, or close faster than any order here; the larger of the last two differences";
    else o << "none";
    o << ")\n";
  }
  return o.str();
}

std::string summary_json(const Report& r) {
  const Problem& p = *r.problem;
  const SolveResult& s = *r.result;
  const NodalFields& f = *r.nodes;
  const NodalExtremes& e = r.nodal;
  const VectorXd& xi = r.xi;
  Json j;
  j["config"] = Json::object();
  for (const auto& [k, v] : r.config) j["config"][k] = v;
  j["grid"] = {{"nx", p.grid.nx}, {"ny", p.grid.ny}, {"h", number(p.grid.h)}, {"unknowns", p.grid.unknowns()},
               {"sample_points", p.sampling.size()}};
  j["model"] = {{"part", r.model}, {"unknowns", r.model_unknowns > 0 ? r.model_unknowns : p.grid.unknowns()}, {"space", r.space}};
  j["converged"] = r.converged;
  j["message"] = r.message;
  j["eps_final"] = number(s.eps / r.eps_unit);
  j["total_iterations"] = s.total_iterations();
  j["levels"] = levels_json(s, r.eps_unit);
  // Extremes of the field w_h over the plate; the nodal maximum apart, labelled as such.
  j["max_w"] = number(r.measures.max_w.value);
  j["max_w_at"] = {number(r.measures.max_w.x), number(r.measures.max_w.y)};
  j["min_w"] = number(r.measures.min_w.value);
  j["min_w_at"] = {number(r.measures.min_w.x), number(r.measures.min_w.y)};
  j["max_abs_w"] = number(std::max(std::abs(r.measures.max_w.value), std::abs(r.measures.min_w.value)));
  j["max_w_nodes"] = number(e.max_w);
  j["max_w_nodes_at"] = {number(f.x[e.argmax_w]), number(f.y[e.argmax_w])};
  j["w_at_points"] = Json::array();
  for (size_t k = 0; k < r.points.size(); ++k)
    j["w_at_points"].push_back({{"x", number(r.points[k].first)}, {"y", number(r.points[k].second)}, {"w", number(r.measures.w_at.at(k))}});
  j["total_contact_force"] = number(r.total_force);
  j["max_xi_samples"] = number(xi.size() ? xi.maxCoeff() : 0.0);
  j["max_xi_nodes"] = number(e.max_xi);
  j["max_abs_m12"] = number(r.measures.max_abs_m12.value);
  j["max_abs_m12_at"] = {number(r.measures.max_abs_m12.x), number(r.measures.max_abs_m12.y)};
  j["max_abs_m12_nodes"] = number(e.max_abs_m12);
  j["line_force"] = line_force_json(r.line, r.line_figures);
  j["constraint_violation"] = number(r.violation);
  j["dip_below_edge"] = number(r.dip_below_edge);
  if (std::isfinite(r.dip_theta)) {
    j["dip_below_edge_theta"] = number(r.dip_theta);
    j["dip_below_edge_rows"] = dip_rows(r);
    if (rows_at(r.dip_cells) == RowsAt::Arc) j["dip_below_edge_cells_inside_arc"] = number(r.dip_cells);
  }
  check_json(j, r);
  // What each bound is about: the certificate, the discrete answer; the error bars, the plate's.
  j["certificate_is"] = "discrete: the distance of this answer from the exact solution of the discrete problem";
  j["error_bar_is"] = "continuum: the estimated distance of each value from the plate's own answer (h -> 0)";
  j["error_bars"] = error_bars_json(r);
  j["refinement"] = numbers(r.refinement);
  j["refinement_undone"] = r.refinement_undone > 0 ? number(r.refinement_undone) : nullptr;
  j["dip_beyond_w_bars"] = dip_beyond_bars(r);
  j["obstacle_jumps_without_edge"] = r.jumps.size();
  j["first_jump_at"] = r.jumps.empty() ? Json(nullptr) : Json{number(r.jumps.front().x), number(r.jumps.front().y)};
  j["contact_nodes"] = Json::array();
  for (int k : e.contact) j["contact_nodes"].push_back({number(f.x[k]), number(f.y[k])});
  if (r.lambda1h > 0)
    j["contraction"] = {{"lambda1h", number(r.lambda1h)}, {"sharp_factor", number(r.sharp_factor)},
                        {"paper_rho", number(r.paper_rho)}, {"at_eps", number(s.eps / r.eps_unit)}};
  j["seconds"] = {{"assemble", number(r.seconds_assemble)}, {"factorize", number(s.seconds_factorize)},
                  {"iterate", number(s.seconds_iterate)}, {"bound", number(s.seconds_bound)},
                  {"total", number(r.seconds_total)}};
  return j.dump(2) + "\n";
}

std::string summary_text(const Report& r) {
  const SolveResult& s = *r.result;
  const NodalFields& f = *r.nodes;
  const NodalExtremes& e = r.nodal;
  std::ostringstream o;
  o << (r.converged ? "converged" : "NOT CONVERGED: " + r.message) << "\n";
  o << "solved on: " << r.model;
  if (r.model_unknowns > 0) o << ", " << r.model_unknowns << " unknowns";
  o << "\nspace: " << r.space << "\n";
  if (!s.levels.empty()) {
    o << "levels (eps: iterations):";
    for (const auto& l : s.levels) o << " " << summary_value(l.eps / r.eps_unit) << ":" << l.iterations;
    o << "  total " << s.total_iterations() << "\n";
  }
  o << "max w = " << summary_value(r.measures.max_w.value) << " at (" << summary_value(r.measures.max_w.x) << ", " << summary_value(r.measures.max_w.y) << "), min w = "
    << summary_value(r.measures.min_w.value) << " at (" << summary_value(r.measures.min_w.x) << ", " << summary_value(r.measures.min_w.y)
    << ") (of w_h over the plate; the largest nodal value is " << summary_value(e.max_w) << " at (" << summary_value(f.x[e.argmax_w]) << ", "
    << summary_value(f.y[e.argmax_w]) << "))\n";
  for (size_t k = 0; k < r.points.size(); ++k)
    o << "w(" << summary_value(r.points[k].first) << ", " << summary_value(r.points[k].second) << ") = " << summary_value(r.measures.w_at.at(k)) << "\n";
  o << "total contact force = " << summary_value(r.total_force) << ", max xi at nodes = "
    << summary_value(e.max_xi) << ", max |m12| = " << summary_value(r.measures.max_abs_m12.value) << " at (" << summary_value(r.measures.max_abs_m12.x) << ", "
    << summary_value(r.measures.max_abs_m12.y) << ") (at the nodes " << summary_value(e.max_abs_m12) << "), contact nodes: " << e.contact.size() << "\n";
  if (!r.line.empty()) {
    const LineForce& l = r.line;
    o << "line load on the edge (" << l.q.size() << " rows, " << rows_are(l) << "): mean " << summary_value(l.mean) << " (total " << summary_value(l.total)
      << " over length " << summary_value(l.length) << "), min " << summary_value(l.min)
      << (std::isfinite(l.theta_min) ? " at theta = " + summary_value(l.theta_min) : std::string()) << ", max " << summary_value(l.max)
      << (std::isfinite(l.theta_max) ? " at theta = " + summary_value(l.theta_max) : std::string());
    if (!l.theta.empty() && l.spline_degree > 0)
      o << "; q(0) = " << summary_value(r.line_figures.q0) << ", q(pi/4) = " << summary_value(r.line_figures.q45) << " (the spline)";
    else if (!l.theta.empty())
      o << "; fitted q(0) = " << summary_value(r.line_figures.fit0) << ", q(pi/4) = " << summary_value(r.line_figures.fit45)
        << " (points: " << summary_value(r.line_figures.q0) << ", " << summary_value(r.line_figures.q45) << ")";
    o << "\n";
    if (std::isfinite(r.dip_below_edge))
      o << "  between the rows the plate dips at most " << summary_value(r.dip_below_edge) << " below the edge (points h/32 apart)"
        << (std::isfinite(r.dip_theta) ? ", deepest at theta = " + summary_value(r.dip_theta) + ", " + dip_rows(r) +
                                             (rows_at(r.dip_cells) == RowsAt::Arc ? " " + fmt("%.2g", r.dip_cells) + " cells inside its nearer end" : "")
                                       : std::string())
        << (r.dip_below_edge > 0 ? ": w_h is at least that far from the plate's answer there, which keeps above the obstacle" : "") << "\n";
    if (!l.fourier.empty() && l.spline_degree == 0) {
      o << "  fit q(theta) ~";
      for (size_t k = 0; k < l.fourier.size(); ++k) o << (k ? " + " : " ") << summary_value(l.fourier[k]) << (k ? " cos " + std::to_string(4 * k) + " theta" : "");
      o << "\n";
    }
  }
  o << error_bars_text(r);
  if (!r.jumps.empty()) {
    const ObstacleJump& j = r.jumps.front();
    o << "WARNING: the obstacle " << (j.ends ? std::string("ends (phi = -inf beyond)") : "jumps by " + summary_value(j.size)) << " at ("
      << summary_value(j.x) << ", " << summary_value(j.y) << ")";
    if (r.jumps.size() > 1) o << " and at " << r.jumps.size() - 1 << " more points of the grid's lines";
    o << ", where no edge rows sit and the plate touches nearby: the constraint there is held at nodes alone, whose contact "
         "line moves by up to a cell from grid to grid, so the answer converges like h and the error bars may not hold (give "
         "the curve with --edge, and --sampling edge)\n";
  }
  if (dip_beyond_bars(r))
    o << "WARNING: the dip below the edge exceeds every error bar on w (" << fmt("%.2g", largest_w_bar(r))
      << "): the rows may resolve the constraint more coarsely than the bars suggest (the default --edge-rows, or a larger n)\n";
  if (r.certificate) {
    const Certificate& c = *r.certificate;
    o << "certificate (discrete: the distance to the discrete answer; relative): violation " << summary_value(c.violation) << ", negative multiplier "
      << summary_value(c.negative_multiplier) << ", complementarity " << summary_value(c.complementarity) << ", stationarity "
      << summary_value(c.stationarity) << (c.worst() <= r.certificate_tol ? " (all <= " : " (NOT all <= ")
      << summary_value(r.certificate_tol) << ")\n";
    if (!r.refinement.empty()) {
      o << "refinement (long-double residual), relative size of each correction:";
      for (double c : r.refinement) o << " " << fmt("%.1e", c);
      o << "\n";
    }
    if (r.refinement_undone > 0)
      o << "WARNING: refinement undone: its first correction (" << fmt("%.1e", r.refinement_undone)
        << " of the answer) was not confirmed by the next, so the answer carries the double solve's round-off, "
           "which may be that large; the certificate bounds the residuals, not this\n";
  }
  if (!r.certificate)
    o << "error bound from the residual of (2a): max |w - w_eps| <= " << summary_value(s.bound.bound) << " (round-off floor "
      << summary_value(s.bound.roundoff) << ")" << (s.converged ? ", within tol" : ", NOT certified") << "\n";
  if (r.lambda1h > 0)
    o << "lambda_1h = " << summary_value(r.lambda1h) << ", contraction per iteration at eps = " << summary_value(s.eps / r.eps_unit) << ": sharp "
      << summary_value(r.sharp_factor) << ", paper's rho " << summary_value(r.paper_rho)
      << "\n";
  char b[128];
  std::snprintf(b, sizeof b, "time: assemble %.3g s, factorise %.3g s, iterate %.3g s, bound %.3g s, total %.3g s\n",
                r.seconds_assemble, s.seconds_factorize, s.seconds_iterate, s.seconds_bound, r.seconds_total);
  o << b;
  return o.str();
}

}  // namespace plate
