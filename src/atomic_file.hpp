// Writing a file whole: into a temporary file beside it, then renamed over it, so a reader never
// sees half a file and an interrupted run leaves the old one (or none).
#pragma once
#include <string>

namespace plate {

// Throws std::runtime_error naming the path if it cannot be written.
void write_file_atomically(const std::string& path, const std::string& content);

// On SIGINT, SIGTERM or SIGHUP: delete the temporary file being written, if any, say on stderr
// that `program` was interrupted (files already renamed into place are whole), and exit with
// 128 + the signal number, as a shell reports a killed program.
void clean_up_on_interrupt(const char* program);

}  // namespace plate
