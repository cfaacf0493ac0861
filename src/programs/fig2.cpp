// fig2: writes results/fig2.csv, fig2_mesh.csv and fig2_fit.md, the data of Fig. 2 of the paper:
// max|xi| * 10^3, max|m12| * 10 and max|w| at the grid nodes against the obstacle height R, on
// h = 1/4 and a fine grid, plus the mesh-independent total contact force. `fig2 --help` for options.
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
#include "eps_limit.hpp"
#include "published.hpp"
#include "schemes.hpp"
#include "words.hpp"

using namespace plate;

namespace {
double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

struct Point {
  int n;
  SamplingKind kind;
  double R, max_xi, max_m12, max_w, force, force_per_length;
};

// The exact discrete w_eps at one fixed eps. With f = 0 the discrete penalised problem is
// positively homogeneous in (R, w) at fixed eps, so every quantity below is exactly linear in R.
Point measure(int n, SamplingKind kind, double R, double eps, double nu, const std::map<std::string, double>& pub) {
  const double r = published(pub, "obstacle_radius");
  const Problem p = make_problem(paper_scene(R), make_grid(n), SamplingSpec{kind});
  const VectorXd w = penalised_path(p, eps).back();
  const NodalFields f = nodal_fields(p, w, eps, nu);
  const double force = total_contact_force(p, contact_force_density(p, w, eps));
  return {n, kind, R, max_abs(f.xi), max_abs(f.m12), max_abs(f.w), force, force / (2 * M_PI * r)};
}

// Least-squares line through the origin, y = slope * R, and its largest residual relative to max|y|.
std::pair<double, double> fit_through_origin(const std::vector<Point>& pts, double Point::*q) {
  double sxy = 0, sxx = 0, ymax = 0, res = 0;
  for (const Point& p : pts) sxy += p.R * (p.*q), sxx += p.R * p.R, ymax = std::max(ymax, std::abs(p.*q));
  const double slope = sxy / sxx;
  for (const Point& p : pts) res = std::max(res, std::abs(p.*q - slope * p.R));
  return {slope, ymax > 0 ? res / ymax : 0.0};
}

// What round-off leaves in these quantities, relative to their size: xi = (phi - S w) / eps loses
// u |phi| / (eps xi), about 5e-10 on h = 1/4 at eps = 1e-10, the most of any quantity here. The fit
// residuals are that round-off and nothing else, so they are printed as a bound over it, and
// the tables carry 7 digits, the last still 100 times above it.
constexpr double kRoundOff = 1e-9;

std::string csv_rows(const std::vector<Point>& pts) {
  std::ostringstream o;
  for (const Point& p : pts)
    o << p.n << "," << to_string(p.kind) << "," << fmt("%.6g", p.R) << "," << fmt("%.6e", p.max_xi) << ","
      << fmt("%.6e", p.max_m12) << "," << fmt("%.6e", p.max_w) << "," << fmt("%.6e", p.force) << ","
      << fmt("%.6e", p.force_per_length) << "\n";
  return o.str();
}

// The mesh study: which quantities settle as h -> 0 and which grow.
std::string mesh_markdown(const std::vector<Point>& pts, double R) {
  std::ostringstream md;
  md << "<!-- Written by build/fig2 (make results); do not edit. -->\n\n"
     << "| $h$ | sampling | $\\max\\xi$ at nodes | $h\\max\\xi$ | $\\max\\lvert m_{12}\\rvert$ | $\\max w$ | total force"
        " | force / $2\\pi r$ |\n|---|---|---:|---:|---:|---:|---:|---:|\n";
  for (const Point& p : pts)
    md << "| 1/" << p.n << " | " << to_string(p.kind) << " | " << fmt("%.5g", p.max_xi) << " | "
       << fmt("%.5g", p.max_xi / p.n) << " | " << fmt("%.5g", p.max_m12) << " | " << fmt("%.6f", p.max_w) << " | "
       << fmt("%.5g", p.force) << " | " << fmt("%.5g", p.force_per_length) << " |\n";
  md << "\nTable: " << words("fig2.mesh_caption", {{"R", fmt("%g", R)}}) << "\n";
  return md.str();
}

const char* kColumns =
    "# Columns: n (h = 1/n), sampling, R (obstacle height), max_xi = max over nodes of the contact force density\n"
    "# (9) (nodal fields, see src/contact.hpp), max_m12 = max over nodes of |m12| (Kirchhoff, nu as above),\n"
    "# max_w = max over nodes of |w|, force = total contact force, force_per_length = force / (2 pi r).\n"
    "n,sampling,R,max_xi,max_m12,max_w,force,force_per_length\n";
}  // namespace

