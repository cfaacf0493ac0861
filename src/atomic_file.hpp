// Writing a file whole: into a temporary file beside it, then renamed over it, so a reader never
// sees half a file and an interrupted run leaves the old one (or none).
#pragma once
#include <string>

namespace plate {

// Throws std::runtime_error naming the path if it cannot be written.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace plate
