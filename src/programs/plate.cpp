// plate: solves one case of the clamped plate over a rigid obstacle and writes its fields and summary.
// Run `plate --help`. The defaults are the paper's problem (unit square, h = 1/4, f = 0, the
// cylinder of height R = 0.0625 and radius 0.25 at the centre), solved exactly with the constraint
// on the cylinder's rim and at the nodes inside it: the answer comes with a certificate.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>

#include "active_set.hpp"
#include "atomic_file.hpp"
#include "contraction.hpp"
#include "error_bar.hpp"
#include "exit_codes.hpp"
#include "extrema.hpp"
#include "fields.hpp"
#include "format.hpp"
#include "mirror.hpp"
#include "norms.hpp"
#include "paper_numbers.hpp"
#include "progress.hpp"
#include "rim_exchange.hpp"
#include "rim_report.hpp"
#include "run_as_measured.hpp"
#include "stopwatch.hpp"
#include "summary.hpp"

namespace {

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

// Refuses grids with nothing to solve.
void check_grid_size(const plate::Grid& g) {
  const long long nodes = static_cast<long long>(g.nx - 1) * (g.ny - 1);
  if (nodes <= 0)
    throw std::invalid_argument("--cells: the grid " + std::to_string(g.nx) + " x " + std::to_string(g.ny) +
                                " has no interior node, so the clamped plate is w = 0 and there is nothing to solve "
                                "(use at least 2 cells across each side)");
}

// Refuses a model that cannot fit (make_grid already refuses counts beyond an int): the estimate is
// the exact solver's measured peak per unknown (results/large/speed_vs_error.md: 15 024 MiB for
// 4 186 116 unknowns at n = 1024, 3.7 KiB each) times the unknowns of the grid actually solved, the
// part of the plate its mirror lines leave, against this machine's physical memory.
void check_memory(const plate::Grid& solved) {
  const double unknowns = solved.unknowns();
  const double need = unknowns * 3.7 * 1024, have = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGE_SIZE);
  if (have > 0 && need > have)
    throw std::invalid_argument("--cells: the " + std::string(solved.is_part() ? "part of the plate solved" : "plate") + " has " +
                                plate::fmt("%.0f", unknowns) + " unknowns, which need about " +
                                plate::fmt("%.3g", need / (1 << 30)) + " GiB, more than this machine's " +
                                plate::fmt("%.3g", have / (1 << 30)) + " GiB");
}

