#include "continuum_limits.hpp"

#include <filesystem>
#include <stdexcept>

#include "csv_table.hpp"

namespace plate {

std::map<std::string, double> read_continuum_limits(const std::string& path) {
  if (!std::filesystem::exists(path)) throw std::runtime_error("cannot read " + path + " (run make continuum first)");
  const CsvTable t = read_csv_table(path);
  std::map<std::string, double> m;
  // Only the quantities the callers measure against: another row without a limit stops nothing.
  for (const char* q : {"max_w", "total_force"}) {
    const auto rows = t.where([&](std::size_t r) { return t.text(r, "sampling") == "edge" && t.text(r, "quantity") == q; });
    if (rows.empty()) throw std::runtime_error(path + " has no edge-sampling limit for " + q);
    m[q] = t.number(rows.front(), "limit");
    m[std::string(q) + "_bar"] = t.number(rows.front(), "bar");
  }
  return m;
}

std::map<std::string, double> read_rim_answer(const std::string& path) {
  if (!std::filesystem::exists(path)) throw std::runtime_error("cannot read " + path + " (run make rim-series first)");
  const CsvTable t = read_csv_table(path);
  std::map<std::string, double> m;
  for (const char* q : {"max_w", "total_force"}) {
    const auto rows = t.where("quantity", q);
    if (rows.empty()) throw std::runtime_error(path + " has no row " + q);
    m[q] = t.number(rows.front(), "value");
    m[std::string(q) + "_bar"] = t.number(rows.front(), "bar");
  }
  return m;
}

}  // namespace plate
