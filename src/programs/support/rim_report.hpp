// What `plate --scheme semi-analytic` writes: the rim-contact series (rim_contact.hpp) with its
// convergence study, as the same summary, JSON keys and line-load CSV as the grid schemes give,
// where a key means the same thing, and without the keys that belong to a grid.
#pragma once
#include <string>

#include "rim_contact.hpp"
#include "summary.hpp"

namespace plate {

// A value of the series to the digits its bar leaves (the last printed at least the bar), and never
// below 1000 u |v|, the floor of the series' bars (rim_answer), where libm's last bits could show.
std::string rim_digits(double v, double bar = 0);

// The line load on the rim at `angles` equally spaced angles from 0 (a fixed set, the same for any
// truncation, so runs can be compared point by point).
std::string rim_line_csv(const RimSeries& s, int angles = kLineLoadAngles);
// A report whose `series` is set, and whose measures.max_abs_m12 holds rim_max_abs_m12's value.
std::string rim_summary_json(const Report& r);
std::string rim_summary_text(const Report& r);

// max |m12| over the plate (Fig. 2's quantity, off the grid): on a lattice of (k + 1)^2 points, then
// on finer lattices about the best one.
double rim_max_abs_m12(const RimSeries& s, double nu, int k = 100);

}  // namespace plate
