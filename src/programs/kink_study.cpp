// kink_study: what the functions that carry the kink at the rim (D31) buy. On the paper's scene,
// an off-centre cylinder and a 1.25 x 1 plate with its cylinder off both centre lines (three scenes
// the rim-contact series solves), the exact solver with the default rows in the plain space and
// with the kink carried, on n = 16 ... 256 (20 ... 320 on the 1.25 plate): the distance of max w
// (the field's peak), the total force and the line load point by point from the series, with the
// observed orders; then the stability section (stability(), below) and the polygons' (D33) and
// (D34) (polygons()). Writes results/kink.{md,csv}, results/kink_stability.csv and kink_polygon.csv. Run by `make kink`; `kink_study --help` lists the options.
#include <CLI/CLI.hpp>

#include <cmath>
#include <iostream>
#include <optional>
#include <sstream>

#include "active_set.hpp"
#include "atomic_file.hpp"
#include "cholesky.hpp"
#include "contact.hpp"
#include "exit_codes.hpp"
#include "extrema.hpp"
#include "format.hpp"
#include "line_force.hpp"
#include "published.hpp"
#include "rim_contact.hpp"
#include "stopwatch.hpp"
#include "verdict.hpp"
#include "words.hpp"

using namespace plate;

namespace {

struct SceneCase {
  std::string name, key;  // the report's words, and the CSV's
  Scene scene;
  int coarsest;  // the grids are coarsest, 2 coarsest, ... (ly a whole number of cells)
};

struct Row {
  std::string scene, space;
  int n = 0, unknowns = 0;
  bool certified = false;
  double cond = NAN;  // estimated 2-norm condition number of K (grids to kCondCells)
  double h = 0, seconds = 0, max_w = 0, force = 0, err_w = 0, err_f = 0, err_line = 0;
};

// Condition numbers are estimated on the grids up to this many cells along x.
constexpr int kCondCells = 128;

// The 2-norm condition number of the SPD matrix K scaled to a unit diagonal, D^-1/2 K D^-1/2: what
// limits a Cholesky solve, which no diagonal scaling changes (van der Sluis), where the unscaled
// number mostly measures how unlike in size the unknowns are (a value, slopes, a twist, and the
// kink functions' coefficients). The largest eigenvalue by power iteration, the smallest by inverse
// iteration with the Cholesky factor, each until its Rayleigh quotient moves by less than 1e-4 of
// itself in a step: an estimate, which a slowly converging power iteration leaves low.
double condition_number(const SpMat& unscaled) {
  const int n = static_cast<int>(unscaled.rows());
  const VectorXd d = unscaled.diagonal().cwiseSqrt().cwiseInverse();
  const SpMat K = d.asDiagonal() * unscaled * d.asDiagonal();
  VectorXd v = VectorXd::Ones(n).normalized();
  double top = 0, bottom = 0;
  for (int it = 0; it < 300; ++it) {
    const VectorXd Kv = K * v;
    const double q = v.dot(Kv);
    v = Kv.normalized();
    if (it > 20 && std::abs(q - top) <= 1e-4 * q) break;
    top = q;
  }
  Cholesky chol;
  chol.analyze(K);
  chol.factorize(K);
  v = VectorXd::Ones(n).normalized();
  for (int it = 0; it < 300; ++it) {
    const VectorXd u = chol.solve(v);
    const double q = v.dot(u);  // Rayleigh quotient of K^-1
    v = u.normalized();
    if (it > 20 && std::abs(q - bottom) <= 1e-4 * q) break;
    bottom = q;
  }
  return top * bottom;
}

// max w (the field's peak) and the total force of a solve, and their relative distances from the
// series where one is given: what both sections of the study measure.
struct Measured {
  double max_w = 0, force = 0, err_w = NAN, err_f = NAN;
};
Measured measure(const SceneSolution& x, const RimSeries* s) {
  Measured m;
  const Problem& p = x.whole();
  m.max_w = extremum_of_w(p, x.result.w, +1).value;
  m.force = total_contact_force(p, x.result.lambda);
  if (s) m.err_w = std::abs(m.max_w - s->max_w().w) / s->max_w().w, m.err_f = std::abs(m.force - s->total_force()) / s->total_force();
  return m;
}

Row solve_one(const SceneCase& c, const RimAnswer& series, bool kink, int n) {
  SamplingSpec spec{SamplingKind::Edge};
  if (kink) spec.enrich.kind = EnrichSpec::Kind::Ring;
  const auto t0 = Clock::now();
  const SceneSolution x = solve_exact_scene(c.scene, n, spec, ExactOptions{});
  Row r;
  r.seconds = seconds_since(t0);
  // The space actually solved: (D31) is left out of a grid it does not fit.
  r.scene = c.key, r.space = x.solved.kink ? "kink" : "plain", r.n = n, r.h = c.scene.lx / n, r.unknowns = x.solved.unknowns();
  r.certified = x.result.converged;
  const RimSeries& s = series.finest;
  const Measured m = measure(x, &s);
  r.max_w = m.max_w, r.force = m.force, r.err_w = m.err_w, r.err_f = m.err_f;
  r.err_line = max_distance(line_force(x.whole(), x.result.lambda), [&](double t) { return s.q(t); }) / s.q_cos.at(0);
  if (n <= kCondCells * c.coarsest / 16) r.cond = condition_number(x.solved.K);
  if (!r.certified) std::cerr << "kink_study: " << c.key << " " << r.space << " n = " << n << ": " << x.result.message << "\n";
  return r;
}

std::string order(double coarse, double fine) { return coarse > 0 && fine > 0 ? fmt("%.2f", std::log2(coarse / fine)) : ""; }

// The least observed order of err over the grids from n = lo to hi (both ends in), and how many
// orders there are.
struct Orders {
  double least = INFINITY;
  int count = 0;
};
Orders orders_between(const std::vector<Row>& rows, const std::string& scene, const std::string& space,
                      double Row::*err, int lo, int hi) {
  Orders o;
  const Row* before = nullptr;
  for (const Row& r : rows) {
    if (r.scene != scene || r.space != space) continue;
    if (before && before->n >= lo && r.n <= hi) o.least = std::min(o.least, std::log2(before->*err / r.*err)), ++o.count;
    before = &r;
  }
  return o;
}

std::string csv(const std::vector<Row>& rows) {
  std::ostringstream o;
  o << "# kink_study: exact solves with the default rows, in the plain space and with the kink carried (D31); errors\n"
       "# relative to the rim-contact series: max w (the field's peak), the total force, and the line load's largest\n"
       "# distance from the series' q over " << kLineLoadAngles << " angles, over the mean load. Made by build/kink_study\n"
       "# cond: the 2-norm condition number of K scaled to a unit diagonal, estimated by power and inverse iteration,\n"
       "# on the grids up to n = 128 (160 on the 1.25 plate)\n"
       "scene,space,n,h,unknowns,certified,max_w,err_max_w,total_force,err_total_force,err_line_pointwise,cond\n";
  for (const Row& r : rows)
    o << r.scene << "," << r.space << "," << r.n << "," << fmt("%.10g", r.h) << "," << r.unknowns << ","
      << (r.certified ? 1 : 0) << "," << fmt("%.12g", r.max_w) << "," << fmt("%.2e", r.err_w) << "," << fmt("%.11g", r.force)
      << "," << fmt("%.2e", r.err_f) << "," << fmt("%.2e", r.err_line) << "," << (std::isfinite(r.cond) ? fmt("%.2e", r.cond) : "") << "\n";
  return o.str();
}

std::string markdown(const std::vector<Row>& rows, const std::vector<SceneCase>& cases) {
  std::ostringstream o;
  o << words("kink_study.intro") << "\n\n";
  for (const SceneCase& c : cases) {
    o << "| space | n | unknowns | max w | order | total force | order | line load, pointwise | order |\n"
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const char* space : {"plain", "kink"}) {
      const Row* before = nullptr;
      for (const Row& r : rows) {
        if (r.scene != c.key || r.space != space) continue;
        o << "| " << (r.space == "kink" ? "kink carried" : "plain") << " | " << r.n << (r.certified ? "" : " (**not certified**)")
          << " | " << r.unknowns << " | " << fmt("%.1e", r.err_w) << " | " << (before ? order(before->err_w, r.err_w) : "")
          << " | " << fmt("%.1e", r.err_f) << " | " << (before ? order(before->err_f, r.err_f) : "") << " | "
          << fmt("%.1e", r.err_line) << " | " << (before ? order(before->err_line, r.err_line) : "") << " |\n";
        before = &r;
      }
    }
    o << "\nTable: " << words("kink_study.scene_caption", {{"scene", c.name}}) << "\n\n";
  }
  o << "| scene | n | cond(K), plain | cond(K), kink carried | ratio |\n|---|---:|---:|---:|---:|\n";
  for (const SceneCase& c : cases)
    for (const Row& p : rows) {
      if (p.scene != c.key || p.space != "plain" || !std::isfinite(p.cond)) continue;
      for (const Row& k : rows)
        if (k.scene == c.key && k.space == "kink" && k.n == p.n && std::isfinite(k.cond))
          o << "| " << c.key << " | " << p.n << " | " << fmt("%.1e", p.cond) << " | " << fmt("%.1e", k.cond) << " | "
            << fmt("%.2f", k.cond / p.cond) << " |\n";
    }
  o << "\nTable: " << words("kink_study.condition_caption") << "\n\n";
  o << words("targets.heading") << "\n\n";
  for (const SceneCase& c : cases) {
    const int lo = 2 * c.coarsest, hi = 16 * c.coarsest;
    const Orders w = orders_between(rows, c.key, "kink", &Row::err_w, lo, hi), f = orders_between(rows, c.key, "kink", &Row::err_f, lo, hi);
    const bool met = w.count >= 3 && f.count >= 3 && w.least >= 3.8 && f.least >= 3.8;
    o << words("kink_study.order_target", {{"scene", c.name}, {"lo", std::to_string(lo)}, {"hi", std::to_string(hi)},
                                           {"status", target_status(met)},
                                           {"least_w", fmt("%.2f", w.least)}, {"least_f", fmt("%.2f", f.least)}})
      << "\n";
  }
  for (const Row& r : rows)
    if (r.scene == cases.front().key && r.space == "kink" && r.n == 128)
      o << words("kink_study.line_load_target", {{"scene", cases.front().name},
                                                 {"status", target_status(r.err_line <= 1e-4)},
                                                 {"error", fmt("%.1e", r.err_line)}})
        << "\n";
  return o.str();
}

