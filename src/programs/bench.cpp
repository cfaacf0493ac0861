// bench: the work-precision study of `make bench`. On the paper's problem with nodal sampling, for
// n = 8, 16, ..., it times one unconstrained factorisation and solve, the exact-constraint solver and
// the penalty schemes (3a) and (5a); each run is a child process, so its peak memory is its own.
// Writes results/speed_vs_error.{csv,md}. `bench --help` lists the options.
#include <CLI/CLI.hpp>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "active_set.hpp"
#include "atomic_file.hpp"
#include "exit_codes.hpp"
#include "contact.hpp"
#include "continuum_limits.hpp"
#include "fields.hpp"
#include "format.hpp"
#include "measurements.hpp"
#include "richardson.hpp"
#include "published.hpp"
#include "schemes.hpp"
#include "stopwatch.hpp"
#include "verdict.hpp"
#include "words.hpp"

using namespace plate;

namespace {

struct Job {
  std::string solver;  // baseline, exact, nonlinear, linear
  int n = 0;
  double tol = 0;      // penalty schemes: OS
};

struct Outcome {
  Job job;
  std::map<std::string, double> v;  // what the child measured
  std::vector<double> nodal;        // nodal values of w (interior nodes)
  double peak_mib = 0;
  bool ok = false;                  // the child ran to the end
};

// The child's work. Times exclude the assembly of the fine-grid problem, which every solver
// shares and which is timed on its own.
std::map<std::string, double> run_job(const Job& job, const Scene& scene, std::vector<double>& nodal) {
  std::map<std::string, double> v;
  const auto t0 = Clock::now();
  Problem p = make_problem(scene, make_grid(job.n), SamplingSpec{SamplingKind::Nodes});
  v["assemble_s"] = seconds_since(t0);
  v["unknowns"] = p.grid.unknowns();
  VectorXd w;
  const auto t1 = Clock::now();
  if (job.solver == "baseline") {
    // One unconstrained solve: analysis, numeric factorisation and a solve, as a user would pay once.
    Cholesky chol;
    chol.analyze(p.K);
    v["analyse_s"] = seconds_since(t1);
    const auto t2 = Clock::now();
    chol.factorize(p.K);
    v["factorise_s"] = seconds_since(t2);
    const auto t3 = Clock::now();
    w = chol.solve(p.M * VectorXd::Ones(p.grid.unknowns()));  // a uniform load; the time does not depend on it
    v["solve_s"] = seconds_since(t3);
    v["converged"] = 1;
  } else if (job.solver == "exact") {
    const ExactResult r = solve_sequenced(p, ExactOptions{});
    w = r.w;
    int its = 0, facts = 0;
    long cols = 0;
    for (const auto& l : r.levels) its += l.pdas_iterations + l.primal_steps, facts += l.factorizations, cols += l.correction_columns;
    v["iterations"] = its;
    v["factorizations"] = facts;
    v["correction_solves"] = cols;
    v["fine_iterations"] = r.levels.back().pdas_iterations + r.levels.back().primal_steps;
    v["active"] = r.levels.back().active;
    v["certificate"] = r.certificate.worst();
    v["converged"] = r.converged;
  } else {
    SolveOptions o;
    o.scheme = job.solver == "linear" ? Scheme::Linear : Scheme::Nonlinear;
    o.tol = job.tol;
    const SolveResult r = solve(p, o);
    w = r.w;
    int facts = 0;
    for (const auto& l : r.levels) facts += l.factorizations;
    v["iterations"] = r.total_iterations();
    v["factorizations"] = facts;
    v["eps"] = r.eps;
    v["converged"] = r.converged;
  }
  v["seconds"] = seconds_since(t1);
  v["w_centre"] = evaluate(p, w, 0.5, 0.5).w;
  for (Eigen::Index q = 0; q < w.size() / 4; ++q) nodal.push_back(w[4 * q]);
  return v;
}

bool is_peer(const Job& job) { return job.solver.rfind("snesvi-", 0) == 0; }

// Where the peer program is, where it reads the paper's numbers, and the certificate it must reach:
// 1e-9, not our 1e-10, because at n = 512 both SNESVI methods stall near 2.3e-10 in round-off (the
// multipliers they are judged by are read off K w - F); ours meets 1e-10 and is timed to it.
struct Peer {
  std::string program, reference;
  double tol = 1e-9;
};
// "snesvi-rsls" (sequenced, as ours), "snesvi-rsls-cold" (max(phi, 0) on the finest grid alone).
std::string peer_method(const Job& job) { return job.solver.substr(7, 4); }
std::string peer_start(const Job& job) {
  const std::string cold = "-cold";
  return job.solver.size() > cold.size() && job.solver.compare(job.solver.size() - cold.size(), cold.size(), cold) == 0
             ? "cold" : "sequenced";
}

// Runs a job in a child process and collects its measurements and its peak resident memory. A
// peer's child becomes the PETSc program itself, which writes the same file.
Outcome run_in_child(const Job& job, const Scene& scene, const std::filesystem::path& scratch, const Peer& peer) {
  Outcome out{job, {}, {}, 0, false};
  const std::filesystem::path file = scratch / ("w_" + job.solver + "_" + std::to_string(job.n) + ".txt");
  std::cout.flush();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("bench: fork failed");
  if (pid == 0 && is_peer(job)) {
    const std::string n = std::to_string(job.n), method = peer_method(job), start = peer_start(job), out = file.string();
    const std::string tol = fmt("%.17g", peer.tol);
    execl(peer.program.c_str(), peer.program.c_str(), "-n", n.c_str(), "--method", method.c_str(), "--start",
          start.c_str(), "--tol", tol.c_str(), "--reference", peer.reference.c_str(), "--out", out.c_str(),
          static_cast<char*>(nullptr));
    std::cerr << "bench: cannot run " << peer.program << "\n";
    _exit(kFailure);
  }
  if (pid == 0) {
    int status = kFailure;
    try {
      Measurements m;
      m.v = run_job(job, scene, m.nodal);
      write_measurements(file, m);
      status = kSuccess;
    } catch (const std::exception& e) {
      std::cerr << "bench: " << job.solver << " n = " << job.n << ": " << e.what() << "\n";
    }
    _exit(status);
  }
  int status = 0;
  struct rusage ru {};
  wait4(pid, &status, 0, &ru);
  out.peak_mib = ru.ru_maxrss / 1024.0;
  // A peer that ran to the end but did not converge (exit 3) still reports what it reached.
  const bool reported = WIFEXITED(status) && (WEXITSTATUS(status) == 0 || (is_peer(job) && WEXITSTATUS(status) == kNotConverged));
  if (!reported) return out;
  Measurements m = read_measurements(file);
  out.v = std::move(m.v);
  out.nodal = std::move(m.nodal);
  std::filesystem::remove(file);
  out.ok = true;
  return out;
}

double max_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

// The plate's max w (the rim-contact series), which lies at the centre: the errors of the centre deflection are
// measured against it, so that bench and time_to_accuracy measure against one answer.
struct Continuum {
  double w = NAN, bar = NAN;
};

double baseline_seconds(const Outcome& b) { return b.v.at("analyse_s") + b.v.at("factorise_s") + b.v.at("solve_s"); }

std::string csv(const std::vector<Outcome>& outcomes, const std::map<int, const Outcome*>& exact_at,
                const std::map<int, const Outcome*>& baseline_at, const Continuum& L) {
  std::ostringstream o;
  o << "# bench (make bench): the paper's problem (cylinder R = 0.0625, f = 0) with nodal sampling.\n"
       "# solver: baseline = one unconstrained analysis + factorisation + solve of K; exact = primal-dual active\n"
       "# sets with grid sequencing; snesvi-rsls, snesvi-ssls = PETSc's SNESVI (build/peer_snesvi) on the identical\n"
       "# problem, sequenced as ours (-cold: started on the finest grid alone), to a certificate of 1e-9; nonlinear = scheme (3a), linear = scheme (5a), both with eps continuation and\n"
       "# stopping tolerance tol. seconds: the solve, without assembling the fine-grid problem (assemble_s);\n"
       "# ratio: seconds / baseline seconds on the same grid; peak_mib: the run's peak resident memory;\n"
       "# error_discrete: max over nodes |w - w_exact| with w_exact the exact solver's answer on the same grid;\n"
       "# error_limit: |w(0.5,0.5) - w_lim| with w_lim = " << fmt("%.9g", L.w) << " +- " << fmt("%.1g", L.bar)
    << " the plate's max w by the rim-contact series (rim_answer.csv);\n"
       "# certificate: worst relative entry of our certificate (exact solver, and the peers' answers judged by it).\n"
       "# Timings vary from run to run.\n";
  o << "solver,n,unknowns,tol,converged,iterations,factorizations,assemble_s,seconds,ratio,peak_mib,w_centre,"
       "error_discrete,error_limit,certificate\n";
  // Grouped by solver and tolerance, so that each forms one block (one line in the plot).
  std::vector<const Outcome*> order;
  for (const char* solver : {"baseline", "exact", "snesvi-rsls", "snesvi-ssls", "snesvi-rsls-cold", "snesvi-ssls-cold", "nonlinear",
                             "linear"})
    for (double tol : {0.0, 1e-6, 1e-8})
      for (const Outcome& r : outcomes)
        if (r.job.solver == solver && r.job.tol == tol) order.push_back(&r);
  for (const Outcome* rp : order) {
    const Outcome& r = *rp;
    if (!r.ok) {
      o << r.job.solver << ',' << r.job.n << ",,,failed,,,,,,,,,,\n";
      continue;
    }
    const auto& v = r.v;
    const bool base = r.job.solver == "baseline";
    const double seconds = base ? baseline_seconds(r) : v.at("seconds");
    const auto b = baseline_at.find(r.job.n);
    const auto e = exact_at.find(r.job.n);
    o << r.job.solver << ',' << r.job.n << ',' << v.at("unknowns") << ',' << (r.job.tol > 0 ? fmt("%g", r.job.tol) : "")
      << ',' << (v.at("converged") != 0 ? "yes" : "no") << ',' << (base ? "" : fmt("%.0f", v.at("iterations"))) << ','
      << (base ? "1" : fmt("%.0f", v.at("factorizations"))) << ',' << fmt("%.4g", v.at("assemble_s")) << ','
      << fmt("%.4g", seconds) << ',' << (b != baseline_at.end() ? fmt("%.3f", seconds / baseline_seconds(*b->second)) : "")
      << ',' << fmt("%.0f", r.peak_mib) << ',';
    if (base) {
      o << ",,,\n";
      continue;
    }
    o << fmt("%.10f", v.at("w_centre")) << ','
      << (e != exact_at.end() ? fmt("%.3e", max_diff(r.nodal, e->second->nodal)) : "") << ','
      << fmt("%.3e", std::abs(v.at("w_centre") - L.w)) << ','
      << (r.job.solver == "exact" || is_peer(r.job) ? fmt("%.2e", v.at("certificate")) : "") << '\n';
  }
  return o.str();
}


using ByN = std::map<int, const Outcome*>;

// `make bench` stops at n = 512. The grid of 1024 shows scale alone; it took about as long as all
// the step's other runs together and more than twice their peak memory (15 GiB, which a machine
// with 16 GiB would swap for), so `make bench-large` runs it by itself (--min-n 1024) into
// results/large/.
struct Limits {
  int min_n = 8, max_exact = 512, max_baseline = 512, max_nonlinear = 128, max_linear = 64;
  int min_peer = 32, max_rsls = 512, max_ssls = 512, max_cold = 256;
  double budget = 60;
};

// The exact solver against one unconstrained factorisation, grid by grid.
void exact_table(std::ostream& md, const ByN& exact_at, const ByN& baseline_at, const Limits& l) {
  md << words("bench.intro", {{"min", std::to_string(l.min_n)}, {"max", std::to_string(l.max_exact)}, {"budget", fmt("%g", l.budget)}}) << "\n\n";
  md << "| $n$ | unknowns | baseline s | of which factorise | exact s | ratio | PDAS its | factorisations | "
        "correction solves | peak MiB | certificate | $w(0.5, 0.5)$ |\n"
        "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& [n, e] : exact_at) {
    const auto b = baseline_at.find(n);
    const auto& ev = e->v;
    md << "| " << n << " | " << fmt("%.0f", ev.at("unknowns")) << " | ";
    if (b != baseline_at.end()) {
      const auto& bv = b->second->v;
      md << fmt("%.3g", baseline_seconds(*b->second)) << " | " << fmt("%.3g", bv.at("factorise_s")) << " | "
         << fmt("%.3g", ev.at("seconds")) << " | " << fmt("%.2f", ev.at("seconds") / baseline_seconds(*b->second)) << " | ";
    } else {
      md << "not run | | " << fmt("%.3g", ev.at("seconds")) << " | | ";
    }
    md
       << fmt("%.0f", ev.at("fine_iterations")) << " | " << fmt("%.0f", ev.at("factorizations")) << " | "
       << fmt("%.0f", ev.at("correction_solves")) << " | " << fmt("%.0f", e->peak_mib) << " | "
       << fmt("%.1e", ev.at("certificate")) << " | " << fmt("%.7f", ev.at("w_centre")) << " |\n";
  }
  md << "\nTable: " << words("bench.exact_caption") << "\n";
}

