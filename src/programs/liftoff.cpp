// liftoff: scenes where the plate lifts off part of the cylinder's rim, which the rim-contact series
// refuses (its premise is contact all round). Each is solved on grids h = 1/16 ... 1/256 three ways:
// the default rows, laid out for the contact (D28); rows at points; and the periodic splines alone
// (the default before, which dips through the obstacle where the contact ends); and once more with
// the default rows and the kink carried (D31), as `plate` solves it by default. FreeFEM's exact
// script on gmsh meshes fitted to the circle is the independent code. Writes results/liftoff.{md,csv}.
// `liftoff --help`.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <sstream>

#include "active_set.hpp"
#include "atomic_file.hpp"
#include "contact.hpp"
#include "error_bar.hpp"
#include "exit_codes.hpp"
#include "extrema.hpp"
#include "fields.hpp"
#include "format.hpp"
#include "freefem.hpp"
#include "line_force.hpp"
#include "progress.hpp"
#include "refinement.hpp"
#include "rim_exchange.hpp"
#include "stopwatch.hpp"
#include "words.hpp"

using namespace plate;

namespace {

struct Case {
  const char* key;   // in the CSV
  const char* name;  // in the report
  double lx, ly, cx, cy;
  int n16;  // cells along x for h = 1/16
};
// The cylinder of the paper (R = 0.0625, radius 0.25) on plates where it does not touch all round.
const Case kScenes[] = {{"2x1-centred", "2 x 1, centred", 2, 1, 1, 0.5, 32},
                         {"1.5x1-centred", "1.5 x 1, centred", 1.5, 1, 0.75, 0.5, 24},
                         {"1.5x1-off-centre", "1.5 x 1, at (0.6, 0.45)", 1.5, 1, 0.6, 0.45, 24}};
constexpr double kR = 0.0625, kRadius = 0.25;

struct Rows {
  const char* key;   // in the CSV
  const char* name;  // in the report
  EdgeRows rows;
  int finest;         // the finest grid, as a multiple of n16 (h = 1/(16 finest))
  bool kink = false;  // the space widened by (D31) on the grids it fits, as `plate` does by default
};
const Rows kRows[] = {{"default", "default (D28)", EdgeRows{}, 16},
                      {"points", "points", EdgeRows::points(), 16},
                      {"splines", "splines alone", EdgeRows::splines(3), 8},
                      {"kink", "default, kink carried (D31)", EdgeRows{}, 16, true}};

struct Run {
  const Case* scene = nullptr;
  const Rows* rows = nullptr;  // null: FreeFEM
  int n = 0;
  double h = 0;
  bool certified = false;
  double max_w = 0, force = 0, dip = 0, seconds = 0;
  double dip_cells = NAN;  // the deepest dip's place: cells inside a spline arc (inf: periodic; NaN: between points)
  double noise_w = 0, noise_force = 0;  // what round-off may change in them (printed above it)
  int arcs = -1, points = 0, exchanged = 0;  // the layout of the default rows (arcs -1: periodic splines)
  bool kinked = false;                        // solved with the functions of (D31)
  bool quarter = false;                       // FreeFEM on the quarter its mirror lines leave
};

Scene scene_of(const Case& s) { return Scene::rectangle(s.lx, s.ly).over(Cylinder{s.cx, s.cy, kRadius, kR}); }

Run solve(const Case& s, const Rows& r, int n) {
  const Scene scene = scene_of(s);
  const auto t0 = Clock::now();
  SamplingSpec spec{SamplingKind::Edge, r.rows};
  if (r.kink) spec.enrich.kind = EnrichSpec::Kind::Ring;
  const SceneSolution x = solve_exact_scene(scene, n, spec, ExactOptions{});
  Run run{&s, &r, n, s.lx / n};
  run.seconds = seconds_since(t0);
  run.certified = x.result.converged;
  run.max_w = extremum_of_w(x.whole(), x.result.w, +1).value;
  run.force = total_contact_force(x.whole(), x.result.lambda);
  const EdgeDip dip = deepest_dip_below_edge(x.whole(), x.result.w);
  run.dip = dip.depth;
  run.dip_cells = cells_inside_spline_arc(x.whole(), dip.theta);
  run.kinked = x.solved.kink.has_value();
  const Sampling& sam = x.whole().sampling;
  if (sam.rim_laid_out()) {
    run.arcs = static_cast<int>(sam.rim.arcs.size());
    for (const RimRow& row : sam.rim_rows) run.points += row.point();
  }
  for (const ExactLevel& l : x.result.levels) run.exchanged += l.exchanged;
  // A refined answer (D22) is the same on every machine to the refinement's floor; else u n^3.
  const Refinement& refined = x.result.levels.back().refinement;
  require_not_undone(refined, "liftoff");
  run.noise_w = refined.w.empty() ? exact_solve_roundoff(n, run.max_w) : refined.noise_w(x.result.w.head(x.whole().grid.unknowns()));
  run.noise_force = refined.w.empty() ? exact_solve_roundoff(n, run.force) : refined.relative_noise_mu() * run.force;
  return run;
}

// FreeFEM's exact script on the O-grid mesh with 4 m cells per quarter circle (its quarter, when
// the scene has mirror lines).
Run freefem(const Case& s, int m, const std::string& work) {
  const Scene scene = scene_of(s);
  // A cylinder at the plate's centre leaves two mirror lines, and FreeFEM can then solve on the quarter
  // mesh (contact_hct.edp -symmetry quarter), a quarter of the unknowns: one mesh finer in the same time.
  const bool quarter = circle_at_centre(scene);
  const std::string base = work + "/" + std::to_string(&s - kScenes) + "_" + std::to_string(m);
  gmsh_mesh(quarter ? "reference/quarter_square_with_circle.geo" : "reference/square_with_circle.geo", circle_numbers(scene, m),
            base + ".msh");
  write_points(base + ".points", {{s.cx, s.cy}});
  const std::string args = scene_args(scene, base + ".points") + (quarter ? " -symmetry quarter" : "");
  const auto t0 = Clock::now();
  const nlohmann::json j = run_freefem("reference/contact_hct.edp", base + ".msh", args, base + ".json");
  const CheckValues v = freefem_values(j, 4 * m, kRadius);
  Run run{&s, nullptr, 4 * m, v.h};
  run.seconds = seconds_since(t0);
  run.certified = v.certified;
  run.max_w = v.max_w;
  run.force = v.force;
  run.dip = NAN;
  run.quarter = quarter;
  run.noise_w = freefem_roundoff(v.h, v.max_w), run.noise_force = freefem_roundoff(v.h, v.force);
  return run;
}

// Which rows failed to hold the plate where it dips deepest (empty: it dips nowhere, or FreeFEM).
std::string dip_on(const Run& r) {
  if (!(r.dip > 0)) return "";
  switch (rows_at(r.dip_cells)) {
    case RowsAt::Points: return "points";
    case RowsAt::Periodic: return "periodic";
    case RowsAt::Arc: return "arc";
  }
  return "";
}

// The same in words, for the report.
std::string dip_place(const Run& r) {
  const std::string on = dip_on(r);
  if (on == "arc") return "on a spline arc, " + fmt("%.1f", r.dip_cells) + " cells in";
  if (on == "points") return "between points";
  if (on == "periodic") return "periodic splines";
  return "—";
}

// The error bar on the finest value of a sequence (error_bar.hpp), as a cell of a verdict: the phrase
// for how it was found is chosen here, its words are in reports/words.md.
std::string bar_cell(const ErrorBar& b) {
  if (b.basis == "none") return "—";
  std::string how;
  if (b.steady) how = words("liftoff.bar_richardson", {{"order", fmt("%.2f", b.order)}});
  else if (b.basis == "last difference") how = words("liftoff.bar_last");
  else if (b.basis == "largest of the last two differences") how = words("liftoff.bar_largest_two");
  else if (b.basis == "the same on every grid") how = words("liftoff.bar_same");
  else throw std::logic_error("liftoff: no words for an error bar found by '" + b.basis + "'");
  return "± " + fmt_up(b.bar) + " (" + how + ")";
}

// Our bar (D29) from the four finest grids of one kind of rows: both of the report's lines that set
// ours against FreeFEM take it so.
ErrorBar finest_bar(const std::vector<double>& values) {
  return error_bar(std::vector<double>(values.end() - std::min<size_t>(4, values.size()), values.end()));
}

// The report: each scene's runs, and our finest answers (default rows; and with the kink carried)
// against FreeFEM's within the sum of the bars. `failures` counts uncertified runs and disagreements.
std::string report(const std::vector<Run>& runs, int& failures) {
  std::ostringstream md;
  md << words("liftoff.intro") << "\n\n";
  failures = 0;
  for (const Case& s : kScenes) {
    md << "### " << s.name << "\n\n| h | rows | certified | max w | total force | dip / R | deepest | layout |\n|---|---|:---:|---:|---:|---:|---|---|\n";
    std::vector<double> ours, theirs, kinked;
    double ours_noise = 0, theirs_noise = 0, kink_noise = 0;  // of the finest of each
    for (const Run& r : runs) {
      if (r.scene != &s) continue;
      if (r.rows == &kRows[0]) ours.push_back(r.max_w), ours_noise = r.noise_w;
      // The bar from grids of one space: those (D31) fits (the coarsest may be plain).
      if (r.rows && r.rows->kink && r.kinked) kinked.push_back(r.max_w), kink_noise = r.noise_w;
      if (!r.rows) theirs.push_back(r.max_w), theirs_noise = r.noise_w;
      failures += !r.certified;
      const std::string layout = !r.rows ? std::to_string(r.n) + " cells a quarter circle" + (r.quarter ? " (quarter mesh, mirror lines)" : "")
                                 : r.arcs >= 0 ? std::to_string(r.arcs) + " spline arcs, " + std::to_string(r.points) + " point rows (" +
                                                      std::to_string(r.exchanged) + " added where the plate dipped)"
                                 : r.rows == &kRows[1] ? "points" : "periodic splines";
      const std::string space = r.rows && r.rows->kink ? (r.kinked ? "; kink carried" : "; plain (D31 does not fit)") : "";
      md << "| " << (!r.rows ? fmt("%.3g", r.h) : "1/" + std::to_string(static_cast<int>(std::lround(1 / r.h)))) << " | "
         << (r.rows ? r.rows->name : "FreeFEM") << " | " << (r.certified ? "yes" : "**no**") << " | " << fmt_value(r.max_w, r.noise_w, 12, "nan") << " | " << fmt_value(r.force, r.noise_force, 12, "nan") << " | "
         << (std::isfinite(r.dip) ? fmt("%.1e", r.dip / kR) : std::string("—")) << " | " << dip_place(r) << " | " << layout << space << " |\n";
    }
    const ErrorBar a = finest_bar(ours);
    const ErrorBar b = error_bar(theirs);
    const double diff = std::abs(a.value - b.value), tol = a.bar + b.bar;
    md << "\nTable: " << words("liftoff.caption", {{"scene", s.name}}) << "\n\n"
       << words("liftoff.verdict_default", {{"ours", fmt_value(a.value, ours_noise, 12, "nan")}, {"ours_bar", bar_cell(a)},
                                            {"theirs", fmt_value(b.value, theirs_noise, 12, "nan")}, {"theirs_bar", bar_cell(b)},
                                            {"diff", fmt("%.1e", diff)}, {"judged", diff <= tol ? ", within" : ", **more than**"},
                                            {"tol", fmt_up(tol)}})
       << "\n\n";
    failures += diff > tol;
    // The same for `plate`'s default, which carries the kink on the grids it fits.
    const ErrorBar k = finest_bar(kinked);
    const double kdiff = std::abs(k.value - b.value), ktol = k.bar + b.bar;
    md << words("liftoff.verdict_kink", {{"ours", fmt_value(k.value, kink_noise, 12, "nan")}, {"ours_bar", bar_cell(k)},
                                         {"diff", fmt("%.1e", kdiff)}, {"judged", kdiff <= ktol ? ", within" : ", **more than**"},
                                         {"tol", fmt_up(ktol)}})
       << "\n\n";
    failures += kdiff > ktol;
  }
  return md.str();
}

}  // namespace

