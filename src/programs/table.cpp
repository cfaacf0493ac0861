// table: writes results/table.md and .csv: the paper's experiment (the table of Kovtunenko 1994)
// rerun with both schemes and both samplings, on h = 1/4 and on finer grids, with the true error
// of every stopped iterate. Run by `make results`; `table --help` lists the options.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "atomic_file.hpp"
#include "exit_codes.hpp"
#include "format.hpp"
#include "contact.hpp"
#include "contraction.hpp"
#include "eps_limit.hpp"
#include "norms.hpp"
#include "published.hpp"
#include "schemes.hpp"
#include "words.hpp"

using namespace plate;

namespace {
struct Run {
  int iterations = 0;
  double eps = 0, last_step = 0, error = 0, estimate = 0, residual = 0;
  bool converged = false;
};

// One run of the paper's method at one tolerance, measured against the eps -> 0 limit.
Run run(const Problem& p, Scheme scheme, double tol, const EpsLimit& limit, double lambda1h) {
  SolveOptions o;
  o.scheme = scheme;
  o.tol = tol;
  const SolveResult r = solve(p, o);
  Run x;
  x.iterations = r.total_iterations();
  x.eps = r.eps;
  x.converged = r.stopped;  // the paper's rules; the error column says how good that was
  x.last_step = r.levels.back().last_step;
  x.error = max_nodal_abs(r.w - limit.w);
  x.residual = penalty_backward_error(p, r.w, r.eps);
  // A posteriori: steps of (5a) shrink at least by q = 1/(1 + eps lambda_1h), so the distance to
  // w_eps is at most q/(1-q) = 1/(eps lambda_1h) times the last step (in the M-norm; we apply
  // it to the C-norm step as an estimate). (3a) reaches w_eps exactly: no such term.
  x.estimate = scheme == Scheme::Linear ? x.last_step / (r.eps * lambda1h) : 0.0;
  return x;
}

// A backward-stable solve leaves a backward error of a few units of round-off (2.2e-16); (3a) at
// its exact w_eps shows at most 4e-16 on every grid of the table.
constexpr double kBackwardErrorFloor = 1e-14;

struct Case {
  int n;
  SamplingKind kind;
  EpsLimit limit;
  double lambda1h;
  std::vector<std::pair<Run, Run>> runs;  // (linear, nonlinear) per published tolerance
};

// What another machine may change in a case's numbers. The iterates and the path carry the round-off
// of a solve (EpsLimit::roundoff); the errors carry, besides, the reference's own error.
struct Noise {
  double w, reference;
};
Noise noise(const Case& c) { return {c.limit.roundoff, c.limit.estimate + c.limit.roundoff}; }

// The estimate is a difference of two extrapolations, each carrying the path's round-off: it is
// printed to the digits above that round-off, and as a bound where round-off is all it is.
std::string reference_error(const EpsLimit& L) {
  const std::string e = fmt_above(L.estimate, L.roundoff, 2);
  return e[0] == '<' ? e : "<= " + e;
}

// The ratio of two differences of the path, each uncertain by twice the round-off of a solution:
// printed one way on every grid, with that uncertainty beside it.
std::string eps_ratio(const EpsLimit& L) {
  const double relative = 2 * L.roundoff * (1 / (L.ratio * L.difference) + 1 / L.difference);
  if (!(L.ratio * relative < 0.5)) return "undetermined (round-off)";
  return fmt("%.2f", L.ratio) + " ± " + fmt("%.0e", std::max(L.ratio * relative, 5e-3));
}

// The a-posteriori estimate is zero by construction for (3a): printed as such, not as a bound.
std::string estimate(const Run& r, double w_noise, double lambda1h, int digits) {
  return r.estimate == 0 ? "0" : fmt_above(r.estimate, w_noise / (r.eps * lambda1h), digits);
}

std::string markdown(const std::vector<Case>& cases, const std::vector<PublishedRow>& table, bool with_paper) {
  std::ostringstream md;
  for (const Case& c : cases) {
    const Noise z = noise(c);
    const std::string caption = words(with_paper ? "table.caption_paper" : "table.caption_fine",
                                      {{"n", std::to_string(c.n)},
                                       {"sampling", std::string(to_string(c.kind)) == "gauss" ? "Gauss points" : "nodes"},
                                       {"unknowns", std::to_string(4 * (c.n - 1) * (c.n - 1))},
                                       {"lambda1h", fmt("%.4f", c.lambda1h)},
                                       {"known", reference_error(c.limit)},
                                       {"ratio", eps_ratio(c.limit)}});
    md << "\n| OS |" << (with_paper ? " paper (5a) | GLT |" : "")
       << " (5a) iterations | final $\\varepsilon$ | last step | error | estimate | (3a) iterations | (3a) final $\\varepsilon$ | (3a) error |\n";
    md << "|---:|" << (with_paper ? "---:|---:|" : "") << "---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (std::size_t i = 0; i < table.size(); ++i) {
      const Run &l = c.runs[i].first, &nl = c.runs[i].second;
      md << "| " << fmt_exact_e(table[i].tolerance) << " |";
      if (with_paper) md << " " << table[i].iterations << " | " << table[i].iterations_glt << " |";
      md << " " << l.iterations << (l.converged ? "" : " (no)") << " | " << fmt("%.0e", l.eps) << " | " << fmt_above(l.last_step, z.w, 2) << " | "
         << fmt_above(l.error, z.reference, 2) << " | " << estimate(l, z.w, c.lambda1h, 2) << " | "
         << nl.iterations << (nl.converged ? "" : " (no)") << " | "
         << fmt("%.0e", nl.eps) << " | " << fmt_above(nl.error, z.reference, 2) << " |\n";
    }
    md << "\nTable: " << caption << "\n";
  }
  return md.str();
}

