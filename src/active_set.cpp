// Primal-dual active sets for the exactly constrained problem, its monotone fallback, its
// certificate, and the sequence of grids that gives it a good start.
#include "active_set.hpp"

#include <cfloat>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <unordered_set>

#include "contact.hpp"
#include "dual_active_set.hpp"
#include "norms.hpp"
#include "rim_exchange.hpp"
#include "stopwatch.hpp"

namespace plate {

namespace {

// The sizes the relative tolerances refer to; never zero, so a plate without contact divides safely.
double value_scale(const VectorXd& w) { return std::max(max_nodal_abs(w), 1e-300); }
double force_scale(const VectorXd& lambda) { return std::max(lambda.cwiseAbs().maxCoeff(), 1e-300); }

// lambda_p = (K w - F)_{value of p} / W_p on held nodes: the force the obstacle must supply there.
VectorXd multipliers(const Problem& p, const VectorXd& w, const NodeSet& held) {
  const VectorXd r = p.K * w - p.F;
  VectorXd lambda = VectorXd::Zero(p.phi.size());
  for (int q = 0; q < lambda.size(); ++q)
    if (held[q]) lambda[q] = r[4 * q] / p.sampling.weights[q];
  return lambda;
}

// How many rows two sets disagree on: the active-set change one iteration makes.
int differing(const NodeSet& a, const NodeSet& b) {
  int d = 0;
  for (size_t q = 0; q < a.size(); ++q) d += a[q] != b[q];
  return d;
}

// A 64-bit fingerprint of a node set, to notice a repeated active set without storing it.
size_t fingerprint(const NodeSet& s) {
  size_t h = 1469598103934665603ull;
  for (size_t q = 0; q < s.size(); ++q)
    if (s[q]) h = (h ^ q) * 1099511628211ull;
  return h;
}

}  // namespace

double Certificate::worst() const {
  return std::max(std::max(violation, negative_multiplier), std::max(complementarity, stationarity));
}

// @region certificate
Certificate certify(const Problem& p, const VectorXd& w, const VectorXd& lambda) {
  Certificate c;
  const double wmax = value_scale(w), lmax = force_scale(lambda);
  const VectorXd Sw = p.sampling.S * w;
  for (int q = 0; q < p.phi.size(); ++q) {
    const double gap = Sw[q] - p.phi[q];  // +inf where there is no obstacle
    c.violation = std::max(c.violation, -gap / wmax);
    c.negative_multiplier = std::max(c.negative_multiplier, -lambda[q] / lmax);
    if (lambda[q] != 0) c.complementarity = std::max(c.complementarity, std::abs(lambda[q] * gap) / (lmax * wmax));
  }
  // Componentwise backward error (Oettli-Prager): the smallest relative change of K, F and the
  // contact forces that makes w exact. A normwise residual would demand the impossible of a matrix
  // whose condition number grows like h^-4. Where every term of a row is itself round-off (a slope
  // that symmetry makes zero), we add ||K_i||_inf ||w||_inf to that row's scale, as Arioli, Demmel
  // and Duff do for sparse systems (SIAM J. Matrix Anal. Appl. 10, 1989).
  const VectorXd force = p.sampling.S.transpose() * p.sampling.weights.cwiseProduct(lambda);
  VectorXd r = -p.F - force, scale = p.F.cwiseAbs() + force.cwiseAbs(), row_max = VectorXd::Zero(r.size());
  VectorXd row_terms = VectorXd::Zero(r.size());
  for (Eigen::Index col = 0; col < p.K.outerSize(); ++col)
    for (SpMat::InnerIterator it(p.K, col); it; ++it) {
      r[it.row()] += it.value() * w[col];
      scale[it.row()] += std::abs(it.value() * w[col]);
      row_max[it.row()] = std::max(row_max[it.row()], std::abs(it.value()));
      row_terms[it.row()] += 1;
    }
  const double w_inf = w.size() ? w.cwiseAbs().maxCoeff() : 0.0;
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    const double normwise = row_max[i] * w_inf;
    double s = scale[i];
    if (s <= 1000 * row_terms[i] * DBL_EPSILON * normwise) s += normwise;
    if (s > 0) c.stationarity = std::max(c.stationarity, std::abs(r[i]) / s);
  }
  return c;
}
// @end certificate

