// prose_numbers: every number the document's prose states, derived from the files in results/ (and
// the published constants in reference/), written to results/numbers.csv as key,value,source. The
// document names a number as {{key}} and paper/filters/numbers.lua puts the value in, so the prose
// cannot drift from the results it describes. Keys whose source is a timing or a package version
// go to results/numbers_machine.csv, so that numbers.csv rebuilds byte for byte.
// `prose_numbers --help` lists the options.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "atomic_file.hpp"
#include "csv_table.hpp"
#include "exit_codes.hpp"
#include "format.hpp"
#include "contact.hpp"
#include "dual_active_set.hpp"
#include "published.hpp"
#include "rim_contact.hpp"
#include "error_bar.hpp"
#include "refinement.hpp"
#include "richardson.hpp"

using namespace plate;

namespace {

struct Range {
  double lo = INFINITY, hi = -INFINITY;
  void add(double v) {
    if (std::isnan(v)) throw std::runtime_error("prose_numbers: a NaN in a range");
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
};

// One file of numbers: key -> (value as printed, where it comes from).
class Numbers {
 public:
  void put(const std::string& key, const std::string& value, const std::string& source) {
    for (const std::string* s : {&key, &value, &source})
      if (s->find(',') != std::string::npos || s->find('\n') != std::string::npos)
        throw std::logic_error("prose_numbers: a comma or newline in \"" + *s + "\"");
    if (!entries_.emplace(key, std::make_pair(value, source)).second)
      throw std::logic_error("prose_numbers: key " + key + " set twice");
  }
  // A range as the two keys key_min and key_max. An empty range (nothing matched) is an error,
  // never an "inf" in the prose.
  void put_range(const std::string& key, const Range& r, const std::function<std::string(double)>& format,
                 const std::string& source) {
    if (!(r.hi >= r.lo)) throw std::runtime_error("prose_numbers: nothing to take " + key + " from: " + source);
    if (!std::isfinite(r.lo) || !std::isfinite(r.hi))
      throw std::runtime_error("prose_numbers: " + key + " is not finite (a zero divisor?) in " + source);
    put(key + "_min", format(r.lo), source);
    put(key + "_max", format(r.hi), source);
  }
  std::string csv(const std::string& what) const {
    std::ostringstream out;
    out << "# Written by build/prose_numbers (make paper): " << what << "\n# The document names each as {{key}}.\n"
        << "key,value,source\n";
    for (const auto& [key, vs] : entries_) out << key << ',' << vs.first << ',' << vs.second << '\n';
    return out.str();
  }

