// crosscheck: writes results/crosscheck.md and .csv (and crosscheck_timings.csv): the paper's
// problem by this code and by FreeFEM (HCT on gmsh meshes), side by side, with the verdict.
// Run by `make crosscheck`; `crosscheck --help` lists the options.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "atomic_file.hpp"
#include "exit_codes.hpp"
#include "crosscheck.hpp"
#include "format.hpp"
#include "freefem.hpp"
#include "published.hpp"

using namespace plate;

namespace {
// Observed order and Richardson limit from the last three values (h halving each time), when the
// last two increments have the same sign; otherwise the sequence is not yet regular.
std::string convergence_note(const std::vector<double>& q) {
  if (q.size() < 3) return "too few grids";
  const double d1 = q[q.size() - 2] - q[q.size() - 3], d2 = q.back() - q[q.size() - 2];
  if (d1 * d2 <= 0 || std::abs(d2) >= std::abs(d1)) return "irregular (increments " + fmt("%+.2e", d1) + ", " + fmt("%+.2e", d2) + ")";
  const double p = std::log2(d1 / d2);
  return "order " + fmt("%.2f", p) + ", Richardson limit " + fmt("%.6g", q.back() + d2 / (std::pow(2.0, p) - 1));
}

struct Series {
  std::string name;
  std::vector<CheckValues> runs;
  std::vector<double> of(double CheckValues::*field) const { return values_of(runs, field); }
};

struct Quantity {
  const char* name;
  double CheckValues::*field;
};
const Quantity kQuantities[] = {{"max w", &CheckValues::max_w},
                                {"w(0.5, 0.25)", &CheckValues::w_rim},
                                {"w(0.5, 0.125)", &CheckValues::w_mid},
                                {"w(0.25, 0.25)", &CheckValues::w_diag},
                                {"total contact force", &CheckValues::force}};

// What the run needs: where the inputs are, the grids of both codes, the shared settings.
struct Setup {
  std::vector<double> lcs = {0.1, 0.05, 0.025, 0.0125};
  std::vector<int> ns = {16, 32, 64, 128};
  std::string geo = "reference/square_with_circle.geo", edp = "reference/penalty_hct.edp", reference = "reference";
  std::string work = "build/crosscheck-work", out = "results";  // not build/crosscheck: the program
  CrossSettings s;
  PaperScene scene;           // from reference/paper_numbers.csv
  double uniform_centre = 0;  // published, from reference/plate_constants.csv
};

// Every run of both codes: the paper's problem, and the clamped square under f = 1.
struct Runs {
  Series ff{"FreeFEM HCT", {}}, gauss{"BFS, Gauss sampling", {}}, nodes{"BFS, nodal sampling", {}};
  std::vector<double> ff_uniform, our_uniform;
};

Runs run_both(const Setup& u) {
  Runs r;
  const CrossSettings& s = u.s;
  std::ostringstream args;
  args.precision(17);
  args << "-R " << s.R << " -tol " << s.tol << " -eps0 " << s.eps_start << " -epsmin " << s.eps_min;
  for (double lc : u.lcs) {
    const std::string msh = u.work + "/mesh_lc" + fmt("%g", lc) + ".msh";
    gmsh_mesh(u.geo, lc, msh);
    std::cerr << "crosscheck: FreeFEM on lc = " << lc << "\n";
    r.ff.runs.push_back(freefem_values(run_freefem(u.edp, msh, args.str(), msh + ".json"), lc));
    r.ff_uniform.push_back(run_freefem(u.edp, msh, "-obstacle none -load 1", msh + ".uniform.json").at("w_centre").get<double>());
  }
  const Field phi = u.scene.obstacle(s.R);
  for (int n : u.ns) {
    std::cerr << "crosscheck: this code on n = " << n << "\n";
    r.gauss.runs.push_back(solve_ours(n, SamplingKind::Gauss, phi, s));
    r.nodes.runs.push_back(solve_ours(n, SamplingKind::Nodes, phi, s));
    r.our_uniform.push_back(uniform_load_centre_ours(n));
  }
  return r;
}

// crosscheck.csv (every run) and crosscheck_timings.csv.
void write_tables(const Setup& u, const Runs& runs) {
  const CrossSettings& s = u.s;
  const Series &ff = runs.ff, &gauss = runs.gauss, &nodes = runs.nodes;
  std::ostringstream csv, timings;
  csv << "# crosscheck: the paper's problem (f = 0, R = " << s.R << ") by two codes; made by build/crosscheck\n"
      << "# code: freefem-hct (reference/penalty_hct.edp), bfs-gauss or bfs-nodes (this code, constraint at\n"
      << "# Gauss points or at nodes); grid, h (cell side; gmsh lc for FreeFEM), unknowns, converged, iterations, final eps,\n"
      << "# max w, w(0.5,0.25) on the contact circle, w(0.5,0.125), w(0.25,0.25), total contact force\n"
      << "code,grid,h,unknowns,converged,iterations,eps_final,max_w,w_0.5_0.25,w_0.5_0.125,w_0.25_0.25,total_force\n";
  timings << "# crosscheck run times in seconds (not byte-identical between runs)\ncode,grid,seconds\n";
  for (const Series* ser : {&ff, &gauss, &nodes})
    for (const auto& r : ser->runs) {
      csv << r.code << "," << r.grid << "," << fmt("%.6g", r.h) << "," << r.unknowns << "," << (r.converged ? 1 : 0)
          << "," << r.iterations << "," << fmt("%.0e", r.eps_final) << "," << fmt("%.7g", r.max_w) << ","
          << fmt("%.7g", r.w_rim) << "," << fmt("%.7g", r.w_mid) << "," << fmt("%.7g", r.w_diag) << ","
          << fmt("%.6g", r.force) << "\n";
      timings << r.code << "," << r.grid << "," << fmt("%.3g", r.seconds) << "\n";
    }
  write_file_atomically(u.out + "/crosscheck.csv", csv.str());
  write_file_atomically(u.out + "/crosscheck_timings.csv", timings.str());
}

// The report's opening: the problem, the two codes, and every run.
void describe(std::ostream& md, const Setup& u, const Runs& runs) {
  const CrossSettings& s = u.s;
  const Series &ff = runs.ff, &gauss = runs.gauss, &nodes = runs.nodes;
  md << "# Cross-code check: this code against FreeFEM\n\n"
     << "Made by `make crosscheck` (`build/crosscheck`); numbers in `crosscheck.csv`, run times in "
        "`crosscheck_timings.csv`.\n\n"
     << "The paper's problem (unit square, f = 0, obstacle R = " << s.R
     << " on the closed disk of radius 0.25 at the centre) solved by two independent codes:\n\n"
     << "* **this code**: Bogner-Fox-Schmit bicubics on n x n squares, constraint sampled at Gauss points or at "
        "the nodes;\n"
     << "* **FreeFEM** (`reference/penalty_hct.edp`): HCT (Hsieh-Clough-Tocher) C^1 triangles on gmsh meshes "
        "of `reference/square_with_circle.geo`, whose edges follow the contact circle; its own assembly, "
        "quadrature (`tripleQF(qf5pT)`) and sparse solver.\n\n"
     << "Both run the nonlinear scheme (3a) with eps_s = " << s.eps_start << " * 10^-s until successive steps and "
     << "successive eps levels differ by at most " << s.tol << " at the nodes (down to eps = " << s.eps_min
     << " at most), so the penalty error is far below the discretisation error. Starting guess w = 0.\n\n";
  md << "| code | grid | unknowns | iterations | final eps | max w | w(0.5, 0.25) | w(0.5, 0.125) | w(0.25, 0.25) | "
        "total contact force |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Series* ser : {&ff, &gauss, &nodes})
    for (const auto& r : ser->runs)
      md << "| " << ser->name << (r.converged ? "" : " (NOT CONVERGED)") << " | " << r.grid << " | " << r.unknowns
         << " | " << r.iterations << " | " << fmt("%.0e", r.eps_final) << " | " << fmt("%.6f", r.max_w) << " | "
         << fmt("%.6f", r.w_rim) << " | " << fmt("%.6f", r.w_mid) << " | " << fmt("%.6f", r.w_diag) << " | "
         << fmt("%.4f", r.force) << " |\n";
}

void convergence(std::ostream& md, const Runs& runs) {
  const Series &ff = runs.ff, &gauss = runs.gauss, &nodes = runs.nodes;
  md << "\n## Convergence of each code\n\nFrom the last three grids of each code (h halving): observed order and "
        "Richardson limit where the last two increments have one sign and shrink; otherwise the sequence is "
        "called irregular (the contact circle cuts each grid differently, so the geometric error does not "
        "decrease smoothly).\n\n| quantity | FreeFEM HCT | BFS, Gauss sampling | BFS, nodal sampling |\n|---|---|---|---|\n";
  for (const auto& q : kQuantities)
    md << "| " << q.name << " | " << convergence_note(ff.of(q.field)) << " | " << convergence_note(gauss.of(q.field))
       << " | " << convergence_note(nodes.of(q.field)) << " |\n";
}

// The verdict: true if every run converged and the codes agree on every quantity.
bool verdict(std::ostream& md, const Runs& runs) {
  const Series &ff = runs.ff, &gauss = runs.gauss, &nodes = runs.nodes;
  bool all_agree = true, all_converged = true;
  for (const Series* ser : {&ff, &gauss, &nodes})
    for (const auto& r : ser->runs) all_converged = all_converged && r.converged;
  md << "\n## Verdict\n\nIf a sequence of grid values converges at least linearly, with a factor of 1/2 or less "
        "per halving of h, the error of its finest value is at most its last increment. The sequences here "
        "are irregular (above), so we bound each code's error by the larger of its last two increments, "
        "which allows one irregular step. The two codes agree if their finest values differ by at most the "
        "sum of these two bounds: that sum is the tolerance below, set by the discretisation errors, not "
        "chosen.\n\n"
        "| quantity | FreeFEM (finest) | BFS (finest) | sampling | difference | tolerance | agree |\n"
        "|---|---|---|---|---|---|---|\n";
  for (const auto& q : kQuantities)
    for (const Series* ours : {&gauss, &nodes}) {
      double diff, tol;
      const bool ok = agree(ff.of(q.field), ours->of(q.field), &diff, &tol);
      all_agree = all_agree && ok;
      md << "| " << q.name << " | " << fmt("%.6g", ff.runs.back().*q.field) << " | "
         << fmt("%.6g", ours->runs.back().*q.field) << " | " << (ours == &gauss ? "Gauss" : "nodes") << " | "
         << fmt("%.2e", diff) << " | " << fmt("%.2e", tol) << " | " << (ok ? "yes" : "**NO**") << " |\n";
    }
  md << "\n**" << (all_agree && all_converged ? "The two codes agree" : "The codes DO NOT agree")
     << "** on every quantity within the tolerance their own convergence justifies"
     << (all_converged ? "." : "; some runs did not converge.") << "\n";

  return all_agree && all_converged;
}

// Both codes against the published centre deflection of the clamped square under f = 1.
bool uniform_load(std::ostream& md, const Setup& u, const Runs& runs) {
  const double published = u.uniform_centre;
  const Series &ff = runs.ff, &gauss = runs.gauss;
  const std::vector<double>&ff_uniform = runs.ff_uniform, &our_uniform = runs.our_uniform;
  md << "\n## The clamped square under uniform load\n\nCentre deflection for f = 1, against the classical "
     << published << " (Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells, Table 35).\n\n"
        "| code | grid | w(0.5, 0.5) | minus published |\n|---|---|---|---|\n";
  for (size_t i = 0; i < u.lcs.size(); ++i)
    md << "| FreeFEM HCT | " << ff.runs[i].grid << " | " << fmt("%.8f", ff_uniform[i]) << " | "
       << fmt("%+.1e", ff_uniform[i] - published) << " |\n";
  for (size_t i = 0; i < u.ns.size(); ++i)
    md << "| BFS | " << gauss.runs[i].grid << " | " << fmt("%.8f", our_uniform[i]) << " | "
       << fmt("%+.1e", our_uniform[i] - published) << " |\n";
  const bool uniform_ok = std::abs(ff_uniform.back() - published) <= error_bound(ff_uniform) + 5e-9 &&
                          std::abs(our_uniform.back() - published) <= error_bound(our_uniform) + 5e-9;
  md << "\nBoth finest values are within their error bound (the larger of the last two increments, plus the published value's rounding, 5e-9) of "
     << published << ": " << (uniform_ok ? "yes" : "**NO**") << ".\n";

  return uniform_ok;
}
}  // namespace