std::string csv(const std::vector<Case>& cases, const std::vector<PublishedRow>& table) {
  std::ostringstream o;
  o << "# Written by build/table (make results). The paper's experiment: unit square, f = 0, phi = 0.0625 on the\n"
       "# disk of radius 0.25 around (0.5, 0.5), w = 0 to start, eps_s = 0.1 * 10^-s, both stopping rules with OS.\n"
       "# Columns: n (h = 1/n), sampling, tolerance OS, paper/GLT iterations (published, h = 1/4 only),\n"
       "# scheme, iterations (all eps levels), final eps, converged (both rules met before eps-min = 1e-12),\n"
       "# last_step = ||w^{n+1} - w^n||_C at the stop, error = ||w - w_ref||_C at the nodes against the eps -> 0\n"
       "# limit w_ref, estimate = last_step / (eps lambda_1h) (linear scheme only), residual = backward error\n"
       "# of the discrete (2a) at the final eps (the residual over the size of its terms). Digits that round-off\n"
       "# could change are not printed: a value within 10 times its round-off floor reads \"< bound\".\n";
  o << "n,sampling,tolerance,paper_iterations,glt_iterations,scheme,iterations,final_eps,converged,last_step,error,"
       "estimate,residual\n";
  for (const Case& c : cases) {
    const Noise z = noise(c);
    for (std::size_t i = 0; i < table.size(); ++i)
      for (int k = 0; k < 2; ++k) {
        const Run& r = k == 0 ? c.runs[i].first : c.runs[i].second;
        o << c.n << "," << to_string(c.kind) << "," << fmt("%.3g", table[i].tolerance) << ","
          << (c.n == 4 ? std::to_string(table[i].iterations) : "") << ","
          << (c.n == 4 ? std::to_string(table[i].iterations_glt) : "") << "," << (k == 0 ? "linear" : "nonlinear")
          << "," << r.iterations << "," << fmt("%.0e", r.eps) << "," << (r.converged ? 1 : 0) << ","
          << fmt_above(r.last_step, z.w, 4) << "," << fmt_above(r.error, z.reference, 4) << ","
          << estimate(r, z.w, c.lambda1h, 4) << "," << fmt_above(r.residual, kBackwardErrorFloor, 4) << "\n";
      }
  }
  return o.str();
}
}  // namespace

int main(int argc, char** argv) {
  plate::clean_up_on_interrupt("table");
  CLI::App app{"table: the paper's experiment (its table) rerun with the linear scheme (5a) and the nonlinear\n"
               "scheme (3a), both samplings, on h = 1/4 and finer grids; writes table.md/.csv and table_fine.md/.csv."};
  std::string reference = "reference", out = "results";
  std::vector<int> fine = {8, 16, 32, 64};
  std::string which = "both";
  app.add_option("--reference", reference, "folder with paper_table.csv and paper_numbers.csv")
      ->check(CLI::ExistingDirectory)
      ->capture_default_str();
  app.add_option("--out", out, "folder for the tables")->capture_default_str();
  app.add_option("--fine", fine, "finer grids n (h = 1/n) for the second table")
      ->delimiter(',')
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  // The paper's grid alone takes a second and the finer grids about 90: make runs them apart, so
  // that the penalty cross-check, which reads only the first, need not wait for the second.
  app.add_option("--which", which, "which tables: paper (h = 1/4: table.md/.csv), fine (table_fine.md/.csv) or both")
      ->check(CLI::IsMember({"paper", "fine", "both"}))
      ->capture_default_str();
  app.footer(kExitStatusHelp);
  if (const int status = parse_options(app, argc, argv, "table"); status >= 0) return status;

  try {
    const auto table = read_paper_table(reference + "/paper_table.csv");
    const auto numbers = read_paper_numbers(reference + "/paper_numbers.csv");
    const Scene scene = paper_scene();
    const int n_paper = paper_cells();
    std::vector<std::pair<int, bool>> grids;  // n, and whether it is the paper's table
    if (which != "fine") grids.emplace_back(n_paper, true);
    if (which != "paper")
      for (int n : fine) grids.emplace_back(n, false);
    std::vector<Case> paper_cases, fine_cases;
    for (const auto& [n, paper] : grids)
      for (SamplingKind kind : {SamplingKind::Gauss, SamplingKind::Nodes}) {
        std::cerr << "table: h = 1/" << n << ", " << to_string(kind) << " sampling\n";
        const Problem p = make_problem(scene, make_grid(n), SamplingSpec{kind});
        Case c{n, kind, eps_limit(p), smallest_eigenpair(p.K, p.M).lambda, {}};
        for (const auto& row : table)
          c.runs.emplace_back(run(p, Scheme::Linear, row.tolerance, c.limit, c.lambda1h),
                              run(p, Scheme::Nonlinear, row.tolerance, c.limit, c.lambda1h));
        (paper ? paper_cases : fine_cases).push_back(std::move(c));
      }
    std::filesystem::create_directories(out);
    const std::string head =
        "<!-- Written by build/table (make results) from reference/paper_table.csv; do not edit. -->\n";
    if (which != "fine") {
      write_file_atomically(out + "/table.md", head + markdown(paper_cases, table, true));
      write_file_atomically(out + "/table.csv", csv(paper_cases, table));
    }
    if (which != "paper") {
      write_file_atomically(out + "/table_fine.md", head + markdown(fine_cases, table, false));
      write_file_atomically(out + "/table_fine.csv", csv(fine_cases, table));
    }
  } catch (const std::exception& e) {
    std::cerr << "table: " << e.what() << "\n";
    return kFailure;
  }
  return kSuccess;
}