 private:
  std::map<std::string, std::pair<std::string, std::string>> entries_;
};

Range range_of(const CsvTable& t, const std::vector<std::size_t>& rows,
               const std::function<double(std::size_t)>& value) {
  if (rows.empty()) throw std::runtime_error(t.path + ": no rows for a range");
  Range r;
  for (std::size_t row : rows) r.add(value(row));
  return r;
}

// Integers and small counts print as such; ratios to two significant digits at most, so that a
// prose range does not claim digits a rerun of a noisy timing would change.
std::string count(double v) { return fmt("%.0f", v); }
std::string ratio(double v) {
  if (v < 100) return fmt("%.2g", v);
  const double unit = std::pow(10.0, std::floor(std::log10(v)) - 1);  // two significant digits
  return fmt("%.0f", std::round(v / unit) * unit);
}

// The paper's table on its own grid (results/table.csv): what the linear scheme's stopping rule
// hides, and what the nonlinear scheme reaches.
void table_numbers(Numbers& num, const std::string& results) {
  const CsvTable t = read_csv_table(results + "/table.csv");
  const auto linear = t.where("scheme", "linear");
  const auto nonlinear = t.where("scheme", "nonlinear");
  const std::string src = "results/table.csv";
  const Range over_tol = range_of(t, linear, [&](std::size_t r) { return t.number(r, "error") / t.number(r, "tolerance"); });
  num.put_range("table.linear_error_over_tol", over_tol, ratio, src + " linear rows: error / tolerance");
  const Range linear_its = range_of(t, linear, [&](std::size_t r) { return t.number(r, "iterations"); });
  num.put("table.linear_iterations_max", count(linear_its.hi), src + " linear rows: iterations");
  const Range its = range_of(t, nonlinear, [&](std::size_t r) { return t.number(r, "iterations"); });
  num.put_range("table.nonlinear_iterations", its, count, src + " nonlinear rows: iterations");
  // The linear scheme's error over the nonlinear scheme's, row pair by row pair (same sampling and OS).
  Range gain;
  for (std::size_t a : linear)
    for (std::size_t b : nonlinear)
      if (t.text(a, "sampling") == t.text(b, "sampling") && t.text(a, "tolerance") == t.text(b, "tolerance"))
        gain.add(t.number(a, "error") / t.number(b, "error"));
  num.put_range("table.error_gain", gain, ratio, src + " linear error / nonlinear error per sampling and OS");
  Range g_over_n;
  for (std::size_t a : linear)
    for (std::size_t b : linear)
      if (t.text(a, "sampling") == "gauss" && t.text(b, "sampling") == "nodes" &&
          t.text(a, "tolerance") == t.text(b, "tolerance"))
        g_over_n.add(t.number(a, "iterations") / t.number(b, "iterations"));
  Range over_paper;
  for (std::size_t r : linear)
    if (t.text(r, "sampling") == "nodes") over_paper.add(t.number(r, "iterations") / t.number(r, "paper_iterations"));
  num.put_range("table.nodes_over_paper", over_paper, ratio, src + " nodes linear rows: iterations / paper_iterations");
  num.put_range("table.gauss_over_nodes_iterations", g_over_n, ratio, src + " linear iterations gauss / nodes per OS");
}

void table_fine_numbers(Numbers& num, const std::string& results) {
  const CsvTable t = read_csv_table(results + "/table_fine.csv");
  const auto linear = t.where("scheme", "linear");
  const std::string src = "results/table_fine.csv";
  const Range err = range_of(t, linear, [&](std::size_t r) { return t.number(r, "error"); });
  num.put_range("table_fine.linear_error", err, [](double v) { return fmt("%.1e", v); }, src + " linear rows: error");
  // Only the runs the paper's rule stopped: a run that failed it says nothing about the rule.
  const auto stopped = t.where([&](std::size_t r) { return t.text(r, "scheme") == "linear" && t.text(r, "converged") == "1"; });
  const Range over_tol = range_of(t, stopped, [&](std::size_t r) { return t.number(r, "error") / t.number(r, "tolerance"); });
  num.put_range("table_fine.linear_error_over_tol", over_tol, ratio, src + " stopped linear rows: error / tolerance");
}

// The cross-check's verdict on the square (results/crosscheck_agreement.csv): the tolerance to which
// the two codes' limits agree, relative to the value.
void crosscheck_numbers(Numbers& num, const std::string& results) {
  const CsvTable t = read_csv_table(results + "/crosscheck_agreement.csv");
  for (const char* q : {"max_w", "total_force", "mean_line_force"}) {
    const auto rows = t.where("quantity", q);
    if (rows.size() != 1) throw std::runtime_error(t.path + ": expected one row for " + q);
    num.put(std::string("crosscheck.") + q + "_relative", t.text(rows[0], "relative"),
            "results/crosscheck_agreement.csv " + std::string(q) + ": relative tolerance of agreement");
  }
}

// The penalty cross-check at fixed eps (results/crosscheck_penalty_limits.csv): the relative
// tolerance of each quantity at the largest eps, the worst over all eps, and at how many eps values
// each quantity, and both, meet their targets (1e-7 for max w, 1e-6 for the force: issue 41's).
void crosscheck_penalty_numbers(Numbers& num, const std::string& results) {
  const CsvTable t = read_csv_table(results + "/crosscheck_penalty_limits.csv");
  const std::string src = "results/crosscheck_penalty_limits.csv";
  const std::map<std::string, double> target = {{"max_w", 1e-7}, {"force", 1e-6}};
  std::map<std::string, bool> met;  // eps -> both quantities within target
  for (const auto& [q, bound] : target) {
    const auto rows = t.where("quantity", q);
    if (rows.empty()) throw std::runtime_error(t.path + ": no " + q + " rows");
    // The document calls the first eps's tolerance FreeFEM's bar, ours being far smaller. If a rebuild
    // finds otherwise the sentence is false, and the build stops here.
    const double ff_bar = parse_number(without_bound(t.text(rows.front(), "freefem_bar")), src + ": freefem_bar"),
                 our_bar = parse_number(without_bound(t.text(rows.front(), "ours_bar")), src + ": ours_bar");
    if (!(ff_bar >= 10 * our_bar))
      throw std::runtime_error(t.path + ": the first " + q + " tolerance is no longer FreeFEM's bar; paper.md says it is");
    num.put("crosscheck_penalty." + q + "_relative_first", t.text(rows.front(), "relative"), src + " first " + q + " row: relative");
    // A relative below round-off is printed as its bound, "< 2e-08": the bound is what it can claim.
    auto relative = [&](std::size_t r) {
      return parse_number(without_bound(t.text(r, "relative")), src + ": relative");
    };
    Range rel;
    std::string worst;
    int meets = 0;
    for (std::size_t r : rows) {
      const double v = relative(r);
      if (v >= rel.hi) worst = t.text(r, "relative");
      rel.add(v);
      meets += v <= bound;
      // The document says that where a tolerance misses its target, FreeFEM's bar is its last
      // increment (its sequence not steady).
      if (v > bound && t.text(r, "freefem_steady") != "0")
        throw std::runtime_error(t.path + ": a " + q + " row misses its target with FreeFEM's order steady; paper.md says it is not");
      const auto [it, fresh] = met.emplace(t.text(r, "eps"), true);
      it->second = it->second && v <= bound;
    }
    num.put("crosscheck_penalty." + q + "_relative_worst", worst, src + " " + q + " rows: largest relative");
    num.put("crosscheck_penalty." + q + "_targets_met", std::to_string(meets), src + " " + q + " rows: relative within " + fmt("%g", bound));
  }
  // The document calls FreeFEM's order at the first eps steady and quotes it: if it is not, the
  // sentence is false, and the build stops here rather than print "steady ()".
  const std::size_t first = t.where("quantity", "max_w").front();
  if (t.text(first, "freefem_order").empty())
    throw std::runtime_error(t.path + ": FreeFEM's order in max w at the first eps is not steady; paper.md says it is");
  num.put("crosscheck_penalty.max_w_order_freefem_first", t.text(first, "freefem_order"), src + " first max_w row: freefem_order");
  num.put("crosscheck_penalty.eps_first", t.text(first, "eps"), src + " first row: eps");
  num.put("crosscheck_penalty.eps_last", t.text(t.rows.size() - 1, "eps"), src + " last row: eps");
  // The document judges the paper's Fig. 2 by the last eps's rows, calling that eps the figure's: if
  // crosscheck_penalty_fig2.csv was made at another, the sentence is false, and the build stops here.
  {
    std::ifstream fig2(results + "/crosscheck_penalty_fig2.csv");
    std::string head;
    std::getline(fig2, head);
    const std::string key = "at eps = ";
    const size_t at = head.find(key);
    const double fig2_eps = at == std::string::npos ? NAN : std::strtod(head.c_str() + at + key.size(), nullptr);
    const double last = t.number(t.rows.size() - 1, "eps");
    if (!(std::abs(fig2_eps - last) <= 1e-12 * last))
      throw std::runtime_error(results + "/crosscheck_penalty_fig2.csv: Fig. 2's eps is not the last fixed eps; paper.md says it is");
  }
  for (const char* q : {"max_w", "force"}) {
    const std::size_t last = t.where("quantity", q).back();
    num.put(std::string("crosscheck_penalty.") + q + "_relative_last", t.text(last, "relative"), src + " last " + q + " row: relative (Fig. 2's eps)");
    // paper.md calls FreeFEM's bar at Fig. 2's eps its last increment: its order there must not be steady.
    if (t.text(last, "freefem_steady") != "0")
      throw std::runtime_error(t.path + ": FreeFEM's " + q + " is steady at Fig. 2's eps; paper.md says its bar is its last increment");
  }
  int count = 0;
  for (const auto& [eps, ok] : met) count += ok;
  num.put("crosscheck_penalty.eps_targets_met", std::to_string(count), src + ": eps values where both relatives meet 1e-7 / 1e-6");
  num.put("crosscheck_penalty.eps_count", std::to_string(met.size()), src + ": eps values");
}

// The point obstacle of the hard cases (results/hard_cases_point.csv): the finest grid's w_c / P.
void hard_cases_numbers(Numbers& num, const std::string& results) {
  const CsvTable t = read_csv_table(results + "/hard_cases_point.csv");
  if (t.rows.empty()) throw std::runtime_error(t.path + ": no rows");
  const std::size_t last = t.rows.size() - 1;
  const std::string src = "results/hard_cases_point.csv finest row";
  num.put("hard_cases.point_n_finest", t.text(last, "n"), src);
  num.put("hard_cases.point_w_over_P_finest", t.text(last, "w_over_P"), src);
  num.put("hard_cases.point_gap_percent_finest", fmt("%.2f", 100 * t.number(last, "relative_difference")), src);
  num.put("hard_cases.point_gap_percent_first", fmt("%.2f", 100 * t.number(0, "relative_difference")),
          "results/hard_cases_point.csv first row");
  num.put("hard_cases.point_n_first", t.text(0, "n"), "results/hard_cases_point.csv first row");
}

// The one number of the speed report that is no timing: how far the nodal grids' exact answer is
// from the continuum answer. It goes to numbers.csv, which it leaves byte-identical on a rebuild.
void bench_error_numbers(Numbers& num, const CsvTable& t) {
  const auto exact = t.where("solver", "exact");
  if (exact.empty()) throw std::runtime_error(t.path + ": no exact rows");
  num.put("bench.nodal_finest_error", fmt("%.1e", t.number(exact.back(), "error_limit")),
          "results/speed_vs_error.csv exact at the largest n: error_limit (against the continuum answer)");
}

// The speed report (results/speed_vs_error.csv): the exact solver against one factorisation, and
// the peers against the exact solver. Timings: these go to the machine's file.
void bench_numbers(Numbers& num, const CsvTable& t) {
  const std::string src = "results/speed_vs_error.csv";
  const auto exact = t.where("solver", "exact");
  // Grids that take milliseconds time the clock more than the solver: the ratios start at n = 32.
  constexpr int kTimedFrom = 32;
  const auto with_ratio = t.where([&](std::size_t r) {
    return t.text(r, "solver") == "exact" && !t.text(r, "ratio").empty() && t.number(r, "n") >= kTimedFrom;
  });
  num.put("bench.ratio_n_from", std::to_string(kTimedFrom), "src/programs/prose_numbers.cpp kTimedFrom");
  const Range rr = range_of(t, with_ratio, [&](std::size_t r) { return t.number(r, "ratio"); });
  num.put_range("bench.exact_ratio", rr, [](double v) { return fmt("%.1f", v); }, src + " exact rows: seconds / baseline seconds");
  const std::size_t finest = with_ratio.back(), largest = exact.back();
  num.put("bench.n_finest", t.text(finest, "n"), src + " largest n with a baseline");
  num.put("bench.exact_seconds_finest", fmt("%.3g", t.number(finest, "seconds")), src + " exact at that n");
  num.put("bench.unknowns_finest_million", fmt("%.2g", t.number(finest, "unknowns") / 1e6), src + " unknowns at that n");
  num.put("bench.n_largest", t.text(largest, "n"), src + " largest exact n");
  num.put("bench.exact_seconds_largest", fmt("%.3g", t.number(largest, "seconds")), src + " exact at the largest n");
  num.put("bench.exact_factorizations_largest", t.text(largest, "factorizations"), src + " exact at the largest n");
  num.put("bench.exact_grids_largest", count(std::log2(t.number(largest, "n") / t.number(exact.front(), "n")) + 1),
          src + " grids of the sequence from the smallest n");
  // What a grid costs against the one with twice the cell size: one factorisation and solve.
  Range growth;
  const auto base = t.where("solver", "baseline");
  for (std::size_t k = 1; k < base.size(); ++k)
    if (t.number(base[k], "n") >= 64) growth.add(t.number(base[k], "seconds") / t.number(base[k - 1], "seconds"));
  num.put_range("bench.baseline_growth", growth, ratio, src + " baseline seconds(n) / seconds(n/2) for n >= 64");
  // The peers' time over ours on the same n, over the runs our certificate accepts.
  // snesvi-rsls is sequenced as ours; snesvi-rsls-cold starts on the finest grid (bench.cpp).
  for (const std::string peer : {"snesvi-rsls", "snesvi-ssls", "snesvi-rsls-cold", "snesvi-ssls-cold"}) {
    Range over;
    for (std::size_t r : t.where("solver", peer)) {
      if (t.text(r, "converged") != "yes") continue;
      for (std::size_t e : exact)
        if (t.text(e, "n") == t.text(r, "n")) over.add(t.number(r, "seconds") / t.number(e, "seconds"));
    }
    std::string key = "bench." + peer.substr(7);  // bench.rsls, bench.rsls_cold, ...
    std::replace(key.begin(), key.end(), '-', '_');
    num.put_range(key + "_over_ours", over, ratio, src + " " + peer + " seconds / exact seconds (certified runs)");
  }
}

// The grid `make bench-large` runs alone (results/large/speed_vs_error.csv): what scale costs.
void bench_large_numbers(Numbers& num, const CsvTable& t) {
  const std::string src = "results/large/speed_vs_error.csv";
  const auto exact = t.where("solver", "exact");
  if (exact.empty()) throw std::runtime_error(t.path + ": no exact rows");
  const std::size_t r = exact.back();
  num.put("bench.large_n", t.text(r, "n"), src + " exact: n");
  num.put("bench.large_unknowns_million", fmt("%.2g", t.number(r, "unknowns") / 1e6), src + " exact: unknowns");
  num.put("bench.large_seconds", fmt("%.3g", t.number(r, "seconds")), src + " exact: seconds");
  num.put("bench.large_gib", fmt("%.1f", t.number(r, "peak_mib") / 1024), src + " exact: peak memory");
}

// The continuum study's limits (results/continuum_limits.csv): how far the nodal total force's
// "steady" Richardson limit lies from the edge-sampling answer, in its own error bars.
void continuum_numbers(Numbers& num, const std::string& results) {
  const CsvTable t = read_csv_table(results + "/continuum_limits.csv");
  const auto row = [&](const std::string& q, const std::string& sampling) {
    for (std::size_t r : t.where("quantity", q))
      if (t.text(r, "sampling") == sampling) return r;
    throw std::runtime_error(t.path + ": no row " + q + "," + sampling);
  };
  for (const char* q : {"max_w", "total_force", "mean_line_force"}) {
    const std::size_t r = row(q, "edge");
    num.put(std::string("continuum.") + q + "_limit", t.text(r, "limit"), "results/continuum_limits.csv " + std::string(q) + " edge limit");
    num.put(std::string("continuum.") + q + "_bar", t.text(r, "bar"), "results/continuum_limits.csv " + std::string(q) + " edge bar");
  }
  const std::size_t nodes = row("total_force", "nodes"), edge = row("total_force", "edge");
  const std::string src = "results/continuum_limits.csv total_force";
  // How far point rows' line load lies from the series' q, and the spline rows' on the same grid.
  const CsvTable q = read_csv_table(results + "/continuum_q.csv");
  const auto points = q.where("sampling", "edge-points");
  if (points.empty()) throw std::runtime_error(q.path + ": no edge-points rows");
  const std::string n_points = q.text(points.front(), "n");
  double scatter = 0, spline = 0;
  for (std::size_t r : points) scatter = std::max(scatter, std::abs(q.number(r, "q") / q.number(r, "q_series") - 1));
  for (std::size_t r : q.where("sampling", "edge"))
    if (q.text(r, "n") == n_points) spline = std::max(spline, std::abs(q.number(r, "q") / q.number(r, "q_series") - 1));
  num.put("continuum.q_scatter_percent", fmt("%.0f", 100 * scatter),
          "results/continuum_q.csv edge-points rows: max |q / q_series - 1| in per cent");
  num.put("continuum.q_spline_off", fmt("%.1e", spline), "results/continuum_q.csv edge rows on the same n: max |q / q_series - 1|");
  num.put("continuum.q_n_points", n_points, "results/continuum_q.csv edge-points n");
  num.put("continuum.nodes_force_limit", t.text(nodes, "limit"), src + " nodes limit");
  num.put("continuum.nodes_force_bar", t.text(nodes, "bar"), src + " nodes bar");
  num.put("continuum.nodes_force_bars_off",
          fmt("%.0f", std::abs(t.number(nodes, "limit") - t.number(edge, "limit")) / t.number(nodes, "bar")),
          src + " |nodes limit - edge limit| / nodes bar");
}

// The yardstick (results/rim_answer.csv) and how the grids approach it (results/continuum_error.csv):
// the pointwise line load's error on every edge grid, and the last observed orders of max w and the force.
void rim_series_numbers(Numbers& num, const std::string& results) {
  const CsvTable a = read_csv_table(results + "/rim_answer.csv");
  for (std::size_t r = 0; r < a.rows.size(); ++r) {
    const std::string q = a.text(r, "quantity");
    num.put("rim." + q, a.text(r, "value"), "results/rim_answer.csv " + q);
    if (!a.text(r, "bar").empty()) num.put("rim." + q + "_bar", a.text(r, "bar"), "results/rim_answer.csv " + q + " bar");
  }
  // The plate alone (results/uniform_load.csv): the finite elements' error at every n, round-off on the finest.
  const CsvTable u = read_csv_table(results + "/uniform_load.csv");
  // A printed error's magnitude: its sign dropped; a bound "< B" stays as printed.
  const auto magnitude = [](const std::string& v) { return v.substr(v.rfind('-', 0) == 0); };
  for (std::size_t r = 0; r < u.rows.size(); ++r) {
    const std::string n = u.text(r, "n"), src = "results/uniform_load.csv n = " + n + ": |";
    if (n == "0") continue;
    num.put("fe.uniform_error_" + n, magnitude(u.text(r, "relative_error")), src + "relative_error|");
    num.put("fe.uniform_refined_error_" + n, magnitude(u.text(r, "relative_error_refined")), src + "relative_error_refined|");
  }
  const CsvTable e = read_csv_table(results + "/continuum_error.csv");
  const std::vector<std::size_t> edge = e.where("sampling", "edge");
  if (edge.size() < 2) throw std::runtime_error(e.path + ": fewer than two edge rows");
  const std::string src = "results/continuum_error.csv edge rows";
  Range line;
  for (std::size_t r : edge) line.add(e.number(r, "err_line_pointwise"));
  num.put_range("continuum.edge_line_error", line, [](double v) { return fmt("%.2g", v); }, src + ": err_line_pointwise");
  // The line load point by point, grid by grid, with its observed order; and point rows' for contrast.
  for (std::size_t i = 0; i < edge.size(); ++i) {
    const std::string n = e.text(edge[i], "n");
    num.put("continuum.edge_line_error_" + n, fmt("%.1e", e.number(edge[i], "err_line_pointwise")), src + " n = " + n + ": err_line_pointwise");
    if (i > 0)
      num.put("continuum.edge_line_order_" + n,
              fmt("%.1f", std::log2(e.number(edge[i - 1], "err_line_pointwise") / e.number(edge[i], "err_line_pointwise"))),
              src + " n = " + n + ": log2 of the ratio to the grid before");
  }
  Range points;
  for (std::size_t r : e.where("sampling", "edge-points")) points.add(e.number(r, "err_line_pointwise"));
  num.put_range("continuum.points_line_error", points, [](double v) { return fmt("%.2g", v); },
                "results/continuum_error.csv edge-points rows: err_line_pointwise");
  const std::size_t last = edge.back(), before = edge[edge.size() - 2];
  num.put("continuum.edge_n_finest", e.text(last, "n"), src + ": finest n");
  num.put("continuum.edge_n_before", e.text(before, "n"), src + ": the n before the finest");
  for (const char* q : {"max_w", "total_force"}) {
    const std::string column = std::string("err_") + q;
    num.put(std::string("continuum.edge_error_") + q + "_finest", e.text(last, column), src + ": finest " + column);
    num.put(std::string("continuum.edge_error_") + q + "_before", e.text(before, column), src + ": " + column + " before the finest");
    num.put(std::string("continuum.edge_order_") + q + "_last",
            fmt("%.1f", std::log2(e.number(before, column) / e.number(last, column))),
            src + ": log2 of the ratio of the last two " + column);
  }
}

// The lift-off scenes (results/liftoff.csv): the deepest dip of the splines alone, and of the
// default rows on each scene's finest grid, both relative to R.
void liftoff_numbers(Numbers& num, const std::string& results) {
  const CsvTable t = read_csv_table(results + "/liftoff.csv");
  const double R = 0.0625;  // the cylinder's height on every lift-off scene (liftoff.cpp)
  const std::string src = "results/liftoff.csv";
  Range splines;
  for (std::size_t r : t.where("rows", "splines")) splines.add(t.number(r, "dip") / R);
  // The largest dip over the scenes, each on its finest grid, of one kind of rows.
  const auto finest_dip = [&](const char* rows) {
    std::map<std::string, std::pair<double, double>> last;  // scene -> (h, dip) of its finest row
    for (std::size_t r : t.where("rows", rows)) {
      auto& l = last[t.text(r, "scene")];
      if (l.first == 0 || t.number(r, "h") < l.first) l = {t.number(r, "h"), t.number(r, "dip") / R};
    }
    Range finest;
    for (const auto& [scene, l] : last) finest.add(l.second);
    return finest.hi;
  };
  const auto percent = [](double v) { return fmt("%.2g", 100 * v) + " %"; };
  num.put("liftoff.spline_dip_max", percent(splines.hi), src + " splines rows: max dip / R");
  num.put("liftoff.default_dip_finest_max", fmt("%.1e", finest_dip("default")), src + " default rows on each scene's finest grid: max dip / R");
  num.put("liftoff.kink_dip_finest_max", fmt("%.1e", finest_dip("kink")), src + " kink rows on each scene's finest grid: max dip / R");
}

// Where and how fast the default rows' dip goes (results/liftoff.csv): how many distinct solves of
// the default rows, with the kink carried or not, dip deepest on a spline arc (a kink row that did
// not carry the kink is the default row's solve again, and is not counted twice); how far inside an
// arc's nearer end on each scene's finest grid, for both; and, per scene, the order at which the
// dip of the runs that carried the kink falls with h, fitted by least squares over their grids and
// from the last two alone.
void liftoff_dip_numbers(Numbers& num, const std::string& results) {
  const CsvTable t = read_csv_table(results + "/liftoff.csv");
  const std::string src = "results/liftoff.csv";
  int solves = 0, on_arcs = 0;
  std::map<std::string, std::map<std::string, std::vector<std::size_t>>> by;  // rows -> scene -> runs
  for (const char* rows : {"default", "kink"})
    for (std::size_t r : t.where("rows", rows)) {
      if (std::string(rows) == "kink" && t.text(r, "kinked") != "1") continue;
      ++solves, on_arcs += t.text(r, "dip_on") == "arc";
      by[rows][t.text(r, "scene")].push_back(r);
    }
  // Each scene's runs coarse to fine: both loops below read the finest as the last.
  for (auto& [rows, scenes] : by)
    for (auto& [scene, runs] : scenes)
      std::sort(runs.begin(), runs.end(), [&](std::size_t a, std::size_t b) { return t.number(a, "h") > t.number(b, "h"); });
  num.put("liftoff.default_solves", std::to_string(solves), src + " default rows and kink rows that carried the kink: runs");
  num.put("liftoff.dips_on_arcs", std::to_string(on_arcs), src + " the same runs with dip_on = arc");
  for (const char* rows : {"default", "kink"}) {
    Range cells;
    for (const auto& [scene, runs] : by[rows]) {
      if (t.text(runs.back(), "dip_on") != "arc")
        throw std::runtime_error("prose_numbers: the finest " + std::string(rows) + " run of " + scene + " in " + src +
                                 " does not dip deepest on a spline arc, which the document's paragraph on the dip assumes");
      cells.add(t.number(runs.back(), "dip_cells"));
    }
    num.put_range(std::string("liftoff.") + rows + "_finest_dip_cells", cells, [](double v) { return fmt("%.1f", v); },
                  src + " " + rows + " rows on each scene's finest grid: dip_cells");
  }
  Range fitted, last;
  for (const auto& [scene, rows] : by["kink"]) {
    if (rows.size() < 3) throw std::runtime_error("prose_numbers: fewer than three grids that carried the kink for " + scene + " in " + src);
    const std::size_t f = rows.back(), b = rows[rows.size() - 2];
    std::vector<double> h, dip;
    for (std::size_t r : rows) h.push_back(t.number(r, "h")), dip.push_back(t.number(r, "dip"));
    fitted.add(loglog_slope(h, dip));
    last.add(std::log(t.number(b, "dip") / t.number(f, "dip")) / std::log(t.number(b, "h") / t.number(f, "h")));
  }
  const auto one = [](double v) { return fmt("%.1f", v); };
  num.put_range("liftoff.kink_dip_order_fitted", fitted, one, src + " kink rows that carried the kink (per scene): least-squares slope of log dip against log h");
  num.put_range("liftoff.kink_dip_order_last", last, one, src + " kink rows that carried the kink (per scene): the dip's order from its two finest grids");
}

// What carrying the kink buys (results/kink.csv): every row's errors and, from the grid before, its
// observed orders, keyed kink.<scene>_<space>_<column>_<n>; scene paper, off_centre or oblong, space
// plain or kink.
void kink_numbers(Numbers& num, const std::string& results) {
  const CsvTable t = read_csv_table(results + "/kink.csv");
  const std::string src = "results/kink.csv";
  std::map<std::string, std::size_t> before;  // scene and space -> the row of the grid before
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    std::string scene = t.text(r, "scene");
    std::replace(scene.begin(), scene.end(), '-', '_');
    const std::string key = "kink." + scene + "_" + t.text(r, "space") + "_", n = t.text(r, "n");
    const std::string where = src + " " + t.text(r, "scene") + " " + t.text(r, "space") + " n = " + n + ": ";
    for (const std::string c : {"err_max_w", "err_total_force", "err_line_pointwise"}) {
      num.put(key + c + "_" + n, fmt("%.1e", t.number(r, c)), where + c);
      if (const auto b = before.find(key); b != before.end())
        num.put(key + "order_" + c.substr(4) + "_" + n, fmt("%.1f", std::log2(t.number(b->second, c) / t.number(r, c))),
                where + "log2 of the ratio of " + c + " to the grid before");
    }
    num.put(key + "unknowns_" + n, t.text(r, "unknowns"), where + "unknowns");
    if (!t.text(r, "cond").empty()) num.put(key + "cond_" + n, fmt("%.1e", t.number(r, "cond")), where + "cond");
    before[key] = r;
  }
  // paper.md says that with the kink carried max w is closer to the series than the plain space on
  // every grid of every scene, that its observed orders are not steady, and that the line load keeps
  // converging to the last grid on every scene (at an order of at least 2; with the knots two cells
  // apart it had stalled there). If a rebuild finds otherwise a sentence is false, and the
  // build stops here.
  std::map<std::string, std::map<std::string, std::map<int, std::size_t>>> rows;  // scene -> space -> n -> row
  for (std::size_t r = 0; r < t.rows.size(); ++r) rows[t.text(r, "scene")][t.text(r, "space")][std::stoi(t.text(r, "n"))] = r;
  const auto w = [&](std::size_t r) { return t.number(r, "err_max_w"); };
  for (auto& [scene, space] : rows) {
    const auto& kink = space["kink"];
    std::vector<double> orders;
    for (auto k = kink.begin(); k != kink.end(); ++k) {
      if (const auto p = space["plain"].find(k->first); p != space["plain"].end() && !(w(k->second) < w(p->second)))
        throw std::runtime_error(t.path + ": with the kink carried max w is not closer than the plain space on " + scene +
                                 ", n = " + std::to_string(k->first) + "; paper.md says it is");
      if (k != kink.begin()) orders.push_back(std::log2(w(std::prev(k)->second) / w(k->second)));
    }
    if (!orders.empty() && *std::max_element(orders.begin(), orders.end()) - *std::min_element(orders.begin(), orders.end()) <= kSteadySpread)
      throw std::runtime_error(t.path + ": with the kink carried max w converges at a steady order on " + scene + "; paper.md says it does not");
    // The line load's order from the scene's last grid but one to its last (n = 128 to 256 on the
    // unit plate).
    if (kink.size() < 2) continue;
    const auto last = std::prev(kink.end()), before = std::prev(last);
    if (!(std::log2(t.number(before->second, "err_line_pointwise") / t.number(last->second, "err_line_pointwise")) >= 2))
      throw std::runtime_error(t.path + ": the line load converges on " + scene + " from n = " + std::to_string(before->first) +
                               " to " + std::to_string(last->first) + " at an order below 2; paper.md says it keeps converging");
  }
}

// The stability section of the kink study (results/kink_stability.csv): the spread of the condition
// number and of the errors over the cut-off's bands on n = 64 and 128, the smallest disk's orders
// against the series, and how many hard runs were certified. paper.md says that the answers at the
// heights 1e-300 and 1e300 and on a plate of side 1e-80, scaled back, are the paper's to round-off,
// that the two disks carry (D31) and the triangle (D33); a rebuild that finds otherwise stops here.
// The polygons of the kink study (results/kink_polygon.csv), where no series gives the answer, on
// the finest grid: the orders two steps give and how large (D33)-(D34)'s steps are against the plain
// space's. paper.md presents the orders where the plate rests on corners (the lifted square, the
// triangle) as the order the corners' functions give back (so at least 3.5 in max w and the force)
// and the plain space's as none (below 1), and that on the pressed square, whose contact has ends along the sides, the order is
// not steady (some order below 2); a rebuild that finds otherwise stops here.
void kink_polygon_numbers(Numbers& num, const std::string& results) {
  const CsvTable t = read_csv_table(results + "/kink_polygon.csv");
  const std::string src = "results/kink_polygon.csv";
  int finest = 0;
  for (std::size_t r = 0; r < t.rows.size(); ++r) finest = std::max(finest, std::stoi(t.text(r, "n")));
  Range corner, plain, ratio, pressed;
  std::map<std::pair<std::string, std::string>, double> plain_step;  // (scene, column) on the finest grid
  for (const std::string space : {"plain", "kink"})
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      if (t.text(r, "space") != space || std::stoi(t.text(r, "n")) != finest) continue;
      const std::string scene = t.text(r, "scene");
      const bool on_corners = scene == "square-lifted" || scene == "acute-triangle";
      for (const std::string col : {"max_w", "force"}) {
        const double o = t.number(r, "order_" + col), step = t.number(r, "step_" + col);
        if (space == "plain") {
          plain_step[{scene, col}] = step;
          if (on_corners) plain.add(o);
          continue;
        }
        if (!plain_step.count({scene, col})) throw std::runtime_error(t.path + ": " + scene + " has no plain run on n = " + std::to_string(finest));
        if (on_corners) corner.add(o), ratio.add(step / plain_step[{scene, col}]);
        else if (scene == "square-pressed") pressed.add(o);
      }
    }
  if (!(corner.lo >= 3.5)) throw std::runtime_error(t.path + ": with the corners' functions an order on the corner scenes is below 3.5; paper.md presents the range as the order they give back");
  if (!(plain.hi < 1)) throw std::runtime_error(t.path + ": the plain space converges at order 1 or more on a corner scene; paper.md says its steps hardly shrink");
  if (!(pressed.lo < 2)) throw std::runtime_error(t.path + ": the pressed square converges at a steady order; paper.md says its contact's ends prevent it");
  const auto f2 = [](double v) { return fmt("%.2f", v); };
  num.put("kink_polygon.finest_n", std::to_string(finest), src + ": the finest n");
  num.put_range("kink_polygon.corner_order", corner, f2, src + " square-lifted and acute-triangle with the kink on the finest n: order_max_w and order_force");
  num.put_range("kink_polygon.plain_order", plain, f2, src + " square-lifted and acute-triangle in the plain space on the finest n: order_max_w and order_force");
  num.put_range("kink_polygon.corner_step_ratio", ratio, [](double v) { return fmt("%.0e", v); }, src + ": kink step / plain step on the corner scenes on the finest n");
  num.put_range("kink_polygon.pressed_order", pressed, f2, src + " square-pressed with the kink on the finest n: order_max_w and order_force");
}