// Issue 43's stability questions: how the cut-off's band (its flat part and where it reaches 0,
// in cells) moves the condition number and the errors on the paper's scene, and whether the
// certificate holds where (D31) is hardest to carry: the smallest disk it fits, a disk as close to
// the clamped edge as it fits, an obstacle height near the ends of double precision, a cylinder of
// height 0 that a downward load presses the plate onto, and a polygon with an acute corner, which
// `plate` solves with (D33) across its sides.
struct StabilityRow {
  std::string study, scene;
  int n = 0;
  KinkBand band;
  std::string space;
  bool certified = false;
  double cond = NAN, max_w = 0, force = 0, err_w = NAN, err_f = NAN;
  double per = 1, per_force = 1;  // max w and the force are reported divided by these (where the scene is scaled)
};

constexpr KinkBand kStudiedBands[] = {{1.5, 2.5}, {1.5, 3.5}, {1.5, 5.5}, {2.5, 4.5}, {4, 8}};

StabilityRow solve_stability(const std::string& study, const std::string& key, const Scene& scene, int n, KinkBand band,
                             const RimAnswer* series) {
  SamplingSpec spec{SamplingKind::Edge};
  spec.enrich.kind = EnrichSpec::Kind::Ring;
  spec.enrich.band = band;
  std::cerr << "kink_study: " << study << ", " << key << ", n = " << n << "\n";
  const SceneSolution x = solve_exact_scene(scene, n, spec, ExactOptions{});
  StabilityRow r;
  r.study = study, r.scene = key, r.n = n, r.band = band;
  r.space = x.solved.kink ? "kink" : "plain";
  r.certified = x.result.converged;
  const Measured m = measure(x, series ? &series->finest : nullptr);
  r.max_w = m.max_w, r.force = m.force, r.err_w = m.err_w, r.err_f = m.err_f;
  if (n <= kCondCells) r.cond = condition_number(x.solved.K);
  if (!r.certified) std::cerr << "kink_study: " << study << " " << key << " n = " << n << ": " << x.result.message << "\n";
  return r;
}

