// reports/words.md read, and the markers of words.hpp rendered from it. Apart from words.hpp, in a
// library of its own that only render_report and the tests link: a change here rebuilds no
// program that computes a result, so `make` reruns none.
#pragma once
#include <map>
#include <string>

namespace plate {

// Each entry is a line "## key" and then its text, one paragraph, with @{name} where a value goes
// (braces alone are TeX's, as in $\lambda_{1h}$). Text before the first entry is the file's own
// introduction. A file that cannot be read, an entry twice or empty, or a '#' heading inside an
// entry is std::invalid_argument, naming the file.
class Words {
 public:
  explicit Words(const std::string& path);
  // `text` with every marker replaced by its entry's words. An unknown key, a value the entry does
  // not use, a slot no value fills, or anything left that looks like a marker or a slot is
  // std::invalid_argument naming them: words must never vanish from a page silently.
  std::string render(const std::string& text) const;
  const std::map<std::string, std::string>& entries() const { return entries_; }

 private:
  std::string path_;
  std::map<std::string, std::string> entries_;
};

}  // namespace plate
