// crosscheck_penalty: the paper's own method, the penalty (2) with the schemes (3a) and (5a), run by
// an independent code (reference/penalty_hct.edp: FreeFEM, HCT triangles on gmsh meshes) beside
// this one. Writes results/crosscheck_penalty.md and four tables:
//   crosscheck_penalty_table.csv  (5a)'s iterations for the paper's eight tolerances: the paper,
//                                 GLT, ours (results/table.csv) and FreeFEM on its two coarsest meshes;
//   crosscheck_penalty_eps.csv    w_eps at fixed eps = 1e-3 ... 1e-8 and Fig. 2's 1e-10, the penalty
//                                 integrated over the true disk (D30), on both codes' refinement sequences,
//                                 their limits compared (crosscheck_penalty_limits.csv); and w_eps -> w at
//                                 the rate eps;
//   crosscheck_penalty_fig2.csv   Fig. 2's quantities against R from FreeFEM beside results/fig2.csv, judged
//                                 by the limits at Fig. 2's eps.
// Run by `make crosscheck`; exit 3 when a check fails. `crosscheck_penalty --help` lists the options.
#include <CLI/CLI.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <algorithm>
#include <cstdlib>
#include <set>
#include <tuple>
#include <thread>
#include <atomic>
#include <exception>
#include <sstream>

#include "active_set.hpp"
#include "atomic_file.hpp"
#include "contact.hpp"
#include "contraction.hpp"
#include "crosscheck.hpp"
#include "csv_table.hpp"
#include "eps_limit.hpp"
#include "exit_codes.hpp"
#include "format.hpp"
#include "freefem.hpp"
#include "extrema.hpp"
#include "mirror.hpp"
#include "norms.hpp"
#include "penalty_integral.hpp"
#include "published.hpp"
#include "richardson.hpp"
#include "verdict.hpp"
#include "words.hpp"

using namespace plate;

namespace {

struct Setup {
  // The contraction with no contact, and lambda_1h, on meshes doubling up to 32 cells a quarter
  // circle: the last three give each code's lambda_1h as h -> 0, which must be the published lambda_1.
  std::vector<int> eigen_levels = {1, 2, 4, 8};
  std::vector<int> eigen_ns = {8, 16, 32, 64};  // ours, Gauss sampling, the whole plate
  std::vector<int> table_levels = {1, 2};      // the .geo's n (4 n cells per quarter circle): the coarsest
  // Fixed eps: the same continuum problem, the penalty integrated over the true disk (D30), in both
  // codes: FreeFEM over the triangles inside the circle and the circular segments beyond their chords,
  // ours by the rule that follows the circle and the curve w = phi through each square.
  std::vector<int> eps_levels = {2, 4, 8, 16};       // FreeFEM's sequence
  std::vector<int> eps_ns = {32, 64, 128, 256, 512};  // ours, on the part of the plate its mirrors leave
  // The last is Fig. 2's eps: there the two limits judge the paper's Fig. 2 converged in the mesh.
  std::vector<double> eps_values = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-10};
  // Ours solves with the obstacle's height times 1 + this: a check that can fail must say "differ"
  // when one code's scene is changed a little (tests/test_crosscheck_penalty.cpp).
  double perturb = 0;
  // The rate w_eps -> w: against each code's exact answer with the same discrete constraint (FreeFEM:
  // the vertices, as contact_hct.edp; ours: the nodes), one grid each, eps down to 1e-10. (Gauss
  // sampling puts many samples where the exact multiplier is tiny, and its w_eps reaches the rate
  // only below eps = 1e-10 at h = 1/64.)
  int rate_level = 4, rate_n = 64;
  std::vector<double> rate_eps = {1e-6, 1e-7, 1e-8, 1e-9, 1e-10};
  std::string parts = "table,eps,rate,fig2";
  int fig2_level = 4;       // FreeFEM's mesh for Fig. 2: h about 1/13
  double fig2_eps = 1e-10;  // as results/fig2.csv
  std::string geo = "reference/square_with_circle.geo", quarter_geo = "reference/quarter_square_with_circle.geo";
  std::string penalty = "reference/penalty_hct.edp";
  std::string exact = "reference/contact_hct.edp", reference = "reference", results = "results";
  std::string work = "build/crosscheck-penalty-work", out = "results";
  Scene scene = paper_scene();
  // What this run has made in --work: the meshes (by level) and the points file, made once each and
  // then reused (never a file an earlier run left there, which may come from another .geo or have
  // been cut short), and the FreeFEM runs so far, which number their output files.
  mutable std::set<std::tuple<int, double, int, bool>> meshes_made;  // (level, grade, ring, quarter)
  mutable bool points_written = false;
  mutable std::atomic<int> penalty_runs{0};
  // FreeFEM runs at a time in the table and at fixed eps: they are independent, single-threaded, and
  // most of the step's time (the 64-cell meshes at small eps), while `make all`'s other steps end early.
  int jobs = std::max(1u, std::thread::hardware_concurrency());
};

// FreeFEM's mesh of level n, the ring inside the circle with `ring` n radial cells graded by `grade`
// (1, 1: the uniform O-grid), of the whole plate or of its lower-left quarter (the circle at the
// plate's centre), meshed by this run and then reused within it.
struct RingGrading {
  double grade = 1;
  int ring = 1;
};
std::string mesh(const Setup& s, int n, RingGrading rg = {}, bool quarter = false) {
  const bool uniform = rg.grade == 1 && rg.ring == 1;
  const std::string msh = s.work + (quarter ? "/quarter" : "/square") + std::to_string(n) +
                          (uniform ? "" : "_ring" + std::to_string(rg.ring) + "_grade" + fmt("%.6g", rg.grade)) + ".msh";
  if (s.meshes_made.insert({n, rg.grade, rg.ring, quarter}).second) {
    auto numbers = circle_numbers(s.scene, n);
    if (!uniform) numbers.insert(numbers.end(), {{"grade", rg.grade}, {"ring", rg.ring}});
    gmsh_mesh(quarter ? s.quarter_geo : s.geo, numbers, msh);
  }
  return msh;
}
// @region layer-grade
// How FreeFEM's ring is graded at fixed eps (D30). Inside the disk the penalised plate obeys
// Lap^2 w + eps^-1 (w - phi) = 0 where it dips, whose solutions vary on the length eps^(1/4): the
// force sits in a layer that thin along the circle, and on a uniform mesh its cells outgrow the
// layer as eps falls, so the increments from mesh to mesh jump about. The ring's map from cell index
// to radius is made `grade` = 2 (ring width) / eps^(1/4) times steeper at the central square than
// at the circle (at least 1), and the ring gets twice the radial cells at every eps, which keeps the
// cells at the square within twice the uniform mesh's. The rule depends on eps and the circle
// alone, not on any answer.
RingGrading layer_grading(const Scene& scene, double eps) {
  const double width = 0.6 * scene.cylinder->radius;  // circle to central square (the .geo's a = 0.4 r)
  return {std::max(1.0, std::round(2 * width / std::pow(eps, 0.25) * 100) / 100), 2};
}
// @end layer-grade
std::string points(const Setup& s) {
  const std::string pts = s.work + "/points.txt";
  if (!s.points_written) write_points(pts, {{s.scene.cylinder->cx, s.scene.cylinder->cy}}), s.points_written = true;
  return pts;
}
PenaltyRun penalty(const Setup& s, int n, const std::string& args, double R, RingGrading rg = {}, bool quarter = false) {
  const Scene scene = at_height(s.scene, R);
  const std::string out = s.work + "/penalty" + std::to_string(++s.penalty_runs) + ".json";
  return penalty_values(run_freefem(s.penalty, mesh(s, n, rg, quarter),
                                    scene_args(scene, points(s)) + " " + args + (quarter ? " -symmetry quarter" : ""), out));
}
// run(0) ... run(count - 1), independent FreeFEM runs, on `jobs` threads; a failure in any is
// thrown once all have ended. The meshes, the points file and FF_LOADPATH must exist before: making
// them is no thread's business.
template <class Run>
void on_workers(int jobs, size_t count, Run run) {
  std::vector<std::exception_ptr> failed(count);
  std::atomic<size_t> next{0};
  auto work = [&] {
    for (size_t i; (i = next++) < count;) try {
        run(i);
      } catch (...) {
        failed[i] = std::current_exception();
      }
  };
  std::vector<std::thread> workers;
  for (int j = 1; j < jobs; ++j) workers.emplace_back(work);
  work();
  for (std::thread& t : workers) t.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}