// A triangle with a corner of about 22 degrees at (0.8, 0.45), lifted to 0.05, no constraint
// outside; its sides are the edge rows' polygon.
Scene acute_triangle() {
  const double vx[3] = {0.3, 0.8, 0.3}, vy[3] = {0.3, 0.45, 0.5};
  Scene s = Scene::rectangle(1, 1).over([vx, vy](double x, double y) {
    for (int k = 0; k < 3; ++k) {  // inside: left of every side, the vertices counter-clockwise
      const int l = (k + 1) % 3;
      if ((vx[l] - vx[k]) * (y - vy[k]) - (vy[l] - vy[k]) * (x - vx[k]) < 0) return -HUGE_VAL;
    }
    return 0.05;
  });
  s.edge = parse_edge("polygon:0.3,0.3;0.8,0.45;0.3,0.5");
  return s;
}

std::vector<StabilityRow> stability(int finest) {
  std::vector<StabilityRow> rows;
  const Scene paper = paper_scene();
  const RimAnswer series = rim_answer(paper);
  for (const KinkBand& b : kStudiedBands)
    for (int n : {64, 128})
      if (n <= finest) rows.push_back(solve_stability("band", "paper", paper, n, b, &series));
  struct Hard {
    std::string key;
    Scene scene;
    int coarsest, finest;
    double per = 1, per_force = 1;
  };
  // The paper's scene with every length times L (and the height with them): w scales with L and the
  // force with 1 / L, so divided by those it is the paper's answer, if the arithmetic holds.
  const auto shrunk = [](double L) {
    return Scene::rectangle(L, L).over(Cylinder{0.5 * L, 0.5 * L, 0.25 * L, paper_scene().cylinder->height * L});
  };
  // On n = 64 the smallest radius (D31) fits, and a paper's disk as near the clamped edge as it fits.
  const double h64 = 1.0 / 64, R = paper_scene().cylinder->height, edge_gap = (KinkBand{}.zero + 1.5) * h64;
  const std::vector<Hard> hard = {
      {"smallest-disk", Scene::rectangle(1, 1).over(Cylinder{0.5, 0.5, kKinkMinRadiusCells * h64, R}), 64, 256},
      {"near-edge", Scene::rectangle(1, 1).over(Cylinder{0.25 + edge_gap, 0.5, 0.25, R}), 64, 256},
      {"height-1e-300", paper_scene(1e-300), 64, 64, 1e-300, 1e-300},
      {"height-1e+300", paper_scene(1e300), 64, 64, 1e300, 1e300},
      {"side-1e-80", shrunk(1e-80), 64, 64, 1e-80, 1e80},
      {"height-0-pressed", Scene::rectangle(1, 1).over(Cylinder{0.5, 0.5, 0.25, 0}).loaded(-1.0), 64, 256},
      {"acute-triangle", acute_triangle(), 64, 128}};
  for (const Hard& c : hard) {
    // The series measures a cylinder's scene with no load where its premise (contact all round)
    // holds and it settles.
    std::optional<RimAnswer> yardstick;
    if (c.scene.cylinder && c.per == 1 && c.per_force == 1 && c.scene.cylinder->height > 0 && c.scene.uniform_load == 0.0) {
      RimAnswer a = rim_answer(c.scene);
      if (a.premise.holds && a.settled) yardstick = std::move(a);
    }
    for (int n = c.coarsest; n <= std::min(c.finest, finest); n *= 2) {
      rows.push_back(solve_stability("hard", c.key, c.scene, n, KinkBand{}, yardstick ? &*yardstick : nullptr));
      rows.back().per = c.per, rows.back().per_force = c.per_force;
    }
  }
  return rows;
}

