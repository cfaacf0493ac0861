// hard_cases: writes results/hard_cases.md, the cases the paper did not try, and
// results/hard_cases_input.md, every kind of bad input; each with what it gets: a certified answer,
// or a failure that says why. Run times go to results/hard_cases_timings.csv, so that the two
// reports rebuild byte for byte.
// `hard_cases --help` lists the options.
#include <CLI/CLI.hpp>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "active_set.hpp"
#include "atomic_file.hpp"
#include "exit_codes.hpp"
#include "contraction.hpp"
#include "eps_limit.hpp"
#include "eps_sweep.hpp"
#include "fields.hpp"
#include "contact.hpp"
#include "format.hpp"
#include "published.hpp"
#include "run_program.hpp"
#include "scenes.hpp"
#include "stopwatch.hpp"
#include "words.hpp"

using namespace plate;

namespace {

// What every section of the report needs: the published constants, the paper's scene, the
// `plate` program and a scratch folder.
struct Context {
  double lambda1 = 0, point = 0, sag = 0;
  Scene scene;
  std::string plate, cases, scratch;
  int fine = 512;
  std::ostringstream* timings = nullptr;  // case,n,run,seconds
  std::ostringstream* point_rows = nullptr;  // the point obstacle's rows, for the document's prose
};

std::string yes_no(bool b) { return b ? "yes" : "**no**"; }

// The failure in a few words, from the solver's message.
std::string why_not(const SweepRow& r) {
  if (r.converged) return "";
  if (r.message.find("round-off") != std::string::npos) return "round-off";
  if (r.message.find("max-iter") != std::string::npos) return "iteration cap";
  if (r.message.find("stopped before") != std::string::npos) return "stalled";
  if (r.message.find("stopped shrinking") != std::string::npos) return "levelled off";
  return r.message;
}

void eps_sweep(std::ostream& md, const Problem& p, const VectorXd& reference, const std::string& reference_name,
               double tol, int cap, double lambda1, const std::string& caption) {
  md << "| scheme | eps | certified | iterations | predicted (5a) | factorisations | error bound | round-off floor"
        " | violation | error vs " << reference_name << " | why not |\n|---|---:|:---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  WordValues smallest;  // said after the table, which a line between rows would cut in two
  for (Scheme s : {Scheme::Nonlinear, Scheme::Linear}) {
    double smallest_certified = 0;
    for (int e = 2; e <= 14; ++e) {
      const double eps = std::pow(10.0, -e);
      std::cerr << "hard_cases: " << to_string(s) << " at eps = " << eps << "\n";
      const SweepRow r = sweep_row(p, s, eps, tol, cap, reference);
      if (r.converged) smallest_certified = eps;
      const std::string predicted =
          s == Scheme::Linear ? fmt("%.0f", predicted_linear_iterations(r.first_step, tol, eps, lambda1)) : "—";
      md << "| " << (s == Scheme::Linear ? "(5a)" : "(3a)") << " | " << fmt("%.0e", eps) << " | "
         << yes_no(r.converged) << " | " << r.iterations << " | " << predicted << " | " << r.factorizations << " | "
         << fmt("%.1e", r.bound.bound) << " | " << fmt("%.1e", r.bound.roundoff) << " | " << fmt("%.1e", r.violation)
         << " | " << fmt("%.1e", r.error) << " | " << why_not(r) << " |\n";
    }
    smallest.emplace_back(s == Scheme::Linear ? "linear" : "nonlinear",
                          smallest_certified > 0 ? fmt("%.0e", smallest_certified) : std::string("none"));
  }
  md << "\nTable: " << caption << " " << words("hard_cases.sweep_caption_tail") << "\n\n"
     << words("hard_cases.smallest_eps", smallest) << "\n\n";
}

std::string table_cell(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  std::string out;
  for (char ch : s) out += ch == '|' ? std::string("\\|") : ch == '\n' ? std::string(" / ") : std::string(1, ch);
  return out;
}

void bad_input(std::ostream& md, const std::string& plate, const std::string& cases, const std::string& scratch) {
  md << "| input | exit status (expected) | message |\n|---|:---:|---|\n";
  int n = 0, as_expected = 0;
  for (const BadInputCase& c : read_bad_inputs(cases)) {
    const std::string json = scratch + "/bad.json";
    std::filesystem::remove(json);
    const bool own_json = c.args.find("--json") != std::string::npos;
    const Captured r = run_captured(plate + " -q " + c.args + (own_json ? "" : " --json " + json));
    const bool file_ok = own_json || (r.status == 3) == std::filesystem::exists(json);
    const bool ok = r.status == c.status && r.output.find(c.names) != std::string::npos && file_ok;
    ++n;
    as_expected += ok;
    md << "| `plate " << table_cell(c.args) << "` | " << r.status << " (" << c.status << ")"
       << (ok ? "" : " **unexpected**") << " | " << table_cell(r.output) << " |\n";
  }
  md << "\nTable: " << words("hard_cases.bad_input_caption") << "\n";
  md << "\n" << words("hard_cases.bad_input_summary", {{"ok", std::to_string(as_expected)}, {"n", std::to_string(n)}}) << "\n\n";
}

void interrupted(std::ostream& md, const std::string& plate, const std::string& scratch) {
  const int n = 256, after_ms = 500;
  const Interrupted r = interrupt_run(plate, {"-n", std::to_string(n), "-q"}, scratch + "/interrupt", after_ms);
  md << words("hard_cases.interrupted", {{"n", std::to_string(n)},
                                         {"after", fmt("%g", after_ms / 1000.0)},
                                         {"status", r.status >= 0 ? std::to_string(r.status) : std::string("(killed)")},
                                         {"message", table_cell(r.message)},
                                         {"files", std::to_string(r.files_left)}})
     << "\n\n";
}

// Each eps alone on the paper's problem, nodal and Gauss sampling, against an eps-free reference.
void small_eps(std::ostream& md, const Context& c) {
  md << "### Small eps\n\n" << words("hard_cases.small_eps_intro", {{"lambda1", fmt("%.5f", c.lambda1)}}) << "\n\n";
  {
    const Problem p = make_problem(c.scene, make_grid(16), SamplingSpec{SamplingKind::Nodes});
    const ExactResult exact = solve_exact(p, ExactOptions{});
    eps_sweep(md, p, exact.w, "exact", 1e-8, 20000, c.lambda1,
              words("hard_cases.sweep_exact_caption", {{"certificate", fmt("%.1e", exact.certificate.worst())}}));
  }
  for (int n : {16, 4}) {  // 4: the paper's own grid
    const Problem p = make_problem(c.scene, make_grid(n), SamplingSpec{SamplingKind::Gauss});
    const EpsLimit limit = eps_limit(p);
    eps_sweep(md, p, limit.w, "limit", 1e-8, 20000, c.lambda1,
              words(n == paper_cells() ? "hard_cases.sweep_limit_caption_paper" : "hard_cases.sweep_limit_caption",
                    {{"n", std::to_string(n)}, {"ratio", fmt("%.3f", limit.ratio)}, {"uncertain", fmt("%.0e", limit.estimate)}}));
  }
}

// An obstacle at one node acts as a point load: w_c / P against Timoshenko's coefficient.
void point_obstacle(std::ostream& md, const Context& c) {
  md << "### A point obstacle\n\n" << words("hard_cases.point_intro", {{"coefficient", fmt("%g", c.point)}})
     << "\n\n| n | P | w_c / P | relative difference |\n"
        "|---:|---:|---:|---:|\n";
  for (int n : {16, 32, 64, 128}) {
    const Grid g = make_grid(n);
    const Problem p = make_problem(Scene::rectangle(g.whole_lx(), g.whole_ly()).over(centre_spike(g, 0.01)).loaded(uniform(0)), g, SamplingSpec{SamplingKind::Nodes});
    const ExactResult r = solve_exact(p, ExactOptions{});
    const double P = p.sampling.weights.dot(r.lambda);
    const std::string force = fmt("%.4f", P), ratio = fmt("%.7f", 0.01 / P),
                      gap = fmt("%+.2e", (0.01 / P - c.point) / c.point);
    const int touching = members(r.active);
    md << "| " << n << (touching == 1 ? "" : " (" + std::to_string(touching) + " touching nodes)") << " | " << force
       << " | " << ratio << " | " << gap
       << (r.converged ? "" : " (not converged)") << " |\n";
    *c.point_rows << n << ',' << members(r.active) << ',' << force << ',' << ratio << ',' << gap << ','
                  << (r.converged ? 1 : 0) << '\n';
  }
  md << "\nTable: " << words("hard_cases.point_caption") << "\n";
}

// Contact on an area: where it starts (the published sag), and how the active set grows with n.
void flat_support(std::ostream& md, const Context& c) {
  md << "\n### A flat support: contact on an area\n\n" << words("hard_cases.flat_intro", {{"sag", fmt("%g", c.sag)}}) << "\n\n";
  for (double factor : {1.01, 0.99}) {
    Problem sag = make_problem(Scene::rectangle(1, 1).over(uniform(-c.sag * factor)).loaded(uniform(-1)), make_grid(32), SamplingSpec{SamplingKind::Nodes});
    const ExactResult r = solve_sequenced(sag, ExactOptions{});
    md << words("hard_cases.flat_sag", {{"factor", fmt("%.2f", factor)},
                                        {"touching", std::to_string(members(r.active))},
                                        {"converged", r.converged ? "" : " (not converged)"}})
       << "\n";
  }
  md << "\n" << words("hard_cases.flat_sequenced") << "\n\n| n | touching nodes | ratio to the coarser grid | force density at "
        "the centre | total force | PDAS its | factorisations | cold start: PDAS its |\n"
        "|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  std::string cold_its, cold_ns;
  int previous = 0;
  for (int n : {32, 64, 128, 256}) {
    const Grid g = make_grid(n);
    Problem p = make_problem(Scene::rectangle(g.whole_lx(), g.whole_ly()).over(uniform(-5e-4)).loaded(uniform(-1)), g, SamplingSpec{SamplingKind::Nodes});
    std::cerr << "hard_cases: flat support, n = " << n << "\n";
    auto t0 = Clock::now();
    const ExactResult r = solve_sequenced(p, ExactOptions{});
    const double s = seconds_since(t0);
    const ExactLevel& l = r.levels.back();
    md << "| " << n << " | " << members(r.active) << " | "
       << (previous ? fmt("%.2f", double(members(r.active)) / previous) : std::string("—")) << " | "
       << (r.lambda[g.node(n / 2, n / 2)] == 0 ? std::string("0") : fmt("%.5f", r.lambda[g.node(n / 2, n / 2)])) << " | " << fmt("%.5f", p.sampling.weights.dot(r.lambda))
       << " | " << l.pdas_iterations << " | " << l.factorizations << (r.converged ? "" : " (not converged)") << " | ";
    *c.timings << "flat support," << n << ",grid-sequenced," << fmt("%.3g", s) << "\n";
    if (n <= 128) {
      t0 = Clock::now();
      const ExactResult cold = solve_exact(p, ExactOptions{});
      *c.timings << "flat support," << n << ",cold start," << fmt("%.3g", seconds_since(t0)) << "\n";
      md << cold.levels.back().pdas_iterations << " |\n";
      cold_its += (cold_its.empty() ? "" : ", ") + std::to_string(cold.levels.back().pdas_iterations);
      cold_ns += (cold_ns.empty() ? "" : ", ") + std::to_string(n);
    } else {
      md << "— |\n";
    }
    previous = members(r.active);
  }
  md << "\nTable: " << words("hard_cases.flat_caption") << "\n";
  md << "\n" << words("hard_cases.flat_after", {{"cold_its", cold_its}, {"cold_ns", cold_ns}}) << "\n\n";
}

// Sixteen bumps: many contact regions, the exact solver against (3a).
void many_regions(std::ostream& md, const Context&) {
  md << "### Many contact regions\n\n" << words("hard_cases.bumps_intro") << "\n\n"
        "| q | regions | touching nodes | certificate | (3a) certified | (3a) regions | (3a) vs exact | eps max lambda |\n"
        "|---:|---:|---:|---:|:---:|---:|---:|---:|\n";
  for (double q : {100.0, 300.0, 1000.0}) {
    const Grid g = make_grid(64);
    const Problem p = make_problem(Scene::rectangle(g.whole_lx(), g.whole_ly()).over(bumps(4, -1.0, -0.01)).loaded(uniform(-q)), g, SamplingSpec{SamplingKind::Nodes});
    const ExactResult r = solve_exact(p, ExactOptions{});
    const SweepRow pen = sweep_row(p, Scheme::Nonlinear, 1e-10, 1e-8, 100, r.w);
    const VectorXd xi = contact_force_density(p, pen.w, 1e-10);
    NodeSet touched(xi.size());
    for (int k = 0; k < xi.size(); ++k) touched[k] = xi[k] > 0;
    md << "| " << q << " | " << contact_regions(g, r.active) << " | " << members(r.active) << " | "
       << fmt("%.1e", r.certificate.worst()) << " | " << yes_no(pen.converged) << " | " << contact_regions(g, touched)
       << " | " << fmt("%.1e", pen.error) << " | " << fmt("%.1e", 1e-10 * r.lambda.maxCoeff()) << " |\n";
  }
  md << "\nTable: " << words("hard_cases.bumps_caption") << "\n";
}

// Complementarity's degenerate case: touched with zero force.
void just_touching_obstacle(std::ostream& md, const Context&) {
  const JustTouching s = just_touching(32);
  const Problem& p = s.touching;
  const ExactResult r = solve_exact(p, ExactOptions{});
  md << "\n### An obstacle that just touches\n\n"
     << words("hard_cases.just_touching", {{"force", fmt("%.1e", p.sampling.weights.dot(r.lambda))},
                                           {"load", fmt("%.1e", s.free_plate.F.lpNorm<1>())},
                                           {"difference", fmt("%.1e", (r.w - s.w_free).lpNorm<Eigen::Infinity>())},
                                           {"certificate", fmt("%.1e", r.certificate.worst())}})
     << "\n\n";
}

// The paper's problem at n = fine: the exact solver and both schemes, and (5a)'s rate.
void million_unknowns(std::ostream& md, const Context& c) {
  // The quarter the square's mirror lines leave is the same discrete problem (mirror.hpp), for the
  // penalty schemes as for the exact solver: the energy and the penalty halve at each line alike.
  const Grid whole = make_grid(c.fine), quarter = part_of(whole, Mirrors{true, true});
  md << "### A million unknowns (n = " << c.fine << ")\n\n"
     << words("hard_cases.million_intro", {{"unknowns", std::to_string(whole.unknowns())}, {"quarter", std::to_string(quarter.unknowns())}})
     << "\n\n"
        "| solver | settings | certified | iterations | factorisations | error bound or certificate | "
        "vs exact |\n|---|---|:---:|---:|---:|---:|---:|\n";
  Problem p = make_problem(c.scene, quarter, SamplingSpec{SamplingKind::Nodes});
  std::cerr << "hard_cases: n = " << c.fine << ", exact\n";
  const auto t0 = Clock::now();
  const ExactResult exact = solve_sequenced(p, ExactOptions{});
  const double s_exact = seconds_since(t0);
  int exact_f = 0;
  for (const auto& l : exact.levels) exact_f += l.factorizations;
  md << "| exact | tol 1e-10 | " << yes_no(exact.converged) << " | " << exact.levels.back().pdas_iterations << " | "
     << exact_f << " | " << fmt("%.1e", exact.certificate.worst()) << " | — |\n";
  *c.timings << "million unknowns," << c.fine << ",exact," << fmt("%.3g", s_exact) << "\n";
  std::vector<double> linear_steps;  // (5a)'s steps in the norm of Theorem 2
  for (auto [s, eps, tol] : {std::tuple{Scheme::Nonlinear, 1e-7, 1e-6}, std::tuple{Scheme::Linear, 1e-4, 1e-6}}) {
    std::cerr << "hard_cases: n = " << c.fine << ", " << to_string(s) << "\n";
    const SweepRow r = sweep_row(p, s, eps, tol, 2000, exact.w);
    if (s == Scheme::Linear) linear_steps = r.steps;
    md << "| " << (s == Scheme::Linear ? "(5a)" : "(3a)") << " | eps " << fmt("%.0e", eps) << ", tol "
       << fmt("%.0e", tol) << " | " << yes_no(r.converged) << " | " << r.iterations << " | " << r.factorizations
       << " | " << fmt("%.1e", r.bound.bound) << " | " << fmt("%.1e", r.error) << " |\n";
    *c.timings << "million unknowns," << c.fine << "," << to_string(s) << "," << fmt("%.3g", r.seconds) << "\n";
  }
  md << "\nTable: " << words("hard_cases.million_caption", {{"n", std::to_string(c.fine)}}) << "\n";
  md << "\n" << words("hard_cases.million_after") << "\n";
  const Problem free = make_problem(Scene::rectangle(quarter.whole_lx(), quarter.whole_ly()).over(uniform(-1)).loaded(uniform(1)), quarter, SamplingSpec{SamplingKind::Nodes});
  const double eps = 1e-3;
  const std::vector<double> steps = linear_step_norms(free, eps, 30);
  const double factor = asymptotic_factor(steps), measured = (1 / factor - 1) / eps;
  md << "\n"
     << words("hard_cases.linear_rate", {{"factor", fmt("%.9f", factor)},
                                         {"measured", fmt("%.4f", measured)},
                                         {"lambda1", fmt("%.5f", c.lambda1)},
                                         {"difference", fmt("%.1e", (measured - c.lambda1) / c.lambda1)},
                                         {"steps", std::to_string(linear_steps.size())},
                                         {"slowest", fmt("%.6f", slowest_factor(linear_steps, 0.0))},
                                         {"bound", fmt("%.6f", 1 / (1 + 1e-4 * c.lambda1))}})
     << "\n\n";
}

// The 3 x 3 case on which plain primal-dual active sets cycle, and the fallback that does not.
void cycling_active_set(std::ostream& md, const Context&) {
  const Problem p = cycling_problem();
  ExactOptions plain;
  plain.globalise = false;
  const ExactResult a = solve_exact(p, plain), b = solve_exact(p, ExactOptions{});
  std::string energies;
  for (double e : b.fallback_energies) energies += (energies.empty() ? "" : " ") + fmt("%.6g", e);
  md << "### The active set that cycles\n\n"
     << words("hard_cases.cycling", {{"plain_converged", yes_no(a.converged)},
                                     {"plain_message", table_cell(a.message)},
                                     {"converged", yes_no(b.converged)},
                                     {"steps", std::to_string(b.levels.back().primal_steps)},
                                     {"energies", energies},
                                     {"certificate", fmt("%.1e", b.certificate.worst())}})
     << "\n\n";
}

// Every line of the bad-input list, and an interrupted run.
void bad_inputs(std::ostream& md, const Context& c) {
  md << "<!-- Written by build/hard_cases (make all); do not edit. -->\n\n"
        "### Bad input\n\n"
     << words("hard_cases.bad_input_intro") << "\n\n";
  bad_input(md, c.plate, c.cases, c.scratch);
  interrupted(md, c.plate, c.scratch);
}
}  // namespace

