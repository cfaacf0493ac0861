// contact_end_study: lift-off scenes with the field of each contact's end carried (contact_end.hpp)
// and each end located by the fit of the gap beyond it, a step towards issue 39 that `plate` does
// not take yet. Two modes.
// - Default: a plate lx x 1 over the paper's cylinder at its centre, solved on the quarter its
//   mirror lines leave (which holds one end, at pi + theta_e): rows averaged against graded clamped
//   splines on the contact arcs [theta_e, pi - theta_e] and its images, points a cell apart off
//   them and `--dense` per cell for four cells beyond each end (from `--skip` cells on); the space
//   widened by F_32 and F_52 at the end (attach_ends; --plain: not), and with --kink by (D31)'s
//   functions too; solved exactly (--refine: refined, D22); the end moved by the fit of the gap
//   from a quarter of a cell to `--fit-cells` beyond it (on s^(3/2), s^(5/2), s^(7/2), or the
//   powers of `--fit-powers`; at most half a cell a step) until it moves less than 1e-9, and with --consistent then pushed on, by bisection, to where no point beyond
//   it bears load. Prints, per grid, the end, max w (at the centre), the two coefficients, the
//   moves and the point rows beyond the end that push.
// - --whole (with --centre x,y): any such scene on the whole plate, every end carried and moved
//   (located_ends.hpp), from the contact of the default solve on the same grid.
//   build/contact_end_study --lx 2 --from 160 --to 320 --step 16 --kink
//   build/contact_end_study --whole --lx 1.5 --centre 0.6,0.45 --kink --from 96 --to 192 --step 48
// Not run by make: what it measures is in the closing notes of issue 39.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "active_set.hpp"
#include "contact.hpp"
#include "contact_end.hpp"
#include "dual_active_set.hpp"
#include "edge.hpp"
#include "extrema.hpp"
#include "located_ends.hpp"
#include "norms.hpp"
#include "rim_exchange.hpp"
#include "mirror.hpp"
#include "rim_rows.hpp"

using namespace plate;

