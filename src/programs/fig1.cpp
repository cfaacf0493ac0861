// fig1: writes the data of Fig. 1: results/fig1_points.csv (the check points where values are
// reported), fig1_surface.dat (the computed deflection on a lattice, for gnuplot's splot) and
// fig1_contact.dat (the sample points where the plate rests on the obstacle). `fig1 --help`.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "atomic_file.hpp"
#include "exit_codes.hpp"
#include "format.hpp"
#include "contact.hpp"
#include "crosscheck.hpp"
#include "eps_limit.hpp"
#include "published.hpp"

using namespace plate;

int main(int argc, char** argv) {
  plate::clean_up_on_interrupt("fig1");
  CLI::App app{"fig1: the data of Fig. 1 (check points; the deflection of the paper's problem and its contact set)."};
  std::string reference = "reference", out = "results", sampling = "gauss";
  int n = 32, lattice = 64;
  double eps = 1e-10;
  app.add_option("--reference", reference, "folder with paper_numbers.csv")->check(CLI::ExistingDirectory)->capture_default_str();
  app.add_option("--out", out, "folder for the outputs")->capture_default_str();
  app.add_option("-n", n, "grid of the computed deflection, n x n cells")->check(CLI::Range(2, 1024))->capture_default_str();
  app.add_option("--lattice", lattice, "the surface is evaluated on (lattice + 1)^2 points")->check(CLI::Range(2, 1000))->capture_default_str();
  app.add_option("--sampling", sampling, "gauss or nodes")->check(CLI::IsMember({"gauss", "nodes"}))->capture_default_str();
  app.add_option("--eps", eps, "penalty parameter (exact discrete w_eps)")->check(CLI::Range(1e-14, 1e-3))->capture_default_str();
  app.footer(kExitStatusHelp);
  if (const int status = parse_options(app, argc, argv, "fig1"); status >= 0) return status;

  try {
    const SamplingKind kind = sampling == "gauss" ? SamplingKind::Gauss : SamplingKind::Nodes;
    const Grid g = make_grid(n);
    const Problem p = make_problem(paper_scene(), g, SamplingSpec{kind});
    const VectorXd w = penalised_path(p, eps).back();

    std::ostringstream points, surface, contact;
    points << "# Written by build/fig1: the check points of results/crosscheck.md and the table (x, y).\nx,y\n0.5,0.5\n";
    for (const auto& c : kCheckPoints) points << c.x << "," << c.y << "\n";
    surface << "# Written by build/fig1: w on a lattice, h = 1/" << n << ", " << sampling
            << " sampling, eps = " << eps << ". Columns: x y w (blank line between rows).\n";
    for (int j = 0; j <= lattice; ++j) {
      for (int i = 0; i <= lattice; ++i) {
        const double x = static_cast<double>(i) / lattice, y = static_cast<double>(j) / lattice;
        surface << fmt("%.6f", x) << " " << fmt("%.6f", y) << " " << fmt("%.8e", evaluate(g, w, x, y).w) << "\n";
      }
      surface << "\n";
    }
    contact << "# Written by build/fig1: sample points where w_h < phi (the constraint is active). Columns: x y w.\n";
    const VectorXd sw = p.sampling.S * w;
    for (int k = 0; k < p.sampling.size(); ++k)
      if (sw[k] < p.phi[k])
        contact << fmt("%.6f", p.sampling.x[k]) << " " << fmt("%.6f", p.sampling.y[k]) << " " << fmt("%.8e", sw[k]) << "\n";
    std::filesystem::create_directories(out);
    write_file_atomically(out + "/fig1_points.csv", points.str());
    write_file_atomically(out + "/fig1_surface.dat", surface.str());
    write_file_atomically(out + "/fig1_contact.dat", contact.str());
  } catch (const std::exception& e) {
    std::cerr << "fig1: " << e.what() << "\n";
    return kFailure;
  }
  return kSuccess;
}
