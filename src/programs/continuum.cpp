// continuum: the h -> 0 limit of the paper's problem. Solves it exactly (no eps) on n = 8 ... 512
// with the constraint on the cylinder's rim (edge sampling), at Gauss points and at the nodes, and
// writes results/continuum.{md,csv}, continuum_error.csv, continuum_q.csv, continuum_answer.md and
// continuum_limits.csv, continuum_timings.csv. Run by `make continuum`; `continuum --help` lists the options.
#include <CLI/CLI.hpp>

#include <cfloat>
#include <cmath>
#include <iostream>
#include <sstream>

#include "active_set.hpp"
#include "atomic_file.hpp"
#include "exit_codes.hpp"
#include "contact.hpp"
#include "format.hpp"
#include "line_force.hpp"
#include "published.hpp"
#include "richardson.hpp"
#include "rim_report.hpp"
#include "roundoff.hpp"
#include "verdict.hpp"
#include "stopwatch.hpp"
#include "words.hpp"

using namespace plate;

namespace {

// The samplings compared: edge rows as the code's default (cubic splines of the angle, D12), edge
// rows at points (the previous default, for comparison), and the paper's two readings of (8).
struct Variant {
  std::string name;
  SamplingSpec spec;
};
std::vector<Variant> variants() {
  return {{"edge", SamplingSpec{SamplingKind::Edge}},
          {"edge-points", SamplingSpec{SamplingKind::Edge, EdgeRows::points()}},
          {"gauss", SamplingSpec{SamplingKind::Gauss}},
          {"nodes", SamplingSpec{SamplingKind::Nodes}}};
}

struct Row {
  std::string kind;  // the variant's name
  int n = 0, unknowns = 0, samples = 0, edge_points = 0;
  bool certified = false;
  double max_w = 0, w_mid = 0, w_diag = 0, force = 0, mean_line = 0, q0 = NAN, q45 = NAN, m12 = 0, seconds = 0;
  LineForce line;
  // What round-off may change in each of the above: for a refined solve, the refinement's floor;
  // otherwise the deflections and the moment as roundoff.hpp estimates, and the forces, read off the
  // multipliers, the worst case u n^3 (exact_solve_roundoff).
  double noise_max_w = 0, noise_w_mid = 0, noise_w_diag = 0, noise_force = 0, noise_mean_line = 0, noise_q0 = 0,
         noise_q45 = 0, noise_m12 = 0, noise_line = 0;
};

// The quantities a reader asks for, each with how it is read from a row.
struct Quantity {
  const char* name;
  const char* column;
  double Row::*field;
  double Row::*noise;
};
const std::vector<Quantity> kQuantities = {
    {"max w", "max_w", &Row::max_w, &Row::noise_max_w},
    {"w(0.5, 0.125)", "w_0.5_0.125", &Row::w_mid, &Row::noise_w_mid},
    {"w(0.25, 0.25)", "w_0.25_0.25", &Row::w_diag, &Row::noise_w_diag},
    {"total force", "total_force", &Row::force, &Row::noise_force},
    {"mean line force", "mean_line_force", &Row::mean_line, &Row::noise_mean_line},
    {"q(0)", "q_theta_0", &Row::q0, &Row::noise_q0},
    {"q(pi/4)", "q_theta_pi_4", &Row::q45, &Row::noise_q45},
    {"max m12", "max_abs_m12", &Row::m12, &Row::noise_m12},
};

Row solve_one(const Variant& v, int n, const Scene& scene) {
  const auto t0 = Clock::now();
  const SceneSolution x = solve_exact_scene(scene, n, v.spec, ExactOptions{});
  const Problem& p = x.whole();
  Row row;
  row.kind = v.name, row.n = n, row.unknowns = p.grid.unknowns(), row.samples = p.sampling.size();
  row.edge_points = p.sampling.edge_size();
  row.certified = x.result.converged;
  const NodalFields f = nodal_fields(p, x.result.w, x.result.lambda, kPoissonRatio);
  int top = 0, twist = 0;  // the nodes of max w and of max |m12|
  for (int k = 0; k < f.size(); ++k) {
    if (f.w[k] > f.w[top]) top = k;
    if (std::abs(f.m12[k]) > std::abs(f.m12[twist])) twist = k;
  }
  row.max_w = f.w[top], row.m12 = std::abs(f.m12[twist]);
  row.w_mid = evaluate(p, x.result.w, 0.5, 0.125).w;
  row.w_diag = evaluate(p, x.result.w, 0.25, 0.25).w;
  row.force = total_contact_force(p, x.result.lambda);
  row.mean_line = row.force / (2 * M_PI * scene.cylinder->radius);  // with f = 0 the whole push is on the rim
  row.line = line_force(p, x.result.lambda);
  // q at 0 and pi/4: the spline's own value; for point rows the cos 4k theta fit, since the points
  // scatter about it by some 10 % (see line_force.hpp).
  if (!row.line.empty()) {
    const bool spline = row.line.spline_degree > 0;
    row.q0 = spline ? line_force_value(row.line, 0) : line_force_fit(row.line, 0);
    row.q45 = spline ? line_force_value(row.line, M_PI / 4) : line_force_fit(row.line, M_PI / 4);
  }
  row.seconds = seconds_since(t0);

  const Refinement& refined = x.result.levels.back().refinement;
  require_not_undone(refined, "continuum");
  if (!refined.w.empty()) {
    // A refined answer (D22) is the same on every machine to the refinement's floor, in w and in the
    // forces alike: the corrections' size once they stop shrinking.
    const double floor_mu = refined.relative_noise_mu();
    row.noise_max_w = row.noise_w_mid = row.noise_w_diag = row.noise_m12 = refined.noise_w(x.result.w);
    row.noise_force = floor_mu * row.force, row.noise_mean_line = floor_mu * row.mean_line;
    row.noise_line = floor_mu * std::max(std::abs(row.line.max), std::abs(row.line.min));
    row.noise_q0 = row.noise_q45 = row.noise_line;
  } else {
    // Round-off of the problem solved (a quarter here), read at the whole plate's points.
    const SolutionRoundoff roundoff(x.solved, x.part_w, x.part_lambda);
    Eigen::MatrixXd outputs(x.solved.grid.unknowns(), 4);
    outputs << roundoff.point_value(f.x[top], f.y[top]), roundoff.point_value(0.5, 0.125), roundoff.point_value(0.25, 0.25),
        roundoff.point_twist(f.x[twist], f.y[twist]) * (1 - kPoissonRatio);
    const std::vector<double> noise = roundoff.of(outputs);
    row.noise_max_w = noise[0], row.noise_w_mid = noise[1], row.noise_w_diag = noise[2], row.noise_m12 = noise[3];
    row.noise_force = exact_solve_roundoff(n, row.force), row.noise_mean_line = exact_solve_roundoff(n, row.mean_line);
    row.noise_q0 = exact_solve_roundoff(n, row.q0), row.noise_q45 = exact_solve_roundoff(n, row.q45);
    // Point values of q scatter more than aggregates between BLAS thread counts (up to 3 u n^3 max q).
    if (!row.line.empty()) row.noise_line = exact_solve_roundoff(n, row.line.max) * row.line.q.size();
  }
  if (!x.result.converged) std::cerr << "continuum: " << v.name << " n = " << n << ": " << x.result.message << "\n";
  return row;
}

std::string row_value(const Row& r, const Quantity& q) { return fmt_value(r.*q.field, r.*q.noise, 10, ""); }

std::vector<double> column(const std::vector<Row>& rows, const std::string& kind, double Row::*field) {
  std::vector<double> v;
  for (const Row& r : rows)
    if (r.kind == kind) v.push_back(r.*field);
  return v;
}

std::string csv(const std::vector<Row>& rows) {
  std::ostringstream o;
  o << "# continuum: the paper's problem (f = 0, R = 0.0625 on the disk of radius 0.25) solved exactly on n x n\n"
       "# grids, four samplings of the constraint; made by build/continuum. max_w and max_abs_m12 over the grid\n"
       "# nodes (nu = 0.3); mean_line_force = total_force / (2 pi r); q_theta: the line load on the rim at\n"
       "# theta = 0 and pi/4: the spline's value (edge), the fit by cos(4 k theta), k = 0..3 (edge-points). Digits down to\n"
       "# 10 times each value's round-off: a refined solve's floor (D22), otherwise src/roundoff.hpp's estimate\n"
       "sampling,n,unknowns,samples,edge_points,certified";
  for (const Quantity& q : kQuantities) o << "," << q.column;
  o << "\n";
  for (const Row& r : rows) {
    o << r.kind << "," << r.n << "," << r.unknowns << "," << r.samples << "," << r.edge_points << ","
      << (r.certified ? 1 : 0);
    for (const Quantity& q : kQuantities) o << "," << row_value(r, q);
    o << "\n";
  }
  return o.str();
}

struct Study {
  std::vector<Row> rows;
  std::vector<int> grids;
  std::vector<std::string> kinds;  // the variants' names, in order
  std::map<std::pair<std::string, std::string>, Extrapolation> fits;
  RimAnswer yardstick;  // the rim-contact series: the answer every row is measured against
};

// How far a row is from the rim-contact series' answer, relative: max w, the total force, and for
// edge sampling the line load at every edge point against the series' q there, over its mean.
struct RowError {
  double max_w, force, line = NAN;
};
RowError error_of(const Row& r, const RimAnswer& y) {
  const RimSeries& s = y.finest;
  // The finest row already holds the series' max w: its search is not repeated for every grid.
  const double w = y.rows.back().max_w, f = s.total_force(), mean = s.q_cos.at(0);
  RowError e{std::abs(r.max_w - w) / w, std::abs(r.force - f) / f};
  if (!r.line.empty()) e.line = max_distance(r.line, [&](double t) { return s.q(t); }) / mean;
  return e;
}
// An observed order from two successive errors (grids h and h / 2), empty where it says nothing.
std::string order_between(double coarse, double fine) {
  if (!(coarse > 0 && fine > 0)) return "";
  return fmt("%.2f", std::log2(coarse / fine));
}


std::string answer(const Study& s) {
  const Extrapolation& w = s.fits.at({"edge", "max w"});
  const Extrapolation& f = s.fits.at({"edge", "total force"});
  const Extrapolation& m = s.fits.at({"edge", "mean line force"});
  const RimSeries& y = s.yardstick.finest;
  const RimAnswer& a = s.yardstick;
  // Each estimate with its bar and how it was found: a cell of a sentence, as a verdict's is of a
  // table. The phrase for how is chosen here and its words are in reports/words.md.
  auto one = [](const Extrapolation& e) {
    const std::string how = e.steady ? words("continuum.basis_richardson", {{"order", format_order(e.orders.back(), e.order_noise.back())}})
                                     : words("continuum.basis_finest");
    return fmt_above(e.limit, e.limit_noise, 9, 'g') + " +- " + bar_number(e, 2) + " (" +
           (bar_is_roundoff(e) ? words("continuum.basis_roundoff", {{"then", how}}) : how) + ")";
  };
  return words("continuum.answer_series", {{"max_w", rim_digits(a.rows.back().max_w, a.bar_max_w)},
                                           {"bar_w", fmt_up(a.bar_max_w)},
                                           {"force", rim_digits(y.total_force(), a.bar_force)},
                                           {"bar_f", fmt_up(a.bar_force)},
                                           {"q0", rim_digits(y.q(0), a.bar_q0)},
                                           {"bar_q0", fmt_up(a.bar_q0)},
                                           {"q45", rim_digits(y.q(M_PI / 4), a.bar_q45)},
                                           {"bar_q45", fmt_up(a.bar_q45)}}) +
         "\n\n" +
         words("continuum.answer_fe", {{"first", std::to_string(s.grids.front())},
                                       {"last", std::to_string(s.grids.back())},
                                       {"max_w", one(w)},
                                       {"force", one(f)},
                                       {"line", one(m)}}) +
         "\n";
}

// The words.md key of a sampling's name, with which its table's caption begins.
std::string sampling_title(const std::string& k) {
  if (k == "edge") return words("continuum.title_edge");
  if (k == "edge-points") return words("continuum.title_edge_points");
  if (k == "gauss") return words("continuum.title_gauss");
  if (k == "nodes") return words("continuum.title_nodes");
  throw std::logic_error("continuum: no caption for the sampling '" + k + "'");
}

std::string markdown(const Study& s) {
  std::ostringstream o;
  o << words("continuum.intro") << "\n\n" << answer(s) << "\n" << words("continuum.runs") << "\n\n";
  for (const std::string& k : s.kinds) {
    // A quantity no run of this sampling has (the line load off the rim) is left out, not shown as n/a.
    std::vector<const Quantity*> shown;
    for (const Quantity& q : kQuantities)
      for (const Row& r : s.rows)
        if (r.kind == k && std::isfinite(r.*q.field)) {
          shown.push_back(&q);
          break;
        }
    o << "| n | unknowns | samples";
    for (const Quantity* q : shown) o << " | " << q->name;
    o << " |\n|---:|---:|---:";
    for (size_t i = 0; i < shown.size(); ++i) o << "|---:";
    o << "|\n";
    for (const Row& r : s.rows) {
      if (r.kind != k) continue;
      o << "| " << r.n << (r.certified ? "" : " (**not certified**)") << " | " << r.unknowns << " | " << r.samples;
      for (const Quantity* q : shown) o << " | " << (std::isfinite(r.*q->field) ? row_value(r, *q) : "n/a");
      o << " |\n";
    }
    o << "\nTable: " << sampling_title(k) << ", " << words("continuum.sampling_caption") << "\n\n";
  }
  o << words("continuum.series_intro") << "\n\n"
       "| sampling | n | max w | order | total force | order | line load, pointwise | order |\n"
       "|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const std::string& k : s.kinds) {
    const Row* before = nullptr;
    for (const Row& r : s.rows) {
      if (r.kind != k) continue;
      const RowError e = error_of(r, s.yardstick);
      const RowError b = before ? error_of(*before, s.yardstick) : RowError{NAN, NAN, NAN};
      o << "| " << k << " | " << r.n << " | " << fmt_above(e.max_w, r.noise_max_w / r.max_w, 2) << " | "
        << order_between(b.max_w, e.max_w) << " | " << fmt_above(e.force, r.noise_force / r.force, 2) << " | "
        << order_between(b.force, e.force) << " | " << (std::isfinite(e.line) ? fmt("%.2e", e.line) : "") << " | "
        << order_between(b.line, e.line) << " |\n";
      before = &r;
    }
  }
  o << "\nTable: " << words("continuum.series_caption") << "\n\n";
  o << words("continuum.orders_intro", {{"spread", fmt("%g", kSteadySpread)}}) << "\n\n"
    << "| quantity | sampling | orders (coarse to fine) | verdict |\n|---|---|---|---|\n";
  for (const Quantity& q : kQuantities)
    for (const std::string& k : s.kinds) {
      const Extrapolation& e = s.fits.at({k, q.name});
      if (e.orders.empty() || !std::isfinite(e.limit)) continue;  // a sampling that has no such value (q off the rim)
      o << "| " << q.name << " | " << k << " | ";
      for (size_t i = 0; i < e.orders.size(); ++i) o << (i ? ", " : "") << format_order(e.orders[i], e.order_noise[i]);
      o << " | " << verdict(e) << " |\n";
    }
  o << "\nTable: " << words("continuum.orders_caption") << "\n";
  return o.str();
}

