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

// The line load on the rim at the angles of r.line_figures (kLineLoadAngles from 0: a fixed set, the
// same for any truncation, so runs can be compared point by point).
std::string rim_line_csv(const Report& r);
// A report whose `series` is set, and whose measures (the peak, max |m12|, w at the points), line
// and line_figures hold the series' values (plate's solve_series).
std::string rim_summary_json(const Report& r);
std::string rim_summary_text(const Report& r);

}  // namespace plate
