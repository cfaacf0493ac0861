// rim_series: the repository's yardstick. The paper's scene solved by the rim-contact series
// (src/rim_contact.hpp) at increasing truncations: results/rim_series.{md,csv} (every output
// against the truncation), results/rim_answer.csv (the answer and its bars, which the continuum
// study, the cross-check and the speed report measure against), and results/uniform_load.csv (the
// finite elements against the series on the plate alone). `rim_series --help`.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>
#include <sstream>

#include "atomic_file.hpp"
#include "active_set.hpp"
#include "cholesky.hpp"
#include "contact.hpp"
#include "exit_codes.hpp"
#include "format.hpp"
#include "published.hpp"
#include "rim_report.hpp"
#include "words.hpp"

using namespace plate;

namespace {

std::string table_csv(const RimAnswer& a) {
  std::ostringstream o;
  o << "# rim_series: the paper's scene (f = 0, R = 0.0625 on the disk of radius 0.25 at the centre of the unit\n"
       "# square) by the rim-contact series at truncation levels 0, 1, ...: harmonics of q (only cos 4k theta\n"
       "# by symmetry), degree of the Trefftz polynomials, clamped-corner terms per family, unknowns; the\n"
       "# outputs; the largest misfit between collocation points relative to R on the edge and on the rim.\n"
       "# Made by build/rim_series; digits above 1000 u relative\n"
       "level,harmonics,degree,corner_terms,unknowns,max_w,total_force,q_theta_0,q_theta_pi_4,edge_residual,rim_residual\n";
  for (const RimConvergenceRow& r : a.rows)
    o << r.level << ',' << r.harmonics << ',' << r.degree << ',' << r.corner_terms << ',' << r.unknowns << ','
      << rim_digits(r.max_w, a.bar_max_w) << ',' << rim_digits(r.total_force, a.bar_force) << ','
      << rim_digits(r.q0, a.bar_q0) << ',' << rim_digits(r.q45, a.bar_q45) << ',' << fmt_up(r.edge_residual) << ',' << fmt_up(r.rim_residual) << '\n';
  return o.str();
}

std::string table_md(const RimAnswer& a) {
  std::ostringstream o;
  o << "| level | harmonics | degree | corner terms | unknowns | max w | total force | q(0) | q(pi/4) | edge misfit | "
       "rim misfit |\n|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const RimConvergenceRow& r : a.rows)
    o << "| " << r.level << " | " << r.harmonics << " | " << r.degree << " | " << r.corner_terms << " | " << r.unknowns
      << " | " << rim_digits(r.max_w, a.bar_max_w) << " | " << rim_digits(r.total_force, a.bar_force) << " | "
      << rim_digits(r.q0, a.bar_q0) << " | " << rim_digits(r.q45, a.bar_q45) << " | " << fmt_up(r.edge_residual) << " | " << fmt_up(r.rim_residual) << " |\n";
  o << "\nTable: " << words("rim_series.caption", {{"levels", std::to_string(a.rows.size())}}) << "\n";
  o << "\n"
    << words("rim_series.bars", {{"from", std::to_string(a.rows.size() - 2)},
                                 {"to", std::to_string(a.rows.size() - 1)},
                                 {"shrink", a.settled ? "at every level" : "NOT at every level"},
                                 {"premise", a.premise.holds ? "holds" : "FAILS: " + a.premise.why},
                                 {"min_q", rim_digits(a.premise.min_q, a.bar_q45)},
                                 {"theta", fmt("%.4g", a.premise.theta_min_q)},
                                 {"gap", fmt("%.3g", a.premise.min_w_minus_R)}})
    << "\n";
  return o.str();
}

// The finite elements against the series where nothing but the plate is discretised: the clamped
// unit square under f = 1, no obstacle, its centre deflection on n = 16 ... finest, solved once in
// double and once refined (D22). In double the error falls with h until the round-off of the
// assembled matrix, the same on every machine, takes over; the refined solve shows it gone.
std::string uniform_load_csv(int finest) {
  const PlateSeries series = solve_clamped_plate(1, 1, 1);
  const double exact = series.at(0.5, 0.5).w;
  std::ostringstream o;
  o << "# rim_series: the clamped unit square under f = 1 (no obstacle), centre deflection by the series (n = 0)\n"
       "# and by Bogner-Fox-Schmit elements on n x n squares, relative error against the series: one Cholesky\n"
       "# solve in double, and the same refined with residuals in long double (D22). Made by build/rim_series\n"
       "n,w_centre,relative_error,w_centre_refined,relative_error_refined\n"
    << "0," << rim_digits(exact) << ",,,\n";
  const Field none = [](double, double) { return -1.0; }, one = [](double, double) { return 1.0; };
  for (int n = 16; n <= finest; n *= 2) {
    const Problem p = make_problem(Scene::rectangle(1, 1).over("-1").loaded("1"), make_grid(n), SamplingSpec{SamplingKind::Nodes});
    Cholesky chol;
    chol.factorize(p.K);
    VectorXd solved = chol.solve(p.F), none;
    const double w = evaluate(p.grid, solved, 0.5, 0.5).w;
    // Printed above what another machine's summation order changes (u n^3, exact_solve_roundoff).
    const double noise = exact_solve_roundoff(n, w);
    const Refinement record = refine(p, chol, {}, Eigen::MatrixXd(), none, solved);  // refines `solved` in place
    const double refined = evaluate(p.grid, solved, 0.5, 0.5).w;
    // What the refinement's last correction still moved: the floor to which it is reproducible.
    const double floor = std::max(record.floor_w(), 1e-16) * std::abs(refined);
    o << n << ',' << fmt_above(w, noise, 10, 'g') << ',' << fmt_above((w - exact) / exact, noise / exact, 3) << ','
      << fmt_above(refined, floor, 13, 'g') << ',' << fmt_above((refined - exact) / exact, floor / exact, 3) << '\n';
  }
  return o.str();
}

std::string answer_csv(const RimAnswer& a) {
  const RimSeries& s = a.finest;
  const RimPeak peak = s.max_w();
  std::ostringstream o;
  o << "# rim_series: the paper's scene by the rim-contact series, the finest truncation; bar: the change from\n"
       "# the truncation before (floored at 1000 u relative). Made by build/rim_series\n"
       "quantity,value,bar\n"
    << "max_w," << rim_digits(peak.w, a.bar_max_w) << ',' << fmt_up(a.bar_max_w) << '\n'
    << "max_w_x," << rim_digits(peak.x) << ",\n"
    << "max_w_y," << rim_digits(peak.y) << ",\n"
    << "total_force," << rim_digits(s.total_force(), a.bar_force) << ',' << fmt_up(a.bar_force) << '\n'
    << "mean_line_force," << rim_digits(s.q_cos.at(0), a.bar_force / (2 * M_PI * s.scene.radius)) << ',' << fmt_up(a.bar_force / (2 * M_PI * s.scene.radius)) << '\n'
    << "q_theta_0," << rim_digits(s.q(0), a.bar_q0) << ',' << fmt_up(a.bar_q0) << '\n'
    << "q_theta_pi_4," << rim_digits(s.q(M_PI / 4), a.bar_q45) << ',' << fmt_up(a.bar_q45) << '\n';
  return o.str();
}

}  // namespace