int main(int argc, char** argv) {
  plate::clean_up_on_interrupt("fig2");
  CLI::App app{"fig2: the data of the paper's Fig. 2 (max|xi|, max|m12|, max|w| at the nodes against the obstacle\n"
               "height R; f = 0) on h = 1/4 and a fine grid, both samplings; writes fig2.csv, fig2_mesh.csv, fig2_fit.md."};
  std::string reference = "reference", out = "results";
  int fine = 64, steps = 8;
  double eps = 1e-10, nu = kPoissonRatio, dR = 0.0125;
  std::vector<int> mesh = {4, 8, 16, 32, 64, 128};
  app.add_option("--reference", reference, "folder with paper_numbers.csv")->check(CLI::ExistingDirectory)->capture_default_str();
  app.add_option("--out", out, "folder for the outputs")->capture_default_str();
  app.add_option("--fine", fine, "the fine grid of the second panel, n (h = 1/n)")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--steps", steps, "number of heights R = dR, 2 dR, ...")->check(CLI::Range(2, 100))->capture_default_str();
  app.add_option("--dR", dR, "height step")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--eps", eps, "the penalty parameter of every run (exact discrete w_eps)")->check(CLI::Range(1e-14, 1e-3))->capture_default_str();
  app.add_option("--nu", nu, "Poisson ratio in m12 = -(1 - nu) w12")->check(CLI::Range(0.0, 0.5))->capture_default_str();
  app.add_option("--mesh", mesh, "grids n of the mesh study at the paper's R")->delimiter(',')->check(CLI::PositiveNumber)->capture_default_str();
  app.footer(kExitStatusHelp);
  if (const int status = parse_options(app, argc, argv, "fig2"); status >= 0) return status;

  try {
    const auto pub = read_paper_numbers(reference + "/paper_numbers.csv");
    const int n_paper = paper_cells();
    std::vector<Point> sweep, study;
    std::ostringstream fit;
    fit << "<!-- Written by build/fig2 (make results); do not edit. -->\n\n"
        << "| grid | sampling | quantity | slope $d/dR$ | largest residual / max |\n|---|---|---|---:|---:|\n";
    for (int n : {n_paper, fine})
      for (SamplingKind kind : {SamplingKind::Nodes, SamplingKind::Gauss}) {
        std::cerr << "fig2: h = 1/" << n << ", " << to_string(kind) << " sampling\n";
        std::vector<Point> line;
        for (int k = 1; k <= steps; ++k) line.push_back(measure(n, kind, k * dR, eps, nu, pub));
        const std::pair<const char*, double Point::*> quantities[] = {
            {"$\\max\\xi$", &Point::max_xi}, {"$\\max\\lvert m_{12}\\rvert$", &Point::max_m12}, {"$\\max w$", &Point::max_w}, {"total force", &Point::force}};
        for (const auto& [name, q] : quantities) {
          const auto [slope, res] = fit_through_origin(line, q);
          fit << "| h = 1/" << n << " | " << to_string(kind) << " | " << name << " | " << fmt("%.6g", slope) << " | "
              << fmt_above(res, kRoundOff, 2) << " |\n";
        }
        sweep.insert(sweep.end(), line.begin(), line.end());
      }
    const double R_paper = published(pub, "obstacle_height");
    for (int n : mesh) {
      std::cerr << "fig2: mesh study, h = 1/" << n << "\n";
      for (SamplingKind kind : {SamplingKind::Nodes, SamplingKind::Gauss}) study.push_back(measure(n, kind, R_paper, eps, nu, pub));
    }
    std::filesystem::create_directories(out);
    std::ostringstream head;
    head << "# Written by build/fig2 (make results): the paper's obstacle (disk of radius 0.25 at the centre) of height R,\n"
         << "# f = 0, exact discrete penalised solution at eps = " << eps << " by the nonlinear scheme (3a), nu = " << nu << ".\n";
    write_file_atomically(out + "/fig2.csv", head.str() + kColumns + csv_rows(sweep));
    write_file_atomically(out + "/fig2_mesh.csv", head.str() + kColumns + csv_rows(study));
    fit << "\nTable: " << words("fig2.fit_caption") << "\n";
    write_file_atomically(out + "/fig2_fit.md", fit.str());
    write_file_atomically(out + "/fig2_mesh.md", mesh_markdown(study, R_paper));
  } catch (const std::exception& e) {
    std::cerr << "fig2: " << e.what() << "\n";
    return kFailure;
  }
  return kSuccess;
}
