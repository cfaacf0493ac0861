// Writing a file whole: into a temporary file beside it, then renamed over it, so a reader never
// sees half a file and an interrupted run leaves the old one (or none).
#pragma once
#include <string>

namespace plate {

// Throws std::runtime_error naming the path if it cannot be written (a full disk included). A
// symlink is written through to its target, which keeps its permissions; a device or a FIFO is
// written directly rather than replaced.
void write_file_atomically(const std::string& path, const std::string& content);

// The file a write to `path` lands in: the target of a symlink, else the path itself.
std::string output_target(const std::string& path);

// Throws std::runtime_error naming the path if a write to it would fail for a reason known now (a
// directory, no permission, a missing folder), so a long run can refuse it before it starts.
void check_writable(const std::string& path);

// For a program's output option: throws std::invalid_argument naming `option` unless `path` names
// a regular file or a new one in a folder where a file can be created now. An empty path, a
// symbolic link, a device, a FIFO and a directory are refused (the output is written whole, to a
// temporary file renamed over the path, which none of them can take as they are). The folder is
// tried by creating a file in it and removing it again: permission bits say nothing to root, and
// some file systems (/sys, /proc) refuse new files whatever they say.
void check_output_file(const std::string& option, const std::string& path);

// On SIGINT, SIGTERM or SIGHUP: delete the temporary file being written, if any, say on stderr
// that `program` was interrupted (files already renamed into place are whole), and exit with
// 128 + the signal number, as a shell reports a killed program.
void clean_up_on_interrupt(const char* program);

}  // namespace plate