// What on_workers needs made first.
void prepare_runs(const Setup& s, const std::vector<int>& levels, const std::vector<RingGrading>& gradings = {{}}, bool quarter = false) {
  for (int n : levels)
    for (const RingGrading& g : gradings) mesh(s, n, g, quarter);
  points(s);
  setenv("FF_LOADPATH", "/usr/lib/freefem++", 0);
}

// penalty_hct.edp's first level and last (equal: one level).
std::string eps_arg(double eps, double eps_min) {
  std::ostringstream a;
  a.precision(17);
  a << " -eps " << eps << " -eps-min " << eps_min;
  return a.str();
}
std::string eps_arg(double eps) { return eps_arg(eps, eps); }

// FreeFEM's way to the solution at one eps by (3a) from w = 0 (the rate's and Fig. 2's runs, and
// the coarsest mesh of each fixed-eps chain, whose finer meshes start from the one before,
// run_fixed_eps). From w = 0 its iterations grow as eps falls, so
// an eps of 1e-8 or less (kPathFrom / 100) is reached by the levels 1e-6, 1e-8, ..., eps, each
// started from the one before (penalty_hct.edp -continuation 2, whose header gives the counts); a
// larger eps is solved from w = 0. The answer is the same discrete solution either way.
constexpr double kPathFrom = 1e-6;
std::string one_eps(double eps) {
  if (eps > kPathFrom / 100 * (1 + 1e-12)) return " -continuation 0" + eps_arg(eps);
  return " -continuation 2" + eps_arg(kPathFrom, eps);
}

// ---- 1. the table ----------------------------------------------------------------------------
struct TableRow {
  PublishedRow paper;
  int ours_nodes = 0, ours_gauss = 0;
  std::vector<int> freefem;  // per level; -1 when not converged
};
struct EigenCheck {
  int level = 0;
  double h = 0, lambda1h = 0, q = 0, measured = 0;  // q = 1/(1 + eps lambda_1h) and the measured factor
  double noise = 0;  // what round-off can move the measured factor (measured_factor_noise)
  bool ok = false;
};
constexpr double kEigenEps = 1e-4;   // eps of the no-contact contraction run
constexpr double kEigenTol = 1e-6;   // |measured - q| allowed above round-off: a 1e-5 relative error in lambda_1h moves q by 1e-6
// The last step. The measured factor, the ratio of the last two steps, carries the other modes, which
// fade as the steps do, and round-off, which grows as they shrink (measured_factor_noise). On the
// 32-cell mesh, stopped at steps of 1e-8, 1e-7 and 1e-6 it was 2.3e-6, 2.6e-7 and 1.5e-8 from
// 1/(1 + eps lambda_1h): round-off wins below 1e-6, and the other modes are gone by then.
constexpr double kEigenStop = 1e-6;
// The least noise a measured factor is printed and judged with: when the steps stopped at 1e-8, a
// rebuild moved its seventh decimal even on the coarse meshes.
constexpr double kMeasuredNoise = 1e-7;
// What round-off can move the measured factor s_n / s_(n-1), the ratio of the last two steps: each of
// the three iterates behind them carries about rho, FreeFEM's estimate for the vertex value at the
// plate's top, which is also where the slowest mode and so the steps are largest; each step then
// moves by up to 2 rho, and the ratio by up to 2 rho (1 + q) / s_(n-1) = 2 rho (1 + q) q / s_n
// < 4 rho / s_n. On the 32-cell mesh rho is 1.2e-13: 5e-5 at steps of 9e-9, where a fixed 1e-6 made
// the verdict depend on the machine (two fresh rebuilds measured 1e-6 and 2.3e-6 from q), and 5e-7
// at steps of 9e-7 (kEigenStop).
double measured_factor_noise(const PenaltyRun& r) {
  return std::max(kMeasuredNoise, 4 * r.max_w_roundoff / r.levels.at(0).last_step);
}

int ours_iterations(const CsvTable& t, const std::string& sampling, double tol) {
  for (size_t r : t.where("sampling", sampling))
    if (t.text(r, "n") == "4" && t.text(r, "scheme") == "linear" &&
        std::abs(t.number(r, "tolerance") - tol) <= 1e-9 * tol)
      return static_cast<int>(t.number(r, "iterations"));
  throw std::runtime_error(t.path + " has no linear row for h = 1/4, " + sampling + ", OS = " + fmt("%g", tol));
}

// ---- 2. fixed eps ----------------------------------------------------------------------------
constexpr const char* kOurDiskCode = "bfs-disk";  // ours, the penalty over the true disk (D30)
struct EpsRun {
  std::string code;
  int cells = 0;
  double h = 0, max_w = 0, force = 0;
  double w_noise = 0, f_noise = 0;  // each value's round-off, to whose digits the CSV prints it
};
struct EpsComparison {
  double eps = 0;
  Extrapolation ff_w, ff_f, our_w, our_f;
  Agreement w, f;
};

// ---- 3. Fig. 2 -------------------------------------------------------------------------------
struct Fig2Row {
  double R = 0;
  double ff_w = 0, ff_m12 = 0, ff_force = 0;
  double our_w = 0, our_m12 = 0, our_force = 0;
};

// A limit in one table cell: "value +- bar", with the order where it is steady; else the finest
// value and its last increment (richardson.hpp). The report says which is which once.
std::string brief(const Extrapolation& e) {
  const size_t t = e.orders.size();
  std::string cell = fmt_above(e.limit, e.limit_noise, 10, 'g') + " +- " + fmt_above(e.bar, e.bar_noise, 2);
  if (e.steady) cell += " (order " + format_order(e.orders[t - 1], e.order_noise[t - 1]) + ")";
  return cell;
}

// FreeFEM's Fig. 2 quantities over R must agree to this (relative): (2) with f = 0 is positively
// homogeneous in (R, w), so only round-off separates them (measured: about 1e-10 at eps = 1e-10).
constexpr double kLinearity = 1e-8;

double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }


// ---- our side at fixed eps ---------------------------------------------------------------------
// The exact discrete w_eps of the paper's scene on h = 1/n for eps = 0.1, 0.01, ... down to eps.
std::pair<Problem, std::vector<VectorXd>> our_path(const Scene& sc, int n, SamplingKind kind, double eps) {
  Problem p = make_problem(sc, make_grid(n), SamplingSpec{kind});
  std::vector<VectorXd> path = penalised_path(p, eps);
  return {std::move(p), std::move(path)};
}
const VectorXd& at_eps(const std::vector<VectorXd>& path, double eps) {
  return path.at(static_cast<size_t>(std::lround(-std::log10(eps / 0.1))));  // path[k]: eps = 0.1 * 10^-k
}

