// The file a benchmark run leaves for the program that started it (bench's children, the SNESVI
// peer): one "key value" line per measurement, then "nodal N" and the N nodal values of w.
#pragma once
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace plate {

struct Measurements {
  std::map<std::string, double> v;
  std::vector<double> nodal;
};

// Throws std::runtime_error if the file cannot be written whole.
void write_measurements(const std::string& path, const Measurements& m);
// What the file holds; an empty Measurements if there is no file.
Measurements read_measurements(const std::string& path);

// What a solver's next, finer grid is expected to take, from its last two runs: the last time
// times their ratio, never less than the last (with no run before, the last time). bench and
// time_to_accuracy end a solver's sequence of grids when this passes their budget.
inline double predicted_next_seconds(double before, double last) {
  return std::isfinite(before) && before > 0 ? last * std::max(last / before, 1.0) : last;
}

}  // namespace plate
