// The exact solver as a user calls it: the hand-off between the two solvers, grid sequencing, rows
// on a circle laid out for the contact, and a scene solved on the part its mirror lines leave.
#include "active_set.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>

#include "contact.hpp"
#include "dual_active_set.hpp"
#include "norms.hpp"
#include "primal_dual.hpp"
#include "rim_exchange.hpp"
#include "stopwatch.hpp"

namespace plate {

ExactResult solve_exact(const Problem& p, const ExactOptions& o, NodeSet initial) {
  // Bounds on nodal values go to the primal-dual method; any other rows to the dual method.
  return p.sampling.nodal_bounds() ? solve_exact_nodes(p, o, std::move(initial)) : solve_exact_rows(p, o, initial);
}


namespace {
// @region grid-sequencing
// A fine sample starts held if the coarse solution, interpolated by its own Hermite cubics, lies on
// or below phi there: a coarse contact line predicts the fine one to within a cell. (`margin`
// also takes samples just above: the dual solver gives those a column of G, which costs little.)
NodeSet predict_active(const Problem& coarse, const VectorXd& wc, const Problem& fine, double margin) {
  NodeSet A(fine.phi.size(), 0);
  const PlateField field(coarse, wc);
  for (int q = 0; q < fine.phi.size(); ++q) {
    if (!std::isfinite(fine.phi[q])) continue;
    const double w = field.value_at(fine.sampling.x[q], fine.sampling.y[q]);
    A[q] = w <= fine.phi[q] + margin;
  }
  return A;
}
// @end grid-sequencing
}  // namespace

namespace {
// @region rim-follows-contact
// Eq. (D28): the rows on a circle fitted to the contact. The coarser grid's contact says where the
// plate touches the whole rim (periodic splines, as on the paper's scene) or which arcs it touches
// (splines there, points elsewhere). After each solve the layout is checked against the contact it
// found, and laid out again from it if the splines reach past the contact's end; points are added
// wherever the plate dips between point rows. After three layouts that do not fit, points alone.
ExactResult solve_rim(Problem& p, const ExactOptions& o, const Problem* coarse, const VectorXd& wc,
                      const VectorXd& lc, double margin, const NodeSet& predicted) {
  RimLayout layout;  // periodic
  // A row touches if it lies within the certificate's tolerance of the obstacle, or within the depth
  // the plate dips below it between rows: an averaged row cannot tell a gap smaller than that from
  // contact (on the paper's scene, n = 32, the diagonal's row lifts 5e-6 where the plate dips 8e-6).
  auto touch = [&](const Problem& q, const VectorXd& w) {
    return std::max(o.tol * std::max(max_nodal_abs(w.head(q.grid.unknowns())), 1e-300), dip_below_edge(q, w));
  };
  if (coarse && rim_follows_contact(*coarse) && !coarse->sampling.rim.periodic) {
    const ContactArcs c = rim_contact(*coarse, wc, lc, touch(*coarse, wc));
    if (!c.whole) layout = rim_layout_for(p, c);
  }
  Cholesky chol;  // one factor for every layout this grid tries
  chol.factorize(p.K);
  const RowExchange exchange = [&](Problem& q, const VectorXd& w, double slack) {
    const std::vector<double> at = rim_dips(q, w, slack);
    if (!at.empty()) append_rim_points(q, at);
    return static_cast<int>(at.size());
  };
  NodeSet initial = predicted;
  ExactResult r;
  int layouts = 0, exchanged = 0;
  for (int round = 0;; ++round) {
    if (!layout.periodic) {
      lay_out_rim(p, layout);
      ++layouts;
      initial = coarse && round == 0 ? predict_active(*coarse, wc, p, margin) : predict_active(p, r.w, p, margin);
    }
    r = solve_exact_rows(p, o, initial, layout.periodic ? RowExchange{} : exchange, &chol);
    exchanged += r.levels.back().exchanged;
    if (!r.converged || rim_layout_fits(p, r.w, r.lambda, touch(p, r.w))) break;
    layout = round < 2 ? rim_layout_for(p, rim_contact(p, r.w, r.lambda, touch(p, r.w))) : rim_points_only(p);
  }
  r.levels.back().layouts = layouts;
  r.levels.back().exchanged = exchanged;
  r.levels.back().factorizations = chol.factorizations();
  return r;
}
// @end rim-follows-contact
}  // namespace

ExactResult solve_sequenced(Problem& p, const ExactOptions& o) {
  validate(o);
  const Grid& g = p.grid;
  std::vector<ExactLevel> coarse_levels;
  std::optional<Problem> coarse;
  VectorXd wc, lc;
  if (o.nested && g.nx % 2 == 0 && g.ny % 2 == 0 && g.whole_nx() / 2 >= o.coarsest) {
    const auto t0 = Clock::now();
    coarse = make_problem(p.scene, coarser(g), p.spec);
    const double seconds_assemble = seconds_since(t0);
    ExactOptions oc = o;
    if (o.measure_levels && !o.measure_levels->coarser) oc.measure_levels.reset();
    ExactResult rc = solve_sequenced(*coarse, oc);
    rc.levels.back().seconds += seconds_assemble;
    coarse_levels = rc.levels;
    wc = std::move(rc.w);  // even an uncertified coarse answer predicts the contact set well
    lc = std::move(rc.lambda);
  }
  const auto t0 = Clock::now();
  const double margin = p.sampling.nodal_bounds() || !wc.size() ? 0.0 : 1e-4 * max_nodal_abs(wc.head(coarse->grid.unknowns()));
  NodeSet initial = wc.size() ? predict_active(*coarse, wc, p, margin) : NodeSet{};
  const double seconds_predict = seconds_since(t0);
  ExactResult r = rim_follows_contact(p) ? solve_rim(p, o, coarse ? &*coarse : nullptr, wc, lc, margin, initial)
                                         : solve_exact(p, o, std::move(initial));
  r.levels.back().seconds += seconds_predict;
  if (o.measure_levels) {
    ExactLevel& l = r.levels.back();
    l.measures = measure_field(p, r.w, o.measure_levels->nu, o.measure_levels->points);
    l.force = p.grid.images() * total_contact_force(p, r.lambda);  // (9), once per image
    l.certified = r.converged;
    l.enriched = p.kink.has_value();
  }
  r.levels.insert(r.levels.begin(), coarse_levels.begin(), coarse_levels.end());
  return r;
}

SceneSolution solve_exact_scene(const Scene& scene, int n, const SamplingSpec& spec, const ExactOptions& o, bool use_mirrors) {
  return solve_exact_scene(scene, n, spec, o, use_mirrors ? find_mirrors(scene, scene.grid(n), spec) : Mirrors{});
}

SceneSolution solve_exact_scene(const Scene& scene, int n, const SamplingSpec& spec, const ExactOptions& o, Mirrors mirrors) {
  SceneSolution s;
  const Grid g = scene.grid(n);
  s.mirrors = mirrors;
  if (!s.mirrors.any()) {
    s.solved = make_problem(scene, g, spec);
    s.result = solve_sequenced(s.solved, o);
    s.part_w = s.result.w, s.part_lambda = s.result.lambda;
    return s;
  }
  s.unfolded = make_samples(scene, g, spec);  // validates the whole plate's obstacle first
  s.solved = make_problem(scene, part_of(g, s.mirrors), spec);
  s.result = solve_sequenced(s.solved, o);
  // Rows laid out for the contact: the whole plate's are the part's layout with its images.
  if (s.solved.sampling.rim_laid_out()) lay_out_rim(*s.unfolded, s.solved.sampling.rim);
  s.part_w = std::move(s.result.w), s.part_lambda = std::move(s.result.lambda);
  const Sampling& whole = s.unfolded->sampling;
  s.result.w = unfold_unknowns(g, s.solved.grid, s.part_w);
  if (s.solved.kink) {  // the part's functions (D31) as the whole plate's, each spline its own
    VectorXd c;
    attach_kink(*s.unfolded, unfold_kink(*s.solved.kink, s.part_w.segment(s.solved.grid.unknowns(), s.solved.kink->size()), c));
    s.result.w.conservativeResize(s.unfolded->unknowns());
    s.result.w.tail(c.size()) = c;
  }
  s.result.lambda = unfold_samples(whole, s.solved.sampling, s.solved.grid, s.part_lambda);
  VectorXd held(s.result.active.size());
  for (size_t q = 0; q < s.result.active.size(); ++q) held[q] = s.result.active[q];
  const VectorXd unfolded = unfold_samples(whole, s.solved.sampling, s.solved.grid, held);
  s.result.active.assign(whole.size(), 0);
  for (int q = 0; q < whole.size(); ++q) s.result.active[q] = unfolded[q] != 0;
  return s;
}

}  // namespace plate
