// The words of the reports (captions and standing sentences) live in reports/words.md, apart from
// the programs that compute the numbers. A program writes a marker where a caption goes, naming the
// entry and the values it fills in; build/render_report puts the words in, for the document
// (include.lua calls it) and for a reader at a terminal. Mending a caption therefore rebuilds the
// document and reruns no solver.
#pragma once
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace plate {

using WordValues = std::vector<std::pair<std::string, std::string>>;

// <!--words key name="value" ...-->: an HTML comment, so that a Markdown viewer shows nothing false
// where the words are not yet put in. A value may not hold '"', "--" or a line break.
std::string words(const std::string& key, const WordValues& values = {});

// reports/words.md read: each entry a line "## key" and then its text, one paragraph, with @{name}
// where a value goes (braces alone are TeX's, as in $\lambda_{1h}$).
class Words {
 public:
  explicit Words(const std::string& path);
  // `text` with every marker replaced by its entry's words. An unknown key, a value the entry does
  // not use, or a slot no value fills is an error (std::runtime_error naming them).
  std::string render(const std::string& text) const;
  const std::map<std::string, std::string>& entries() const { return entries_; }

 private:
  std::string path_;
  std::map<std::string, std::string> entries_;
};

}  // namespace plate
