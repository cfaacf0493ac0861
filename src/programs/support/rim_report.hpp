// What `plate --scheme semi-analytic` writes: the rim-contact series (rim_contact.hpp) with its
// convergence study, as the same summary, JSON keys and line-load CSV as the grid schemes give,
// where a key means the same thing, and without the keys that belong to a grid.
#pragma once
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "published.hpp"
#include "rim_contact.hpp"

namespace plate {

struct RimReport {
  std::vector<std::pair<std::string, std::string>> config;  // every option, echoed
  const RimAnswer* answer = nullptr;
  double max_abs_m12 = NAN;  // searched once (rim_max_abs_m12) by whoever fills the report
  std::vector<std::pair<double, double>> points;  // where the user asked for w
  double nu = kPoissonRatio;
  bool converged = false;
  std::string message;  // why not
  double seconds_total = 0;
};

// A value of the series to the digits its bar leaves (the last printed at least the bar), and never
// below 1000 u |v|, the floor of the series' bars (rim_answer), where libm's last bits could show.
std::string rim_digits(double v, double bar = 0);

// The line load on the rim at `angles` equally spaced angles from 0 (a fixed set, the same for any
// truncation, so runs can be compared point by point).
constexpr int kRimAngles = 720;
std::string rim_line_csv(const RimSeries& s, int angles = kRimAngles);
std::string rim_summary_json(const RimReport& r);
std::string rim_summary_text(const RimReport& r);

// max |m12| over the plate (Fig. 2's quantity, off the grid): on a lattice of (k + 1)^2 points, then
// on finer lattices about the best one.
double rim_max_abs_m12(const RimSeries& s, double nu, int k = 100);

}  // namespace plate