void penalty_table(std::ostream& md, const std::vector<Outcome>& outcomes, const ByN& exact_at, const ByN& baseline_at) {
  md << "\n| scheme | tol | $n$ | converged | iterations | factorisations | s | ratio to baseline | error (discrete) |\n"
        "|---|---:|---:|---|---:|---:|---:|---:|---:|\n";
  for (const Outcome& r : outcomes) {
    if (r.job.solver != "nonlinear" && r.job.solver != "linear") continue;
    if (!r.ok) {
      md << "| " << r.job.solver << " | " << fmt("%g", r.job.tol) << " | " << r.job.n << " | failed | | | | | |\n";
      continue;
    }
    const auto b = baseline_at.find(r.job.n);
    const auto e = exact_at.find(r.job.n);
    md << "| " << (r.job.solver == "linear" ? "(5a)" : "(3a)") << " | " << fmt("%g", r.job.tol) << " | "
       << r.job.n << " | " << (r.v.at("converged") != 0 ? "yes" : "**no**") << " | " << fmt("%.0f", r.v.at("iterations"))
       << " | " << fmt("%.0f", r.v.at("factorizations")) << " | " << fmt("%.3g", r.v.at("seconds")) << " | "
       << (b != baseline_at.end() ? fmt("%.1f", r.v.at("seconds") / baseline_seconds(*b->second)) : "") << " | "
       << (e != exact_at.end() ? fmt("%.1e", max_diff(r.nodal, e->second->nodal)) : "") << " |\n";
  }
  md << "\nTable: " << words("bench.penalty_caption") << "\n";
}

