#include "csv_table.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace plate {

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    out.push_back(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

std::size_t CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  throw std::runtime_error(path + ": no column \"" + name + "\"");
}

const std::string& CsvTable::text(std::size_t row, const std::string& name) const {
  if (row >= rows.size()) throw std::runtime_error(path + ": no row " + std::to_string(row));
  return rows[row][column(name)];
}

double parse_number(const std::string& s, const std::string& where) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != s.size()) throw std::runtime_error(where + ": \"" + s + "\" is not a number");
  return v;
}

double CsvTable::number(std::size_t row, const std::string& name) const {
  return parse_number(text(row, name), path + ": row " + std::to_string(row + 1) + ", column " + name);
}

std::vector<std::size_t> CsvTable::where(const std::function<bool(std::size_t)>& keep) const {
  std::vector<std::size_t> out;
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (keep(r)) out.push_back(r);
  return out;
}

std::vector<std::size_t> CsvTable::where(const std::string& name, const std::string& value) const {
  const std::size_t c = column(name);
  return where([&](std::size_t r) { return rows[r][c] == value; });
}

CsvTable read_csv_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  CsvTable t;
  t.path = path;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (t.columns.empty()) {
      t.columns = split_csv_line(line);
      continue;
    }
    auto f = split_csv_line(line);
    if (f.size() != t.columns.size())
      throw std::runtime_error(path + ": " + std::to_string(f.size()) + " fields where the header has " +
                               std::to_string(t.columns.size()) + ": \"" + line + "\"");
    t.rows.push_back(std::move(f));
  }
  if (t.columns.empty()) throw std::runtime_error(path + ": no header line");
  return t;
}

}  // namespace plate
