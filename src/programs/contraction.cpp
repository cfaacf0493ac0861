// contraction: writes results/contraction.md and .csv, Theorem 2 checked numerically: lambda_1h, the
// measured factor by which the linear scheme (5a) shrinks its steps and the energy of its steps, the
// sharp factor 1/(1 + eps lambda_1h), its square, and the paper's rho from (6). `contraction --help` lists the options.
#include <CLI/CLI.hpp>

#include <cfloat>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "atomic_file.hpp"
#include "exit_codes.hpp"
#include "format.hpp"
#include "contraction.hpp"
#include "eps_limit.hpp"
#include "norms.hpp"
#include "published.hpp"
#include "schemes.hpp"
#include "words.hpp"

using namespace plate;

namespace {
// f = 1 and phi = -1: the plate never reaches the obstacle, so every step is linear.
Problem no_contact_problem(int n, SamplingKind kind) {
  return make_problem(Scene::rectangle(1, 1).over("-1").loaded("1"), make_grid(n), SamplingSpec{kind});
}
Problem paper_problem(int n, SamplingKind kind) { return make_problem(paper_scene(), make_grid(n), SamplingSpec{kind}); }

// (D7) on the paper's own grid: at one eps, the linear scheme's step at every iteration, its true
// distance to the exact penalised solution w_eps, and the bound step / (eps lambda_1h) that (D7)
// puts on that distance (all at the nodes, in the maximum norm, as the paper's table measures).
// Iterations are kept on a logarithmic grid, so that the file stays small.
std::string linear_history(const Problem& p, double eps, double lambda, int max_iter) {
  const VectorXd w_eps = penalised_path(p, eps).back();
  // Round-off on this grid, measured between thread counts and OpenBLAS's kernels: a step moved by
  // up to 0.6 u max|w|, an error (which carries w_eps's own round-off) by up to 9 u max|w|; ten times
  // each is taken. A row whose step or error is within ten times that says nothing more: the curve ends.
  const double step_noise = 10 * DBL_EPSILON * max_nodal_abs(w_eps), error_noise = 10 * step_noise;
  std::ostringstream o;
  o << "# Written by build/contraction (make results): the linear scheme (5a) on the paper's grid, h = 1/"
    << p.grid.nx << ", nodal sampling, eps = " << fmt("%.0e", eps) << ", from w = 0; lambda_1h = " << fmt("%.4f", lambda)
    << "\n# step = max nodal |w^n - w^(n-1)|, error = max nodal |w^n - w_eps|, bound = step / (eps lambda_1h) (D7)\n"
       "iteration,step,error,bound\n";
  VectorXd last = VectorXd::Zero(p.grid.unknowns());
  int next_kept = 1;
  SolveOptions opt = fixed_eps_options(Scheme::Linear, eps, 1e-300, max_iter);
  opt.on_iterate = [&](double, int k, const VectorXd& w) {
    const double step = max_nodal_abs(w - last), error = max_nodal_abs(w - w_eps);
    last = w;
    if (k < next_kept) return;
    next_kept = std::max(k + 1, static_cast<int>(k * 1.08));
    if (error < 10 * error_noise || step < 10 * step_noise) return;
    o << k << ',' << fmt_above(step, step_noise, 4) << ',' << fmt_above(error, error_noise, 4) << ','
      << fmt_above(step / (eps * lambda), step_noise / (eps * lambda), 4) << '\n';
  };
  Cholesky chol;
  chol.analyze(p.K + p.M);  // every pattern K + S^T D S can have (spline rows reach past an element)
  VectorXd w = VectorXd::Zero(p.grid.unknowns());
  linear_scheme_level(p, eps, w, chol, opt);
  return o.str();
}
}  // namespace