// The peers: PETSc's SNESVI on the identical discrete problem, against our exact solver.
void peers_table(std::ostream& md, const std::vector<Outcome>& outcomes, const ByN& exact_at, const Peer& peer) {
  md << "\n" << words("bench.peers_intro", {{"program", peer.program}, {"tol", fmt("%g", peer.tol)}}) << "\n\n"
        "| $n$ | solver | certified | Newton its | factorisations | s | ratio to ours | peak MiB | certificate | "
        "largest nodal difference to ours |\n|---:|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Outcome& r : outcomes) {
    if (!is_peer(r.job)) continue;
    md << "| " << r.job.n << " | " << r.job.solver.substr(7) << " | ";
    if (!r.ok) {
      md << "failed | | | | | | | |\n";
      continue;
    }
    const auto e = exact_at.find(r.job.n);
    const double ours = e != exact_at.end() ? e->second->v.at("seconds") : NAN;
    md << (r.v.at("converged") != 0 ? "yes" : "**no**") << " | " << fmt("%.0f", r.v.at("iterations")) << " | "
       << fmt("%.0f", r.v.at("factorizations")) << " | " << fmt("%.3g", r.v.at("seconds")) << " | "
       << (std::isfinite(ours) ? fmt("%.1f", r.v.at("seconds") / ours) : "") << " | " << fmt("%.0f", r.peak_mib) << " | "
       << fmt("%.1e", r.v.at("certificate")) << " | "
       << (e != exact_at.end() ? fmt("%.1e", max_diff(r.nodal, e->second->nodal)) : "") << " |\n";
  }
  md << "\nTable: " << words("bench.peers_caption") << "\n";
}