// ---- 1. the table: (5a)'s counts, lambda_1h measured as (5a)'s contraction with no contact, and its limit
// lambda_1h as h -> 0 from one code's meshes, against the published continuum lambda_1.
struct EigenLimit {
  std::string who;
  Extrapolation limit;
  bool ok = false;
};
struct TablePart {
  std::vector<TableRow> table;
  std::vector<EigenCheck> eigen;
  std::vector<EigenLimit> limits;  // FreeFEM's, ours
  std::vector<double> our_lambdas;  // on s.eigen_ns
  bool ok = true;
};
// The published lambda_1 is given to four decimals (reference/plate_constants.csv): half a unit of
// the last is what it can claim. An eigenvalue solved to 1e-12 carries round-off far below that.
constexpr double kLambda1Rounding = 5e-5, kEigenNoise = 1e-9;
EigenLimit judge_lambda1(const std::string& who, const std::vector<double>& lambdas, double lambda1) {
  EigenLimit l{who, extrapolate(lambdas, std::vector<double>(lambdas.size(), kEigenNoise * lambda1)), false};
  l.ok = std::abs(l.limit.limit - lambda1) <= l.limit.bar + l.limit.order_doubt + kLambda1Rounding;
  return l;
}
TablePart run_table(const Setup& s, const std::vector<PublishedRow>& paper, const CsvTable& ours_table, double lambda1) {
  TablePart part;
  auto& table = part.table;
  auto& eigen = part.eigen;
  bool& all_ok = part.ok;
  std::cerr << "crosscheck_penalty: the table (FreeFEM's linear scheme, " << paper.size() << " tolerances)\n";
  prepare_runs(s, s.table_levels);
  const size_t levels = s.table_levels.size();
  std::vector<PenaltyRun> runs(paper.size() * levels);
  on_workers(s.jobs, runs.size(), [&](size_t i) {
    runs[i] = penalty(s, s.table_levels[i % levels], "-scheme linear -sampling vertices -tol " + fmt("%.17g", paper[i / levels].tolerance),
                      s.scene.cylinder->height);
  });
  for (size_t k = 0; k < paper.size(); ++k) {
    const PublishedRow& p = paper[k];
    TableRow row{p, ours_iterations(ours_table, "nodes", p.tolerance), ours_iterations(ours_table, "gauss", p.tolerance), {}};
    for (size_t j = 0; j < levels; ++j) {
      const PenaltyRun& r = runs[k * levels + j];
      row.freefem.push_back(r.converged ? r.iterations : -1);
      if (!r.converged) all_ok = false;
    }
    table.push_back(row);
  }
  for (int n : s.eigen_levels) {
    const Scene below = at_height(s.scene, -1);  // far under the plate: no contact
    const std::string out = s.work + "/eigen" + std::to_string(n) + ".json";
    const PenaltyRun r = penalty_values(run_freefem(
        s.penalty, mesh(s, n),
        scene_args(below, points(s)) + " -load 1 -continuation 0 -eigen 1 -tol " + fmt("%g", kEigenStop) + eps_arg(kEigenEps), out));
    EigenCheck e{n, r.h, r.lambda1h, 1 / (1 + kEigenEps * r.lambda1h), r.levels.at(0).last_ratio, measured_factor_noise(r), false};
    // A factor that round-off can move by more than the tolerance cannot be judged: that fails too.
    e.ok = r.converged && e.noise <= kEigenTol && std::abs(e.measured - e.q) <= kEigenTol + e.noise;
    all_ok = all_ok && e.ok;
    eigen.push_back(e);
  }
  // Ours on the same sequence of halvings, the paper's Gauss sampling (its mass is the L2 mass of the
  // bicubics, as FreeFEM's penalty mass is of its triangles).
  for (int n : s.eigen_ns) {
    const Problem p = make_problem(at_height(s.scene, -1), make_grid(n), SamplingSpec{SamplingKind::Gauss});
    part.our_lambdas.push_back(smallest_eigenpair(p.K, p.M).lambda);
  }
  std::vector<double> ff_lambdas;
  for (const EigenCheck& e : eigen) ff_lambdas.push_back(e.lambda1h);
  part.limits = {judge_lambda1("FreeFEM", ff_lambdas, lambda1), judge_lambda1("ours", part.our_lambdas, lambda1)};
  for (const EigenLimit& l : part.limits) all_ok = all_ok && l.ok;
  return part;
}