std::string certificate_failure(const Certificate& c, double tol) {
  std::ostringstream m;
  m << "the active set settled but the certificate fails: worst relative residual " << c.worst() << " > tol = " << tol
    << " (violation " << c.violation << ", negative multiplier " << c.negative_multiplier << ", complementarity "
    << c.complementarity << ", stationarity " << c.stationarity << ")";
  return m.str();
}

double energy(const Problem& p, const VectorXd& w) { return 0.5 * w.dot(p.K * w) - p.F.dot(w); }

void validate(const ExactOptions& o) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument(what);
  };
  require(std::isfinite(o.tol) && o.tol > 0, "tol must be finite and > 0");
  require(o.tol >= 1e-14, "tol must be >= 1e-14: the certificate is computed in double precision");
  require(o.max_iter >= 1, "max-iter must be >= 1");
  require(o.coarsest >= 2, "coarsest must be >= 2");
  require(o.max_correction >= 0, "max-correction must be >= 0");
}

namespace {

struct Step {
  VectorXd w, lambda;
};

// @region monotone-fallback
// Holds every free node at or below phi, at phi exactly. Returns whether any was strictly below.
bool hold_touching(const Problem& p, NodeSet& W, VectorXd& w) {
  bool violated = false;
  for (int q = 0; q < p.phi.size(); ++q)
    if (!W[q] && w[4 * q] <= p.phi[q]) {
      violated = violated || w[4 * q] < p.phi[q];
      W[q] = 1;
      w[4 * q] = p.phi[q];
    }
  return violated;
}

// The monotone fallback: a primal active-set method from a feasible point. The working set W holds
// every node where w touches phi, so after a node with lambda < 0 is released the step to the next
// blocking node is positive and the energy falls strictly; no W can come back, the method ends.
bool primal_active_set(const Problem& p, FixedSetSolver& fs, NodeSet& W, Step& s, const ExactOptions& o,
                       int& steps, ExactResult& res) {
  const int nodes = static_cast<int>(p.phi.size());
  // A feasible start: hold every violated node until none is (W only grows).
  for (;;) {
    s.w = fs.solve(W);
    ++steps;
    if (!hold_touching(p, W, s.w)) break;
    if (steps >= o.max_iter) return false;
  }
  while (steps < o.max_iter) {
    // s.w minimises the energy on W and is feasible.
    s.lambda = multipliers(p, s.w, W);
    res.fallback_energies.push_back(energy(p, s.w));
    const double lmax = force_scale(s.lambda);
    int j = -1;
    for (int q = 0; q < nodes; ++q)
      if (W[q] && s.lambda[q] < -o.tol * lmax && (j < 0 || s.lambda[q] < s.lambda[j])) j = q;
    if (j < 0) return true;
    W[j] = 0;
    // Move towards the minimiser on the smaller set until a free node would cross phi.
    for (;;) {
      const VectorXd target = fs.solve(W);
      ++steps;
      const VectorXd d = target - s.w;
      double alpha = 1.0;
      for (int q = 0; q < nodes; ++q)
        if (!W[q] && d[4 * q] < 0) alpha = std::min(alpha, (p.phi[q] - s.w[4 * q]) / d[4 * q]);
      s.w += alpha * d;
      if (alpha >= 1.0) {
        s.w = target;
        break;
      }
      hold_touching(p, W, s.w);
      if (steps >= o.max_iter) return false;
    }
  }
  return false;
}
// @end monotone-fallback

}  // namespace

