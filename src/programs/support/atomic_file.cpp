// Temporary file + fsync-free rename: rename(2) within one directory is atomic. Symlinks are
// followed, devices and FIFOs written directly, and every write error (ENOSPC too) is reported.
#include "atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace plate {

namespace {
// The handler may only touch plain memory and call async-signal-safe functions (unlink, write,
// _exit), so the temporary path and the message live in fixed buffers.
char pending_tmp[4096];
volatile sig_atomic_t have_pending = 0;
char interrupt_message[512];
size_t interrupt_message_length = 0;

extern "C" void on_interrupt(int sig) {
  if (have_pending) ::unlink(pending_tmp);
  if (::write(STDERR_FILENO, interrupt_message, interrupt_message_length) < 0) {
  }
  ::_exit(128 + sig);
}

struct Pending {  // marks the temporary file for the handler while it exists
  explicit Pending(const std::string& tmp) {
    if (tmp.size() < sizeof pending_tmp) {
      std::memcpy(pending_tmp, tmp.c_str(), tmp.size() + 1);
      have_pending = 1;
    }
  }
  ~Pending() { have_pending = 0; }
};
}  // namespace

void clean_up_on_interrupt(const char* program) {
  const int got = std::snprintf(interrupt_message, sizeof interrupt_message,
                                "%s: interrupted by a signal; no file is left half-written\n", program);
  interrupt_message_length = got < 0 ? 0 : std::min<size_t>(got, sizeof interrupt_message - 1);
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaction(sig, &action, nullptr);
}

namespace {
// Writes all of `content` to an open descriptor; false on any error (ENOSPC included).
bool write_all(int fd, const std::string& content) {
  size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw std::runtime_error("cannot write " + path + ": " + why);
}
}  // namespace

std::string output_target(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path p(path);
  if (!fs::is_symlink(fs::symlink_status(p, ec))) return path;
  // Follow the link (and links to links) to the file it names; the link itself stays.
  return fs::weakly_canonical(p, ec).string();
}

void check_writable(const std::string& path) {
  namespace fs = std::filesystem;
  const std::string target = output_target(path);
  struct stat st {};
  if (::stat(target.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) fail(path, "it is a directory");
    if (::access(target.c_str(), W_OK) != 0) fail(path, std::strerror(errno));
    return;
  }
  const fs::path parent = fs::path(target).parent_path().empty() ? fs::path(".") : fs::path(target).parent_path();
  if (::access(parent.c_str(), W_OK) != 0) fail(path, std::strerror(errno));
}

void check_output_file(const std::string& option, const std::string& path) {
  namespace fs = std::filesystem;
  auto refuse = [&](const std::string& why) { throw std::invalid_argument(option + " '" + path + "': " + why); };
  if (path.empty()) throw std::invalid_argument(option + ": the path is empty; name a file");
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0) {
    if (S_ISLNK(st.st_mode)) refuse("a symbolic link; name the file itself (the output replaces the path it is given)");
    if (S_ISDIR(st.st_mode)) refuse("a directory; name a file");
    if (!S_ISREG(st.st_mode)) refuse("a device, FIFO or socket, not a regular file; name a file (outputs are written whole)");
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);  // no O_TRUNC: the old file stays as it is
    if (fd < 0) refuse(std::string("cannot be written: ") + std::strerror(errno));
    ::close(fd);
  }
  const fs::path parent = fs::path(path).parent_path().empty() ? fs::path(".") : fs::path(path).parent_path();
  const std::string probe = (parent / (".plate-probe." + std::to_string(::getpid()))).string();
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) refuse(std::string("no file can be created in its folder: ") + std::strerror(errno));
  ::close(fd);
  ::unlink(probe.c_str());
}

void write_file_atomically(const std::string& path, const std::string& content) {
  const std::string target = output_target(path);
  struct stat st {};
  const bool exists = ::stat(target.c_str(), &st) == 0;
  if (exists && S_ISDIR(st.st_mode)) fail(path, "it is a directory");
  if (exists && !S_ISREG(st.st_mode)) {
    // A device or a FIFO: no half-written file can be left, and replacing it would destroy it.
    const int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) fail(path, std::strerror(errno));
    const bool ok = write_all(fd, content);
    const int err = errno;
    if (::close(fd) != 0 || !ok) fail(path, std::strerror(ok ? errno : err));
    return;
  }
  const std::string tmp = target + ".tmp." + std::to_string(::getpid());
  const Pending pending(tmp);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) fail(path, std::strerror(errno));
  bool ok = write_all(fd, content);
  int err = errno;
  if (ok && exists && ::fchmod(fd, st.st_mode & 07777) != 0) ok = false, err = errno;  // keep the old permissions
  if (::close(fd) != 0 && ok) ok = false, err = errno;
  if (!ok) {
    ::unlink(tmp.c_str());
    fail(path, std::strerror(err));
  }
  if (std::rename(tmp.c_str(), target.c_str()) != 0) {
    err = errno;
    ::unlink(tmp.c_str());
    fail(path, std::strerror(err));
  }
}

}  // namespace plate