// The limits, machine-readable, for the bench's time to accuracy and for the document.
std::string limits(const Study& s) {
  std::ostringstream o;
  o << "# continuum: Richardson limits (edge sampling rows are the continuum answer); made by build/continuum\n"
       "# steady: 1 if the last two observed orders differ by at most " << fmt("%g", kSteadySpread)
    << ", and then limit is Richardson's and bar its\n"
       "# distance to the previous Richardson limit; 0: limit is the finest value and bar its last increment.\n"
       "# A bar within 10 times the round-off estimate of the limit (src/roundoff.hpp) is that estimate instead\n"
       "quantity,sampling,steady,order,limit,bar\n";
  for (const Quantity& q : kQuantities)
    for (const std::string& k : s.kinds) {
      const Extrapolation& e = s.fits.at({k, q.name});
      if (e.orders.empty() || !std::isfinite(e.limit)) continue;  // a sampling that has no such value (q off the rim)
      o << q.column << "," << k << "," << (e.steady ? 1 : 0) << ","
        << (e.steady ? format_order(e.orders.back(), e.order_noise.back()) : "") << "," << fmt_value(e.limit, e.limit_noise, 10, "")
        << "," << bar_number(e) << "\n";
    }
  return o.str();
}

// Relative error of every row against the rim-contact series, for the figure and the speed report.
std::string errors(const Study& s) {
  std::ostringstream o;
  o << "# continuum: |value - answer| / |answer| for max w and the total force, the answer being the rim-contact\n"
       "# series' (rim_series.md); err_line_pointwise (edge sampling): max over the edge points of |q - q_series| over\n"
       "# the mean load. Made by build/continuum\n"
       "sampling,n,h,err_max_w,err_total_force,err_line_pointwise\n";
  const double w_bar = s.yardstick.bar_max_w, f_bar = s.yardstick.bar_force;
  for (const Row& r : s.rows) {
    const RowError e = error_of(r, s.yardstick);
    o << r.kind << "," << r.n << "," << fmt("%.10g", 1.0 / r.n) << ","
      << fmt_above(e.max_w, (r.noise_max_w + w_bar) / r.max_w, 5) << ","
      << fmt_above(e.force, (r.noise_force + f_bar) / r.force, 5) << ","
      << (std::isfinite(e.line) ? fmt_above(e.line, r.noise_line / r.line.mean, 3) : "")
      << "\n";
  }
  return o.str();
}