// Issue 43's polygons: (D33) and (D34) against the plain space on three scenes with a polygon's edge,
// which no series solves, so each is measured against itself, grid against grid. The square lifts
// the plate as the paper's cylinder does, and the plate then rests on its four corners alone (point
// loads, which (D34) carries and no function across the sides can); pressed onto a square of height
// 0, the plate rests on each corner and each side's middle and lifts off between them; the acute
// triangle is the hard scenes'.
struct PolygonRow {
  std::string scene, space;
  int n = 0, functions = 0;
  bool certified = false;
  double max_w = 0, force = 0;
};

Scene square(double height, double load) {
  const std::string inside = "(x>=0.3 && x<=0.7 && y>=0.3 && y<=0.7)";
  return Scene::rectangle(1, 1)
      .over(inside + " ? " + fmt("%.17g", height) + " : -inf", parse_edge("polygon:0.3,0.3;0.7,0.3;0.7,0.7;0.3,0.7"))
      .loaded(load);
}

std::vector<PolygonRow> polygons(int finest) {
  const std::vector<std::pair<std::string, Scene>> scenes = {
      {"square-lifted", square(0.0625, 0)}, {"square-pressed", square(0, -1)}, {"acute-triangle", acute_triangle()}};
  std::vector<PolygonRow> rows;
  for (const auto& [key, scene] : scenes)
    for (bool kink : {false, true})
      for (int n = 32; n <= finest; n *= 2) {
        SamplingSpec spec{SamplingKind::Edge};
        if (kink) spec.enrich.kind = EnrichSpec::Kind::Sides;
        std::cerr << "kink_study: polygons, " << key << (kink ? " kink" : " plain") << ", n = " << n << "\n";
        const SceneSolution x = solve_exact_scene(scene, n, spec, ExactOptions{});
        if (kink && !x.solved.kink) continue;  // (D33) and (D34) do not fit this grid: its plain run is there already
        PolygonRow r;
        r.scene = key, r.space = x.solved.kink ? "kink" : "plain", r.n = n, r.certified = x.result.converged;
        r.functions = x.solved.kink ? x.solved.kink->size() : 0;
        const Measured m = measure(x, nullptr);
        r.max_w = m.max_w, r.force = m.force;
        if (!r.certified) std::cerr << "kink_study: polygons " << key << " n = " << n << ": " << x.result.message << "\n";
        rows.push_back(r);
      }
  return rows;
}

