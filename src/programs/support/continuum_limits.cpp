#include "continuum_limits.hpp"

#include <filesystem>
#include <stdexcept>

#include "csv_table.hpp"

namespace plate {

std::map<std::string, double> read_continuum_limits(const std::string& path) {
  if (!std::filesystem::exists(path)) throw std::runtime_error("cannot read " + path + " (run make continuum first)");
  const CsvTable t = read_csv_table(path);
  std::map<std::string, double> m;
  for (const std::size_t r : t.where("sampling", "edge")) {
    const std::string& q = t.text(r, "quantity");
    m[q] = t.number(r, "limit");
    m[q + "_bar"] = t.number(r, "bar");
  }
  for (const char* q : {"max_w", "total_force"})
    if (!m.count(q)) throw std::runtime_error(path + " has no edge-sampling limit for " + q);
  return m;
}

}  // namespace plate
