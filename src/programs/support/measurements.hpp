// The file a benchmark run leaves for the program that started it (bench's children, the SNESVI
// peer): one "key value" line per measurement, then "nodal N" and the N nodal values of w.
#pragma once
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

}  // namespace plate