int main(int argc, char** argv) {
  plate::clean_up_on_interrupt("contraction");
  CLI::App app{"contraction: Theorem 2 of the paper checked on the discrete problem; writes contraction.md."};
  std::string reference = "reference", out = "results";
  std::vector<int> grids = {4, 16};
  std::vector<double> epss = {1e-2, 1e-3, 1e-4};
  app.add_option("--reference", reference, "folder with paper_numbers.csv")->check(CLI::ExistingDirectory)->capture_default_str();
  app.add_option("--out", out, "folder for the report")->capture_default_str();
  app.add_option("--n", grids, "grids n (h = 1/n)")->delimiter(',')->check(CLI::Range(2, 256))->capture_default_str();
  app.add_option("--eps", epss, "penalty parameters")->delimiter(',')->check(CLI::Range(1e-8, 1.0))->capture_default_str();
  app.footer(kExitStatusHelp);
  if (const int status = parse_options(app, argc, argv, "contraction"); status >= 0) return status;
  try {
    std::ostringstream md;
    std::string history;
    md << "<!-- Written by build/contraction (make results); do not edit. -->\n\n"
       << "| $h$ | sampling | $\\varepsilon$ | $\\lambda_{1h}$ | $q = 1/(1 + \\varepsilon\\lambda_{1h})$ | measured, no contact"
          " | slowest, paper's obstacle | $q^2$ | slowest energy ratio, paper's obstacle"
          " | paper's $\\rho$, $c = 1/\\lambda_{1h}$ |\n"
          "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    std::ostringstream csv;
    csv << "# Written by build/contraction (make results): the factors of contraction.md\n"
           "n,sampling,eps,lambda_1h,q,measured_no_contact,slowest_obstacle,q2,energy_obstacle,rho\n";
    for (int n : grids)
      for (SamplingKind kind : {SamplingKind::Gauss, SamplingKind::Nodes}) {
        std::cerr << "contraction: h = 1/" << n << ", " << to_string(kind) << " sampling\n";
        const Problem free = no_contact_problem(n, kind), paper = paper_problem(n, kind);
        const double lambda = smallest_eigenpair(free.K, free.M).lambda;
        for (double eps : epss) {
          const double q = sharp_contraction(lambda, eps);
          const int iterations = static_cast<int>(std::min(20000.0, 40.0 / (1 - q)));  // e^-40 of the first step
          VectorXd settled;
          std::vector<double> energies;
          const std::vector<double> steps = linear_step_norms(paper, eps, iterations, &settled, &energies);
          // The energy ratio through the same reading as the steps: on sqrt(E), then squared. Once
          // the contact set has settled, the iteration is self-adjoint in the energy, so its energy
          // ratio tends to the square of the settled factor.
          std::vector<double> root_energies(energies.size());
          for (std::size_t k = 0; k < energies.size(); ++k) root_energies[k] = std::sqrt(energies[k]);
          const double settled_paper = settled_factor(paper, eps, settled);
          const double no_contact = settled_factor(free, eps, VectorXd::Zero(free.grid.unknowns()));
          const double slowest = slowest_factor(steps, settled_paper);
          const double energy = std::pow(slowest_factor(root_energies, settled_paper), 2);
          const double rho = paper_rho(1 / lambda, eps);
          // Nine digits are printed: each factor is computed where round-off stays below the 12th.
          md << "| 1/" << n << " | " << to_string(kind) << " | " << fmt("%.0e", eps) << " | " << fmt("%.4f", lambda)
             << " | " << fmt("%.9f", q) << " | " << fmt("%.9f", no_contact) << " | " << fmt("%.9f", slowest) << " | "
             << fmt("%.9f", q * q) << " | " << fmt("%.9f", energy) << " | " << fmt("%.9f", rho) << " |\n";
          csv << n << ',' << to_string(kind) << ',' << fmt("%.0e", eps) << ',' << fmt("%.4f", lambda) << ','
              << fmt("%.9f", q) << ',' << fmt("%.9f", no_contact) << ',' << fmt("%.9f", slowest) << ','
              << fmt("%.9f", q * q) << ',' << fmt("%.9f", energy) << ',' << fmt("%.9f", rho) << '\n';
        }
      }
    md << "\nTable: " << words("contraction.caption") << "\n";
    {
      std::cerr << "contraction: the linear scheme's history on the paper's grid\n";
      const int n = paper_cells();  // the paper's h = 1/4
      const Problem free = no_contact_problem(n, SamplingKind::Nodes);
      history = linear_history(paper_problem(n, SamplingKind::Nodes), 1e-6,
                               smallest_eigenpair(free.K, free.M).lambda, 40000);
    }
    std::filesystem::create_directories(out);
    write_file_atomically(out + "/linear_history.csv", history);
    write_file_atomically(out + "/contraction.md", md.str());
    write_file_atomically(out + "/contraction.csv", csv.str());
  } catch (const std::exception& e) {
    std::cerr << "contraction: " << e.what() << "\n";
    return kFailure;
  }
  return kSuccess;
}