int main(int argc, char** argv) {
  clean_up_on_interrupt("rim_series");
  CLI::App app{"rim_series: the paper's scene by the rim-contact series at increasing truncations, the\n"
               "repository's reference answer (results/rim_series.{md,csv}, results/rim_answer.csv)."};
  std::string out = "results", reference = "reference";
  int levels = 6, finest = 512;
  app.add_option("--out", out, "folder for the results")->capture_default_str();
  app.add_option("--reference", reference, "folder with paper_numbers.csv")->check(CLI::ExistingDirectory)->capture_default_str();
  app.add_option("--levels", levels, "truncation levels 0 ... levels - 1")->check(CLI::Range(3, 9))->capture_default_str();
  app.add_option("--finest", finest, "finest grid of the uniform-load check (uniform_load.csv)")
      ->check(CLI::Range(16, 1024))
      ->capture_default_str();
  app.footer(kExitStatusHelp);
  if (const int status = parse_options(app, argc, argv, "rim_series"); status >= 0) return status;
  return run_guarded("rim_series", [&] {
    if (finest & (finest - 1)) throw std::invalid_argument("--finest must be 16 times a power of two (16, 32, ...)");
    const RimAnswer a = rim_answer(paper_scene(), levels);
    write_file_atomically(out + "/rim_series.csv", table_csv(a));
    write_file_atomically(out + "/rim_series.md", table_md(a));
    write_file_atomically(out + "/rim_answer.csv", answer_csv(a));
    write_file_atomically(out + "/uniform_load.csv", uniform_load_csv(finest));
    if (!a.premise.holds || !a.settled) {
      std::cerr << "rim_series: " << (a.premise.holds ? "the series has not settled" : "the premise fails: " + a.premise.why) << "\n";
      return kNotConverged;
    }
    return kSuccess;
  });
}