// ---- 2. fixed eps: both codes' sequences and their limits ----------------------------------------
struct EpsPart {
  std::vector<EpsRun> eps_runs;
  std::vector<EpsComparison> comparisons;
  std::vector<std::array<double, 4>> rate;  // per eps: FreeFEM dw, df; ours dw, df
  std::array<double, 4> rate_noise{};       // round-off in each column
  bool rate_ok = true, ok = true;
  // FreeFEM's levels that ended where their steps stalled at round-off (penalty_hct.edp, region
  // roundoff-stop): how many, and the largest such step beside its round-off estimate.
  int roundoff_stops = 0;
  double roundoff_step = 0, roundoff_estimate = 0;
};
void run_fixed_eps(const Setup& s, EpsPart& part) {
  std::cerr << "crosscheck_penalty: fixed eps (" << s.eps_values.size() << " values, FreeFEM and this code)\n";
  const Scene& sc = s.scene;
  const Scene ours = at_height(sc, sc.cylinder->height * (1 + s.perturb));
  // FreeFEM's runs (index k L + j: eps k, mesh j) and ours (-1: each grid's path of w_eps through
  // the eps values, once) on s.jobs threads. Each eps is a chain over FreeFEM's meshes, coarse to
  // fine: the coarsest solved from w = 0 (one_eps), each finer one started from the one before it
  // (penalty_hct.edp -save, -start): the same discrete solution in far fewer steps on the finest
  // mesh. The chains go from the smallest eps up, the costliest first, with ours
  // (about a minute) after the first. A value's round-off: the floor of Newton's
  // corrections (1e-12 of w, penalty_integral.cpp), and through the penalty eps^-1 times that over
  // the band where it acts.
  std::vector<RingGrading> gradings;
  for (double eps : s.eps_values) gradings.push_back(layer_grading(sc, eps));
  // FreeFEM solves on the quarter of the plate the mirror lines leave when the circle sits at its
  // centre: a fourth of the unknowns (penalty_hct.edp -symmetry quarter).
  const bool quarter = circle_at_centre(sc);
  prepare_runs(s, s.eps_levels, gradings, quarter);
  const size_t L = s.eps_levels.size();
  std::vector<PenaltyRun> ff_runs(s.eps_values.size() * L);
  std::vector<long> order;
  for (size_t k = s.eps_values.size(); k-- > 0;) order.push_back(static_cast<long>(k));
  order.insert(order.begin() + std::min<size_t>(1, order.size()), -1);
  struct OurValues { std::vector<double> w, f, w_noise, f_noise; };
  std::vector<OurValues> our(s.eps_values.size());
  on_workers(s.jobs, order.size(), [&](size_t t) {
    if (const long k = order[t]; k >= 0) {
      const double eps = s.eps_values[k];
      std::string start;
      for (size_t j = 0; j < L; ++j) {
        // A start is only ever the one this chain just wrote: never a file an earlier run left.
        const std::string saved = s.work + "/w_eps" + std::to_string(k) + "_mesh" + std::to_string(j) + ".txt";
        std::filesystem::remove(saved);
        const std::string how = j == 0 ? one_eps(eps) : " -continuation 0" + eps_arg(eps) + start;
        ff_runs[k * L + j] = penalty(s, s.eps_levels[j], "-scheme nonlinear -sampling disk -tol 1e-13" + how + " -save " + shell_word(saved),
                                     sc.cylinder->height, gradings[k], quarter);
        // A run that did not converge ends its chain; the comparison below says which and why.
        if (!ff_runs[k * L + j].converged) break;
        start = " -start-mesh " + shell_word(mesh(s, s.eps_levels[j], gradings[k], quarter)) + " -start " + shell_word(saved);
      }
      return;
    }
    for (int n : s.eps_ns) {
      const Grid whole = ours.grid(n);
      const SamplingSpec spec{SamplingKind::Gauss};
      const Problem p = make_problem(ours, part_of(whole, find_mirrors(ours, whole, spec)), spec);
      const double parts = p.grid.images();
      const std::vector<VectorXd> path = penalised_path_exactly(p, s.eps_values);
      for (size_t k = 0; k < path.size(); ++k) {
        const double eps = s.eps_values[k];
        const double mw = extremum_of_w(p, path[k], 1).value;
        const PenaltyRule rule = penalty_rule(p, &path[k]);
        const double force = parts * penalised_force(p, rule, path[k], eps);
        our[k].w.push_back(mw), our[k].f.push_back(force);
        our[k].w_noise.push_back(1e-12 * std::abs(mw));
        our[k].f_noise.push_back(parts * rule.weights.sum() * 1e-12 * std::abs(mw) / eps);
      }
    }
  });
  for (size_t k = 0; k < s.eps_values.size(); ++k) {
    const double eps = s.eps_values[k];
    std::vector<double> fw, ff, fwn, ffn;
    for (size_t j = 0; j < s.eps_levels.size(); ++j) {
      const int n = s.eps_levels[j];
      const PenaltyRun& r = ff_runs[k * s.eps_levels.size() + j];
      if (!r.converged) throw std::runtime_error("penalty_hct.edp did not converge at eps = " + fmt("%g", eps) + ": " + r.why);
      for (const PenaltyLevel& l : r.levels)
        if (l.stopped_at_roundoff > 0) {
          ++part.roundoff_stops;
          if (l.last_step > part.roundoff_step) part.roundoff_step = l.last_step, part.roundoff_estimate = l.stopped_at_roundoff;
        }
      part.eps_runs.push_back({kFreefemCode, 4 * n, r.h, r.max_w, r.force, r.max_w_roundoff, r.force_roundoff});
      fw.push_back(r.max_w), ff.push_back(r.force);
      fwn.push_back(r.max_w_roundoff), ffn.push_back(r.force_roundoff);
    }
    for (size_t j = 0; j < s.eps_ns.size(); ++j)
      part.eps_runs.push_back({kOurDiskCode, s.eps_ns[j], 1.0 / s.eps_ns[j], our[k].w[j], our[k].f[j], our[k].w_noise[j], our[k].f_noise[j]});
    EpsComparison c{eps, extrapolate(fw, fwn), extrapolate(ff, ffn), extrapolate(our[k].w, our[k].w_noise),
                    extrapolate(our[k].f, our[k].f_noise), {}, {}};
    // A steady bar compares two triples that share the order observed; each bar here also carries how
    // far its limit moves with the order (richardson.hpp: order_doubt), so that orders that agree by
    // chance cannot make the check stricter than the codes are.
    for (Extrapolation* e : {&c.ff_w, &c.ff_f, &c.our_w, &c.our_f}) e->bar += e->order_doubt;
    c.w = compare_limits(c.ff_w, c.our_w);
    c.f = compare_limits(c.ff_f, c.our_f);
    part.ok = part.ok && c.w.agree && c.f.agree;
    part.comparisons.push_back(c);
  }
}

// ---- 2'. the rate w_eps -> w against each code's exact answer with the same discrete constraint ---
void run_rate(const Setup& s, EpsPart& part) {
  auto& rate = part.rate;
  auto& rate_noise = part.rate_noise;
  bool& rate_ok = part.rate_ok;
  const Scene& sc = s.scene;

  std::cerr << "crosscheck_penalty: the rate w_eps -> w (eps down to " << s.rate_eps.back() << ")\n";
  const nlohmann::json ff_exact = run_freefem(s.exact, mesh(s, s.rate_level), scene_args(sc, points(s)), s.work + "/exact.json");
  if (!ff_exact.at("converged").get<bool>()) throw std::runtime_error("contact_hct.edp did not settle");
  const double ff_w0 = ff_exact.at("max_w").get<double>(), ff_f0 = ff_exact.at("total_contact_force").get<double>();
  const double ff_h = ff_exact.at("hmax").get<double>();
  rate_noise = {2 * freefem_roundoff(ff_h, ff_w0), 2 * freefem_roundoff(ff_h, ff_f0), 0, 0};
  const CheckValues our_exact = solve_ours(sc, s.rate_n, SamplingSpec{SamplingKind::Nodes});
  rate_noise[2] = 2 * exact_solve_roundoff(s.rate_n, our_exact.max_w);
  rate_noise[3] = 2 * exact_solve_roundoff(s.rate_n, our_exact.force);
  const auto [p, path] = our_path(sc, s.rate_n, SamplingKind::Nodes, s.rate_eps.back());
  for (double eps : s.rate_eps) {
    const PenaltyRun r = penalty(s, s.rate_level, "-scheme nonlinear -sampling vertices -tol 1e-14" + one_eps(eps), sc.cylinder->height);
    if (!r.converged) throw std::runtime_error("penalty_hct.edp did not converge at eps = " + fmt("%g", eps) + ": " + r.why);
    const VectorXd& w = at_eps(path, eps);
    rate.push_back({ff_w0 - r.max_w, ff_f0 - r.force, our_exact.max_w - max_nodal_abs(w),
                    our_exact.force - total_contact_force(p, contact_force_density(p, w, eps))});
  }
  // w_eps -> w at the rate eps: each decade divides the difference by 10 once the contact set of
  // w_eps is that of w (the last three decades here).
  for (size_t k = rate.size() - 3; k + 1 < rate.size(); ++k)
    for (int q = 0; q < 4; ++q) rate_ok = rate_ok && std::abs(rate[k][q] / rate[k + 1][q] - 10) <= 1;
  part.ok = part.ok && rate_ok;
}