// The line load on a quarter of the rim (the square's symmetries give the rest) beside the series':
// the spline rows' function at 181 angles on every grid from n = 32, and the point rows' values on
// n = 128, where they scatter. Point values scatter more than aggregates between BLAS thread counts
// (up to 3 u n^3 max q), so each is printed above the number of values times that bound.
std::string line_loads(const Study& s) {
  std::ostringstream o;
  o << "# continuum: the line load q (force per unit length) on the rim, theta in [0, pi/2], and the rim-contact\n"
       "# series' q_series at the same angle; sampling edge: the spline of the rows' multipliers (D12) at 181\n"
       "# angles, n = 32 ... finest; edge-points: the point values on n = 128. Made by build/continuum; printed\n"
       "# to the digits round-off leaves the same on every machine; distance: |q - q_series| over the series' mean load\n"
       "sampling,n,theta,q,q_series,distance\n";
  const RimSeries& y = s.yardstick.finest;
  for (const Row& r : s.rows) {
    const bool spline = r.kind == "edge" && r.n >= 32, points = r.kind == "edge-points" && r.n == 128;
    if (!spline && !points) continue;
    const double noise = r.noise_line;
    auto put = [&](double t, double q) {
      o << r.kind << "," << r.n << "," << fmt("%.10g", t) << "," << fmt_value(q, noise, 10, "") << "," << fmt("%.10g", y.q(t)) << ","
        << fmt_above(std::abs(q - y.q(t)) / y.q_cos.at(0), noise / y.q_cos.at(0), 3) << "\n";
    };
    if (spline)
      for (int k = 0; k <= 180; ++k) put(M_PI / 2 * k / 180, line_force_value(r.line, M_PI / 2 * k / 180));
    else
      for (size_t k = 0; k < r.line.q.size(); ++k)
        if (r.line.theta[k] <= M_PI / 2 + 1e-12) put(r.line.theta[k], r.line.q[k]);
  }
  return o.str();
}

}  // namespace