void kink_stability_numbers(Numbers& num, const std::string& results) {
  const CsvTable t = read_csv_table(results + "/kink_stability.csv");
  const std::string src = "results/kink_stability.csv";
  Range cond, ew, ef, ew64, order_w, order_f, flat, zero;
  int hard = 0, certified = 0;
  std::vector<std::size_t> smallest;
  double paper_w = NAN, paper_f = NAN, side_w = NAN, side_f = NAN;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const std::string study = t.text(r, "study"), scene = t.text(r, "scene"), n = t.text(r, "n");
    if (study == "band" && t.text(r, "flat") == fmt("%g", kKinkFlatCells) && t.text(r, "zero") == fmt("%g", kKinkZeroCells) && n == "64")
      side_w = t.number(r, "max_w"), side_f = t.number(r, "force"), paper_w = side_w / paper_scene().cylinder->height,
      paper_f = side_f / paper_scene().cylinder->height;
    if (study == "band") flat.add(t.number(r, "flat")), zero.add(t.number(r, "zero"));
    if (study == "band" && n == "64") ew64.add(t.number(r, "err_max_w"));
    if (study == "band" && n == "128") cond.add(t.number(r, "cond")), ew.add(t.number(r, "err_max_w")), ef.add(t.number(r, "err_total_force"));
    if (study != "hard") continue;
    ++hard, certified += t.text(r, "certified") == "1";
    if (scene == "smallest-disk") smallest.push_back(r);
    if (scene == "acute-triangle" && t.text(r, "space") != "kink")
      throw std::runtime_error(t.path + ": the triangle is solved plain; paper.md says it carries (D33)");
    if ((scene == "smallest-disk" || scene == "near-edge") && t.text(r, "space") != "kink")
      throw std::runtime_error(t.path + ": " + scene + " n = " + n + " is solved plain; paper.md says (D31) fits it");
  }
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    // Within the printed digits' last unit and round-off: the problem is homogeneous in the height.
    for (const auto& [prefix, w, f] : {std::tuple{"height-1e", paper_w, paper_f}, std::tuple{"side-1e", side_w, side_f}})
      if (t.text(r, "scene").rfind(prefix, 0) == 0 &&
          !(std::abs(t.number(r, "max_w") - w) <= 1e-11 * w && std::abs(t.number(r, "force") - f) <= 1e-10 * f))
        throw std::runtime_error(t.path + ": " + t.text(r, "scene") + " scaled back is not the paper's answer to round-off; paper.md says it is");
  // paper.md: on n = 64 and 128 the default band has the least error in max w, and on n = 128 the
  // largest in the force.
  // The bands are studied on n = 64 and 128 only, whose least errors ew64 and ew already hold.
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    if (t.text(r, "study") == "band" && t.text(r, "flat") == fmt("%g", kKinkFlatCells) && t.text(r, "zero") == fmt("%g", kKinkZeroCells) &&
        (t.number(r, "err_max_w") != (t.text(r, "n") == "64" ? ew64 : ew).lo || (t.text(r, "n") == "128" && t.number(r, "err_total_force") != ef.hi)))
      throw std::runtime_error(t.path + ": the default band is not the best in max w on n = " + t.text(r, "n") +
                               " (or not the worst in the force on n = 128); paper.md says it is");
  for (std::size_t k = 1; k < smallest.size(); ++k) {
    order_w.add(std::log2(t.number(smallest[k - 1], "err_max_w") / t.number(smallest[k], "err_max_w")));
    order_f.add(std::log2(t.number(smallest[k - 1], "err_total_force") / t.number(smallest[k], "err_total_force")));
  }
  const auto e1 = [](double v) { return fmt("%.1e", v); };
  const auto f1 = [](double v) { return fmt("%.1f", v); };
  const auto g = [](double v) { return fmt("%g", v); };
  num.put_range("kink_stability.band_flat", flat, g, src + " band rows: flat");
  num.put_range("kink_stability.band_zero", zero, g, src + " band rows: zero");
  num.put_range("kink_stability.band_cond_128", cond, e1, src + " band rows n = 128: cond");
  num.put_range("kink_stability.band_err_max_w_128", ew, e1, src + " band rows n = 128: err_max_w");
  num.put_range("kink_stability.band_err_max_w_64", ew64, e1, src + " band rows n = 64: err_max_w");
  num.put_range("kink_stability.band_err_total_force_128", ef, e1, src + " band rows n = 128: err_total_force");
  num.put_range("kink_stability.smallest_disk_order_max_w", order_w, f1, src + " smallest-disk: log2 of err_max_w over the grid before");
  num.put_range("kink_stability.smallest_disk_order_total_force", order_f, f1, src + " smallest-disk: log2 of err_total_force over the grid before");
  if (!smallest.empty()) {
    const std::size_t last = smallest.back();
    num.put("kink_stability.smallest_disk_finest_n", t.text(last, "n"), src + " smallest-disk: the finest n");
    num.put("kink_stability.smallest_disk_err_max_w_finest", e1(t.number(last, "err_max_w")), src + " smallest-disk finest: err_max_w");
  }
  num.put("kink_stability.hard_runs", std::to_string(hard), src + " hard rows");
  num.put("kink_stability.hard_certified", std::to_string(certified), src + " hard rows with certified = 1");
}