// Every output path given is checked before the solve (a file is created in its folder and removed),
// so a bad one fails at once and leaves nothing.
void check_outputs(const std::vector<std::pair<const CLI::Option*, std::string>>& outputs) {
  std::vector<std::string> targets;
  for (const auto& [opt, p] : outputs) {
    if (!opt->count()) continue;
    plate::check_output_file(opt->get_name(), p);
    const std::string t = std::filesystem::weakly_canonical(p).string();
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


// Every option, as given or by default; the handles of those whose presence changes the run.
// The defaults are the paper's problem, as reference/paper_numbers.csv states it (paper_numbers.hpp).
struct Options {
  int n = static_cast<int>(plate::paper::kSide / plate::paper::kH + 0.5);
  double lx = plate::paper::kSide, ly = plate::paper::kSide;
  std::string obstacle = "cylinder", load = plate::fmt("%.17g", plate::paper::kLoad), scheme = "exact", sampling = "edge", edge = "auto", edge_rows = "auto",
              symmetry = "auto", estimate = "auto", enrich = "auto";
  double R = plate::paper::kObstacleHeight, radius = plate::paper::kObstacleRadius, nu = plate::kPoissonRatio;
  std::string centre = plate::fmt("%.17g", plate::paper::kObstacleCx) + "," + plate::fmt("%.17g", plate::paper::kObstacleCy);
  plate::SolveOptions opt;
  double eps_fixed = 0;
  std::vector<std::string> points;
  std::string csv_path, json_path, line_csv_path;
  bool rate = false, quiet = false, no_globalise = false, no_nested = false;
  CLI::Option *eps_opt = nullptr, *tol_opt = nullptr, *max_iter_opt = nullptr, *csv_opt = nullptr, *json_opt = nullptr,
              *line_csv_opt = nullptr;
  CLI::Option_group *grid = nullptr, *exact = nullptr, *penalty = nullptr;
};

// The options in groups by what they belong to, so that a scheme refuses by name the options of the
// groups it has no use for (refuse_group below), and --help lists them so.
void add_exact_options(CLI::App& app, Options& o) {
  o.exact = app.add_option_group("The exact scheme", "--scheme exact");
  o.exact->add_option("--symmetry", o.symmetry,
                      "auto (solve on the half or quarter of the plate that the scene's mirror lines x = lx/2, y = ly/2 "
                      "leave, found by checking phi and f at every sample against its mirror image; the outputs are the "
                      "whole plate's) or none (always the whole plate)")
      ->check(CLI::IsMember({"auto", "none"}))
      ->capture_default_str();
  o.exact->add_option("--estimate", o.estimate,
                      "auto (an error bar on each answer's distance from the plate's own, from the grids n/8, n/4, n/2 "
                      "that grid sequencing solves anyway (D29): Richardson where the observed order is steady, else the "
                      "last differences, marked NOT STEADY) or off")
      ->check(CLI::IsMember({"auto", "off"}))
      ->capture_default_str();
  o.exact->add_option("--enrich", o.enrich,
                      "auto (on a circle with edge sampling, the space widened by functions that carry the kink of the "
                      "line load at the rim (D31), on every grid of the sequence where the circle is at least 2 cells "
                      "in radius and " + plate::fmt("%g", plate::kKinkZeroCells + 1.5) + " cells from the clamped edges; "
                      "the plain space elsewhere, and the error bars from the grids that carry it; on a convex polygon, "
                      "the same across each side (D33) and a function for the point load at each corner (D34), where "
                      "every side is at least 2 cells long and they clear the clamped edges), ring or sides (the "
                      "same for a circle or a polygon, and an error where it does not fit the grid asked for) or none "
                      "(the plain space)")
      ->check(CLI::IsMember({"auto", "ring", "sides", "none"}))
      ->capture_default_str();
  o.exact->add_flag("--no-globalise", o.no_globalise, "end with an error if the active set repeats, instead of the monotone fallback");
  o.exact->add_flag("--no-nested", o.no_nested, "start from an empty active set, not from the coarser grid");
}

void add_options(CLI::App& app, Options& o) {
  app.get_formatter()->column_width(34);
  app.add_option("--scheme", o.scheme,
                 "exact: no penalty, the constraint held exactly (primal-dual active sets for nodes, a dual "
                 "active-set method for any other sampling), certified; nonlinear: penalty scheme (3a), "
                 "refactorised when the contact set changes; linear: penalty scheme (5a), one factorisation per "
                 "eps, slow at small eps (its answers often fail the error bound); semi-analytic: no grid, the "
                 "cylinder's scene only: a line load on the rim in a Fourier series and biharmonic series fitted "
                 "to the clamped edge (about 13 digits in max w; exit 3 if the contact is not the whole rim)")
      ->check(CLI::IsMember({"linear", "nonlinear", "exact", "semi-analytic"}))
      ->capture_default_str();

  CLI::Option_group* scene = app.add_option_group("The scene", "what is solved, whatever the scheme");
  scene->add_option("--lx", o.lx, "width of the rectangle")->check(kFinitePositive)->capture_default_str();
  scene->add_option("--ly", o.ly, "height of the rectangle (a whole number of cells)")->check(kFinitePositive)->capture_default_str();
  scene->add_option("--obstacle", o.obstacle,
                    "'cylinder' (height R on the disk of --radius around --centre, no constraint outside) "
                    "or an expression in x, y (muparser; 'inf' is infinity: -inf means no constraint)")
      ->capture_default_str();
  scene->add_option("-R,--obstacle-height", o.R, "height R of the cylinder")->check(kFinite)->capture_default_str();
  scene->add_option("--radius", o.radius, "radius of the cylinder")->check(kFinitePositive)->capture_default_str();
  scene->add_option("--centre", o.centre, "centre of the cylinder, 'x,y'")->capture_default_str();
  scene->add_option("--load", o.load, "load f(x, y): a number or an expression in x, y")->capture_default_str();

  o.grid = app.add_option_group("The grid and its rows", "schemes exact, nonlinear and linear");
  o.grid->add_option("-n,--cells", o.n, "cells along x; the mesh size is h = lx / n")->check(kCellCount)->capture_default_str();
  o.grid->add_option("--sampling", o.sampling,
                     "where w >= phi is imposed: edge (points on the obstacle's edge, weighted by arc length, and the "
                     "grid nodes), edge-gauss (edge points and Gauss points), gauss (4x4 Gauss points per element, (8) "
                     "as printed), nodes (grid nodes, weight h^2)")
      ->check(CLI::IsMember({"edge", "edge-gauss", "gauss", "nodes"}))
      ->capture_default_str();
  o.grid->add_option("--edge", o.edge,
                     "the obstacle's edge for edge sampling: auto (the cylinder's rim; none for an expression), none "
                     "(interior samples alone), circle:cx,cy,r, or polygon:x1,y1;x2,y2;... (about one point per h)")
      ->capture_default_str();
  o.grid->add_option("--edge-rows", o.edge_rows,
                     "how edge sampling constrains the edge: auto (on a circle, cubic B-spline averages where the plate "
                     "touches all along an arc and points where the contact ends or the plate is free (D28); points on "
                     "a polygon), points (one row per point, about a cell apart: the line load scatters by some 10 %), "
                     "spline (periodic spline averages all round, knots h^(3/7) r^(4/7) apart), or "
                     "spline:DEGREE[,CELLS] (degree 1 ... 5, knots CELLS cells apart if given)")
      ->capture_default_str();
  o.tol_opt = o.grid->add_option("--tol", o.opt.tol,
                                 "OS, relative to the size of the answer (max |phi| at the samples, or the free plate's "
                                 "max |w| if larger): stop when steps, and successive eps levels, are within tol times that "
                                 "size (max over nodes); with --scheme exact the bound on every relative certificate entry "
                                 "(default there 1e-10)")
      ->check(kFinitePositive)
      ->capture_default_str();
  o.max_iter_opt = o.grid->add_option("--max-iter", o.opt.max_iter, "iteration cap per eps level; reaching it is a failure")
      ->check(kIterationCap)
      ->capture_default_str();
  o.csv_opt = o.grid->add_option("--csv", o.csv_path, "write the nodal fields (CSV) here");

  add_exact_options(app, o);

  o.penalty = app.add_option_group("The penalty schemes", "--scheme nonlinear or linear");
  o.eps_opt = o.penalty->add_option("--eps", o.eps_fixed,
                                    "solve at this eps only (no continuation); every eps is in units of lx^4, so it means "
                                    "the same in any unit of length")
      ->check(kFinitePositive);
  o.penalty->add_option("--eps-start", o.opt.eps_start, "first eps of the continuation")
      ->check(kFinitePositive)
      ->capture_default_str()
      ->excludes(o.eps_opt);
  o.penalty->add_option("--eps-min", o.opt.eps_min, "smallest eps tried before the continuation is declared failed")
      ->check(kFinitePositive)
      ->capture_default_str()
      ->excludes(o.eps_opt);
  o.penalty->add_flag("--rate", o.rate, "also compute lambda_1h and the linear scheme's contraction factors");

  CLI::Option_group* out = app.add_option_group("Outputs", "every scheme");
  out->add_option("--nu", o.nu, "Poisson's ratio for the bending moments")->check(kFinite & CLI::Range(-1.0, 0.5))->capture_default_str();
  out->add_option("--point", o.points, "report w at 'x,y' (repeatable)");
  o.json_opt = out->add_option("--json", o.json_path, "write the summary (JSON) here");
  o.line_csv_opt = out->add_option("--line-csv", o.line_csv_path,
                                   "write the line load q(theta) at the edge points (CSV) here; semi-analytic: at " +
                                       std::to_string(plate::kLineLoadAngles) + " fixed angles");
  out->add_flag("-q,--quiet", o.quiet, "print nothing but errors");
}

// Every option of the program, its groups' included, in the order --help lists them.
std::vector<const CLI::Option*> all_options(const CLI::App& app) {
  std::vector<const CLI::Option*> all = app.get_options();
  for (const CLI::App* group : app.get_subcommands([](const CLI::App*) { return true; }))
    for (const CLI::Option* opt : group->get_options()) all.push_back(opt);
  return all;
}

// Throws std::invalid_argument naming the first option of `group` that was given: the scheme has
// no use for any of them.
void refuse_group(const CLI::Option_group* group, const std::string& why) {
  for (const CLI::Option* opt : group->get_options())
    if (opt->count()) throw std::invalid_argument(opt->get_name() + " has no meaning for " + why);
}

// The scene the options state, built once for every scheme: the cylinder (--obstacle cylinder,
// its rim the edge unless --edge says otherwise) or an expression obstacle, and the load.
plate::Scene scene_of(const Options& o) {
  using namespace plate;
  const Scene rectangle = Scene::rectangle(o.lx, o.ly);
  Scene s;
  if (o.obstacle == "cylinder") {
    const auto [cx, cy] = parse_pair("--centre", o.centre);
    s = rectangle.over(Cylinder{cx, cy, o.radius, o.R});
  } else {
    s = rectangle.over(o.obstacle);
  }
  if (o.edge != "auto") s.edge = parse_edge(o.edge);
  return s.loaded(o.load);
}

// The three models plate offers: the finite elements with the constraint held exactly, with a
// penalty, and the rim-contact series.
enum class Model { Exact, Penalty, Series };

// What to solve and how, once every option has been checked.
struct Run {
  Model model = Model::Exact;
  plate::Scene scene;
  plate::Grid g;  // the whole plate's (not for the series)
  plate::SamplingSpec spec;
  plate::SolveOptions opt;
  plate::ExactOptions exact_opt;
  plate::Mirrors mirrors;  // the exact scheme's, found once (none with --symmetry none)
  int solved_unknowns = 0;  // of the part the mirrors leave, or of the whole grid
  std::optional<plate::Problem> penalised;  // the penalty schemes' problem, assembled before the echo
  bool estimate = true;
  plate::Report report;
};

// "auto", "points", "spline" or "spline:DEGREE[,CELLS]"; throws std::invalid_argument naming
// --edge-rows otherwise.
plate::EdgeRows parse_edge_rows(const std::string& text) {
  if (text == "auto") return {};
  if (text == "points") return plate::EdgeRows::points();
  if (text == "spline") return plate::EdgeRows::splines(plate::EdgeRows{}.degree);
  const std::string bad = "--edge-rows '" + text + "': expected auto, points, spline or spline:DEGREE[,CELLS] (DEGREE 1 ... 5, CELLS > 0)";
  if (text.rfind("spline:", 0) != 0) throw std::invalid_argument(bad);
  const std::string rest = text.substr(7);
  char* end = nullptr;
  const double degree = std::strtod(rest.c_str(), &end);
  double cells = 0;
  if (*end == ',') {
    const char* c = end + 1;
    cells = std::strtod(c, &end);
    if (end == c || !(cells > 0) || !std::isfinite(cells)) throw std::invalid_argument(bad);
  }
  if (*end != '\0' || !(degree >= 1 && degree <= 5 && degree == std::floor(degree))) throw std::invalid_argument(bad);
  return plate::EdgeRows::splines(static_cast<int>(degree), cells);
}

// The --point options, each inside the lx x ly plate the model solves (a grid's is its cells' own
// extent, to round-off); throws std::invalid_argument naming --point.
std::vector<std::pair<double, double>> points_of(const Options& o, double lx, double ly) {
  std::vector<std::pair<double, double>> points;
  for (const auto& p : o.points) points.push_back(parse_pair("--point", p));
  for (const auto& [x, y] : points)
    if (x < 0 || x > lx || y < 0 || y > ly)
      throw std::invalid_argument("--point " + std::to_string(x) + "," + std::to_string(y) + " is outside the plate");
  return points;
}

// Every output of a run, formatted whole before any is written (empty: not asked for).
struct Outputs {
  std::string csv, json, line_csv, summary;
};

// Writes the files whole, prints the summary, and says why a run is not an answer; the exit status.
// A run that is not an answer says so in every output, the CSVs in their first line, so that a file
// read later cannot be mistaken for one. A model without a file (the series has no nodal CSV) has
// refused its option before it got here.
int write_outputs(const Options& o, const Outputs& out, const plate::Report& report) {
  const std::string warning = report.converged ? "" : "# NOT CONVERGED: " + report.message + "\n";
  if (!o.csv_path.empty()) plate::write_file_atomically(o.csv_path, warning + out.csv);
  if (!o.json_path.empty()) plate::write_file_atomically(o.json_path, out.json);
  if (!o.line_csv_path.empty()) plate::write_file_atomically(o.line_csv_path, warning + out.line_csv);
  if (!o.quiet) std::cout << out.summary;
  if (!report.converged) {
    std::cerr << "plate: error: " << report.message << "\n";
    return plate::kNotConverged;
  }
  return plate::kSuccess;
}

// The options the series models; it refuses the others by name rather than ignoring them.
const std::vector<std::string> kSeriesOptions = {"--lx",  "--ly",  "--obstacle", "--obstacle-height", "--radius",   "--centre", "--load",
                                                 "--scheme", "--nu", "--point",   "--json",            "--line-csv", "--quiet"};

// Throws std::invalid_argument naming the option at fault; nothing has been written yet. The scene
// is built here, once, for every model.
Run check(const Options& o) {
  using namespace plate;
  Run r;
  r.model = o.scheme == "semi-analytic" ? Model::Series : o.scheme == "exact" ? Model::Exact : Model::Penalty;
  if (r.model == Model::Series) {
    for (const CLI::Option_group* g : {o.grid, o.exact, o.penalty})
      refuse_group(g, "--scheme semi-analytic (no grid, no eps; its bars are the series' own)");
    if (o.obstacle != "cylinder")
      throw std::invalid_argument("--obstacle: --scheme semi-analytic models the cylinder only, not '" + o.obstacle + "'");
    r.scene = scene_of(o);
    rim_scene(r.scene);  // the series models a cylinder under a uniform load; it refuses anything else by name
    check_outputs({{o.json_opt, o.json_path}, {o.line_csv_opt, o.line_csv_path}});
    r.report.nu = o.nu;
    r.report.points = points_of(o, o.lx, o.ly);
    return r;
  }
  r.g = make_grid(o.n, o.lx, o.ly);
  check_grid_size(r.g);
  check_outputs({{o.json_opt, o.json_path}, {o.csv_opt, o.csv_path}, {o.line_csv_opt, o.line_csv_path}});
  r.scene = scene_of(o);
  r.spec = SamplingSpec{sampling_kind(o.sampling), parse_edge_rows(o.edge_rows)};
  if (r.spec.rows.kind == EdgeRows::Kind::Splines && !(has_edge(r.spec.kind) && r.scene.edge.kind == EdgeCurve::Kind::Circle))
    throw std::invalid_argument("--edge-rows spline needs edge sampling of a circle (--sampling edge, the cylinder or --edge circle:...)");
  if (!o.line_csv_path.empty() && !has_edge(r.spec.kind))
    throw std::invalid_argument("--line-csv needs edge sampling (--sampling edge or edge-gauss)");
  const bool exact = r.model == Model::Exact;
  r.opt = o.opt;
  r.opt.scheme = o.scheme == "linear" ? Scheme::Linear : Scheme::Nonlinear;
  if (exact)
    refuse_group(o.penalty, "--scheme exact (no eps: the constraint is held exactly)");
  else
    refuse_group(o.exact, "the penalty schemes (it applies to --scheme exact only)");
  if (exact && o.enrich != "none") {
    const bool edge = r.spec.kind == SamplingKind::Edge;
    const bool circle = edge && r.scene.edge.kind == EdgeCurve::Kind::Circle, polygon = edge && r.scene.edge.kind == EdgeCurve::Kind::Polygon;
    if (o.enrich == "ring" && !circle)
      throw std::invalid_argument("--enrich ring needs edge sampling of a circle (--sampling edge, the cylinder or --edge circle:...)");
    if (o.enrich == "sides" && !polygon)
      throw std::invalid_argument("--enrich sides needs edge sampling of a polygon (--sampling edge and --edge polygon:...)");
    if (const std::string why = kink_misfit(r.g, r.scene.edge); o.enrich != "auto" && !why.empty())
      throw std::invalid_argument("--enrich " + o.enrich + ": " + why);
    if (circle) r.spec.enrich.kind = EnrichSpec::Kind::Ring;
    if (polygon) r.spec.enrich.kind = EnrichSpec::Kind::Sides;
  }
  // The memory the model solved needs: the part the mirrors leave, for the exact scheme. A grid whose
  // smallest part would not fit is refused first, before the mirrors are looked for on all its nodes.
  if (exact && o.symmetry == "auto") {
    check_memory(part_of(r.g, plate::Mirrors{r.g.nx % 2 == 0, r.g.ny % 2 == 0}));
    r.mirrors = find_mirrors(r.scene, r.g, r.spec);
  }
  const Grid solved = part_of(r.g, r.mirrors);
  check_memory(solved);
  r.solved_unknowns = solved.unknowns();
  r.report.model = describe(r.mirrors);
  r.report.nu = o.nu;
  r.estimate = o.estimate == "auto";
  r.exact_opt.tol = o.tol_opt->count() ? o.opt.tol : r.exact_opt.tol;
  r.exact_opt.max_iter = o.max_iter_opt->count() ? o.opt.max_iter : r.exact_opt.max_iter;
  r.exact_opt.globalise = !o.no_globalise;
  r.exact_opt.nested = !o.no_nested;
  if (exact) validate(r.exact_opt);
  if (*o.eps_opt) {
    r.opt.eps_start = o.eps_fixed;
    r.opt.continuation = false;
  }
  validate(r.opt);
  r.report.points = points_of(o, r.g.lx(), r.g.ly());
  return r;
}

// The effective value of every option `keep` takes, given or default (a flag: true or false), or
// the value the model uses instead where `solved` gives one (the exact scheme's own tol and
// iteration cap), then the values the model derived from them (`scaled`); printed under `header`
// unless --quiet, so that a run can be reproduced from its output and the echo is what is solved.
using Config = std::vector<std::pair<std::string, std::string>>;
Config echo(const CLI::App& app, const Options& o, const std::string& header, const std::function<bool(const CLI::Option*)>& keep,
            const std::function<std::optional<std::string>(const CLI::Option*)>& solved = {}, const Config& scaled = {}) {
  Config config;
  for (const auto* opt : all_options(app)) {
    if (!keep(opt)) continue;
    std::string value = opt->count() ? CLI::detail::join(opt->reduced_results(), " ") : opt->get_default_str();
    if (value.empty()) value = "(none)";
    if (opt->get_expected_max() == 0) value = opt->count() ? "true" : "false";  // a flag
    if (solved)
      if (const auto v = solved(opt)) value = *v;
    config.emplace_back(opt->get_name(), value);
  }
  config.insert(config.end(), scaled.begin(), scaled.end());
  if (!o.quiet) {
    std::cout << header << "\n";
    for (const auto& [k, v] : config) std::cout << "  " << k << " = " << v << "\n";
  }
  return config;
}

// Error bars from the last four grids of the sequence (or three, or two), each certified and each
// with half the cells of the next, all in one space. Where the kink functions (D31) fit the finest
// grid alone, from the plain space's grids below it and the step to the finest. None otherwise,
// with the reason.
void set_error_bars(Run& r, const std::vector<plate::ExactLevel>& levels) {
  using namespace plate;
  if (!r.estimate) return;
  std::vector<const ExactLevel*> use, below;  // the finest grid's space; the other's, below it
  std::string stop;  // why the grids below the coarsest used were not used, if any were solved
  for (auto it = levels.rbegin(); it != levels.rend() && use.size() < 4; ++it) {
    // Grids of one space only: a coarser grid that (D31) did not fit converges otherwise. Where the
    // finest grid has its space to itself, the other space's grids below it serve instead.
    const bool same = use.empty() || it->enriched == use.back()->enriched;
    if (!same && use.size() > 1) {
      r.report.bar_grids_note = "the coarser grids, which the kink functions (D31) do not fit, were solved in the plain space and are left out";
      break;
    }
    std::vector<const ExactLevel*>& into = same && below.empty() ? use : below;
    if (into.size() == 4) break;
    const ExactLevel* above = !into.empty() ? into.back() : !use.empty() ? use.back() : nullptr;
    if (!it->measures || !it->certified || (above && 2 * it->cells != above->cells)) {
      const std::string grid = "the grid n = " + std::to_string(it->cells) + " of the sequence ";
      stop = grid + (!it->certified ? "is not certified" : !it->measures ? "was not measured" : "does not have half the cells of the next");
      break;
    }
    into.push_back(&*it);
  }
  std::reverse(use.begin(), use.end());
  std::reverse(below.begin(), below.end());
  const bool across = use.size() == 1 && below.size() >= 2;
  if (use.size() < 2 && !across) {
    // Why not: a grid below was not certified (stop), a single grid of the other space, or no
    // coarser grid at all (sequencing halves n while it stays even and at least coarsest).
    if (stop.empty() && below.size() == 1) {  // then use holds the finest grid alone
      const int n = use[0]->cells;
      stop = "n = " + std::to_string(below[0]->cells) + " is solved in the plain space, since the kink functions (D31) do not fit it; use n = " +
             std::to_string(2 * n) + ", " + std::to_string(4 * n) + ", ...";
    }
    if (stop.empty())
      stop = r.exact_opt.nested ? "the grid sequence has no coarser grid: it halves the grid it solves (with --symmetry auto, the part the mirror lines "
                                  "leave) while both its sides have an even number of cells and n / 2 is at least " +
                                      std::to_string(r.exact_opt.coarsest) + "; n = 16, 32, 64, ... always have one"
                                : "--no-nested solves no coarser grid";
    r.report.bar_note = stop;
    return;
  }
  if (across) {
    const char* which = r.scene.edge.kind == EdgeCurve::Kind::Polygon ? "the kink (D33) and the corners' functions (D34)" : "the kink (D31)";
    r.report.bar_grids_note = "n = " + std::to_string(use[0]->cells) + " carries " + which + ", which the coarser grids do not fit: each bar is its step from n = " +
                              std::to_string(below.back()->cells) + " plus that grid's own bar";
    for (const auto* l : below) r.report.bar_grids.push_back(l->cells);
  }
  for (const auto* l : use) r.report.bar_grids.push_back(l->cells);
  auto add = [&](const std::string& name, auto get) {
    std::vector<double> v, c;
    for (const auto* l : use) v.push_back(get(*l));
    for (const auto* l : below) c.push_back(get(*l));
    r.report.bars.emplace_back(name, across ? error_bar_across(v.back(), c) : error_bar(v));
  };
  add("max w", [](const ExactLevel& l) { return l.measures->max_w.value; });
  add("min w", [](const ExactLevel& l) { return l.measures->min_w.value; });
  add("total contact force", [](const ExactLevel& l) { return l.force; });
  add("max |m12|", [](const ExactLevel& l) { return l.measures->max_abs_m12.value; });
  for (size_t k = 0; k < r.report.points.size(); ++k)
    add("w(" + fmt("%.10g", r.report.points[k].first) + ", " + fmt("%.10g", r.report.points[k].second) + ")",
        [k](const ExactLevel& l) { return l.measures->w_at.at(k); });
}

// A converged answer with an output too large for a double would be written as nulls with exit 0;
// it is bad input instead. (R = 1e306 once came this way, with a force of about 6e308; its
// certificate's sums now overflow to NaN, which fails it, and overflow_risk names the obstacle. A
// run that did not converge says so, and exits 3.)
void refuse_overflow(const plate::Report& r) {
  std::vector<std::pair<std::string, double>> outputs{{"max w", r.measures.max_w.value},
                                                      {"min w", r.measures.min_w.value},
                                                      {"the total contact force", r.total_force},
                                                      {"max |m12|", r.measures.max_abs_m12.value}};
  for (size_t k = 0; k < r.measures.w_at.size(); ++k) outputs.emplace_back("w at --point " + std::to_string(k + 1), r.measures.w_at[k]);
  for (const auto& [name, v] : outputs)
    if (!std::isfinite(v))
      throw std::invalid_argument("--obstacle-height, --obstacle or --load: " + name + " = " + plate::fmt("%g", v) +
                                  ": the answer overflows double precision; state the problem in other units");
}

// The exact solver's answer in the penalty schemes' form, for one report: on the part of the plate
// the scene's mirror lines leave (unless --symmetry none), unfolded onto the whole plate. The finest
// grid is measured as it is done (those are the answer's measures), and with --estimate every grid.
plate::SolveResult solve_exactly(Run& r, plate::SceneSolution& scene, plate::VectorXd& xi, plate::Progress& progress) {
  using namespace plate;
  if (!progress.quiet()) r.exact_opt.on_iterate = [&](int cells, int iteration, int held, int changed) {
    const std::string grid = "grid " + std::to_string(cells) + " cells: ";
    if (iteration == 0)
      progress.stage(grid + "starting with " + std::to_string(held) + " candidate rows");
    else
      progress.stage(grid + "active-set iteration " + std::to_string(iteration) + ", " + std::to_string(held) +
                     " rows held, " + std::to_string(changed) + " to change");
  };
  // The coarser grids are measured only for the error bars.
  r.exact_opt.measure_levels = ExactOptions::LevelMeasures{r.report.nu, r.report.points, r.estimate};
  scene = solve_exact_scene(r.scene, r.g.nx, r.spec, r.exact_opt, r.mirrors);
  set_error_bars(r, scene.result.levels);
  const ExactResult& exact = scene.result;
  SolveResult result;
  result.w = exact.w;
  result.converged = exact.converged;
  result.message = exact.message;
  for (const auto& l : exact.levels) result.seconds_iterate += l.seconds;
  xi = exact.lambda;
  r.report.measures = *exact.levels.back().measures;
  r.report.total_force = exact.levels.back().force;
  r.report.certificate = &exact.certificate;
  r.report.certificate_tol = r.exact_opt.tol;
  r.report.model_unknowns = scene.solved.unknowns();
  r.report.space = scene.solved.kink ? "Bogner-Fox-Schmit and " + std::to_string(scene.solved.kink->size()) +
                                           (scene.solved.kink->polygon() ? " functions carrying the kink across the polygon's sides (D33) and the point loads at its corners (D34)"
                                                                          : " functions carrying the kink at the rim (D31)")
                                     : "Bogner-Fox-Schmit";
  r.report.refinement = exact.levels.back().refinement.w;
  r.report.refinement_undone = exact.levels.back().refinement.undone;
  return result;
}

// Scheme (3a) or (5a) with eps continuation, and the force density its answer implies.
plate::SolveResult solve_penalty(Run& r, const plate::Problem& problem, plate::VectorXd& xi, plate::Progress& progress) {
  using namespace plate;
  const double L4 = r.opt.eps_unit;
  VectorXd last;
  if (!progress.quiet())  // the hook copies each iterate: not worth it when nothing is printed
    r.opt.on_iterate = [&](double eps, int iteration, const VectorXd& w) {
      const double step = last.size() ? max_nodal_abs(w - last) : max_nodal_abs(w);
      last = w;
      progress.step("eps = " + fmt("%g", eps / L4) + ": iteration " + std::to_string(iteration) + ", step " +
                    fmt("%.2e", step));
    };
  SolveResult result = solve(problem, r.opt);
  xi = contact_force_density(problem, result.w, result.eps);
  return result;
}

// A penalty run's answer is not converged if the plate sinks deeper into the obstacle than tol,
// whatever the steps say (the penalty lets it in by about eps xi): `below`, the constraint violation.
void judge_penalty(const Run& r, double below, plate::SolveResult& result) {
  using namespace plate;
  if (!result.converged || below <= r.opt.tol) return;
  result.converged = false;
  result.message = fmt("the plate lies %.3g below the obstacle at a sample point", below) +
                   fmt(", more than tol = %.3g (the penalty's own error at eps = ", r.opt.tol) +
                   fmt("%g); use a smaller --eps-min or --scheme exact", result.eps / r.opt.eps_unit);
}

// Scale-free penalty: eps in units of L^4 (the stiffness K ~ L^-2 against eps^-1 M ~ L^2 / eps),
// OS relative to the size of the answer, which needs the assembled problem. Done before the echo, so
// that it states the values solved with; the other models need no scaling. On the unit square eps
// is unchanged.
Config scale(Run& r, plate::Progress& progress, plate::Clock::time_point t0) {
  using namespace plate;
  if (r.model == Model::Series) return {};
  const double L4 = std::pow(r.g.lx(), 4);
  r.opt.eps_start *= L4;
  r.opt.eps_min *= L4;
  r.opt.eps_unit = L4;
  r.report.eps_unit = L4;
  if (r.model == Model::Exact) return {};
  progress.stage("assembling " + std::to_string(r.g.unknowns()) + " unknowns");
  r.penalised = make_problem(r.scene, r.g, r.spec);
  r.report.seconds_assemble = seconds_since(t0);
  const double size = answer_scale(*r.penalised);  // a factorisation under a load: asked once
  r.opt.tol *= size;
  // The penalty schemes stop on steps within tol times the answer's size; where that product leaves
  // double precision's normal range (the cylinder at R = 1e-320), they would refuse a tol the user
  // never gave, so the scene is named instead.
  if (!(r.opt.tol >= DBL_MIN))
    throw std::invalid_argument("--obstacle-height, --obstacle or --load: the answer's size (" + fmt("%g", size) +
                                ") times --tol is " + fmt("%g", r.opt.tol) + ", below double precision's normal range (" +
                                fmt("%g", DBL_MIN) + "); state the problem in other units");
  return {{"tol (absolute: --tol times the answer's size)", fmt("%.6g", r.opt.tol)}, {"eps unit (lx^4)", fmt("%.6g", L4)}};
}

// The echo: every option a model uses, with the values it solves with, under a header that says
// what is solved.
Config echo_run(const CLI::App& app, const Options& o, const Run& r, const Config& scaled) {
  if (r.model == Model::Series)
    return echo(app, o, "plate: the rim-contact series (no grid)", [&](const CLI::Option* opt) {
      return std::find(kSeriesOptions.begin(), kSeriesOptions.end(), opt->get_name()) != kSeriesOptions.end();
    });
  std::ostringstream header;
  header << "plate: " << r.g.nx << " x " << r.g.ny << " cells, h = " << r.g.h << ", " << r.g.unknowns() << " unknowns";
  if (r.solved_unknowns != r.g.unknowns()) header << ", " << r.solved_unknowns << " of them on the " << r.report.model << " solved";
  const bool exact = r.model == Model::Exact;
  return echo(app, o, header.str(), [](const CLI::Option* opt) { return opt->get_name() != "--help"; },
              [&](const CLI::Option* opt) -> std::optional<std::string> {
                if (exact && opt == o.tol_opt) return plate::fmt("%g", r.exact_opt.tol);
                if (exact && opt == o.max_iter_opt) return std::to_string(r.exact_opt.max_iter);
                return std::nullopt;
              },
              scaled);
}

// The CSV says what its bounds are about, as the summary does: the certificate the discrete
// answer, the error bars the plate's.
std::string bounds_header(const plate::Report& report) {
  using namespace plate;
  std::string bounds;
  if (report.certificate) bounds = "# certificate (discrete): worst relative entry " + fmt("%.2g", report.certificate->worst()) + "\n";
  std::istringstream bar_lines(error_bars_text(report));
  for (std::string line; std::getline(bar_lines, line);) bounds += "# " + line + "\n";
  return bounds;
}

// A grid model: solve, then compute once everything the outputs state of the answer, then format.
Outputs solve_grid(const Options& o, Run& r, plate::SceneSolution& scene, plate::SolveResult& result, plate::NodalFields& nodes,
                   plate::Progress& progress, plate::Clock::time_point t0) {
  using namespace plate;
  VectorXd xi;
  const bool exact = r.model == Model::Exact;
  if (exact) {
    progress.stage("solving (exact scheme, " + o.sampling + " sampling)");
    result = solve_exactly(r, scene, xi, progress);
  } else {
    progress.stage("assembled; solving (" + o.scheme + " scheme, " + o.sampling + " sampling)");
    result = solve_penalty(r, *r.penalised, xi, progress);
  }
  const Problem& problem = exact ? scene.whole() : *r.penalised;
  if (!result.converged)
    for (const auto risk : {overflow_risk, underflow_risk})
      if (const std::string why = risk(exact ? scene.solved : *r.penalised); !why.empty()) throw std::invalid_argument(why);
  // Everything the outputs state of the answer, once: the exact solver measured its own (the field's
  // extremes, w at the points, the force) as it solved every grid; the penalty's are measured here.
  r.report.violation = constraint_violation(problem, result.w);
  if (!exact) {
    judge_penalty(r, r.report.violation, result);
    r.report.measures = measure_field(problem, result.w, r.report.nu, r.report.points);
    r.report.total_force = total_contact_force(problem, xi);
    r.report.penalty_residual = penalty_residual(problem, result.w, result.eps);
  }
  progress.stage(result.converged ? "solved; writing the outputs" : "not converged; writing the outputs");
  nodes = nodal_fields(problem, result.w, xi, r.report.nu);
  r.report.nodal = nodal_extremes(nodes);
  const EdgeDip dip = deepest_dip_below_edge(problem, result.w);
  r.report.dip_below_edge = dip.depth;
  r.report.dip_theta = dip.theta;
  r.report.dip_cells = cells_inside_spline_arc(problem, dip.theta);
  // The obstacle's jumps where no edge rows sit (edge sampling puts them on the edge curve; nodes
  // and Gauss points have none), kept where the plate touches the jump's higher side at a node
  // within two cells: a jump the plate keeps clear of constrains nothing.
  const PlateField field(problem, result.w);
  const double touch = 1e-6 * std::max(std::abs(r.report.measures.max_w.value), std::abs(r.report.measures.min_w.value));
  auto touches_near = [&](const ObstacleJump& j) {
    const int i0 = static_cast<int>(std::floor(j.x / r.g.h)), j0 = static_cast<int>(std::floor(j.y / r.g.h));
    for (int i = std::max(i0 - 1, 1); i <= std::min(i0 + 2, r.g.nx - 1); ++i)
      for (int k = std::max(j0 - 1, 1); k <= std::min(j0 + 2, r.g.ny - 1); ++k) {
        const double p = r.scene.obstacle(r.g.x(i), r.g.y(k));
        const bool higher = std::isfinite(p) && (j.ends || std::abs(p - j.upper) < 0.5 * j.size);
        if (higher && field.at(r.g.x(i), r.g.y(k)).w - p <= touch) return true;
      }
    return false;
  };
  for (const ObstacleJump& j : obstacle_jumps(r.g, r.scene.obstacle, has_edge(r.spec.kind) ? r.scene.edge : EdgeCurve{}))
    if (touches_near(j)) r.report.jumps.push_back(j);
  r.report.xi = xi;
  r.report.line = line_force(problem, xi);
  r.report.line_figures = line_figures(problem, r.report.line);
  if (o.rate) {
    r.report.lambda1h = smallest_eigenpair(problem.K, problem.M).lambda;
    r.report.sharp_factor = sharp_contraction(r.report.lambda1h, result.eps);
    r.report.paper_rho = paper_rho(1.0 / r.report.lambda1h, result.eps);
  }
  r.report.problem = &problem;
  r.report.result = &result;
  r.report.nodes = &nodes;
  r.report.seconds_total = seconds_since(t0);
  r.report.converged = result.converged, r.report.message = result.message;
  if (result.converged) refuse_overflow(r.report);
  return {o.csv_path.empty() ? "" : bounds_header(r.report) + nodal_csv(nodes), o.json_path.empty() ? "" : summary_json(r.report),
          o.line_csv_path.empty() ? "" : line_force_csv(problem, r.report.line, r.report.line_figures),
          o.quiet ? "" : summary_text(r.report)};
}

// --scheme semi-analytic: the cylinder's scene by the rim-contact series (rim_contact.hpp), no grid;
// its values are read off the finest truncation once, then formatted.
Outputs solve_series(const Options& o, Run& r, std::optional<plate::RimAnswer>& answer, plate::Clock::time_point t0) {
  using namespace plate;
  // The last three truncations: enough for a bar that has been seen to shrink (rim_series shows all six).
  answer = rim_answer(r.scene, 6, false, 3);  // in long double where double's round-off stalls it
  const RimSeries& s = answer->finest;
  Report& report = r.report;
  report.series = &*answer;
  const RimConvergenceRow& last = answer->rows.back();  // its peak, found once by rim_answer's search
  report.measures.max_w = {last.max_w, last.x_max, last.y_max};
  for (const auto& [x, y] : report.points) report.measures.w_at.push_back(s.w(x, y));
  report.measures.max_abs_m12.value = rim_max_abs_m12(s, report.nu);
  report.line = rim_line_force(s);
  report.line_figures = rim_line_figures(s, report.line);
  report.converged = answer->premise.holds && answer->settled;
  if (!answer->premise.holds)
    report.message = "the contact is not the whole rim (" + answer->premise.why +
                     "), so the rim-contact series does not solve this scene: use --scheme exact";
  else if (!answer->settled)
    report.message = "the series has not settled: its last change is not below the one before";
  report.seconds_total = seconds_since(t0);
  return {"", o.json_path.empty() ? "" : rim_summary_json(report), o.line_csv_path.empty() ? "" : rim_line_csv(report),
          o.quiet ? "" : rim_summary_text(report)};
}

}  // namespace

int main(int argc, char** argv) {
  using namespace plate;
  run_as_measured(argv);
  clean_up_on_interrupt("plate");
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
  Options o;
  add_options(app, o);
  // CLI11 has its own exit codes; every bad input exits with the one documented in --help.
  if (const int status = parse_options(app, argc, argv, "plate"); status >= 0) return status;
  const auto t0 = Clock::now();
  // One pipeline for every model: check the options and build the scene, scale, echo, solve and
  // measure, format, write.
  return run_guarded("plate", [&] {
    Run r = check(o);
    Progress progress("plate", o.quiet);
    r.report.config = echo_run(app, o, r, scale(r, progress, t0));
    // What the report points into lives here, until the outputs are written.
    SceneSolution scene;
    SolveResult result;
    NodalFields nodes;
    std::optional<RimAnswer> answer;
    const Outputs out = r.model == Model::Series ? solve_series(o, r, answer, t0) : solve_grid(o, r, scene, result, nodes, progress, t0);
    return write_outputs(o, out, r.report);
  });
}