// Target (issue 42): at n = 256 and 512, at least 3 times faster than the fastest certified SNESVI
// configuration run there (cold or sequenced, rsls or ssls). When none is certified, the fastest
// uncertified one is reported as such, with how far its certificate and its answer are from ours,
// so the target is never silently "not measured".
void peer_target(std::ostream& md, const std::vector<Outcome>& outcomes, const ByN& exact_at, int max_rsls, int max_ssls) {
  for (const int n : {256, 512}) {
    const auto e = exact_at.find(n);
    const Outcome* fastest = nullptr;
    for (const bool want_certified : {true, false}) {
      for (const Outcome& r : outcomes)
        if (is_peer(r.job) && r.job.n == n && r.ok && (!want_certified || r.v.at("converged") != 0) &&
            (!fastest || r.v.at("seconds") < fastest->v.at("seconds")))
          fastest = &r;
      if (fastest) break;
    }
    if (e == exact_at.end() || !fastest) {
      md << words("bench.peer_target_missing", {{"n", std::to_string(n)}, {"rsls", std::to_string(max_rsls)},
                                                {"ssls", std::to_string(max_ssls)}})
         << "\n";
      continue;
    }
    const double ratio = fastest->v.at("seconds") / e->second->v.at("seconds");
    const bool certified = fastest->v.at("converged") != 0;
    WordValues v{{"n", std::to_string(n)},
                 {"ours", fmt("%.3g", e->second->v.at("seconds"))},
                 {"peer", fmt("%.3g", fastest->v.at("seconds"))},
                 {"config", fastest->job.solver.substr(7)},
                 {"ratio", fmt("%.1f", ratio)},
                 {"status", target_status(ratio >= 3)}};
    if (!certified)
      v.insert(v.end(), {{"cert", fmt("%.1e", fastest->v.at("certificate"))},
                         {"our_cert", fmt("%.1e", e->second->v.at("certificate"))},
                         {"diff", fmt("%.1e", max_diff(fastest->nodal, e->second->nodal))}});
    md << words(certified ? "bench.peer_target_certified" : "bench.peer_target_uncertified", v) << "\n";
  }
}

