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

// The same keys from the rim-contact series' answer (results/rim_answer.csv, written by
// build/rim_series): the yardstick that bench and time_to_accuracy measure against, its bars some
// orders of magnitude below what any grid reaches.
std::map<std::string, double> read_rim_answer(const std::string& path);

}  // namespace plate
