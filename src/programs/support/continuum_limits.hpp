// The continuum answer as the continuum study wrote it (results/continuum_limits.csv): the edge
// sampling's limit of each quantity and its error bar. The programs that measure an error against
// the continuum (bench, time_to_accuracy) read it here, so that they measure against one answer.
#pragma once
#include <map>
#include <string>

namespace plate {

// quantity -> limit, and quantity + "_bar" -> its error bar, for the rows of edge sampling. Throws
// std::runtime_error naming the file when it is missing (run `make continuum` first) or lacks the
// limit of max_w or total_force.
std::map<std::string, double> read_continuum_limits(const std::string& path);

}  // namespace plate
