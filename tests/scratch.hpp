// A folder of the test's own under the system's temporary folder, removed with everything in it when
// the object goes, pass or fail: a test run leaves nothing behind (ctest runs each test as a process
// of its own, so a static Scratch lives exactly as long as one test).
#pragma once
#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace plate {

class Scratch {
 public:
  explicit Scratch(const std::string& tag) {
    std::string pattern = (std::filesystem::temp_directory_path() / ("plate_" + tag + "_XXXXXX")).string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot make a scratch folder from " + pattern);
    dir_ = pattern;
  }
  ~Scratch() {
    std::error_code ignored;  // a destructor must not throw; a folder already gone is fine
    std::filesystem::remove_all(dir_, ignored);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;

  const std::filesystem::path& dir() const { return dir_; }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

 private:
  std::filesystem::path dir_;
};

}  // namespace plate
