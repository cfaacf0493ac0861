// plate: solves one case of the clamped plate over a rigid obstacle and writes its fields and summary.
// Run `plate --help`. The defaults are the paper's problem (unit square, h = 1/4, f = 0, the
// cylinder of height R = 0.0625 and radius 0.25 at the centre), solved exactly with the constraint
// on the cylinder's rim and at the nodes inside it: the answer comes with a certificate.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "atomic_file.hpp"
#include "contraction.hpp"
#include "dual_active_set.hpp"
#include "fields.hpp"
#include "format.hpp"
#include "stopwatch.hpp"
#include "summary.hpp"

namespace {

// Exit codes beyond CLI11's own (which it uses for options it cannot parse).
constexpr int kBadInput = 2, kNotConverged = 3, kFailure = 4;

const CLI::Validator kFinitePositive(
    [](std::string& s) {
      const double v = std::strtod(s.c_str(), nullptr);
      return (std::isfinite(v) && v > 0) ? std::string() : "must be a finite number > 0, got " + s;
    },
    "FINITE > 0");
const CLI::Validator kCellCount(
    [](std::string& s) {
      char* end = nullptr;
      const long v = std::strtol(s.c_str(), &end, 10);
      if (end == s.c_str() || *end != '\0') return "must be a whole number, got " + s;
      return (v >= 1 && v <= (1 << 14)) ? std::string() : "must be between 1 and 16384, got " + s;
    },
    "INT in [1, 16384]");
const CLI::Validator kIterationCap(
    [](std::string& s) {
      char* end = nullptr;
      const double v = std::strtod(s.c_str(), &end);  // "1e9" is a whole number too
      if (end == s.c_str() || *end != '\0' || v != std::floor(v)) return "must be a whole number, got " + s;
      if (!(v >= 1 && v <= 1e9)) return "must be between 1 and 1e9, got " + s;
      s = std::to_string(static_cast<long>(v));
      return std::string();
    },
    "INT in [1, 1e9]");
const CLI::Validator kFinite(
    [](std::string& s) {
      const double v = std::strtod(s.c_str(), nullptr);
      return std::isfinite(v) ? std::string() : "must be a finite number, got " + s;
    },
    "FINITE");

std::pair<double, double> parse_pair(const std::string& option, const std::string& text) {
  std::istringstream in(text);
  double x, y;
  char comma;
  if (!(in >> x >> comma >> y) || comma != ',' || !(in >> std::ws).eof() || !std::isfinite(x) || !std::isfinite(y))
    throw std::invalid_argument(option + " must be two finite numbers 'x,y', got '" + text + "'");
  return {x, y};
}


// Refuses grids with nothing to solve and grids that cannot fit (make_grid already refuses counts
// beyond an int): the memory estimate is the exact solver's measured peak per unknown (results/speed_vs_error.md:
// about 3.5 KiB at n = 1024) against this machine's physical memory.
void check_grid_size(const plate::Grid& g) {
  const long long nodes = static_cast<long long>(g.nx - 1) * (g.ny - 1), unknowns = 4 * nodes;
  if (nodes <= 0)
    throw std::invalid_argument("--cells: the grid " + std::to_string(g.nx) + " x " + std::to_string(g.ny) +
                                " has no interior node, so the clamped plate is w = 0 and there is nothing to solve "
                                "(use at least 2 cells across each side)");
  const double need = unknowns * 3.5 * 1024, have = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGE_SIZE);
  if (have > 0 && need > have)
    throw std::invalid_argument("--cells: " + std::to_string(unknowns) + " unknowns need about " +
                                plate::fmt("%.3g", need / (1 << 30)) + " GiB, more than this machine's " +
                                plate::fmt("%.3g", have / (1 << 30)) + " GiB");
}

// Every output path is checked before the solve, so a bad one fails at once and leaves nothing.
void check_outputs(const std::vector<std::string>& paths) {
  std::vector<std::string> targets;
  for (const auto& p : paths) {
    if (p.empty()) continue;
    plate::check_writable(p);
    const std::string t = std::filesystem::weakly_canonical(plate::output_target(p)).string();
    if (std::find(targets.begin(), targets.end(), t) != targets.end())
      throw std::invalid_argument("--json, --csv and --line-csv must name different files, but two name " + p);
    targets.push_back(t);
  }
}