// The step from the grid before in the same scene and space, and the order two steps give.
struct Steps {
  double w = NAN, f = NAN;
  std::string order_w, order_f;
};
std::vector<Steps> steps_of(const std::vector<PolygonRow>& rows) {
  std::vector<Steps> out(rows.size());
  for (size_t i = 1; i < rows.size(); ++i) {
    if (rows[i - 1].scene != rows[i].scene || rows[i - 1].space != rows[i].space) continue;
    out[i].w = std::abs(rows[i].max_w - rows[i - 1].max_w), out[i].f = std::abs(rows[i].force - rows[i - 1].force);
    if (std::isfinite(out[i - 1].w)) out[i].order_w = order(out[i - 1].w, out[i].w), out[i].order_f = order(out[i - 1].f, out[i].f);
  }
  return out;
}

std::string polygon_csv(const std::vector<PolygonRow>& rows) {
  std::ostringstream o;
  o << "# kink_study, polygons: exact solves with the default rows (points on a polygon), in the plain space\n"
       "# and with (D33) and (D34) (plate --enrich sides, on every grid they fit), on n = 32 ... finest; no series solves\n"
       "# these scenes, so step_* is the distance from the grid before and order_* the order two steps give.\n"
       "# Made by build/kink_study\n"
       "scene,space,n,functions,certified,max_w,force,step_max_w,step_force,order_max_w,order_force\n";
  const std::vector<Steps> st = steps_of(rows);
  for (size_t i = 0; i < rows.size(); ++i) {
    const PolygonRow& r = rows[i];
    o << r.scene << "," << r.space << "," << r.n << "," << r.functions << "," << (r.certified ? 1 : 0) << "," << fmt("%.12g", r.max_w)
      << "," << fmt("%.11g", r.force) << "," << (std::isfinite(st[i].w) ? fmt("%.2e", st[i].w) : "") << ","
      << (std::isfinite(st[i].f) ? fmt("%.2e", st[i].f) : "") << "," << st[i].order_w << "," << st[i].order_f << "\n";
  }
  return o.str();
}

