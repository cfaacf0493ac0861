// printf-style formatting of one number, for the tables and reports the programs write.
#pragma once
#include <cstdio>
#include <string>

namespace plate {
inline std::string fmt(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}
}  // namespace plate