int main(int argc, char** argv) {
  clean_up_on_interrupt("liftoff");
  CLI::App app{"liftoff: scenes where the plate lifts off part of the rim, by the default rows (D28), rows at points,\n"
               "the periodic splines alone, and FreeFEM on fitted meshes; writes liftoff.md and liftoff.csv.\n" +
               std::string(kExitStatusHelp)};
  std::string out = "results", work = "build/liftoff-work";
  int freefem_finest = 8;
  app.add_option("--out", out, "folder for the results")->capture_default_str();
  app.add_option("--work", work, "folder for the meshes and FreeFEM's files")->capture_default_str();
  app.add_option("--freefem-finest", freefem_finest,
                 "FreeFEM's finest mesh of a whole plate: 4 m cells per quarter circle, m = 2, 4, ... this (a quarter mesh, one finer)")
      ->check(CLI::Range(2, 64))
      ->capture_default_str();
  if (const int status = parse_options(app, argc, argv, "liftoff"); status >= 0) return status;
  return run_guarded("liftoff", [&] {
    for (const char* f : {"/liftoff.md", "/liftoff.csv", "/liftoff_timings.csv"}) check_output_file("--out", out + f);
    std::filesystem::create_directories(work);
    Progress progress("liftoff", false);
    std::vector<Run> runs;
    for (const Case& s : kScenes) {
      for (const Rows& r : kRows)
        for (int k = 1; k <= r.finest; k *= 2) {
          progress.stage(std::string(s.name) + ", " + r.name + ", h = 1/" + std::to_string(16 * k));
          runs.push_back(solve(s, r, s.n16 * k));
        }
      for (int m = 2; m <= (circle_at_centre(scene_of(s)) ? 2 * freefem_finest : freefem_finest); m *= 2) {  // one finer on a quarter
        progress.stage(std::string(s.name) + ", FreeFEM, " + std::to_string(4 * m) + " cells a quarter circle");
        runs.push_back(freefem(s, m, work));
      }
    }
    // The numbers.
    std::ostringstream csv;
    csv << "# liftoff: scenes where the plate lifts off part of the rim (R = 0.0625, radius 0.25), by three kinds\n"
           "# of rows and the default rows with the kink carried (D31; rows kink, as plate solves by default), on\n"
           "# the grids h = lx/n, and by FreeFEM's exact script (n: cells along a quarter of the circle; h: the\n"
           "# longest mesh edge). max_w is the field's maximum; dip the plate's largest depth below the rim\n"
           "# between rows (h/32 apart); arcs and points the layout of the default rows (arcs -1: periodic\n"
           "# splines); exchanged the point rows added where the plate dipped; dip_on the rows where the dip is\n"
           "# deepest (arc: on a spline arc, dip_cells inside its nearer end; points: off every arc; periodic:\n"
           "# periodic splines); kinked 1 where the run carried the kink (D31). Digits above round-off. Made\n"
           "# by build/liftoff; the run times are in liftoff_timings.csv\n"
           "scene,rows,n,h,certified,max_w,total_force,dip,arcs,points,exchanged,dip_on,dip_cells,kinked\n";
    std::ostringstream timings;
    timings << "# liftoff: seconds per run (this machine, this run)\nscene,rows,n,seconds\n";
    for (const Run& r : runs) {
      csv << r.scene->key << ',' << (r.rows ? r.rows->key : "freefem") << ',' << r.n << ',' << fmt("%.6g", r.h) << ',' << (r.certified ? 1 : 0) << ','
          << fmt_value(r.max_w, r.noise_w, 12, "nan") << ',' << fmt_value(r.force, r.noise_force, 12, "nan") << ','
          << (std::isfinite(r.dip) ? fmt("%.2e", r.dip) : std::string()) << ',' << r.arcs << ',' << r.points << ',' << r.exchanged << ','
          << dip_on(r) << ',' << (rows_at(r.dip_cells) == RowsAt::Arc ? fmt("%.1f", r.dip_cells) : std::string()) << ','
          << (r.kinked ? 1 : 0) << '\n';
      timings << r.scene->key << ',' << (r.rows ? r.rows->key : "freefem") << ',' << r.n << ',' << fmt("%.3g", r.seconds) << '\n';
    }
    int failures = 0;
    const std::string md = report(runs, failures);
    write_file_atomically(out + "/liftoff.csv", csv.str());
    write_file_atomically(out + "/liftoff_timings.csv", timings.str());
    write_file_atomically(out + "/liftoff.md", md);
    if (failures) {
      std::cerr << "liftoff: " << failures << " runs uncertified or codes that differ by more than their bars (see liftoff.md)\n";
      return kNotConverged;
    }
    return kSuccess;
  });
}
