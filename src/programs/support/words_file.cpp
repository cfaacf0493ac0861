#include "words_file.hpp"

#include "words.hpp"

#include <fstream>
#include <regex>
#include <set>
#include <stdexcept>

namespace plate {

namespace {
std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == ' ' || s.back() == '\r' || s.back() == '\t')) s.pop_back();
  return s;
}
}  // namespace

Words::Words(const std::string& path) : path_(path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("cannot read the reports' words from " + path + " (--words names another file)");
  std::string line, key, text;
  auto close = [&] {
    if (key.empty()) return;
    text = trimmed(text);
    if (text.empty()) throw std::invalid_argument(path + ": the entry " + key + " has no words");
    if (!entries_.emplace(key, text).second) throw std::invalid_argument(path + ": the entry " + key + " is there twice");
  };
  while (std::getline(in, line)) {
    line = trimmed(line);
    if (line.rfind("## ", 0) == 0) {
      close();
      key = trimmed(line.substr(3)), text.clear();
    } else if (!key.empty() && line.rfind("#", 0) == 0) {
      throw std::invalid_argument(path + ": a heading inside the entry " + key + ": " + line);
    } else if (!key.empty() && !line.empty()) {
      text += line + " ";  // a paragraph's lines are one line of the report
    }
  }
  close();
}

std::string Words::render(const std::string& text) const {
  static const std::regex marker("<!--words (" + kWordKeyChars + ")((?: " + kWordNameChars + "=\"[^\"]*\")*)-->");
  static const std::regex value("(" + kWordNameChars + ")=\"([^\"]*)\"");
  static const std::regex slot("@\\{(" + kWordNameChars + ")\\}");
  std::string out;
  auto begin = text.cbegin();
  for (std::sregex_iterator m(text.begin(), text.end(), marker), end; m != end; ++m) {
    const std::string key = (*m)[1];
    const auto entry = entries_.find(key);
    if (entry == entries_.end()) throw std::invalid_argument(path_ + " has no entry " + key);
    std::map<std::string, std::string> given;
    const std::string list = (*m)[2];
    for (std::sregex_iterator v(list.begin(), list.end(), value); v != end; ++v) {
      // A value may itself be a marker (a phrase the program chose, such as how a bar was found):
      // it is rendered first. Each level peels one layer of escaping, so this ends; the entries
      // themselves are never rendered again.
      std::string given_value = unescape_word_value((*v)[2]);
      if (given_value.find("<!--words") != std::string::npos) given_value = render(given_value);
      if (!given.emplace((*v)[1], given_value).second) throw std::invalid_argument(key + ": the value " + std::string((*v)[1]) + " is given twice");
    }
    std::set<std::string> used;
    std::string filled;
    const std::string& words = entry->second;
    auto from = words.cbegin();
    for (std::sregex_iterator s(words.begin(), words.end(), slot); s != end; ++s) {
      const std::string name = (*s)[1];
      const auto g = given.find(name);
      if (g == given.end()) throw std::invalid_argument(path_ + ": " + key + " needs @{" + name + "}, and the report gives no value for it");
      filled.append(from, (*s)[0].first).append(g->second);
      used.insert(name);
      from = (*s)[0].second;
    }
    filled.append(from, words.cend());
    if (filled.find("@{") != std::string::npos) throw std::invalid_argument(path_ + ": " + key + " has a slot that is not @{letters, digits, _}");
    for (const auto& [name, v] : given)
      if (!used.count(name)) throw std::invalid_argument(path_ + ": " + key + " has no @{" + name + "}, which the report fills");
    out.append(begin, (*m)[0].first).append(filled);
    begin = (*m)[0].second;
  }
  out.append(begin, text.cend());
  // A marker the pattern did not take (a name with '-', two spaces) would vanish as an HTML comment.
  if (const size_t left = out.find("<!--words"); left != std::string::npos)
    throw std::invalid_argument("a marker that cannot be read: " + out.substr(left, out.find('\n', left) - left));
  return out;
}

}  // namespace plate
