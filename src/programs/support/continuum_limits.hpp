// The continuum answer as the continuum study wrote it (results/continuum_limits.csv): the edge
// sampling's limit of each quantity and its error bar. The programs that measure an error against
// the continuum (bench, time_to_accuracy) read it here, so that they measure against one answer.
#pragma once
#include <map>
#include <string>

namespace plate {

// "max_w" and "total_force" -> the edge-sampling limit, and the same with "_bar" -> its error bar.
// Throws std::runtime_error naming the file when it is missing (run `make continuum` first), lacks
// either limit, or holds one that is not a number.
std::map<std::string, double> read_continuum_limits(const std::string& path);

}  // namespace plate
