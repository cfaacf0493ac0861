// Formatting of the outputs. Numbers carry 10 significant digits; JSON has no infinity, so an
// absent obstacle (-inf) is written as null.
#include "summary.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "contraction.hpp"

namespace plate {

namespace {
std::string num(double v) {
  if (!std::isfinite(v)) return "null";
  char b[32];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}
std::string csv_num(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char b[32];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}
std::string quoted(const std::string& s) {
  std::string o = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') {
      o += '\\';
      o += ch;
    } else if (static_cast<unsigned char>(ch) < 0x20) {
      char b[8];
      std::snprintf(b, sizeof b, "\\u%04x", ch);
      o += b;
    } else {
      o += ch;
    }
  }
  return o + "\"";
}

struct Extremes {
  int argmax_w = 0;
  double max_w = -INFINITY, max_abs_w = 0, max_xi = 0, max_abs_m12 = 0;
  std::vector<int> contact;
};
Extremes extremes(const NodalFields& f) {
  Extremes e;
  for (int k = 0; k < f.size(); ++k) {
    if (f.w[k] > e.max_w) e.max_w = f.w[k], e.argmax_w = k;
    e.max_abs_w = std::max(e.max_abs_w, std::abs(f.w[k]));
    e.max_xi = std::max(e.max_xi, f.xi[k]);
    e.max_abs_m12 = std::max(e.max_abs_m12, std::abs(f.m12[k]));
    if (f.contact[k]) e.contact.push_back(k);
  }
  return e;
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

std::string line_force_csv(const Problem& p, const LineForce& f) {
  std::ostringstream o;
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
std::string line_force_json(const Report& r) {
  const LineForce& f = r.line;
  if (f.empty()) return "  \"line_force\": null,\n";
  std::ostringstream o;
  o << "  \"line_force\": {\"points\": " << f.q.size() << ", \"length\": " << num(f.length) << ", \"total\": "
    << num(f.total) << ", \"mean\": " << num(f.mean) << ", \"min\": " << num(f.min) << ", \"max\": " << num(f.max);
  if (!f.theta.empty())
    o << ", \"q_fit_theta_0\": " << num(line_force_fit(f, 0)) << ", \"q_fit_theta_pi_4\": " << num(line_force_fit(f, M_PI / 4))
      << ", \"q_point_theta_0\": " << num(line_force_at(f, 0)) << ", \"q_point_theta_pi_4\": " << num(line_force_at(f, M_PI / 4));
  for (const auto& [key, v] : {std::pair{"fourier_cos_4k_theta", &f.fourier}, {"theta", &f.theta}, {"q", &f.q}}) {
    o << ",\n    \"" << key << "\": [";
    for (size_t k = 0; k < v->size(); ++k) o << (k ? ", " : "") << num((*v)[k]);
    o << "]";
  }
  o << "},\n";
  return o.str();
}
}  // namespace

std::string summary_json(const Report& r) {
  const Problem& p = *r.problem;
  const SolveResult& s = *r.result;
  const NodalFields& f = *r.nodes;
  const Extremes e = extremes(f);
  const VectorXd& xi = r.xi;
  const double violation = (p.phi - p.sampling.S * s.w).cwiseMax(0.0).maxCoeff();
  std::ostringstream o;
  o << "{\n  \"config\": {";
  for (size_t i = 0; i < r.config.size(); ++i)
    o << (i ? ", " : "") << quoted(r.config[i].first) << ": " << quoted(r.config[i].second);
  o << "},\n  \"grid\": {\"nx\": " << p.grid.nx << ", \"ny\": " << p.grid.ny << ", \"h\": " << num(p.grid.h)
    << ", \"unknowns\": " << p.grid.unknowns() << ", \"sample_points\": " << p.sampling.size() << "},\n";
  o << "  \"converged\": " << (s.converged ? "true" : "false") << ",\n";
  o << "  \"message\": " << quoted(s.message) << ",\n";
  o << "  \"eps_final\": " << num(s.eps / r.eps_unit) << ",\n  \"total_iterations\": " << s.total_iterations() << ",\n";
  o << "  \"levels\": [";
  for (size_t i = 0; i < s.levels.size(); ++i) {
    const LevelRecord& l = s.levels[i];
    o << (i ? ",\n    " : "\n    ") << "{\"eps\": " << num(l.eps / r.eps_unit) << ", \"iterations\": " << l.iterations
      << ", \"factorizations\": " << l.factorizations << ", \"last_step\": " << num(l.last_step)
      << ", \"level_change\": " << (l.level_change < 0 ? "null" : num(l.level_change))
      << ", \"converged\": " << (l.converged ? "true" : "false") << "}";
  }
  o << "\n  ],\n";
  o << "  \"max_w\": " << num(e.max_w) << ",\n  \"max_w_at\": [" << num(f.x[e.argmax_w]) << ", "
    << num(f.y[e.argmax_w]) << "],\n  \"max_abs_w\": " << num(e.max_abs_w) << ",\n";
  o << "  \"w_at_points\": [";
  for (size_t i = 0; i < r.points.size(); ++i) {
    const auto [x, y] = r.points[i];
    const PointValues v = evaluate(p.grid, s.w, x, y);
    o << (i ? ", " : "") << "{\"x\": " << num(x) << ", \"y\": " << num(y) << ", \"w\": " << num(v.w) << "}";
  }
  o << "],\n";
  o << "  \"total_contact_force\": " << num(total_contact_force(p, xi)) << ",\n";
  o << "  \"max_xi_samples\": " << num(xi.size() ? xi.maxCoeff() : 0.0) << ",\n";
  o << "  \"max_xi_nodes\": " << num(e.max_xi) << ",\n";
  o << "  \"max_abs_m12\": " << num(e.max_abs_m12) << ",\n";
  o << line_force_json(r);
  o << "  \"constraint_violation\": " << num(violation) << ",\n";
  if (r.certificate) {
    const Certificate& c = *r.certificate;
    o << "  \"certificate\": {\"violation\": " << num(c.violation) << ", \"negative_multiplier\": "
      << num(c.negative_multiplier) << ", \"complementarity\": " << num(c.complementarity)
      << ", \"stationarity\": " << num(c.stationarity) << ", \"tol\": " << num(r.certificate_tol) << "},\n";
    o << "  \"penalty_residual\": null,\n";
    o << "  \"residual_ok\": " << (c.worst() <= r.certificate_tol ? "true" : "false") << ",\n";
  } else {
    o << "  \"penalty_residual\": " << num(penalty_residual(p, s.w, s.eps)) << ",\n";
    o << "  \"error_bound\": {\"bound\": " << num(s.bound.bound) << ", \"roundoff\": " << num(s.bound.roundoff)
      << ", \"green_centre\": " << num(s.bound.green) << "},\n";
    o << "  \"residual_ok\": " << (s.converged ? "true" : "false") << ",\n";
  }
  o << "  \"contact_nodes\": [";
  for (size_t i = 0; i < e.contact.size(); ++i)
    o << (i ? ", " : "") << "[" << num(f.x[e.contact[i]]) << ", " << num(f.y[e.contact[i]]) << "]";
  o << "],\n";
  if (r.lambda1h > 0) {
    o << "  \"contraction\": {\"lambda1h\": " << num(r.lambda1h)
      << ", \"sharp_factor\": " << num(sharp_contraction(r.lambda1h, s.eps))
      << ", \"paper_rho\": " << num(paper_rho(1.0 / r.lambda1h, s.eps)) << ", \"at_eps\": " << num(s.eps / r.eps_unit) << "},\n";
  }
  o << "  \"seconds\": {\"assemble\": " << num(r.seconds_assemble) << ", \"factorize\": "
    << num(s.seconds_factorize) << ", \"iterate\": " << num(s.seconds_iterate) << ", \"bound\": " << num(s.seconds_bound) << ", \"total\": "
    << num(r.seconds_total) << "}\n}\n";
  return o.str();
}

std::string summary_text(const Report& r) {
  const SolveResult& s = *r.result;
  const NodalFields& f = *r.nodes;
  const Extremes e = extremes(f);
  const VectorXd& xi = r.xi;
  std::ostringstream o;
  o << (s.converged ? "converged" : "NOT CONVERGED: " + s.message) << "\n";
  if (!s.levels.empty()) {
    o << "levels (eps: iterations):";
    for (const auto& l : s.levels) o << " " << num(l.eps / r.eps_unit) << ":" << l.iterations;
    o << "  total " << s.total_iterations() << "\n";
  }
  o << "max w over the grid nodes = " << num(e.max_w) << " at (" << num(f.x[e.argmax_w]) << ", " << num(f.y[e.argmax_w])
    << ")\n";
  for (const auto& [x, y] : r.points)
    o << "w(" << num(x) << ", " << num(y) << ") = " << num(evaluate(r.problem->grid, s.w, x, y).w) << "\n";
  o << "total contact force = " << num(total_contact_force(*r.problem, xi)) << ", max xi at nodes = "
    << num(e.max_xi) << ", max |m12| at nodes = " << num(e.max_abs_m12) << ", contact nodes: " << e.contact.size()
    << "\n";
  if (!r.line.empty()) {
    const LineForce& l = r.line;
    o << "line load on the edge (" << l.q.size() << " points): mean " << num(l.mean) << " (total " << num(l.total)
      << " over length " << num(l.length) << "), min " << num(l.min) << ", max " << num(l.max);
    if (!l.theta.empty())
      o << "; fitted q(0) = " << num(line_force_fit(l, 0)) << ", q(pi/4) = " << num(line_force_fit(l, M_PI / 4))
        << " (points: " << num(line_force_at(l, 0)) << ", " << num(line_force_at(l, M_PI / 4)) << ")";
    o << "\n";
    if (!l.fourier.empty()) {
      o << "  fit q(theta) ~";
      for (size_t k = 0; k < l.fourier.size(); ++k) o << (k ? " + " : " ") << num(l.fourier[k]) << (k ? " cos " + std::to_string(4 * k) + " theta" : "");
      o << "\n";
    }
  }
  if (r.certificate) {
    const Certificate& c = *r.certificate;
    o << "certificate (relative): violation " << num(c.violation) << ", negative multiplier "
      << num(c.negative_multiplier) << ", complementarity " << num(c.complementarity) << ", stationarity "
      << num(c.stationarity) << (c.worst() <= r.certificate_tol ? " (all <= " : " (NOT all <= ")
      << num(r.certificate_tol) << ")\n";
  }
  if (!r.certificate)
    o << "error bound from the residual of (2a): max |w - w_eps| <= " << num(s.bound.bound) << " (round-off floor "
      << num(s.bound.roundoff) << ")" << (s.converged ? ", within tol" : ", NOT certified") << "\n";
  if (r.lambda1h > 0)
    o << "lambda_1h = " << num(r.lambda1h) << ", contraction per iteration at eps = " << num(s.eps / r.eps_unit) << ": sharp "
      << num(sharp_contraction(r.lambda1h, s.eps)) << ", paper's rho " << num(paper_rho(1.0 / r.lambda1h, s.eps))
      << "\n";
  char b[128];
  std::snprintf(b, sizeof b, "time: assemble %.3g s, factorise %.3g s, iterate %.3g s, bound %.3g s, total %.3g s\n",
                r.seconds_assemble, s.seconds_factorize, s.seconds_iterate, s.seconds_bound, r.seconds_total);
  o << b;
  return o.str();
}

}  // namespace plate