// Package versions of the machine that built the document (results/versions.csv, from dpkg).
void version_numbers(Numbers& num, const std::string& results) {
  const CsvTable t = read_csv_table(results + "/versions.csv");
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    num.put("version." + t.text(r, "package"), t.text(r, "version"), "results/versions.csv (dpkg-query)");
}

// How long `make all` takes here: its wall time, the build included (the row "make all" of
// results/rebuild_times.csv, written by scripts/step_report.sh), or where no whole run was timed the
// sum of its steps' last successful times (scripts/step.sh keeps one row per step).
void rebuild_numbers(Numbers& num, const std::string& results) {
  const CsvTable t = read_csv_table(results + "/rebuild_times.csv");
  double seconds = 0, wall = NAN;
  std::size_t steps = 0;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    if (t.text(r, "step") == "make all") {
      wall = t.number(r, "seconds");  // the whole run's wall time, steps side by side and the build included
      continue;
    }
    if (t.text(r, "step").rfind("make all", 0) == 0) continue;  // "make all: steps", the same without the build
    seconds += t.number(r, "seconds"), ++steps;
  }
  if (!(seconds > 0)) throw std::runtime_error("prose_numbers: rebuild_times.csv holds no step");
  const bool measured = std::isfinite(wall);
  num.put("rebuild.minutes", fmt("%.0f", std::ceil((measured ? wall : seconds) / 60)),
          measured ? "results/rebuild_times.csv: make all's wall time" : "results/rebuild_times.csv: the steps' seconds summed");
  num.put("rebuild.steps", count(steps), "results/rebuild_times.csv: rows");
}