// Where the nodal grids stand against the plate's answer: the error that no solver removes.
void against_continuum(std::ostream& md, const ByN& exact_at, const Continuum& L) {
  md << "\n" << words("bench.continuum_error", {{"w", fmt("%.9g", L.w)}, {"bar", fmt("%.1g", L.bar)}}) << " ";
  if (exact_at.empty()) return void(md << "\n");
  const auto& [n, e] = *exact_at.rbegin();
  md << words("bench.nodal_error", {{"distance", fmt("%.1e", std::abs(e->v.at("w_centre") - L.w))}, {"n", std::to_string(n)}})
     << "\n";
}

void targets(std::ostream& md, const ByN& exact_at, const ByN& baseline_at, const Limits& l) {
  md << "\n" << words("targets.heading") << "\n\n";
  const auto e512 = exact_at.find(512), b512 = baseline_at.find(512);
  if (e512 != exact_at.end() && b512 != baseline_at.end()) {
    const double ratio = e512->second->v.at("seconds") / baseline_seconds(*b512->second);
    const double cert = e512->second->v.at("certificate");
    md << words("bench.target_512", {{"ours", fmt("%.3g", e512->second->v.at("seconds"))},
                                     {"baseline", fmt("%.3g", baseline_seconds(*b512->second))},
                                     {"ratio", fmt("%.2f", ratio)},
                                     {"status", target_status(ratio <= 3)},
                                     {"aim", target_status(ratio <= 2)},
                                     {"cert", fmt("%.1e", cert)},
                                     {"cert_status", target_status(cert <= 1e-10)},
                                     {"mib", fmt("%.0f", e512->second->peak_mib)},
                                     {"mib_status", target_status(e512->second->peak_mib < 4096)}})
       << "\n";
  } else if (l.max_exact < 512) {
    md << words("bench.not_run", {{"n", "512"}, {"min", std::to_string(l.min_n)}, {"max", std::to_string(l.max_exact)}}) << "\n";
  } else if (l.min_n <= 512) {
    md << words("bench.target_512_missing") << "\n";
  }  // else the grid is make bench's, not this run's (make bench-large)
  const auto e1024 = exact_at.find(1024);
  if (e1024 != exact_at.end())
    md << words("bench.target_1024", {{"unknowns", fmt("%.0f", e1024->second->v.at("unknowns"))},
                                      {"seconds", fmt("%.3g", e1024->second->v.at("seconds"))},
                                      {"mib", fmt("%.0f", e1024->second->peak_mib)},
                                      {"gib", fmt("%.2f", e1024->second->peak_mib / 1024)},
                                      {"status", target_status(e1024->second->peak_mib < 24 * 1024)}})
       << "\n";
  else
    md << words("bench.not_run", {{"n", "1024"}, {"min", std::to_string(l.min_n)}, {"max", std::to_string(l.max_exact)}}) << "\n";
  std::vector<double> N, T;
  for (const auto& [n, b] : baseline_at)
    if (n >= 64) N.push_back(b->v.at("unknowns")), T.push_back(b->v.at("assemble_s"));
  if (N.size() >= 2) {
    const double slope = loglog_slope(N, T);
    std::string per_unknown;
    for (size_t i = 0; i < N.size(); ++i) per_unknown += (i ? ", " : "") + fmt("%.2g", T[i] / N[i] * 1e9) + " ns";
    md << words("bench.assembly_target", {{"slope", fmt("%.2f", slope)},
                                          {"max", std::to_string(l.max_baseline)},
                                          {"status", target_status(slope < 1.15)},
                                          {"per_unknown", per_unknown}})
       << "\n";
  }
}