// ---- 3. Fig. 2 from FreeFEM at each R of results/fig2.csv, beside ours on its finest grid -------
struct Fig2Part {
  std::vector<Fig2Row> fig2;
  int our_n = 0;
  double fig2_linearity = 0;
  EpsComparison judged;  // the fixed-eps comparison at Fig. 2's eps and the paper's R
  bool ok = true;
};
// Whether eps is Fig. 2's (the eps values are typed in, so equal to the last digit).
bool is_fig2_eps(const Setup& s, double eps) { return std::abs(eps - s.fig2_eps) <= 1e-12 * s.fig2_eps; }
Fig2Part run_fig2(const Setup& s, const CsvTable& ours_fig2, const EpsPart& eps) {
  Fig2Part part;
  auto& fig2 = part.fig2;
  std::cerr << "crosscheck_penalty: Fig. 2 (FreeFEM at eps = " << s.fig2_eps << ")\n";
  for (size_t r : ours_fig2.where("sampling", "nodes")) part.our_n = std::max(part.our_n, static_cast<int>(ours_fig2.number(r, "n")));
  for (size_t r : ours_fig2.where("sampling", "nodes")) {
    if (static_cast<int>(ours_fig2.number(r, "n")) != part.our_n) continue;
    const double R = ours_fig2.number(r, "R");
    const PenaltyRun f = penalty(s, s.fig2_level, "-scheme nonlinear -tol 1e-13" + one_eps(s.fig2_eps), R);
    if (!f.converged) throw std::runtime_error("penalty_hct.edp did not converge for Fig. 2 at R = " + fmt("%g", R) + ": " + f.why);
    fig2.push_back({R, f.max_w, f.max_m12, f.force, ours_fig2.number(r, "max_w"), ours_fig2.number(r, "max_m12"),
                    ours_fig2.number(r, "force")});
  }
  // Each code's figure above comes from one mesh, so their difference is mostly the two meshes'. The
  // figure is judged in the mesh's limit instead: at Fig. 2's eps and the paper's R, by the fixed-eps
  // comparison (both codes' Richardson limits of the penalty over the true disk, D30), and at every
  // other R by linearity, which (2) with f = 0 makes exact. max |m12| at the rim and the nodal
  // maximum of xi depend on the grid by nature: shown, not judged.
  const EpsComparison* judged = nullptr;
  for (const EpsComparison& c : eps.comparisons)
    if (is_fig2_eps(s, c.eps)) judged = &c;
  if (!judged) throw std::logic_error("Fig. 2 is judged by the fixed-eps comparison at its eps, which was not run");
  part.judged = *judged;
  // And FreeFEM's quantities are linear in R, as the paper's Fig. 2 shows and (2) implies for f = 0.
  for (const Fig2Row& f : fig2)
    part.fig2_linearity = std::max({part.fig2_linearity, rel(f.ff_w / f.R, fig2[0].ff_w / fig2[0].R),
                                    rel(f.ff_force / f.R, fig2[0].ff_force / fig2[0].R), rel(f.ff_m12 / f.R, fig2[0].ff_m12 / fig2[0].R)});
  part.ok = judged->w.agree && judged->f.agree && part.fig2_linearity <= kLinearity;
  return part;
}

// ---- the files ----------------------------------------------------------------------------------
std::string table_csv(const Setup& s, const TablePart& part) {
  const auto& table = part.table;
  std::ostringstream tcsv;
  tcsv << "# Written by build/crosscheck_penalty (make crosscheck). Iterations of the linear scheme (5a) over the\n"
          "# whole continuation eps_s = 0.1 * 10^-s with both stopping rules at OS, the paper's obstacle, w = 0 to start.\n"
          "# paper, glt: published (h = 1/4); ours_nodes, ours_gauss: results/table.csv (h = 1/4); freefem_n<k>: \n"
          "# reference/penalty_hct.edp, vertex sampling, on the gmsh mesh with 4k cells per quarter circle (-1: not converged).\n";
  tcsv << "tolerance,paper,glt,ours_nodes,ours_gauss";
  for (int n : s.table_levels) tcsv << ",freefem_n" << n;
  tcsv << "\n";
  for (const TableRow& t : table) {
    tcsv << fmt("%g", t.paper.tolerance) << "," << t.paper.iterations << "," << t.paper.iterations_glt << ","
         << t.ours_nodes << "," << t.ours_gauss;
    for (int c : t.freefem) tcsv << "," << c;
    tcsv << "\n";
  }
  return tcsv.str();
}

std::string eps_csv(const Setup& s, const EpsPart& part) {
  const auto& eps_runs = part.eps_runs;
  const auto& comparisons = part.comparisons;
  std::ostringstream ecsv;
  ecsv << "# Written by build/crosscheck_penalty (make crosscheck). The exact discrete penalised solution w_eps at\n"
          "# fixed eps (the paper's obstacle, f = 0), the penalty integrated over the true disk (D30): FreeFEM\n"
          "# (penalty_hct.edp -sampling disk, (3a); cells per quarter circle) and this code (bfs-disk; n squares per side).\n"
          "# max_w: FreeFEM's largest vertex value, ours the field's maximum (both at the centre here);\n"
          "# force = the penalty force eps^-1 (phi - w)^+ integrated over the disk.\n";
  ecsv << "eps,code,cells,h,max_w,force\n";
  for (size_t k = 0, i = 0; k < comparisons.size(); ++k)
    for (size_t j = 0; j < s.eps_levels.size() + s.eps_ns.size(); ++j, ++i) {
      const EpsRun& r = eps_runs[i];
      // to the digits each code's round-off leaves (FreeFEM's estimate from its residual; ours, Newton's floor)
      ecsv << fmt("%g", comparisons[k].eps) << "," << r.code << "," << r.cells << "," << fmt("%.6g", r.h) << ","
           << fmt_above(r.max_w, r.w_noise, 10, 'g') << "," << fmt_above(r.force, r.f_noise, 10, 'g') << "\n";
    }
  return ecsv.str();
}

// A difference, a tolerance and a tolerance over the value, each printed to the digits its round-off
// leaves (a digit below that differs from machine to machine, and from one FreeFEM build to the next).
std::string difference_text(const Agreement& a) { return fmt_above(a.difference, a.difference_noise, 2); }
std::string tolerance_text(const Agreement& a) { return fmt_above(a.tolerance, a.tolerance_noise, 2); }
std::string relative_text(const Agreement& a, double value) {
  return fmt_above(a.tolerance / std::abs(value), a.tolerance_noise / std::abs(value), 2);
}
std::string relative_difference_text(const Agreement& a, double value) {
  return fmt_above(a.difference / std::abs(value), a.difference_noise / std::abs(value), 2);
}

// The comparison itself, a row per eps and quantity: what the document quotes and check-results reads.
std::string limits_csv(const EpsPart& part) {
  std::ostringstream csv;
  csv << "# Written by build/crosscheck_penalty (make crosscheck). Each code's Richardson limit of the penalised\n"
         "# problem at fixed eps (the penalty over the true disk, D30) with its bar (where steady, (D13)'s bar plus how far\n"
         "# the limit moves with the order inside the steady spread, richardson.hpp's order_doubt); steady = 1 where the observed\n"
         "# order is steady (order: the last one, else empty); tolerance = the sum of the bars; relative = tolerance\n"
         "# over our limit, the smallest relative change of the scene the row detects; agree = difference <= tolerance.\n";
  csv << "eps,quantity,freefem_limit,freefem_bar,freefem_steady,freefem_order,ours_limit,ours_bar,ours_steady,"
         "ours_order,difference,tolerance,relative,agree\n";
  auto order = [](const Extrapolation& e) {
    return e.steady ? format_order(e.orders.back(), e.order_noise.back()) : std::string();
  };
  for (const EpsComparison& c : part.comparisons)
    for (int q = 0; q < 2; ++q) {
      const Extrapolation& ff = q == 0 ? c.ff_w : c.ff_f;
      const Extrapolation& us = q == 0 ? c.our_w : c.our_f;
      const Agreement& a = q == 0 ? c.w : c.f;
      csv << fmt("%g", c.eps) << "," << (q == 0 ? "max_w" : "force") << ","
          << fmt_above(ff.limit, ff.limit_noise, 10, 'g') << "," << fmt_above(ff.bar, ff.bar_noise, 2) << ","
          << ff.steady << "," << order(ff) << "," << fmt_above(us.limit, us.limit_noise, 10, 'g') << ","
          << fmt_above(us.bar, us.bar_noise, 2) << "," << us.steady << "," << order(us) << ","
          << difference_text(a) << "," << tolerance_text(a) << "," << relative_text(a, us.limit) << "," << a.agree << "\n";
    }
  return csv.str();
}