// Our own choices that the prose states, from the constants the code uses.
void model_numbers(Numbers& num) {
  num.put("model.nu", fmt("%g", kPoissonRatio), "src/contact.hpp kPoissonRatio");
  num.put("model.rim_oversampling", fmt("%g", RimSeriesOptions{}.oversampling),
          "src/rim_contact.hpp RimSeriesOptions::oversampling");
  num.put("richardson.steady_spread", fmt("%g", kSteadySpread), "src/richardson.hpp kSteadySpread");
  num.put("model.correction_block", count(kCorrectionBlock), "src/fixed_set.hpp kCorrectionBlock");
  num.put("model.max_correction", count(ExactOptions{}.max_correction), "src/active_set.hpp ExactOptions::max_correction");
  num.put("model.gram_block", count(kGramBlock), "src/dual_active_set.hpp kGramBlock");
  num.put("model.kink_flat_cells", fmt("%g", kKinkFlatCells), "src/kink_enrichment.hpp kKinkFlatCells");
  num.put("model.kink_zero_cells", fmt("%g", kKinkZeroCells), "src/kink_enrichment.hpp kKinkZeroCells");
  num.put("model.kink_clearance_cells", fmt("%g", kKinkZeroCells + 1.5), "src/kink_enrichment.hpp kKinkZeroCells + 1.5");
  num.put("model.kink_radius_cells", fmt("%g", kKinkMinRadiusCells), "src/kink_enrichment.hpp kKinkMinRadiusCells");
  num.put("model.kink_knot_cells", fmt("%g", kKinkKnotCells), "src/kink_enrichment.hpp kKinkKnotCells");
  num.put("model.largest_order", fmt("%g", kLargestOrder), "src/error_bar.hpp kLargestOrder");
  num.put("model.kink_knot_cells_min", fmt("%g", kKinkKnotCellsMin), "src/kink_enrichment.hpp kKinkKnotCellsMin");
  num.put("model.kink_knots_at_least", count(kKinkKnotsAtLeast), "src/kink_enrichment.hpp kKinkKnotsAtLeast");
  const char* part[3] = {"inside", "middle", "cutoff"};
  for (int k = 0; k < 3; ++k) {
    num.put(std::string("model.kink_rule_") + part[k] + "_angle", count(kKinkRule[k].angle), "src/kink_enrichment.hpp kKinkRule");
    num.put(std::string("model.kink_rule_") + part[k] + "_radius", count(kKinkRule[k].radius), "src/kink_enrichment.hpp kKinkRule");
  }
  num.put("model.refine_largest_first", fmt("%g", kRefineLargestFirst), "src/refinement.hpp kRefineLargestFirst");
  num.put("model.refine_contraction", fmt("%g", kRefineContraction), "src/refinement.hpp kRefineContraction");
}

