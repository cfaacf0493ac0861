// printf-style formatting of one number, for the tables and reports the programs write, and the
// rule that keeps those tables the same on every machine: print no digit that round-off decides.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace plate {
inline std::string fmt(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

// v rounded up to one significant digit: a bound stays a bound when it is printed.
inline std::string fmt_up(double v) {
  if (!(v > 0) || !std::isfinite(v)) return fmt("%.0e", v);
  const double p = std::pow(10.0, std::floor(std::log10(v)));
  double lead = std::ceil(v / p * (1 - 1e-12));  // 3e-11 stays 3e-11 when it is exact
  return fmt("%.0e", lead * p);
}

// A given value (a tolerance the paper prints, 1.3e-4 or 6.25e-7) in the exponent form with the
// fewest digits that read back as the same double, so that a column of them has one look.
inline std::string fmt_exact_e(double v) {
  for (int d = 0; d < 17; ++d) {
    const std::string s = fmt(("%." + std::to_string(d) + "e").c_str(), v);
    if (std::strtod(s.c_str(), nullptr) == v) return s;
  }
  return fmt("%.17e", v);
}

// @region fmt-above
// v to the digits that `noise` (a bound on what round-off, or another machine, may change in it)
// cannot reach: the last digit printed is at least 10 times the noise, and at most `max_digits`
// significant digits. A v within 10 noise of zero is printed as the bound "< 10 noise".
// style 'e' prints 2.1e-06; 'g' prints as %g does (0.0976920952).
inline std::string fmt_above(double v, double noise, int max_digits, char style = 'e') {
  if (!std::isfinite(v)) return fmt("%g", v);
  int digits = max_digits;
  if (noise > 0) {
    if (!(std::abs(v) >= 10 * noise)) return "< " + fmt_up(10 * noise);
    // the last digit printed, 10^(e - digits + 1) with e the exponent of v, is at least 10 noise
    digits = static_cast<int>(std::floor(std::log10(std::abs(v))) - std::ceil(std::log10(10 * noise))) + 1;
  }
  digits = std::clamp(digits, 1, max_digits);
  const std::string f = style == 'g' ? "%." + std::to_string(digits) + "g" : "%." + std::to_string(digits - 1) + "e";
  return fmt(f.c_str(), v);
}
// @end fmt-above
// A measured value in a report's cell or CSV field: fmt_above in the %g style, and `missing` where
// there is no value. Each report chooses max_digits once (10 for the grids' values, 12 where the
// lift-off scenes' values differ in the ninth digit).
inline std::string fmt_value(double v, double noise, int max_digits, const char* missing = "n/a") {
  return std::isfinite(v) ? fmt_above(v, noise, max_digits, 'g') : missing;
}
// v to `digits` significant digits, as %g prints it: for values with no noise estimate, whose
// printing must not be what limits them (the series' 13 settled digits print with 15).
inline std::string fmt_digits(double v, int digits) { return fmt(("%." + std::to_string(digits) + "g").c_str(), v); }

// The number in what fmt_above printed: the value, or for "< b" the bound b that it claims.
inline std::string without_bound(const std::string& printed) {
  return printed.rfind("< ", 0) == 0 ? printed.substr(2) : printed;
}
}  // namespace plate