// The size of the answer (answer_scale), with the free plate solved only when there is a load.
double answer_scale(const plate::Problem& p) {
  plate::VectorXd w_free = plate::VectorXd::Zero(p.grid.unknowns());
  if (p.F.lpNorm<Eigen::Infinity>() > 0) {
    plate::Cholesky chol;
    chol.factorize(p.K);
    w_free = chol.solve(p.F);
  }
  const double s = plate::answer_scale(p, w_free);
  return s > 0 ? s : p.grid.lx();  // no obstacle and no load: w = 0; any length will do
}

}  // namespace

int main(int argc, char** argv) {
  plate::clean_up_on_interrupt("plate");
  using namespace plate;
  CLI::App app{
      "plate: a clamped elastic plate over a rigid obstacle (V. A. Kovtunenko, 1994).\n"
      "Finds w with Lap^2 w = f + xi, w >= phi, xi >= 0, xi (w - phi) = 0 on [0,lx] x [0,ly],\n"
      "w = dw/dn = 0 on the boundary, by the penalty problem (2): Lap^2 w + eps^-1 min(w - phi, 0) = f,\n"
      "with Bogner-Fox-Schmit elements (8), w >= phi imposed at sample points (--sampling).\n"
      "Default: --scheme exact --sampling edge. The constraint is imposed with no eps at points on the\n"
      "obstacle's edge (the cylinder's rim, where the paper's plate touches) and at the nodes inside it, and\n"
      "the answer is certified (violation, multiplier signs, complementarity, backward error <= tol). We\n"
      "chose this default because it is the one that answers for every n: the paper's penalty schemes stop on\n"
      "step sizes that do not bound the error, and nodes or Gauss points alone miss the contact circle, so\n"
      "they converge slowly and irregularly as h -> 0. The penalty problem (2), Lap^2 w + eps^-1 min(w - phi, 0)\n"
      "= f, is solved by the nonlinear scheme (3a) or the linear scheme (5a) with eps_s = eps-start * 10^-s\n"
      "until successive eps levels agree within tol, from w = 0 (--sampling gauss reproduces the paper).\n"
      "Exit status: 0 converged, 2 bad input, 3 not converged (outputs are still written), 4 other failure."};
  app.get_formatter()->column_width(34);

  int n = 4;
  double lx = 1.0, ly = 1.0;
  std::string obstacle = "cylinder", load = "0", scheme = "exact", sampling = "edge", edge = "auto";
  double R = 0.0625, radius = 0.25, nu = 0.3;
  std::string centre = "0.5,0.5";
  SolveOptions opt;
  double eps_fixed = 0;
  std::vector<std::string> points;
  std::string csv_path, json_path, line_csv_path;
  bool rate = false, quiet = false;

  app.add_option("-n,--cells", n, "cells along x; the mesh size is h = lx / n")
      ->check(kCellCount)
      ->capture_default_str();
  app.add_option("--lx", lx, "width of the rectangle")->check(kFinitePositive)->capture_default_str();
  app.add_option("--ly", ly, "height of the rectangle (a whole number of cells)")
      ->check(kFinitePositive)
      ->capture_default_str();
  app.add_option("--obstacle", obstacle,
                 "'cylinder' (height R on the disk of --radius around --centre, no constraint outside) "
                 "or an expression in x, y (muparser; 'inf' is infinity: -inf means no constraint)")
      ->capture_default_str();
  app.add_option("-R,--obstacle-height", R, "height R of the cylinder")->check(kFinite)->capture_default_str();
  app.add_option("--radius", radius, "radius of the cylinder")->check(kFinitePositive)->capture_default_str();
  app.add_option("--centre", centre, "centre of the cylinder, 'x,y'")->capture_default_str();
  app.add_option("--load", load, "load f(x, y): a number or an expression in x, y")->capture_default_str();
  app.add_option("--scheme", scheme,
                     "exact: no penalty, the constraint held exactly (primal-dual active sets for nodes, a dual "
                     "active-set method for any other sampling), certified; nonlinear: penalty scheme (3a), "
                     "refactorised when the contact set changes; linear: penalty scheme (5a), one factorisation per "
                     "eps, slow at small eps (its answers often fail the error bound)")
          ->check(CLI::IsMember({"linear", "nonlinear", "exact"}))
          ->capture_default_str();
  app.add_option("--sampling", sampling,
                 "where w >= phi is imposed: edge (points on the obstacle's edge, weighted by arc length, and the "
                 "grid nodes), edge-gauss (edge points and Gauss points), gauss (4x4 Gauss points per element, (8) "
                 "as printed), nodes (grid nodes, weight h^2)")
      ->check(CLI::IsMember({"edge", "edge-gauss", "gauss", "nodes"}))
      ->capture_default_str();
  app.add_option("--edge", edge,
                 "the obstacle's edge for edge sampling: auto (the cylinder's rim; none for an expression), none "
                 "(interior samples alone), circle:cx,cy,r, or polygon:x1,y1;x2,y2;... (about one point per h)")
      ->capture_default_str();
  auto* eps_opt = app.add_option("--eps", eps_fixed, "solve at this eps only (no continuation); every eps is in units of lx^4, so it means the same in any unit of length")->check(kFinitePositive);
  auto* eps_start_opt = app.add_option("--eps-start", opt.eps_start, "first eps of the continuation")
      ->check(kFinitePositive)
      ->capture_default_str()
      ->excludes(eps_opt);
  auto* eps_min_opt = app.add_option("--eps-min", opt.eps_min, "smallest eps tried before the continuation is declared failed")
      ->check(kFinitePositive)
      ->capture_default_str()
      ->excludes(eps_opt);
  auto* tol_opt = app.add_option("--tol", opt.tol,
                 "OS, relative to the size of the answer (max |phi| at the samples, or the free plate's max |w| if larger): "
                 "stop when steps, and successive eps levels, are within tol times that size (max over nodes); "
                 "with --scheme exact the bound on every relative certificate entry (default there 1e-10)")
      ->check(kFinitePositive)
      ->capture_default_str();
  app.add_option("--max-iter", opt.max_iter, "iteration cap per eps level; reaching it is a failure")
      ->check(kIterationCap)
      ->capture_default_str();
  app.add_option("--nu", nu, "Poisson's ratio for the bending moments")
      ->check(kFinite & CLI::Range(-1.0, 0.5))
      ->capture_default_str();
  app.add_option("--point", points, "report w at 'x,y' (repeatable)");
  app.add_option("--csv", csv_path, "write the nodal fields (CSV) here");
  app.add_option("--json", json_path, "write the summary (JSON) here");
  app.add_option("--line-csv", line_csv_path, "write the line load q(theta) at the edge points (CSV) here");
  bool no_globalise = false, no_nested = false;
  app.add_flag("--no-globalise", no_globalise,
               "exact scheme: end with an error if the active set repeats, instead of the monotone fallback");
  app.add_flag("--no-nested", no_nested, "exact scheme: start from an empty active set, not from the coarser grid");
  app.add_flag("--rate", rate, "also compute lambda_1h and the linear scheme's contraction factors");
  app.add_flag("-q,--quiet", quiet, "print nothing but errors");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // CLI11 has its own exit codes; every bad input exits with the one documented in --help.
    std::cerr << "plate: bad input: " << e.what() << "\n";
    return kBadInput;
  }

  const auto t0 = plate::Clock::now();
  try {
    const Grid g = make_grid(n, lx, ly);
    check_grid_size(g);
    check_outputs({json_path, csv_path, line_csv_path});
    Field phi;
    SamplingSpec spec{sampling_kind(sampling), {}};
    if (obstacle == "cylinder") {
      const auto [cx, cy] = parse_pair("--centre", centre);
      phi = cylinder(cx, cy, radius, R);
      if (edge == "auto") spec.edge = circle_edge(cx, cy, radius);
    } else {
      phi = expression("--obstacle", obstacle);
    }
    if (edge != "auto") spec.edge = parse_edge(edge);
    if (!line_csv_path.empty() && !has_edge(spec.kind))
      throw std::invalid_argument("--line-csv needs edge sampling (--sampling edge or edge-gauss)");
    const Field f = expression("--load", load);
    const bool exact = scheme == "exact";
    opt.scheme = scheme == "linear" ? Scheme::Linear : Scheme::Nonlinear;
    if (exact) {
      for (const auto* o : {eps_opt, eps_start_opt, eps_min_opt})
        if (o->count()) throw std::invalid_argument(o->get_name() + " has no meaning for --scheme exact (there is no eps)");
      if (rate) throw std::invalid_argument("--rate describes the linear scheme's contraction: it needs a penalty scheme");
    } else if (no_globalise || no_nested) {
      throw std::invalid_argument("--no-globalise and --no-nested apply to --scheme exact only");
    }
    ExactOptions exact_opt;
    exact_opt.tol = tol_opt->count() ? opt.tol : exact_opt.tol;
    exact_opt.max_iter = app.get_option("--max-iter")->count() ? opt.max_iter : exact_opt.max_iter;
    exact_opt.globalise = !no_globalise;
    exact_opt.nested = !no_nested;
    if (exact) validate(exact_opt);
    if (*eps_opt) {
      opt.eps_start = eps_fixed;
      opt.continuation = false;
    }
    validate(opt);
    Report report;
    for (const auto& p : points) report.points.push_back(parse_pair("--point", p));
    for (const auto& [x, y] : report.points)
      if (x < 0 || x > g.lx() || y < 0 || y > g.ly())
        throw std::invalid_argument("--point " + std::to_string(x) + "," + std::to_string(y) +
                                    " is outside the plate");
    // Echo the effective value of every option, given or default, so a run can be reproduced from its output.
    for (const auto* o : app.get_options()) {
      if (o->get_name() == "--help") continue;
      std::string value = o->count() ? CLI::detail::join(o->reduced_results(), " ") : o->get_default_str();
      if (value.empty()) value = "(none)";
      if (o->get_expected_max() == 0) value = o->count() ? "true" : "false";  // a flag
      if (exact && o == tol_opt) value = plate::fmt("%g", exact_opt.tol);
      if (exact && o->get_name() == "--max-iter") value = std::to_string(exact_opt.max_iter);
      report.config.emplace_back(o->get_name(), value);
    }

    if (!quiet) {
      std::cout << "plate: " << g.nx << " x " << g.ny << " cells, h = " << g.h << ", " << g.unknowns()
                << " unknowns\n";
      for (const auto& [k, v] : report.config) std::cout << "  " << k << " = " << v << "\n";
    }
    const Problem problem = make_problem(g, spec, phi, f);
    report.seconds_assemble = seconds_since(t0);
    // Scale-free penalty: eps in units of L^4 (the stiffness K ~ L^-2 against eps^-1 M ~ L^2 / eps),
    // OS relative to the size of the answer. On the unit square eps is unchanged.
    const double L4 = std::pow(g.lx(), 4), scale = exact ? 1.0 : answer_scale(problem);
    opt.eps_start *= L4;
    opt.eps_min *= L4;
    opt.eps_unit = L4;
    report.eps_unit = L4;
    opt.tol *= scale;

    SolveResult result;
    ExactResult exact_result;
    VectorXd xi;
    if (exact) {
      exact_result = solve_exact(problem, phi, f, exact_opt);
      result.w = exact_result.w;
      result.converged = exact_result.converged;
      result.message = exact_result.message;
      for (const auto& l : exact_result.levels) result.seconds_iterate += l.seconds;
      xi = exact_result.lambda;
      report.certificate = &exact_result.certificate;
      report.certificate_tol = exact_opt.tol;
    } else {
      result = solve(problem, opt);
      xi = contact_force_density(problem, result.w, result.eps);
      const double below = (problem.phi - problem.sampling.S * result.w).cwiseMax(0.0).maxCoeff();
      if (result.converged && below > opt.tol) {  // the penalty lets the plate into the obstacle by about eps xi
        result.converged = false;
        result.message = plate::fmt("the plate lies %.3g below the obstacle at a sample point", below) +
                         plate::fmt(", more than tol = %.3g (the penalty's own error at eps = ", opt.tol) +
                         plate::fmt("%g); use a smaller --eps-min or --scheme exact", result.eps / L4);
      }
      report.config.emplace_back("tol (absolute: --tol times the answer's size)", plate::fmt("%.6g", opt.tol));
      report.config.emplace_back("eps unit (lx^4)", plate::fmt("%.6g", L4));
    }
    const NodalFields nodes = nodal_fields(problem, result.w, phi, xi, nu);
    report.xi = xi;
    report.line = line_force(problem, xi);
    if (rate) report.lambda1h = smallest_eigenpair(problem.K, problem.M).lambda;
    report.problem = &problem;
    report.result = &result;
    report.nodes = &nodes;
    report.seconds_total = seconds_since(t0);

    // A run that is not an answer says so in every output, so a file read later cannot be mistaken for one.
    const std::string warning = result.converged ? "" : "# NOT CONVERGED: " + result.message + "\n";
    if (!csv_path.empty()) write_file_atomically(csv_path, warning + nodal_csv(nodes));
    if (!json_path.empty()) write_file_atomically(json_path, summary_json(report));
    if (!line_csv_path.empty()) write_file_atomically(line_csv_path, warning + line_force_csv(problem, report.line));
    if (!quiet) std::cout << summary_text(report);
    if (!result.converged) {
      std::cerr << "plate: error: " << result.message << "\n";
      return kNotConverged;
    }
    return 0;
  } catch (const std::invalid_argument& e) {
    std::cerr << "plate: bad input: " << e.what() << "\n";
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "plate: error: " << e.what() << "\n";
    return kFailure;
  }
}