// One run of the linear scheme (results/linear_history.csv): after its first step, how the true
// error stands to the step the stopping rule sees, and the bound (D7) to the error.
void linear_history_numbers(Numbers& num, const std::string& results) {
  const CsvTable t = read_csv_table(results + "/linear_history.csv");
  // The last iterations reach round-off, where step and error are noise: their ratios are left out.
  constexpr double kAboveRoundoff = 1e-12;
  const std::string src = "results/linear_history.csv iterations >= 2 with error >= 1e-12";
  const auto after_first = t.where([&](std::size_t r) {
    return t.number(r, "iteration") >= 2 && t.number(r, "error") >= kAboveRoundoff;
  });
  const auto over = [&](const char* a, const char* b) {
    return range_of(t, after_first, [&, a, b](std::size_t r) { return t.number(r, a) / t.number(r, b); });
  };
  num.put_range("history.error_over_step", over("error", "step"), ratio, src + ": error / step");
  num.put_range("history.bound_over_error", over("bound", "error"), ratio, src + ": bound / error");
}

// Published constants the prose quotes, with their reference.
void published_numbers(Numbers& num, const std::string& reference) {
  const std::string src = "reference/plate_constants.csv";
  num.put("published.lambda1", fmt("%.10f", plate_constant(reference, "lambda1")), src + " (Bjorstad and Tjostheim 1999)");
  num.put("published.point_centre", fmt("%.5f", plate_constant(reference, "point_centre")), src + " (Timoshenko)");
}

}  // namespace

