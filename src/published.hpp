// The paper's published numbers, read from reference/*.csv so that tests and reports quote one
// source: the table of the experiment and every other number the text states.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "assemble.hpp"

namespace plate {

struct PublishedRow {
  double tolerance = 0;    // OS
  int iterations = 0;      // linear scheme (5a), as printed
  int iterations_glt = 0;  // Glowinski, Lions, Tremolieres, same example
};

// reference/paper_table.csv. Throws std::runtime_error naming the file on a missing file or a bad row.
std::vector<PublishedRow> read_paper_table(const std::string& path);

// reference/paper_numbers.csv as key -> value. Throws std::runtime_error likewise.
std::map<std::string, double> read_paper_numbers(const std::string& path);

// One value of read_paper_numbers' map; throws std::runtime_error naming a missing key.
double published(const std::map<std::string, double>& numbers, const std::string& key);

// The paper's obstacle read from those numbers: `height` on its disk, no constraint outside it.
Field paper_obstacle(const std::map<std::string, double>& numbers, double height);
// The same with the published height.
Field paper_obstacle(const std::map<std::string, double>& numbers);

// The paper's grid, n = 1/h cells per side.
int paper_cells(const std::map<std::string, double>& numbers);

}  // namespace plate