ExactResult solve_exact(const Problem& p, const ExactOptions& o, NodeSet initial) {
  validate(o);
  // Rows that are not bounds on nodal values go to the dual solver.
  if (!p.sampling.nodal_bounds()) return solve_exact_rows(p, o, initial);
  const auto t0 = Clock::now();
  const int nodes = static_cast<int>(p.phi.size());
  ExactResult res;
  ExactLevel level;
  level.cells = p.grid.whole_nx();
  NodeSet A = initial.empty() ? NodeSet(nodes, 0) : std::move(initial);
  if (static_cast<int>(A.size()) != nodes) throw std::invalid_argument("initial active set has the wrong size");
  for (int q = 0; q < nodes; ++q)
    if (A[q] && !std::isfinite(p.phi[q])) A[q] = 0;  // no obstacle there: nothing to hold
  level.predicted = members(A);
  if (o.on_iterate) o.on_iterate(p.grid.whole_nx(), 0, level.predicted, 0);
  FixedSetSolver fs(p.K, p.F, p.phi, o.max_correction);
  std::unordered_set<size_t> seen{fingerprint(A)};
  Step s;
  bool done = false;
// @region primal-dual-active-set
  // (D9)-(D10): solve with A held, read lambda on A, then keep the nodes that push (lambda > 0)
  // and add the free nodes that went below phi. Stop when the set repeats itself.
  while (level.pdas_iterations < o.max_iter) {
    s.w = fs.solve(A);
    ++level.pdas_iterations;
    s.lambda = multipliers(p, s.w, A);
    const double wmax = value_scale(s.w), lmax = force_scale(s.lambda);
    NodeSet next(nodes, 0);
    for (int q = 0; q < nodes; ++q)
      next[q] = A[q] ? s.lambda[q] > -o.tol * lmax : p.phi[q] - s.w[4 * q] > o.tol * wmax;
    if (o.on_iterate) o.on_iterate(p.grid.whole_nx(), level.pdas_iterations, members(A), differing(A, next));
    if (next == A) {
      done = true;
      break;
    }
    if (!seen.insert(fingerprint(next)).second) {
      res.cycled = true;
      break;
    }
    A.swap(next);
  }
// @end primal-dual-active-set
  if (!done && o.globalise) {
    done = primal_active_set(p, fs, A, s, o, level.primal_steps, res);
  }
  res.w = std::move(s.w);
  res.lambda = std::move(s.lambda);
  res.active = std::move(A);
  res.certificate = certify(p, res.w, res.lambda);
  std::ostringstream m;
  if (!done) {
    if (res.cycled && !o.globalise)
      m << "the primal-dual active-set iteration cycled (an active set came back after " << level.pdas_iterations
        << " iterations) and globalisation is off";
    else
      m << "the active-set iterations did not finish in max-iter = " << o.max_iter << " steps";
  } else if (res.certificate.worst() > o.tol) {
    m << certificate_failure(res.certificate, o.tol);
  }
  res.message = m.str();
  res.converged = res.message.empty();
  level.active = members(res.active);
  level.factorizations = fs.factorizations();
  level.correction_columns = fs.correction_columns();
  level.seconds = seconds_since(t0);
  res.levels.push_back(level);
  return res;
}