int main(int argc, char** argv) {
  clean_up_on_interrupt("prose_numbers");
  CLI::App app{"prose_numbers: the numbers the document's prose states, from results/; writes numbers.csv and "
               "numbers_machine.csv."};
  std::string results = "results", reference = "reference", out = "results";
  app.add_option("--results", results, "folder with the results to read")->check(CLI::ExistingDirectory)->capture_default_str();
  app.add_option("--reference", reference, "folder with plate_constants.csv")->check(CLI::ExistingDirectory)->capture_default_str();
  app.add_option("--out", out, "folder for numbers.csv and numbers_machine.csv")->capture_default_str();
  app.footer(kExitStatusHelp);
  if (const int status = parse_options(app, argc, argv, "prose_numbers"); status >= 0) return status;
  try {
    Numbers fixed, machine;
    table_numbers(fixed, results);
    table_fine_numbers(fixed, results);
    crosscheck_numbers(fixed, results);
    crosscheck_penalty_numbers(fixed, results);
    hard_cases_numbers(fixed, results);
    continuum_numbers(fixed, results);
    rim_series_numbers(fixed, results);
    liftoff_numbers(fixed, results);
    liftoff_dip_numbers(fixed, results);
    kink_numbers(fixed, results);
    kink_stability_numbers(fixed, results);
    kink_polygon_numbers(fixed, results);
    linear_history_numbers(fixed, results);
    published_numbers(fixed, reference);
    model_numbers(fixed);
    const CsvTable speed = read_csv_table(results + "/speed_vs_error.csv");
    bench_error_numbers(fixed, speed);
    bench_numbers(machine, speed);
    bench_large_numbers(machine, read_csv_table(results + "/large/speed_vs_error.csv"));
    version_numbers(machine, results);
    rebuild_numbers(machine, results);
    write_file_atomically(out + "/numbers.csv", fixed.csv("numbers that rebuild byte for byte"));
    write_file_atomically(out + "/numbers_machine.csv",
                          machine.csv("numbers of this machine (timings, package versions); they vary"));
  } catch (const std::exception& e) {
    std::cerr << "prose_numbers: " << e.what() << '\n';
    return kFailure;
  }
  return 0;
}
