// Reading the small CSV files of reference/: '#' lines are comments, the first other line names
// the columns, fields are separated by commas and never quoted.
#include "published.hpp"

#include "csv_table.hpp"
#include "fields.hpp"
#include "paper_numbers.hpp"

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace plate {
namespace {
using Rows = std::vector<std::vector<std::string>>;

// Data rows (header dropped) with at least `columns` fields.
Rows read_rows(const std::string& path, std::size_t columns) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  Rows rows;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    auto f = split_csv_line(line);
    if (f.size() < columns) throw std::runtime_error(path + ": too few fields in \"" + line + "\"");
    rows.push_back(std::move(f));
  }
  return rows;
}

}  // namespace

std::vector<PublishedRow> read_paper_table(const std::string& path) {
  std::vector<PublishedRow> table;
  for (const auto& f : read_rows(path, 3))
    table.push_back({parse_number(f[0], path), static_cast<int>(parse_number(f[1], path)),
                     static_cast<int>(parse_number(f[2], path))});
  if (table.empty()) throw std::runtime_error(path + ": no rows");
  return table;
}

std::map<std::string, double> read_paper_numbers(const std::string& path) {
  std::map<std::string, double> numbers;
  for (const auto& f : read_rows(path, 2)) numbers[f[0]] = parse_number(f[1], path);
  return numbers;
}

double published(const std::map<std::string, double>& numbers, const std::string& key, const std::string& source) {
  const auto it = numbers.find(key);
  if (it == numbers.end()) throw std::runtime_error(source + " has no key " + key);
  return it->second;
}

Scene paper_scene() { return paper_scene(paper::kObstacleHeight); }

Scene paper_scene(double R) {
  return Scene::rectangle(paper::kSide, paper::kSide).over(Cylinder{paper::kObstacleCx, paper::kObstacleCy, paper::kObstacleRadius, R}).loaded(paper::kLoad);
}

int paper_cells() { return static_cast<int>(std::lround(paper::kSide / paper::kH)); }

double plate_constant(const std::string& reference_dir, const std::string& key) {
  const std::string path = reference_dir + "/plate_constants.csv";
  return published(read_paper_numbers(path), key, path);
}

}  // namespace plate
