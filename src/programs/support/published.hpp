// The paper's published numbers, read from reference/*.csv so that tests and reports quote one
// source: the table of the experiment and every other number the text states.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "scene.hpp"

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
// `source` names the file the numbers came from, for the message.
double published(const std::map<std::string, double>& numbers, const std::string& key,
                 const std::string& source = "reference/paper_numbers.csv");

// The paper's experiment as reference/paper_numbers.csv states it (CMake bakes its numbers into
// paper_numbers.hpp: the one place they are spelled): the unit square, f = 0, the obstacle of
// height R on the closed disk (10), no constraint outside; its rim is the scene's edge.
Scene paper_scene();
Scene paper_scene(double R);  // the same cylinder at height R
int paper_cells();            // n = 1/h squares per side

// A published constant of the clamped plate (uniform_centre, point_centre, lambda1), from
// reference_dir/plate_constants.csv. Throws std::runtime_error naming a missing file or key.
double plate_constant(const std::string& reference_dir, const std::string& key);

}  // namespace plate