std::string polygon_markdown(const std::vector<PolygonRow>& rows) {
  std::ostringstream o;
  o << "### Polygons\n\n| scene | space | n | max w | step | order | total force | step | order | certified |\n"
       "|---|---|---:|---:|---:|---:|---:|---:|---:|:---:|\n";
  const std::vector<Steps> st = steps_of(rows);
  for (size_t i = 0; i < rows.size(); ++i) {
    const PolygonRow& r = rows[i];
    const auto step = [](double v) { return std::isfinite(v) ? fmt("%.1e", v) : std::string("—"); };
    o << "| " << r.scene << " | " << (r.space == "kink" ? "kink carried (" + std::to_string(r.functions) + " functions)" : "plain")
      << " | " << r.n << " | " << fmt("%.10g", r.max_w) << " | " << step(st[i].w) << " | " << (st[i].order_w.empty() ? "—" : st[i].order_w)
      << " | " << fmt("%.9g", r.force) << " | " << step(st[i].f) << " | " << (st[i].order_f.empty() ? "—" : st[i].order_f) << " | "
      << (r.certified ? "yes" : "**no**") << " |\n";
  }
  o << "\nTable: " << words("kink_study.polygon_caption") << "\n";
  return o.str();
}

std::string stability_csv(const std::vector<StabilityRow>& rows) {
  std::ostringstream o;
  o << "# kink_study, stability: exact solves with the default rows and (D31) asked for (plate --enrich auto),\n"
       "# 'band': the paper's scene with chi flat to `flat` cells outside the rim and 0 from `zero` cells on,\n"
       "# errors relative to the rim-contact series; 'hard': scenes where (D31) is hardest to carry, with the\n"
       "# default band (space: plain where it does not fit or the edge is no circle). cond as in kink.csv.\n"
       "# On the scaled scenes max_w and force are divided by the height (heights) or by L and 1 / L (side L).\n"
       "# Made by build/kink_study\n"
       "study,scene,n,flat,zero,space,certified,cond,max_w,force,err_max_w,err_total_force\n";
  for (const StabilityRow& r : rows) {
    o << r.study << "," << r.scene << "," << r.n << "," << fmt("%g", r.band.flat) << "," << fmt("%g", r.band.zero) << ","
      << r.space << "," << (r.certified ? 1 : 0) << "," << (std::isfinite(r.cond) ? fmt("%.2e", r.cond) : "") << ","
      << fmt("%.12g", r.max_w / r.per) << "," << fmt("%.11g", r.force / r.per_force) << ","
      << (std::isfinite(r.err_w) ? fmt("%.2e", r.err_w) : "") << "," << (std::isfinite(r.err_f) ? fmt("%.2e", r.err_f) : "") << "\n";
  }
  return o.str();
}

