#include "rim_report.hpp"

#include "format.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

namespace plate {
namespace {
using Json = nlohmann::ordered_json;

// The series settles to about 13 digits: print 15, so the bars speak, not the printing.
std::string series_value(double v) { return fmt_digits(v, 15); }
Json number(double v) { return std::isfinite(v) ? Json(std::stod(series_value(v))) : Json(nullptr); }
std::string bar(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.2g", v);
  return b;
}

}  // namespace

std::string rim_digits(double v, double bar) {
  return fmt_above(v, std::max(bar, 1000 * DBL_EPSILON * std::abs(v)) / 10, 15, 'g');
}

std::string rim_line_csv(const Report& r) {
  const LineFigures& g = r.line_figures;
  std::ostringstream o;
  o << "# plate --scheme semi-analytic: the contact force per unit length q on the rim, at " << g.theta.size()
    << " equally spaced angles theta about the disk's centre (the series' own q, not point samples)\n"
       "theta,x,y,q\n";
  for (size_t k = 0; k < g.theta.size(); ++k)
    o << series_value(g.theta[k]) << ',' << series_value(g.x[k]) << ',' << series_value(g.y[k]) << ',' << series_value(g.q[k]) << '\n';
  return o.str();
}

std::string rim_summary_json(const Report& r) {
  const RimAnswer& a = *r.series;
  const RimSeries& s = a.finest;
  Json j;
  j["config"] = Json::object();
  for (const auto& [k, v] : r.config) j["config"][k] = v;
  j["scheme"] = "semi-analytic";
  j["converged"] = r.converged;
  j["message"] = r.message;
  j["max_w"] = number(r.measures.max_w.value);
  j["max_w_at"] = {number(r.measures.max_w.x), number(r.measures.max_w.y)};
  j["max_w_bar"] = number(a.bar_max_w);
  j["w_at_points"] = Json::array();
  for (size_t k = 0; k < r.points.size(); ++k)
    j["w_at_points"].push_back({{"x", number(r.points[k].first)}, {"y", number(r.points[k].second)}, {"w", number(r.measures.w_at.at(k))}});
  j["total_contact_force"] = number(r.line.total);
  j["total_contact_force_bar"] = number(a.bar_force);
  j["max_abs_m12"] = number(r.measures.max_abs_m12.value);
  Json line = {{"angles", r.line.q.size()}, {"length", number(r.line.length)}, {"total", number(r.line.total)},
               {"mean", number(r.line.mean)}};
  line["min"] = number(r.line.min), line["max"] = number(r.line.max);
  line["q_theta_0"] = number(r.line_figures.q0), line["q_theta_0_bar"] = number(a.bar_q0);
  line["q_theta_pi_4"] = number(r.line_figures.q45), line["q_theta_pi_4_bar"] = number(a.bar_q45);
  Json cosines = Json::array(), sines = Json::array();
  for (double c : s.q_cos) cosines.push_back(number(c));
  for (double c : s.q_sin) sines.push_back(number(c));
  line["fourier_cos_m_theta"] = cosines, line["fourier_sin_m_theta"] = sines;
  j["line_force"] = line;
  j["premise"] = {{"holds", a.premise.holds}, {"min_q", number(a.premise.min_q)},
                  {"theta_min_q", number(a.premise.theta_min_q)}, {"min_w_minus_R_in_disk", number(a.premise.min_w_minus_R)},
                  {"why", a.premise.why}};
  j["settled"] = a.settled;
  j["levels"] = Json::array();
  for (const RimConvergenceRow& row : a.rows)
    j["levels"].push_back({{"level", row.level}, {"harmonics", row.harmonics}, {"degree", row.degree},
                           {"corner_terms", row.corner_terms}, {"unknowns", row.unknowns}, {"max_w", number(row.max_w)},
                           {"total_force", number(row.total_force)}, {"q_theta_0", number(row.q0)},
                           {"q_theta_pi_4", number(row.q45)}, {"edge_residual", number(row.edge_residual)},
                           {"rim_residual", number(row.rim_residual)}});
  j["seconds"] = {{"total", number(r.seconds_total)}};
  return j.dump(2) + "\n";
}

std::string rim_summary_text(const Report& r) {
  const RimAnswer& a = *r.series;
  std::ostringstream o;
  o << (r.converged ? "converged" : "NOT CONVERGED: " + r.message) << "\n";
  o << "series: " << a.rows.size() << " truncations, the last with " << a.rows.back().unknowns
    << " unknowns; the bars are the change from the one before" << (a.settled ? "" : " (NOT settled)") << "\n";
  o << "max w = " << series_value(r.measures.max_w.value) << " +- " << bar(a.bar_max_w) << " at (" << series_value(r.measures.max_w.x) << ", "
    << series_value(r.measures.max_w.y) << ")\n";
  for (size_t k = 0; k < r.points.size(); ++k)
    o << "w(" << series_value(r.points[k].first) << ", " << series_value(r.points[k].second) << ") = " << series_value(r.measures.w_at.at(k)) << "\n";
  o << "total contact force = " << series_value(r.line.total) << " +- " << bar(a.bar_force) << ", max |m12| = "
    << series_value(r.measures.max_abs_m12.value) << " (searched on the plate)\n";
  o << "line load on the rim: mean " << series_value(r.line.mean) << ", q(0) = " << series_value(r.line_figures.q0) << " +- "
    << bar(a.bar_q0) << ", q(pi/4) = " << series_value(r.line_figures.q45) << " +- " << bar(a.bar_q45) << "\n";
  o << "premise (contact along the whole rim): " << (a.premise.holds ? "holds" : "FAILS: " + a.premise.why)
    << "; min q = " << series_value(a.premise.min_q) << ", min (w - R) inside the disk = " << series_value(a.premise.min_w_minus_R) << "\n";
  char b[64];
  std::snprintf(b, sizeof b, "time: total %.3g s\n", r.seconds_total);
  o << b;
  return o.str();
}

}  // namespace plate