// Each solver runs on finer grids while its next run, predicted from the growth of its last two
// (time times the ratio of the last two times), stays within `budget` seconds: beyond that it would
// only show a slow solver being slower. The solvers the targets need (ours, the unconstrained
// baseline, and SNESVI's sequenced rsls, its fastest configuration) run to their limits regardless.
bool budget_exempt(const std::string& solver) { return solver == "exact" || solver == "baseline" || solver == "snesvi-rsls"; }

std::string report(const std::vector<Outcome>& outcomes, const ByN& exact_at, const ByN& baseline_at, const Limits& l,
                   const Peer& peer, const Continuum& c) {
  std::ostringstream md;
  // A run of one grid (make bench-large) has no peers or penalty schemes: no empty tables for them.
  auto ran = [&](auto pred) { return std::any_of(outcomes.begin(), outcomes.end(), [&](const Outcome& o) { return pred(o.job.solver); }); };
  const bool peers = ran([](const std::string& s) { return s.rfind("snesvi", 0) == 0; });
  const bool penalty = ran([](const std::string& s) { return s == "nonlinear" || s == "linear"; });
  exact_table(md, exact_at, baseline_at, l);
  if (peers) peers_table(md, outcomes, exact_at, peer);
  if (penalty) penalty_table(md, outcomes, exact_at, baseline_at);
  against_continuum(md, exact_at, c);
  targets(md, exact_at, baseline_at, l);
  if (peers) peer_target(md, outcomes, exact_at, l.max_rsls, l.max_ssls);
  return md.str();
}
}  // namespace