namespace {

constexpr double kRadius = 0.25, kHeight = 0.0625;

struct Answer {
  bool converged = false;
  double max_w = 0, theta_e = 0;
  std::vector<double> coefficients;
  int pushing = 0;  // point rows beyond the end that carry load
  double nearest_push = 0, push_load = 0;  // the first of them: cells beyond the end, and its line load
};

bool with_kink = false;  // the space widened by (D31) too
bool refined = false;    // the refinement (D22)
double fit_cells = 6;    // the fit's reach beyond the end

// --fit-powers: end_shift's fit with other powers of s, the first two 3/2 and 5/2.
std::vector<double> fit_powers;
double shift_by_powers(const std::vector<double>& s, const std::vector<double>& gap) {
  Eigen::MatrixXd A(s.size(), fit_powers.size());
  Eigen::VectorXd b = Eigen::Map<const Eigen::VectorXd>(gap.data(), static_cast<Eigen::Index>(gap.size()));
  for (size_t i = 0; i < s.size(); ++i)
    for (size_t k = 0; k < fit_powers.size(); ++k) A(i, k) = std::pow(s[i], fit_powers[k]);
  const Eigen::VectorXd c = A.colPivHouseholderQr().solve(b);
  if (!(c[1] > 0)) throw std::invalid_argument("--fit-powers: the gap does not open like an end's");
  return -0.4 * c[0] / c[1];
}

// One solve with the end at theta_e; `fields` empty: the plain space. `shift` gets the fit's move of
// the end (an angle, at most half a cell). The end's cut-off is checked here against the quarter's
// mirror lines too, for the message; attach_ends checks it again.
Answer solve_once(const Scene& scene, int n, double theta_e, const std::vector<EndField>& fields, double dense, double skip, double& shift) {
  SamplingSpec spec{SamplingKind::Edge, EdgeRows{}};
  if (with_kink) spec.enrich.kind = EnrichSpec::Kind::Ring;
  const Grid whole = scene.grid(n);
  Problem p = make_problem(scene, part_of(whole, find_mirrors(scene, whole, spec)), spec);
  const Grid& g = p.grid;
  const double h = g.h, a = kRadius, cx = g.lx(), cy = g.ly();
  const int k = static_cast<int>(fields.size());
  const ContactEnd end{cx, cy, a, M_PI + theta_e, -1, 0.05, 0.1};
  const double ex = cx + a * std::cos(end.theta), ey = cy + a * std::sin(end.theta);
  if (std::min({cx - ex, cy - ey, ex, ey}) < end_reach(end))  // the mirror lines, and the clamped edges
    throw std::invalid_argument("--start: the end's cut-off would cross a mirror line or a clamped edge");
  ContactArcs contact;  // [theta_e, pi - theta_e] and its images
  contact.arcs = {{theta_e, M_PI - theta_e}, {M_PI + theta_e, 2 * M_PI - theta_e}};
  lay_out_for_ends(p, contact, dense, skip);
  if (k) attach_ends(p, std::vector<ContactEnd>(k, end), fields);
  ExactOptions o;
  o.refine = refined;
  const ExactResult r = solve_exact_rows(p, o, NodeSet{}, RowExchange{}, nullptr);
  const PlateField field(p, r.w);
  auto w_at = [&](double x, double y) { return field.at(x, y).w; };
  Answer out;
  out.converged = r.converged;
  out.max_w = w_at(cx, cy);
  out.theta_e = theta_e;
  for (int f = 0; f < k; ++f) out.coefficients.push_back(r.w[p.unknowns() - k + f]);
  for (int e = 0; e < p.sampling.edge_size(); ++e) {
    const double beyond = end.theta - p.sampling.edge.theta[e];  // the quarter's end is free for smaller angles
    if (p.sampling.rim_rows[e].point() && beyond > 0 && beyond < 4 * h / a && r.lambda[p.sampling.edge_begin + e] > 0) {
      if (!out.pushing++) out.nearest_push = beyond * a / h, out.push_load = r.lambda[p.sampling.edge_begin + e];
    }
  }
  // The gap beyond the end from a quarter of a cell to `fit_cells` cells, and the fit's move, at most
  // half a cell.
  std::vector<double> at, gap;
  for (int i = 0; i < 80; ++i) {
    const double s = (0.25 + (fit_cells - 0.25) * i / 79.0) * h, th = M_PI + theta_e - s / a;
    at.push_back(s), gap.push_back(w_at(cx + a * std::cos(th), cy + a * std::sin(th)) - kHeight);
  }
  shift = std::clamp(fit_powers.empty() ? end_shift(at, gap) : shift_by_powers(at, gap), -h / 2, h / 2) / a;
  return out;
}

// --whole: any cylinder's scene on the whole plate (located_ends.hpp), every end carried and moved,
// from the contact of the default solve on the same grid. Prints, per grid, max w (the extremum of
// the field) and the force, the ends' angles, the moves, and the pushing rows beyond each end.
int run_whole(const Scene& scene, int from, int to, int step, const EndsOptions& opt) {
  std::printf("%6s %16s %14s %6s  %s\n", "n", "max w", "force", "moves", "ends (theta, pushing, at)");
  for (int n = from; n <= to; n = step ? n + step : 2 * n) {
    try {
      const SceneSolution d = solve_exact_scene(scene, n, SamplingSpec{SamplingKind::Edge, EdgeRows{}}, ExactOptions{}, false);
      const double touch = std::max(1e-10 * max_nodal_abs(d.result.w.head(d.solved.grid.unknowns())), dip_below_edge(d.solved, d.result.w));
      const EndsSolve r = solve_located_ends(scene, n, rim_contact(d.solved, d.result.w, d.result.lambda, touch), ExactOptions{}, opt);
      if (!r.result.converged || !r.settled) {
        std::fprintf(stderr, "contact_end_study: n = %d: %s\n", n, r.result.converged ? "the ends did not settle" : "a solve did not converge");
        return 3;
      }
      const Extremum m = extremum_of_w(r.problem, r.result.w, 1);
      std::printf("%6d %16.12f %14.9f %6d ", n, m.value, total_contact_force(r.problem, r.result.lambda), r.moves);
      for (size_t k = 0; k < r.pushing.size(); ++k)
        std::printf(" (%.9f, %d, %.3f)", r.problem.ends[2 * k].theta, r.pushing[k], r.nearest_push[k]);
      std::printf("\n");
      std::fflush(stdout);
    } catch (const std::invalid_argument& e) {
      std::fprintf(stderr, "contact_end_study: n = %d: %s\n", n, e.what());
      return 2;
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The lift-off scene with the contact's ends carried and located (issue 39's next step)."};
  double lx = 2, start = 0.99, dense = 8, skip = 0;
  int from = 64, to = 512, step = 0;
  bool plain = false, consistent = false;
  app.add_option("--lx", lx, "the plate's length (height 1), the cylinder at its centre")->check(CLI::Range(1.2, 4.0));
  app.add_option("--start", start, "the first guess of theta_e, in radians")->check(CLI::Range(0.5, 1.5));
  app.add_option("--from", from, "cells along x on the first grid")->check(CLI::Range(32, 2048));
  app.add_option("--to", to, "cells along x on the last grid")->check(CLI::Range(32, 2048));
  app.add_option("--step", step, "cells added from grid to grid (0: doubled)")->check(CLI::Range(0, 512));
  app.add_option("--dense", dense, "point rows per cell for four cells beyond each end")->check(CLI::Range(1.0, 32.0));
  app.add_option("--skip", skip, "no dense point rows within this many cells beyond each end")->check(CLI::Range(0.0, 4.0));
  app.add_flag("--consistent", consistent, "then extend the contact by bisection until no point beyond an end pushes");
  app.add_flag("--kink", with_kink, "the kink of the line load carried too (D31)");
  app.add_flag("--refine", refined, "refine each solve (D22)");
  app.add_option("--fit-powers", fit_powers, "the fit's powers of s, from 3/2 and 5/2 (default 3/2, 5/2, 7/2)")->delimiter(',')->expected(3, 8);
  app.add_option("--fit-cells", fit_cells, "how far beyond the end the fit reads the gap, in cells")->check(CLI::Range(1.0, 12.0));
  app.add_flag("--plain", plain, "the plain space (the end still located by the fit)");
  bool whole = false;
  std::vector<double> centre;
  app.add_flag("--whole", whole, "the whole plate, every end carried (located_ends.hpp), from the default solve's contact");
  app.add_option("--centre", centre, "with --whole: the cylinder's centre (default the plate's)")->expected(2)->delimiter(',');
  CLI11_PARSE(app, argc, argv);
  if (whole) {
    if (refined || consistent || plain || skip > 0 || app.count("--start") || app.count("--fit-cells") || app.count("--fit-powers"))
      return std::fprintf(stderr, "contact_end_study: --whole takes --lx, --centre, --kink, --dense and the grids only\n"), 2;
    const double cx = centre.empty() ? lx / 2 : centre[0], cy = centre.empty() ? 0.5 : centre[1];
    EndsOptions opt;
    opt.dense = dense;
    if (with_kink) opt.enrich.kind = EnrichSpec::Kind::Ring;
    return run_whole(Scene::rectangle(lx, 1).over(Cylinder{cx, cy, kRadius, kHeight}), from, to, step, opt);
  }
  const Scene scene = Scene::rectangle(lx, 1).over(Cylinder{lx / 2, 0.5, kRadius, kHeight});
  const std::vector<EndField> fields = plain ? std::vector<EndField>{} : std::vector<EndField>{EndField::Gap32, EndField::Gap52};
  // pushing: point rows within four cells beyond the end that carry load; the first at `at` cells
  // beyond the end, with line load `load`.
  std::printf("%6s %12s %16s %12s %12s %6s %8s %7s %10s\n", "n", "theta_e", "max w", "c_32", "c_52", "moves", "pushing", "at", "load");
  for (int n = from; n <= to; n = step ? n + step : 2 * n) {
    double theta = start, shift = 0;
    Answer a;
    int moves = 0;
    for (; moves < 30; ++moves) {
      try {
        a = solve_once(scene, n, theta, fields, dense, skip, shift);
      } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "contact_end_study: n = %d, end at %.9f: %s\n", n, theta, e.what());
        return 2;
      }
      if (!a.converged) {
        std::fprintf(stderr, "contact_end_study: the solve on n = %d did not converge\n", n);
        return 3;
      }
      if (std::abs(shift) < 1e-9) break;
      theta -= shift;  // the quarter's end is at pi + theta_e, free for smaller angles
    }
    if (moves == 30) {
      std::fprintf(stderr, "contact_end_study: on n = %d the end still moved by %.2e after 30 moves\n", n, shift);
      return 3;
    }
    if (consistent && a.pushing) {  // the shortest extension of the contact at which no point beyond pushes
      const double cell = (lx / n) / kRadius;
      double lo = theta, hi = theta - 0.5 * cell;
      Answer b = solve_once(scene, n, hi, fields, dense, skip, shift);
      if (b.pushing) { std::fprintf(stderr, "still pushing half a cell on\n"); return 3; }
      for (int it = 0; it < 14; ++it) {
        const double mid = 0.5 * (lo + hi);
        Answer m = solve_once(scene, n, mid, fields, dense, skip, shift);
        if (m.pushing) lo = mid; else hi = mid, b = m;
      }
      a = b;
    }
    std::printf("%6d %12.9f %16.12f %12.4e %12.4e %6d %8d %7.4f %10.3e\n", n, a.theta_e, a.max_w,
                a.coefficients.empty() ? 0.0 : a.coefficients[0], a.coefficients.size() < 2 ? 0.0 : a.coefficients[1], moves,
                a.pushing, a.nearest_push, a.push_load);
    std::fflush(stdout);
  }
}