std::string fig2_csv(const Setup& s, const Fig2Part& part) {
  const auto& fig2 = part.fig2;
  const int our_n = part.our_n;
  std::ostringstream fcsv;
  fcsv << "# Written by build/crosscheck_penalty (make crosscheck). Fig. 2's quantities against R at eps = "
       << fmt("%g", s.fig2_eps) << ", (3a), nu = 0.3:\n# FreeFEM on the mesh with " << 4 * s.fig2_level
       << " cells per quarter circle (max over vertices; m12 the largest over the triangles at a vertex) and ours from\n"
          "# results/fig2.csv at h = 1/" << our_n << " (nodal sampling; m12 averaged over the elements at a node).\n";
  fcsv << "R,freefem_max_w,freefem_max_m12,freefem_force,ours_max_w,ours_max_m12,ours_force\n";
  for (const Fig2Row& f : fig2)
    fcsv << fmt("%g", f.R) << "," << fmt("%.7e", f.ff_w) << "," << fmt("%.7e", f.ff_m12) << "," << fmt("%.7e", f.ff_force)
         << "," << fmt("%.7e", f.our_w) << "," << fmt("%.7e", f.our_m12) << "," << fmt("%.7e", f.our_force) << "\n";

  return fcsv.str();
}

std::string table_md(const Setup& s, const TablePart& part, const CsvTable& ours_contraction, double lambda1) {
  const auto& table = part.table;
  const auto& eigen = part.eigen;
  // Our factors at the eps FreeFEM's are measured at, from the contraction check (results/contraction.csv).
  auto our_row = [&](const std::string& sampling) {
    for (size_t r : ours_contraction.where("sampling", sampling))
      if (ours_contraction.text(r, "n") == "4" && ours_contraction.number(r, "eps") == kEigenEps) return r;
    throw std::runtime_error(ours_contraction.path + " has no h = 1/4, eps = " + fmt("%g", kEigenEps) + " row for " + sampling);
  };
  std::ostringstream md;
  md << "### The table\n\n| OS | paper | GLT | ours, nodes | ours, Gauss |";
  for (int n : s.table_levels) md << " FreeFEM, " << 4 * n << " cells |";
  md << "\n|---:|---:|---:|---:|---:|";
  for (size_t k = 0; k < s.table_levels.size(); ++k) md << "---:|";
  md << "\n";
  for (const TableRow& t : table) {
    md << "| " << fmt_exact_e(t.paper.tolerance) << " | " << t.paper.iterations << " | " << t.paper.iterations_glt << " | "
       << t.ours_nodes << " | " << t.ours_gauss << " |";
    for (int c : t.freefem) md << " " << (c < 0 ? std::string("not converged") : std::to_string(c)) << " |";
    md << "\n";
  }
  md << "\nTable: " << words("crosscheck_penalty.table_caption") << "\n";
  md << "\n| discretisation | $h$ | lambda_1h | measured factor | 1/(1 + eps lambda_1h) |\n|---|---:|---:|---:|---:|\n";
  for (const char* sampling : {"nodes", "gauss"}) {
    const size_t r = our_row(sampling);
    md << "| ours, " << (std::string(sampling) == "gauss" ? "Gauss" : "nodes") << " | 1/4 | "
       << fmt("%.4f", ours_contraction.number(r, "lambda_1h")) << " | " << ours_contraction.text(r, "measured_no_contact")
       << " | " << ours_contraction.text(r, "q") << " |\n";
  }
  auto ff_row = [&](const EigenCheck& e) {
    md << "| FreeFEM, " << 4 * e.level << " cells per quarter circle | " << fmt("%.3f", e.h) << " | " << fmt("%.4f", e.lambda1h) << " | "
       << fmt_above(e.measured, e.noise, 10, 'g') << " | " << fmt("%.7f", e.q) << (e.ok ? "" : " (differs)") << " |\n";
  };
  // The paper's table sits on its two coarsest meshes; the finer ones serve the limit, in a section
  // of their own (the document's Part I shows this one).
  for (const EigenCheck& e : eigen)
    if (std::count(s.table_levels.begin(), s.table_levels.end(), e.level)) ff_row(e);
  md << "| continuum (Bjørstad and Tjøstheim 1999) | 0 | " << fmt("%.4f", lambda1) << " | — | — |\n";
  md << "\nTable: " << words("crosscheck_penalty.eigen_caption", {{"eps", fmt("%g", kEigenEps)}}) << "\n\n";
  double noise = 0;
  for (const EigenCheck& e : eigen) noise = std::max(noise, e.noise);
  md << words("crosscheck_penalty.eigen_judged", {{"tol", fmt("%g", kEigenTol)}, {"noise", fmt_up(noise)}}) << "\n\n";
  md << "### lambda_1h as h -> 0\n\n| discretisation | $h$ | lambda_1h | measured factor | 1/(1 + eps lambda_1h) |\n|---|---:|---:|---:|---:|\n";
  for (const EigenCheck& e : eigen) ff_row(e);
  for (size_t k = 0; k < s.eigen_ns.size(); ++k)
    md << "| ours, Gauss | 1/" << s.eigen_ns[k] << " | " << fmt("%.4f", part.our_lambdas[k]) << " | — | "
       << fmt("%.7f", 1 / (1 + kEigenEps * part.our_lambdas[k])) << " |\n";
  for (const EigenLimit& l : part.limits)
    md << "| " << (l.who == "ours" ? "ours, Gauss" : l.who) << ", h -> 0 | 0 | " << brief(l.limit) << " | — | — |\n";
  md << "| continuum (Bjørstad and Tjøstheim 1999) | 0 | " << fmt("%.4f", lambda1) << " | — | — |\n";
  md << "\nTable: " << words("crosscheck_penalty.eigen_limit_caption", {{"eps", fmt("%g", kEigenEps)}}) << "\n\n";
  // Each code's lambda_1h in the limit against the published value: the table's rate as h -> 0.
  const EigenLimit& ff = part.limits.at(0);
  const EigenLimit& ours = part.limits.at(1);
  md << words("crosscheck_penalty.eigen_limit_judged",
              {{"ff_cells", std::to_string(4 * s.eigen_levels.front()) + " ... " + std::to_string(4 * s.eigen_levels.back())},
               {"n", std::to_string(s.eigen_ns.front()) + " ... " + std::to_string(s.eigen_ns.back())},
               {"ff", brief(ff.limit)},
               {"ours", brief(ours.limit)},
               {"lambda1", fmt("%.4f", lambda1)},
               {"ff_judged", ff.ok ? "agrees" : "DIFFERS"},
               {"ours_judged", ours.ok ? "agrees" : "DIFFERS"}})
     << "\n\n";
  return md.str();
}

