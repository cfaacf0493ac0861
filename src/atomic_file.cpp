// Temporary file + fsync-free rename: rename(2) within one directory is atomic.
#include "atomic_file.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <algorithm>
#include <cstring>
#include <fstream>
#include <stdexcept>

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

void write_file_atomically(const std::string& path, const std::string& content) {
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  const Pending pending(tmp);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    out << content;
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      throw std::runtime_error("cannot write " + path + ": write failed");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write " + path + ": " + why);
  }
}

}  // namespace plate