namespace {
// @region grid-sequencing
// A fine sample starts held if the coarse solution, interpolated by its own Hermite cubics, lies on
// or below phi there: a coarse contact line predicts the fine one to within a cell. (`margin`
// also takes samples just above: the dual solver gives those a column of G, which costs little.)
NodeSet predict_active(const Grid& coarse, const VectorXd& wc, const Problem& fine, double margin) {
  NodeSet A(fine.phi.size(), 0);
  for (int q = 0; q < fine.phi.size(); ++q) {
    if (!std::isfinite(fine.phi[q])) continue;
    const double w = evaluate(coarse, wc, fine.sampling.x[q], fine.sampling.y[q]).w;
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
ExactResult solve_rim(Problem& p, const Field& obstacle, const ExactOptions& o, const Problem* coarse, const VectorXd& wc,
                      const VectorXd& lc, double margin, const NodeSet& predicted) {
  RimLayout layout;  // periodic
  // A row touches if it lies within the certificate's tolerance of the obstacle, or within the depth
  // the plate dips below it between rows: an averaged row cannot tell a gap smaller than that from
  // contact (on the paper's scene, n = 32, the diagonal's row lifts 5e-6 where the plate dips 8e-6).
  auto touch = [&](const Problem& q, const VectorXd& w) {
    return std::max(o.tol * value_scale(w), dip_below_edge(q, w, obstacle));
  };
  if (coarse && rim_follows_contact(*coarse) && !coarse->sampling.rim.periodic) {
    const ContactArcs c = rim_contact(*coarse, wc, lc, touch(*coarse, wc));
    if (!c.whole) layout = rim_layout_for(p, c);
  }
  Cholesky chol;  // one factor for every layout this grid tries
  chol.factorize(p.K);
  const RowExchange exchange = [&](Problem& q, const VectorXd& w, double slack) {
    const std::vector<double> at = rim_dips(q, w, obstacle, slack);
    if (!at.empty()) append_rim_points(q, at, obstacle);
    return static_cast<int>(at.size());
  };
  NodeSet initial = predicted;
  ExactResult r;
  int layouts = 0, exchanged = 0;
  for (int round = 0;; ++round) {
    if (!layout.periodic) {
      lay_out_rim(p, layout, obstacle);
      ++layouts;
      initial = coarse && round == 0 ? predict_active(coarse->grid, wc, p, margin) : predict_active(p.grid, r.w, p, margin);
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

ExactResult solve_exact(Problem& p, const Field& obstacle, const Field& load, const ExactOptions& o) {
  validate(o);
  const Grid& g = p.grid;
  std::vector<ExactLevel> coarse_levels;
  std::optional<Problem> coarse;
  VectorXd wc, lc;
  if (o.nested && g.nx % 2 == 0 && g.ny % 2 == 0 && g.whole_nx() / 2 >= o.coarsest) {
    const auto t0 = Clock::now();
    coarse = make_problem(coarser(g), p.spec, obstacle, load);
    const double seconds_assemble = seconds_since(t0);
    ExactResult rc = solve_exact(*coarse, obstacle, load, o);
    rc.levels.back().seconds += seconds_assemble;
    coarse_levels = rc.levels;
    wc = std::move(rc.w);  // even an uncertified coarse answer predicts the contact set well
    lc = std::move(rc.lambda);
  }
  const auto t0 = Clock::now();
  const double margin = p.sampling.nodal_bounds() || !wc.size() ? 0.0 : 1e-4 * max_nodal_abs(wc);
  NodeSet initial = wc.size() ? predict_active(coarse->grid, wc, p, margin) : NodeSet{};
  const double seconds_predict = seconds_since(t0);
  ExactResult r = rim_follows_contact(p) ? solve_rim(p, obstacle, o, coarse ? &*coarse : nullptr, wc, lc, margin, initial)
                                         : solve_exact(p, o, std::move(initial));
  r.levels.back().seconds += seconds_predict;
  if (o.on_level) o.on_level(p, r);
  r.levels.insert(r.levels.begin(), coarse_levels.begin(), coarse_levels.end());
  return r;
}

ExactResult solve_exact(const Grid& g, const Field& obstacle, const Field& load, const ExactOptions& o) {
  return solve_exact(g, SamplingSpec{}, obstacle, load, o);
}

ExactResult solve_exact(const Grid& g, const SamplingSpec& spec, const Field& obstacle, const Field& load,
                        const ExactOptions& o) {
  const auto t0 = Clock::now();
  Problem p = make_problem(g, spec, obstacle, load);
  const double seconds_assemble = seconds_since(t0);
  ExactResult r = solve_exact(p, obstacle, load, o);
  r.levels.back().seconds += seconds_assemble;
  return r;
}

SceneSolution solve_exact_scene(const Grid& g, const SamplingSpec& spec, const Field& obstacle, const Field& load,
                                const ExactOptions& o, bool use_mirrors) {
  SceneSolution s;
  if (use_mirrors) s.mirrors = find_mirrors(g, spec, obstacle, load);
  if (!s.mirrors.any()) {
    s.solved = make_problem(g, spec, obstacle, load);
    s.result = solve_exact(s.solved, obstacle, load, o);
    s.part_w = s.result.w, s.part_lambda = s.result.lambda;
    return s;
  }
  s.unfolded = make_samples(g, spec, obstacle);  // validates the whole plate's obstacle first
  s.solved = make_problem(part_of(g, s.mirrors), spec, obstacle, load);
  s.result = solve_exact(s.solved, obstacle, load, o);
  // Rows laid out for the contact: the whole plate's are the part's layout with its images.
  if (s.solved.sampling.rim_laid_out()) lay_out_rim(*s.unfolded, s.solved.sampling.rim, obstacle);
  s.part_w = std::move(s.result.w), s.part_lambda = std::move(s.result.lambda);
  const Sampling& whole = s.unfolded->sampling;
  s.result.w = unfold_unknowns(g, s.solved.grid, s.part_w);
  s.result.lambda = unfold_samples(whole, s.solved.sampling, s.solved.grid, s.part_lambda);
  VectorXd held(s.result.active.size());
  for (size_t q = 0; q < s.result.active.size(); ++q) held[q] = s.result.active[q];
  const VectorXd unfolded = unfold_samples(whole, s.solved.sampling, s.solved.grid, held);
  s.result.active.assign(whole.size(), 0);
  for (int q = 0; q < whole.size(); ++q) s.result.active[q] = unfolded[q] != 0;
  return s;
}

double exact_solve_roundoff(int n, double v) {
  return DBL_EPSILON * std::pow(static_cast<double>(n), 3) * std::abs(v);
}

}  // namespace plate
