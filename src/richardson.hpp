// Observed order and Richardson extrapolation of a sequence computed on grids h, h/2, h/4, ...:
// the h -> 0 limit with an error bar, stated only where the order is steady.
#pragma once
#include <vector>

namespace plate {

struct Extrapolation {
  std::vector<double> orders;  // from each triple (k, k+1, k+2); NaN where the increments change sign or grow
  bool steady = false;         // the last two orders exist and differ by at most `spread`
  // Steady: Richardson from the last triple, and its distance to the Richardson limit of the triple
  // before. Not steady: the finest value, and the last increment (the error of the finest value if
  // the increments from there on at least halve each time, which nothing here can check).
  double limit = 0, bar = 0;
  // Steady: how far the limit moves if the order is taken `spread` lower or higher, as far as two
  // orders may differ and still be called steady. `bar` compares two triples that both use orders
  // observed alike, so it does not carry this doubt; a comparison that must hold may add it. 0 when
  // not steady; infinite when the order lowered by `spread` is not positive.
  double order_doubt = 0;
  // What the round-off of the values (the `noise` passed in) can change in each of the above.
  std::vector<double> order_noise;
  double limit_noise = 0, bar_noise = 0;
};

// Eq. (D13): v_h = v + C h^p + ..., p from successive increments, v ~ v_h/4 + d / (2^p - 1).
// noise[k] bounds the round-off in values[k] (empty: none).
// Two observed orders within this of each other are called steady.
constexpr double kSteadySpread = 0.3;
Extrapolation extrapolate(const std::vector<double>& values, const std::vector<double>& noise = {},
                          double spread = kSteadySpread);

// The least-squares slope of log y against log x: an order over many grids (x the mesh size, or
// the unknowns) where a sequence is too irregular for the order of successive increments.
double loglog_slope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace plate