std::string stability_markdown(const std::vector<StabilityRow>& rows) {
  std::ostringstream o;
  o << "### Stability\n\n| band (cells) | n | cond(K) | max w, relative error | total force, relative error | certified |\n"
       "|---|---:|---:|---:|---:|:---:|\n";
  for (const StabilityRow& r : rows)
    if (r.study == "band")
      o << "| " << fmt("%g", r.band.flat) << " to " << fmt("%g", r.band.zero) << " | " << r.n << " | "
        << (std::isfinite(r.cond) ? fmt("%.2e", r.cond) : "—") << " | " << fmt("%.1e", r.err_w) << " | " << fmt("%.1e", r.err_f)
        << " | " << (r.certified ? "yes" : "**no**") << " |\n";
  o << "\nTable: " << words("kink_study.band_caption") << "\n\n";
  o << "| scene | n | space | cond(K) | max w | vs series | total force | vs series | certified |\n"
       "|---|---:|---|---:|---:|---:|---:|---:|:---:|\n";
  for (const StabilityRow& r : rows)
    if (r.study == "hard") {
      o << "| " << r.scene << " | " << r.n << " | " << (r.space == "kink" ? "kink carried" : "plain") << " | "
        << (std::isfinite(r.cond) ? fmt("%.2e", r.cond) : "—") << " | " << fmt("%.10g", r.max_w / r.per) << " | "
        << (std::isfinite(r.err_w) ? fmt("%.1e", r.err_w) : "—") << " | " << fmt("%.9g", r.force / r.per_force) << " | "
        << (std::isfinite(r.err_f) ? fmt("%.1e", r.err_f) : "—") << " | " << (r.certified ? "yes" : "**no**") << " |\n";
    }
  o << "\nTable: "
    << words("kink_study.hard_caption", {{"radius_cells", fmt("%g", kKinkMinRadiusCells)}, {"clearance_cells", fmt("%g", KinkBand{}.zero + 1.5)}})
    << "\n";
  return o.str();
}

}  // namespace

int main(int argc, char** argv) {
  clean_up_on_interrupt("kink_study");
  CLI::App app{"kink_study: the plain space against the one that carries the kink at the rim (D31), on three scenes\n"
               "the rim-contact series solves, n = 16 ... finest."};
  std::string out = "results";
  int finest = 256;
  app.add_option("--out", out, "folder for the results")->capture_default_str();
  app.add_option("--finest", finest, "cells on the finest grid of the unit square (the 1.25 plate gets 5/4 of it)")
      ->check(CLI::IsMember({64, 128, 256, 512}))
      ->capture_default_str();
  app.footer(kExitStatusHelp);
  if (const int status = parse_options(app, argc, argv, "kink_study"); status >= 0) return status;
  return run_guarded("kink_study", [&] {
    const std::vector<SceneCase> cases = {
        {"The paper's scene", "paper", paper_scene(), 16},
        {"The cylinder at (0.45, 0.5)", "off-centre", Scene::rectangle(1, 1).over(Cylinder{0.45, 0.5, 0.25, 0.0625}), 16},
        {"A 1.25 x 1 plate with the cylinder at (0.6, 0.45)", "oblong", Scene::rectangle(1.25, 1).over(Cylinder{0.6, 0.45, 0.25, 0.0625}), 20}};
    std::vector<Row> rows;
    for (const SceneCase& c : cases) {
      const RimAnswer series = rim_answer(c.scene);
      if (!series.premise.holds || !series.settled)
        throw std::runtime_error(c.name + ": the rim-contact series gives no answer to measure against");
      for (bool kink : {false, true})
        for (int n = c.coarsest; n <= finest * c.coarsest / 16; n *= 2) {
          std::cerr << "kink_study: " << c.key << (kink ? " kink" : " plain") << ", n = " << n << "\n";
          Row r = solve_one(c, series, kink, n);
          if (kink && r.space != "kink") continue;  // a coarse grid (D31) does not fit: its plain run is there already
          rows.push_back(r);
        }
    }
    const std::vector<StabilityRow> stable = stability(finest);
    const std::vector<PolygonRow> polygon = polygons(finest);
    write_file_atomically(out + "/kink.csv", csv(rows));
    write_file_atomically(out + "/kink_stability.csv", stability_csv(stable));
    write_file_atomically(out + "/kink_polygon.csv", polygon_csv(polygon));
    write_file_atomically(out + "/kink.md", markdown(rows, cases) + "\n" + stability_markdown(stable) + "\n" + polygon_markdown(polygon));
    for (const Row& r : rows)
      if (!r.certified) return kNotConverged;
    for (const StabilityRow& r : stable)
      if (!r.certified) return kNotConverged;
    for (const PolygonRow& r : polygon)
      if (!r.certified) return kNotConverged;
    return kSuccess;
  });
}