int main(int argc, char** argv) {
  plate::clean_up_on_interrupt("hard_cases");
  CLI::App app{"hard_cases: the cases the paper did not try (tiny eps, point and area contact, many contact regions,\n"
               "zero-force contact, n = 512, the cycling active set) and every kind of bad input for `plate`;\n"
               "writes hard_cases.md, hard_cases_input.md, hard_cases_point.csv and hard_cases_timings.csv."};
  std::string out = "results", reference = "reference";
  Context c;
  c.cases = "tests/bad_input.tsv", c.scratch = "build/hard-cases-work";
  c.plate = (std::filesystem::path(argv[0]).parent_path() / "plate").string();
  app.add_option("--out", out, "folder for the report")->capture_default_str();
  app.add_option("--reference", reference, "folder with plate_constants.csv and paper_numbers.csv")
      ->check(CLI::ExistingDirectory)->capture_default_str();
  app.add_option("--cases", c.cases, "the bad-input list")->check(CLI::ExistingFile)->capture_default_str();
  app.add_option("--plate", c.plate, "the plate program")->check(CLI::ExistingFile)->capture_default_str();
  app.add_option("--scratch", c.scratch, "folder for temporary files")->capture_default_str();
  app.add_option("--fine", c.fine, "the fine grid n")->check(CLI::Range(8, 4096))->capture_default_str();
  app.footer(kExitStatusHelp);
  if (const int status = parse_options(app, argc, argv, "hard_cases"); status >= 0) return status;
  try {
    std::filesystem::create_directories(c.scratch);
    const std::string constants_path = reference + "/plate_constants.csv";
    const auto constants = read_paper_numbers(constants_path);
    c.lambda1 = published(constants, "lambda1", constants_path);
    c.point = published(constants, "point_centre", constants_path);
    c.sag = published(constants, "uniform_centre", constants_path);
    c.scene = paper_scene();
    std::ostringstream md, input, timings;
    timings << "# hard_cases run times in seconds (they vary between runs)\ncase,n,run,seconds\n";
    c.timings = &timings;
    std::ostringstream point;
    point << "# hard_cases: the point obstacle (centre node, height 0.01, f = 0); w_c / P against the published "
             "coefficient\nn,touching,P,w_over_P,relative_difference,certified\n";
    c.point_rows = &point;
    md << "<!-- Written by build/hard_cases (make all); do not edit. -->\n\n";
    for (auto section : {small_eps, point_obstacle, flat_support, many_regions, just_touching_obstacle,
                         million_unknowns, cycling_active_set})
      section(md, c);
    bad_inputs(input, c);
    std::filesystem::create_directories(out);
    write_file_atomically(out + "/hard_cases.md", md.str());
    write_file_atomically(out + "/hard_cases_input.md", input.str());
    write_file_atomically(out + "/hard_cases_timings.csv", timings.str());
    write_file_atomically(out + "/hard_cases_point.csv", point.str());
  } catch (const std::exception& e) {
    std::cerr << "hard_cases: " << e.what() << "\n";
    return kFailure;
  }
  return kSuccess;
}