std::string eps_md(const Setup& s, const EpsPart& part) {
  const auto& comparisons = part.comparisons;
  std::ostringstream md;
  // "agree" in every row says nothing a row can be read for: a row that differs is marked instead.
  md << "### Fixed eps\n\n| eps | quantity | FreeFEM | this code | difference | tolerance |\n"
        "|---:|---|---|---|---:|---:|\n";
  for (const EpsComparison& c : comparisons) {
    md << "| " << fmt("%g", c.eps) << " | max w | " << brief(c.ff_w) << " | " << brief(c.our_w) << " | "
       << difference_text(c.w) << (c.w.agree ? "" : " **DIFFER**") << " | " << tolerance_text(c.w) << " |\n";
    md << "| " << fmt("%g", c.eps) << " | force | " << brief(c.ff_f) << " | " << brief(c.our_f) << " | "
       << difference_text(c.f) << (c.f.agree ? "" : " **DIFFER**") << " | " << tolerance_text(c.f) << " |\n";
  }
  int steady = 0;  // the caption says how the cells were made, as they were
  for (const EpsComparison& c : comparisons)
    for (const Extrapolation* e : {&c.ff_w, &c.ff_f, &c.our_w, &c.our_f}) steady += e->steady;
  md << "\nTable: "
     << words("crosscheck_penalty.eps_caption", {{"cells_first", std::to_string(4 * s.eps_levels.front())},
                                                 {"cells_last", std::to_string(4 * s.eps_levels.back())},
                                                 {"n_first", std::to_string(s.eps_ns.front())},
                                                 {"n_last", std::to_string(s.eps_ns.back())},
                                                 {"grade_first", fmt("%.3g", layer_grading(s.scene, s.eps_values.front()).grade)},
                                                 {"grade_last", fmt("%.3g", layer_grading(s.scene, s.eps_values.back()).grade)}})
     << " " << words(steady == 0 ? "crosscheck_penalty.eps_cells_unsteady" : "crosscheck_penalty.eps_cells_steady");
  if (part.roundoff_stops > 0)
    md << " " << words("crosscheck_penalty.eps_roundoff_stops", {{"count", std::to_string(part.roundoff_stops)},
                                                                 {"step", fmt("%.3g", part.roundoff_step)},
                                                                 {"estimate", fmt("%.3g", part.roundoff_estimate)}});
  md << "\n";
  // With f = 0, (2) is positively homogeneous in (phi, w): a relative change d of the obstacle's height
  // changes w_eps and the force by the same d. So a row resolves a change of the scene of its
  // tolerance over its value, and no smaller.
  double worst_w = 0, worst_f = 0, best_w = INFINITY;
  std::string worst_w_text, worst_f_text, best_w_text;
  for (const EpsComparison& c : comparisons) {
    const double rw = c.w.tolerance / std::abs(c.our_w.limit), rf = c.f.tolerance / std::abs(c.our_f.limit);
    const std::string tw = relative_text(c.w, c.our_w.limit);
    if (rw > worst_w) worst_w = rw, worst_w_text = tw;
    if (rf > worst_f) worst_f = rf, worst_f_text = relative_text(c.f, c.our_f.limit);
    // The lower end is the smallest bound the rows print: a row below round-off claims its bound.
    const double printed = std::stod(without_bound(tw));
    if (printed < best_w) best_w = printed, best_w_text = tw;
  }
  md << "\n"
     << words("crosscheck_penalty.resolution",
              {{"w_range", best_w_text == worst_w_text ? worst_w_text : best_w_text + " to " + worst_w_text},
               {"w_target", worst_w <= 1e-7 ? "met" : "NOT met"},
               {"f_worst", worst_f_text},
               {"f_target", worst_f <= 1e-6 ? "met" : "NOT met"}})
     << "\n";
  return md.str();
}

std::string rate_md(const Setup& s, const EpsPart& part) {
  const auto& rate = part.rate;
  const auto& rate_noise = part.rate_noise;
  const bool rate_ok = part.rate_ok;
  std::ostringstream md;
  md << "| eps | FreeFEM: $\\max w - \\max w_\\varepsilon$ | $F - F_\\varepsilon$ | this code: $\\max w - \\max w_\\varepsilon$ "
        "| $F - F_\\varepsilon$ |\n"
        "|---:|---:|---:|---:|---:|\n";
  for (size_t k = 0; k < rate.size(); ++k)
    md << "| " << fmt("%g", s.rate_eps[k]) << " | " << fmt_above(rate[k][0], rate_noise[0], 3) << " | "
       << fmt_above(rate[k][1], rate_noise[1], 3) << " | " << fmt_above(rate[k][2], rate_noise[2], 3) << " | "
       << fmt_above(rate[k][3], rate_noise[3], 3) << " |\n";
  md << "\nTable: "
     << words("crosscheck_penalty.rate_caption", {{"cells", std::to_string(4 * s.rate_level)}, {"n", std::to_string(s.rate_n)}})
     << " " << words(rate_ok ? "crosscheck_penalty.rate_met" : "crosscheck_penalty.rate_not_met") << "\n\n";
  return md.str();
}

std::string fig2_md(const Setup& s, const Fig2Part& part) {
  const auto& fig2 = part.fig2;
  const EpsComparison& c = part.judged;
  std::ostringstream md;
  md << "### The paper's Fig. 2\n\n| $R$ | $\\max w$: FreeFEM | ours | $\\max\\lvert m_{12}\\rvert$: FreeFEM | ours | force: FreeFEM | ours |\n"
        "|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Fig2Row& f : fig2)
    md << "| " << fmt("%g", f.R) << " | " << fmt("%.6f", f.ff_w) << " | " << fmt("%.6f", f.our_w) << " | "
       << fmt("%.5f", f.ff_m12) << " | " << fmt("%.5f", f.our_m12) << " | " << fmt("%.4f", f.ff_force) << " | "
       << fmt("%.4f", f.our_force) << " |\n";
  md << "\nTable: "
     << words("crosscheck_penalty.fig2_caption",
              {{"cells", std::to_string(4 * s.fig2_level)}, {"n", std::to_string(part.our_n)}, {"eps", fmt("%g", s.fig2_eps)}})
     << "\n";
  md << "\n"
     << words("crosscheck_penalty.fig2_judged",
              {{"R", fmt("%g", s.scene.cylinder->height)},
               {"eps", fmt("%g", s.fig2_eps)},
               // Where FreeFEM's values have no steady order its "limit" is its finest mesh and its bar the
               // last increment (richardson.hpp): the reader is told, since the sentence says "limits".
               {"ff_unsteady", c.ff_w.steady && c.ff_f.steady ? "" : " " + words("crosscheck_penalty.fig2_ff_unsteady")},
               {"ff_w", brief(c.ff_w)},
               {"our_w", brief(c.our_w)},
               {"w_diff", relative_difference_text(c.w, c.our_w.limit)},
               {"w_tol", relative_text(c.w, c.our_w.limit)},
               {"w_missed", c.w.agree ? "" : " : NOT within"},
               {"ff_f", brief(c.ff_f)},
               {"our_f", brief(c.our_f)},
               {"f_diff", relative_difference_text(c.f, c.our_f.limit)},
               {"f_tol", relative_text(c.f, c.our_f.limit)},
               {"f_missed", c.f.agree ? "" : " : NOT within"},
               {"linear", part.fig2_linearity <= kLinearity ? "agree" : "DO NOT agree"},
               {"heights", std::to_string(fig2.size())},
               {"linearity", fmt("%g", kLinearity)}})
     << "\n";
  return md.str();
}

