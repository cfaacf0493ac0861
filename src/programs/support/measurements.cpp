// The measurements file: written with 17 digits, so a value read back is the value written.
#include "measurements.hpp"

#include <fstream>
#include <stdexcept>

namespace plate {

void write_measurements(const std::string& path, const Measurements& m) {
  std::ofstream f(path);
  f.precision(17);
  for (const auto& [key, value] : m.v) f << key << ' ' << value << '\n';
  f << "nodal " << m.nodal.size() << '\n';
  for (double x : m.nodal) f << x << '\n';
  if (!f.flush()) throw std::runtime_error("cannot write " + path);
}

Measurements read_measurements(const std::string& path) {
  Measurements m;
  std::ifstream f(path);
  for (std::string key; f >> key;) {
    if (key == "nodal") {
      size_t count = 0;
      f >> count;
      m.nodal.resize(count);
      for (double& x : m.nodal) f >> x;
      break;
    }
    f >> m.v[key];
  }
  return m;
}

}  // namespace plate
