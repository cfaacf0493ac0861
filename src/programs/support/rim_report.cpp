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
double theta_at(int k, int angles) { return 2 * M_PI * k / angles; }
std::string bar(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.2g", v);
  return b;
}
// The finest truncation's peak, found once by rim_answer's search.
RimPeak finest_peak(const RimAnswer& a) { return {a.rows.back().x_max, a.rows.back().y_max, a.rows.back().max_w}; }

}  // namespace

std::string rim_digits(double v, double bar) {
  return fmt_above(v, std::max(bar, 1000 * DBL_EPSILON * std::abs(v)) / 10, 15, 'g');
}

double rim_max_abs_m12(const RimSeries& s, double nu, int k) {
  double best = -1, bx = 0, by = 0;
  auto look = [&](double x, double y) {
    x = std::clamp(x, 0.0, s.scene.lx), y = std::clamp(y, 0.0, s.scene.ly);
    if (const double m = std::abs(s.moments(x, y, nu).m12); m > best) best = m, bx = x, by = y;
  };
  // |m12| is unchanged by a mirror of the scene (m12 changes sign), so a symmetric scene's lower
  // left quarter holds its largest value.
  const int last = s.symmetry == RimSymmetry::None ? k : k / 2;
  for (int i = 0; i <= last; ++i)
    for (int j = 0; j <= last; ++j) look(s.scene.lx * i / k, s.scene.ly * j / k);
  // Then about the best lattice point, on lattices five times finer each round (m12 is continuous,
  // its gradient may jump across the rim: the search closes in on the point, not on a zero slope).
  // Each axis steps by its own lattice spacing, so a round always reaches the neighbouring rows.
  for (double sx = s.scene.lx / k / 5, sy = s.scene.ly / k / 5; sx > 1e-9 * s.scene.lx; sx /= 5, sy /= 5) {
    const double x0 = bx, y0 = by;
    for (int i = -6; i <= 6; ++i)
      for (int j = -6; j <= 6; ++j) look(x0 + i * sx, y0 + j * sy);
  }
  return best;
}

std::string rim_line_csv(const RimSeries& s, int angles) {
  std::ostringstream o;
  o << "# plate --scheme semi-analytic: the contact force per unit length q on the rim, at " << angles
    << " equally spaced angles theta about the disk's centre (the series' own q, not point samples)\n"
       "theta,x,y,q\n";
  for (int k = 0; k < angles; ++k) {
    const double t = theta_at(k, angles);
    o << series_value(t) << ',' << series_value(s.scene.cx + s.scene.radius * std::cos(t)) << ','
      << series_value(s.scene.cy + s.scene.radius * std::sin(t)) << ',' << series_value(s.q(t)) << '\n';
  }
  return o.str();
}

std::string rim_summary_json(const Report& r) {
  const RimAnswer& a = *r.series;
  const RimSeries& s = a.finest;
  const RimPeak peak = finest_peak(a);
  Json j;
  j["config"] = Json::object();
  for (const auto& [k, v] : r.config) j["config"][k] = v;
  j["scheme"] = "semi-analytic";
  j["converged"] = r.converged;
  j["message"] = r.message;
  j["max_w"] = number(peak.w);
  j["max_w_at"] = {number(peak.x), number(peak.y)};
  j["max_w_bar"] = number(a.bar_max_w);
  j["w_at_points"] = Json::array();
  for (const auto& [x, y] : r.points) j["w_at_points"].push_back({{"x", number(x)}, {"y", number(y)}, {"w", number(s.w(x, y))}});
  j["total_contact_force"] = number(s.total_force());
  j["total_contact_force_bar"] = number(a.bar_force);
  j["max_abs_m12"] = number(r.measures.max_abs_m12.value);
  Json line = {{"angles", kLineLoadAngles}, {"length", number(2 * M_PI * s.scene.radius)}, {"total", number(s.total_force())},
               {"mean", number(s.q_cos.empty() ? NAN : s.q_cos[0])}};
  double lo = INFINITY, hi = -INFINITY;
  for (int k = 0; k < kLineLoadAngles; ++k) {
    const double q = s.q(theta_at(k, kLineLoadAngles));
    lo = std::min(lo, q), hi = std::max(hi, q);
  }
  line["min"] = number(lo), line["max"] = number(hi);
  line["q_theta_0"] = number(s.q(0)), line["q_theta_0_bar"] = number(a.bar_q0);
  line["q_theta_pi_4"] = number(s.q(M_PI / 4)), line["q_theta_pi_4_bar"] = number(a.bar_q45);
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
  const RimSeries& s = a.finest;
  const RimPeak peak = finest_peak(a);
  std::ostringstream o;
  o << (r.converged ? "converged" : "NOT CONVERGED: " + r.message) << "\n";
  o << "series: " << a.rows.size() << " truncations, the last with " << a.rows.back().unknowns
    << " unknowns; the bars are the change from the one before" << (a.settled ? "" : " (NOT settled)") << "\n";
  o << "max w = " << series_value(peak.w) << " +- " << bar(a.bar_max_w) << " at (" << series_value(peak.x) << ", " << series_value(peak.y) << ")\n";
  for (const auto& [x, y] : r.points) o << "w(" << series_value(x) << ", " << series_value(y) << ") = " << series_value(s.w(x, y)) << "\n";
  o << "total contact force = " << series_value(s.total_force()) << " +- " << bar(a.bar_force) << ", max |m12| = "
    << series_value(r.measures.max_abs_m12.value) << " (searched on the plate)\n";
  o << "line load on the rim: mean " << series_value(s.q_cos.empty() ? NAN : s.q_cos[0]) << ", q(0) = " << series_value(s.q(0)) << " +- "
    << bar(a.bar_q0) << ", q(pi/4) = " << series_value(s.q(M_PI / 4)) << " +- " << bar(a.bar_q45) << "\n";
  o << "premise (contact along the whole rim): " << (a.premise.holds ? "holds" : "FAILS: " + a.premise.why)
    << "; min q = " << series_value(a.premise.min_q) << ", min (w - R) inside the disk = " << series_value(a.premise.min_w_minus_R) << "\n";
  char b[64];
  std::snprintf(b, sizeof b, "time: total %.3g s\n", r.seconds_total);
  o << b;
  return o.str();
}

}  // namespace plate