// Whether --parts asks for `part`.
bool wants(const Setup& s, const std::string& part) {
  for (const std::string& p : split_csv_line(s.parts))
    if (p == part) return true;
  return false;
}
// What is wrong with the options, naming the option; empty if nothing.
std::string refusal(const Setup& s) {
  std::string bad;
  for (size_t k = 0; k < s.eps_values.size(); ++k)
    if (!(s.eps_values[k] > 0 && s.eps_values[k] <= 0.01) || (k > 0 && !(s.eps_values[k] < s.eps_values[k - 1])))
      bad = "--eps: the values must decrease and lie in (0, 0.01]";
  if (s.eps_values.empty()) bad = "--eps: give at least one value";
  for (size_t k = 0; k < s.eps_ns.size(); ++k)
    if (s.eps_ns[k] < 8 || s.eps_ns[k] > 1024 || s.eps_ns[k] % 2 || (k > 0 && s.eps_ns[k] <= s.eps_ns[k - 1]))
      bad = "--grids: each an even number from 8 to 1024, increasing";
  if (s.eps_ns.size() < 3) bad = "--grids: at least three grids (an observed order needs three)";
  for (size_t k = 0; k < s.eps_levels.size(); ++k)
    if (s.eps_levels[k] < 1 || s.eps_levels[k] > 32 || (k > 0 && s.eps_levels[k] <= s.eps_levels[k - 1]))
      bad = "--meshes: each from 1 to 32, increasing";
  if (s.eps_levels.size() < 3) bad = "--meshes: at least three meshes (an observed order needs three)";
  if (!std::isfinite(s.perturb) || std::abs(s.perturb) >= 0.5) bad = "--perturb: a finite number of size below 0.5";
  if (!bad.empty()) return bad;
  for (const std::string& part : split_csv_line(s.parts))
    if (part != "table" && part != "eps" && part != "rate" && part != "fig2") return "--parts: unknown part \"" + part + "\" (table, eps, rate, fig2)";
  if (wants(s, "fig2") && !(wants(s, "eps") && std::any_of(s.eps_values.begin(), s.eps_values.end(), [&](double e) { return is_fig2_eps(s, e); })))
    return "--parts: fig2 is judged by the fixed-eps comparison at its eps, " + fmt("%g", s.fig2_eps) + ": give eps in --parts and that value in --eps";
  return "";
}

}  // namespace


int main(int argc, char** argv) {
  CLI::App app{"The penalty cross-check: FreeFEM's penalty script (reference/penalty_hct.edp) against the "
               "paper's table, this code's w_eps at fixed eps, and Fig. 2. " +
               std::string(kExitStatusHelp)};
  Setup s;
  app.add_option("--out", s.out, "folder for crosscheck_penalty.md and its tables")->capture_default_str();
  app.add_option("--work", s.work, "folder for FreeFEM's meshes, points and JSON")->capture_default_str();
  app.add_option("--results", s.results, "folder with table.csv, contraction.csv and fig2.csv (ours)")
      ->capture_default_str();
  app.add_option("--reference", s.reference, "folder with the paper's numbers and the FreeFEM scripts")
      ->capture_default_str();
  app.add_option("--parts", s.parts, "which checks to run, comma-separated: table, eps, rate, fig2 (the report holds only those, and only their CSVs are rewritten)")
      ->capture_default_str();
  app.add_option("--eps", s.eps_values, "fixed eps: the values compared, decreasing, each at most 0.01")->delimiter(',')->capture_default_str();
  app.add_option("--grids", s.eps_ns, "fixed eps: our grids (squares per side, even, coarse to fine, at least three)")
      ->delimiter(',')->capture_default_str();
  app.add_option("--meshes", s.eps_levels, "fixed eps: FreeFEM's meshes (the .geo's n: 4 n cells per quarter circle; "
                 "coarse to fine, at least three)")->delimiter(',')->capture_default_str();
  app.add_option("--jobs", s.jobs, "FreeFEM runs at a time (the table and fixed eps)")->check(CLI::Range(1, 64))->capture_default_str();
  app.add_option("--perturb", s.perturb, "fixed eps: ours solves with the obstacle's height times 1 + this, to show that "
                 "the check detects a changed scene (it must then say the codes differ)")->capture_default_str();
  if (int code = parse_options(app, argc, argv, "crosscheck_penalty"); code >= 0) return code;
  if (const std::string bad = refusal(s); !bad.empty()) {
    std::cerr << "crosscheck_penalty: bad input: " << bad << "\n";
    return kBadInput;
  }
  s.geo = s.reference + "/square_with_circle.geo";
  s.quarter_geo = s.reference + "/quarter_square_with_circle.geo";
  s.penalty = s.reference + "/penalty_hct.edp";
  s.exact = s.reference + "/contact_hct.edp";
  clean_up_on_interrupt("crosscheck_penalty");
  try {
    for (const char* f : {"crosscheck_penalty.md", "crosscheck_penalty_table.csv", "crosscheck_penalty_eps.csv",
                          "crosscheck_penalty_limits.csv", "crosscheck_penalty_fig2.csv"})
      check_writable(s.out + "/" + f);
    std::filesystem::create_directories(s.work);
    const auto numbers = read_paper_numbers(s.reference + "/paper_numbers.csv");
    const std::vector<PublishedRow> paper = read_paper_table(s.reference + "/paper_table.csv");
    const CsvTable ours_table = read_csv_table(s.results + "/table.csv");
    const CsvTable ours_contraction = read_csv_table(s.results + "/contraction.csv");
    const CsvTable ours_fig2 = read_csv_table(s.results + "/fig2.csv");
    const double lambda1 = plate_constant(s.reference, "lambda1");

    TablePart table;
    EpsPart eps;
    Fig2Part fig2;
    if (wants(s, "table")) table = run_table(s, paper, ours_table, lambda1);
    if (wants(s, "eps")) run_fixed_eps(s, eps);
    if (wants(s, "rate")) run_rate(s, eps);
    if (wants(s, "fig2")) fig2 = run_fig2(s, ours_fig2, eps);
    const bool all_ok = table.ok && eps.ok && fig2.ok;

    std::string md = "<!-- Written by build/crosscheck_penalty (make crosscheck); do not edit. -->\n\n";
    if (wants(s, "table")) md += table_md(s, table, ours_contraction, lambda1);
    if (wants(s, "eps")) md += eps_md(s, eps);
    if (wants(s, "rate")) md += rate_md(s, eps);
    if (wants(s, "fig2")) md += fig2_md(s, fig2);
    md += "\n" + words(all_ok ? "crosscheck_penalty.verdict_agree" : "crosscheck_penalty.verdict_fail") + "\n";
    if (wants(s, "table")) write_file_atomically(s.out + "/crosscheck_penalty_table.csv", table_csv(s, table));
    if (wants(s, "eps")) write_file_atomically(s.out + "/crosscheck_penalty_eps.csv", eps_csv(s, eps));
    if (wants(s, "eps")) write_file_atomically(s.out + "/crosscheck_penalty_limits.csv", limits_csv(eps));
    if (wants(s, "fig2")) write_file_atomically(s.out + "/crosscheck_penalty_fig2.csv", fig2_csv(s, fig2));
    write_file_atomically(s.out + "/crosscheck_penalty.md", md);
    std::cerr << "crosscheck_penalty: " << (all_ok ? "every check agrees" : "some checks fail") << " (" << s.out
              << "/crosscheck_penalty.md)\n";
    return all_ok ? kSuccess : kNotConverged;
  } catch (const std::exception& e) {
    std::cerr << "crosscheck_penalty: " << e.what() << "\n";
    return kFailure;
  }
}