int main(int argc, char** argv) {
  plate::clean_up_on_interrupt("crosscheck");
  CLI::App app{"crosscheck: the paper's problem (f = 0, R = 0.0625 on the disk of radius 0.25) by this code\n"
               "and by FreeFEM (HCT elements, gmsh meshes following the contact circle); writes the report."};
  Setup u;
  app.add_option("--lc", u.lcs, "gmsh mesh sizes, coarse to fine, halving")->delimiter(',')->capture_default_str();
  app.add_option("--n", u.ns, "our grids n x n, coarse to fine, doubling")->delimiter(',')->capture_default_str();
  app.add_option("--geo", u.geo, "gmsh geometry")->check(CLI::ExistingFile)->capture_default_str();
  app.add_option("--edp", u.edp, "FreeFEM script")->check(CLI::ExistingFile)->capture_default_str();
  app.add_option("--reference", u.reference, "folder with paper_numbers.csv and plate_constants.csv")
      ->check(CLI::ExistingDirectory)->capture_default_str();
  app.add_option("--work", u.work, "folder for meshes and FreeFEM outputs")->capture_default_str();
  app.add_option("--out", u.out, "folder for the report")->capture_default_str();
  app.add_option("--tol", u.s.tol, "tolerance of both codes' stopping rules")->capture_default_str();
  app.add_option("--eps-min", u.s.eps_min, "smallest eps of both continuations")->capture_default_str();
  app.footer(kExitStatusHelp);
  if (const int status = parse_options(app, argc, argv, "crosscheck"); status >= 0) return status;
  if (u.lcs.size() < 2 || u.ns.size() < 2) {
    std::cerr << "crosscheck: bad input: need at least two --lc and two --n values\n";
    return kBadInput;
  }
  try {
    std::filesystem::create_directories(u.work);
    std::filesystem::create_directories(u.out);
    u.scene = read_paper_scene(u.reference);
    u.s.R = u.scene.height;
    u.uniform_centre = plate_constant(u.reference, "uniform_centre");
    const Runs runs = run_both(u);
    write_tables(u, runs);
    std::ostringstream md;
    describe(md, u, runs);
    convergence(md, runs);
    const bool agreed = verdict(md, runs);
    const bool uniform_ok = uniform_load(md, u, runs);
    write_file_atomically(u.out + "/crosscheck.md", md.str());
    std::cerr << "crosscheck: wrote " << u.out << "/crosscheck.md: " << (agreed && uniform_ok ? "agree" : "DISAGREE") << "\n";
    return agreed && uniform_ok ? kSuccess : kNotConverged;
  } catch (const std::exception& e) {
    std::cerr << "crosscheck: error: " << e.what() << "\n";
    return kFailure;
  }
}
