// contraction: writes results/contraction.md, Theorem 2 checked numerically: lambda_1h, the measured
// factor by which the linear scheme (5a) shrinks its steps, the sharp factor 1/(1 + eps lambda_1h),
// its square, and the paper's rho from (6). `contraction --help` lists the options.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "atomic_file.hpp"
#include "exit_codes.hpp"
#include "format.hpp"
#include "contraction.hpp"
#include "published.hpp"

using namespace plate;

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
    const PaperScene scene = read_paper_scene(reference);
    const Field paper_phi = scene.obstacle();
    std::ostringstream md;
    md << "<!-- Written by build/contraction (make results); do not edit. -->\n\n"
       << "| h | sampling | eps | lambda_1h | q = 1/(1 + eps lambda_1h) | measured, no contact | slowest, paper's obstacle"
          " | q^2 | paper's rho, c = 1/lambda_1h |\n|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (int n : grids)
      for (SamplingKind kind : {SamplingKind::Gauss, SamplingKind::Nodes}) {
        std::cerr << "contraction: h = 1/" << n << ", " << to_string(kind) << " sampling\n";
        // f = 1 and phi = -1: the plate never reaches the obstacle, so every step is linear.
        const Problem free = make_problem(make_grid(n), kind, [](double, double) { return -1.0; },
                                          [](double, double) { return 1.0; });
        const Problem paper = make_problem(make_grid(n), kind, paper_phi, [](double, double) { return 0.0; });
        const double lambda = smallest_eigenpair(free.K, free.M).lambda;
        for (double eps : epss) {
          const double q = sharp_contraction(lambda, eps);
          const int iterations = static_cast<int>(std::min(20000.0, 40.0 / (1 - q)));  // e^-40 of the first step
          VectorXd settled;
          const std::vector<double> steps = linear_step_norms(paper, eps, iterations, &settled);
          // Nine digits are printed: each factor is computed where round-off stays below the 12th.
          md << "| 1/" << n << " | " << to_string(kind) << " | " << fmt("%.0e", eps) << " | " << fmt("%.4f", lambda)
             << " | " << fmt("%.9f", q) << " | " << fmt("%.9f", settled_factor(free, eps, VectorXd::Zero(free.grid.unknowns())))
             << " | " << fmt("%.9f", slowest_factor(steps, settled_factor(paper, eps, settled))) << " | "
             << fmt("%.9f", q * q) << " | " << fmt("%.9f", paper_rho(1 / lambda, eps)) << " |\n";
        }
      }
    std::filesystem::create_directories(out);
    write_file_atomically(out + "/contraction.md", md.str());
  } catch (const std::exception& e) {
    std::cerr << "contraction: " << e.what() << "\n";
    return kFailure;
  }
  return kSuccess;
}