int main(int argc, char** argv) {
  plate::clean_up_on_interrupt("bench");
  CLI::App app{"bench: work-precision study of the exact-constraint solver and the penalty schemes (make bench; make bench-large for n = 1024)"};
  std::string out_dir = "results", paper_numbers = "reference/paper_numbers.csv", limits = "results/rim_answer.csv";
  Limits l;
  Peer peer{(std::filesystem::path(argv[0]).parent_path() / "peer_snesvi").string(), "reference"};
  app.add_option("--out", out_dir, "folder for speed_vs_error.csv and .md")->capture_default_str();
  app.add_option("--answer", limits, "the plate's answer (make rim-series writes it)")->capture_default_str();
  app.add_option("--paper-numbers", paper_numbers, "published numbers (the obstacle)")->check(CLI::ExistingFile)->capture_default_str();
  app.add_option("--min-n", l.min_n, "coarsest grid for every solver (a power of two >= 8; make bench-large: 1024)")
      ->check(CLI::IsMember({8, 16, 32, 64, 128, 256, 512, 1024, 2048}))
      ->capture_default_str();
  app.add_option("--max-exact", l.max_exact, "finest grid for the exact solver (a power of two >= 8)")
      ->check(CLI::IsMember({8, 16, 32, 64, 128, 256, 512, 1024, 2048}))
      ->capture_default_str();
  app.add_option("--max-baseline", l.max_baseline, "finest grid for the unconstrained factorisation and solve")
      ->check(CLI::Range(8, 2048))
      ->capture_default_str();
  app.add_option("--max-nonlinear", l.max_nonlinear, "finest grid for scheme (3a)")->check(CLI::Range(8, 2048))->capture_default_str();
  app.add_option("--max-linear", l.max_linear, "finest grid for scheme (5a)")->check(CLI::Range(8, 2048))->capture_default_str();
  app.add_option("--peer", peer.program, "the PETSc program (SNESVI)")
      ->check(CLI::ExistingFile)
      ->capture_default_str();
  app.add_option("--min-peer", l.min_peer, "coarsest grid for the peers")->check(CLI::Range(8, 2048))->capture_default_str();
  app.add_option("--max-rsls", l.max_rsls, "finest grid for SNESVI rsls (0: none)")->check(CLI::Range(0, 2048))->capture_default_str();
  app.add_option("--max-ssls", l.max_ssls, "finest grid for SNESVI ssls (0: none)")->check(CLI::Range(0, 2048))->capture_default_str();
  app.add_option("--max-cold", l.max_cold, "finest grid for SNESVI started cold (0: none)")->check(CLI::Range(0, 2048))->capture_default_str();
  app.add_option("--budget", l.budget, "seconds: a solver whose next run is predicted to take longer stops (not ours, "
                 "the baseline or sequenced rsls, which the targets need)")->check(CLI::PositiveNumber)->capture_default_str();
  app.footer(kExitStatusHelp);
  if (const int status = parse_options(app, argc, argv, "bench"); status >= 0) return status;
  if (l.min_n > l.max_exact) {
    std::cerr << "bench: bad input: --min-n (" << l.min_n << ") is above --max-exact (" << l.max_exact << "): no grid to run\n";
    return kBadInput;
  }
  peer.reference = std::filesystem::path(paper_numbers).parent_path().string();
  if (peer.reference.empty()) peer.reference = ".";
  try {
    // Read first, so that a missing continuum study stops the run before its half hour of solves.
    const auto lim = read_rim_answer(limits);
    const Continuum continuum{lim.at("max_w"), lim.at("max_w_bar")};
    const Scene scene = paper_scene();
    const std::filesystem::path scratch = std::filesystem::temp_directory_path() / ("plate_bench_" + std::to_string(getpid()));
    std::filesystem::create_directories(scratch);
    std::vector<Job> jobs;
    for (int n = l.min_n; n <= l.max_exact; n *= 2) {
      if (n <= l.max_baseline) jobs.push_back({"baseline", n, 0});
      jobs.push_back({"exact", n, 0});
      if (n >= l.min_peer && n <= l.max_rsls) jobs.push_back({"snesvi-rsls", n, 0});
      if (n >= l.min_peer && n <= l.max_ssls) jobs.push_back({"snesvi-ssls", n, 0});
      if (n >= l.min_peer && n <= std::min(l.max_cold, l.max_rsls)) jobs.push_back({"snesvi-rsls-cold", n, 0});
      if (n >= l.min_peer && n <= std::min(l.max_cold, l.max_ssls)) jobs.push_back({"snesvi-ssls-cold", n, 0});
      for (double tol : {1e-6, 1e-8})
        if (n <= l.max_nonlinear) jobs.push_back({"nonlinear", n, tol});
      if (n <= l.max_linear) jobs.push_back({"linear", n, 1e-6});
    }
    std::vector<Outcome> outcomes;
    std::map<int, const Outcome*> exact_at, baseline_at;
    std::set<std::string> over_budget;  // solver (and tol) whose next run would take longer than the budget
    std::map<std::string, double> last_seconds;
    for (const Job& job : jobs) {
      const std::string series = job.solver + fmt(" %g", job.tol);
      if (over_budget.count(series)) continue;
      std::cout << "bench: " << job.solver << " n = " << job.n << (job.tol > 0 ? " tol = " + fmt("%g", job.tol) : "")
                << " ..." << std::flush;
      outcomes.push_back(run_in_child(job, scene, scratch, peer));
      const Outcome& o = outcomes.back();
      std::cout << (o.ok ? fmt(" %.3g s", o.v.at("seconds")) + fmt(", peak %.0f MiB", o.peak_mib) : " FAILED") << "\n";
      if (!o.ok || budget_exempt(job.solver)) continue;
      const double t = o.v.at("seconds"), before = last_seconds.count(series) ? last_seconds[series] : NAN;
      if (predicted_next_seconds(before, t) > l.budget) over_budget.insert(series);
      last_seconds[series] = t;
    }
    for (const Outcome& o : outcomes)
      if (o.ok && o.job.solver == "exact") exact_at[o.job.n] = &o;
      else if (o.ok && o.job.solver == "baseline") baseline_at[o.job.n] = &o;
    std::filesystem::remove_all(scratch);
    std::filesystem::create_directories(out_dir);
    write_file_atomically(out_dir + "/speed_vs_error.csv", csv(outcomes, exact_at, baseline_at, continuum));
    write_file_atomically(out_dir + "/speed_vs_error.md", report(outcomes, exact_at, baseline_at, l, peer, continuum));
    std::cout << "bench: wrote " << out_dir << "/speed_vs_error.csv and .md\n";
    return kSuccess;
  } catch (const std::exception& e) {
    std::cerr << "bench: error: " << e.what() << "\n";
    return kFailure;
  }
}