int main(int argc, char** argv) {
  clean_up_on_interrupt("continuum");
  CLI::App app{"continuum: the h -> 0 limit of the paper's problem, from exact solves with edge, Gauss and nodal\n"
               "sampling on n = coarsest, 2 coarsest, ..., finest, with observed orders and Richardson limits."};
  std::string out = "results", numbers = "reference/paper_numbers.csv";
  int coarsest = 8, finest = 512;
  app.add_option("--out", out, "folder for the results")->capture_default_str();
  app.add_option("--numbers", numbers, "the paper's numbers (obstacle)")->check(CLI::ExistingFile)->capture_default_str();
  app.add_option("--coarsest", coarsest, "cells on the coarsest grid")->check(CLI::Range(2, 1024))->capture_default_str();
  app.add_option("--finest", finest, "cells on the finest grid")->check(CLI::Range(8, 2048))->capture_default_str();
  app.footer(kExitStatusHelp);
  if (const int status = parse_options(app, argc, argv, "continuum"); status >= 0) return status;
  return run_guarded("continuum", [&] {
    if (finest < 4 * coarsest) throw std::invalid_argument("--finest must be at least 4 times --coarsest (three grids)");
    const auto pub = read_paper_numbers(numbers);
    const Scene scene = paper_scene();
    Study s;
    s.yardstick = rim_answer(scene);
    if (!s.yardstick.premise.holds || !s.yardstick.settled)
      throw std::runtime_error("the rim-contact series gives no answer to measure against: " +
                               (s.yardstick.premise.holds ? std::string("its truncations have not settled")
                                                          : "its premise fails: " + s.yardstick.premise.why));
    for (int n = coarsest; n <= finest; n *= 2) s.grids.push_back(n);
    std::ostringstream timings;
    timings << "# continuum run times in seconds (assembly and exact solve, grid-sequenced); not byte-identical\n"
               "sampling,n,seconds\n";
    for (const Variant& v : variants()) {
      s.kinds.push_back(v.name);
      for (int n : s.grids) {
        std::cerr << "continuum: " << v.name << " sampling, n = " << n << "\n";
        s.rows.push_back(solve_one(v, n, scene));
        timings << v.name << "," << n << "," << fmt("%.3g", s.rows.back().seconds) << "\n";
      }
    }
    for (const Quantity& q : kQuantities)
      for (const std::string& k : s.kinds)
        s.fits[{k, q.name}] = extrapolate(column(s.rows, k, q.field), column(s.rows, k, q.noise));
    write_file_atomically(out + "/continuum.csv", csv(s.rows));
    write_file_atomically(out + "/continuum_error.csv", errors(s));
    write_file_atomically(out + "/continuum_q.csv", line_loads(s));
    write_file_atomically(out + "/continuum_answer.md", answer(s));
    write_file_atomically(out + "/continuum_limits.csv", limits(s));
    write_file_atomically(out + "/continuum.md", markdown(s));
    write_file_atomically(out + "/continuum_timings.csv", timings.str());
    for (const Row& r : s.rows)
      if (!r.certified) return kNotConverged;
    return kSuccess;
  });
}
