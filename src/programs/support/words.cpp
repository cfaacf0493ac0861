#include "words.hpp"

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

namespace plate {

std::string words(const std::string& key, const WordValues& values) {
  std::string out = "<!--words " + key;
  for (const auto& [name, value] : values) {
    if (value.find('"') != std::string::npos || value.find("--") != std::string::npos || value.find('\n') != std::string::npos)
      throw std::invalid_argument("words(" + key + "): the value of " + name + " holds '\"', \"--\" or a line break: " + value);
    out += " " + name + "=\"" + value + "\"";
  }
  return out + "-->";
}

Words::Words(const std::string& path) : path_(path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read the reports' words from " + path);
  std::string line, key, text;
  auto close = [&] {
    if (key.empty()) return;
    while (!text.empty() && text.back() == ' ') text.pop_back();
    if (text.empty()) throw std::runtime_error(path + ": the entry " + key + " has no words");
    if (!entries_.emplace(key, text).second) throw std::runtime_error(path + ": the entry " + key + " is there twice");
  };
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0) {
      close();
      key = line.substr(3), text.clear();
    } else if (!key.empty() && !line.empty()) {
      text += line + " ";  // a paragraph's lines are one line of the report
    }
  }
  close();
}

std::string Words::render(const std::string& text) const {
  static const std::regex marker(R"(<!--words ([A-Za-z0-9_.\-]+)((?: [A-Za-z0-9_]+="[^"]*")*)-->)");
  static const std::regex value(R"(([A-Za-z0-9_]+)="([^"]*)\")");
  static const std::regex slot(R"(@\{([A-Za-z0-9_]+)\})");
  std::string out;
  auto begin = text.cbegin();
  for (std::sregex_iterator m(text.begin(), text.end(), marker), end; m != end; ++m) {
    const std::string key = (*m)[1];
    const auto entry = entries_.find(key);
    if (entry == entries_.end()) throw std::runtime_error(path_ + " has no entry " + key);
    std::map<std::string, std::string> given;
    const std::string list = (*m)[2];
    for (std::sregex_iterator v(list.begin(), list.end(), value); v != end; ++v) given[(*v)[1]] = (*v)[2];
    std::set<std::string> used;
    std::string filled;
    const std::string& words = entry->second;
    auto from = words.cbegin();
    for (std::sregex_iterator s(words.begin(), words.end(), slot); s != end; ++s) {
      const std::string name = (*s)[1];
      const auto g = given.find(name);
      if (g == given.end()) throw std::runtime_error(path_ + ": " + key + " needs @{" + name + "}, and the report gives no value for it");
      filled.append(from, (*s)[0].first).append(g->second);
      used.insert(name);
      from = (*s)[0].second;
    }
    filled.append(from, words.cend());
    for (const auto& [name, v] : given)
      if (!used.count(name)) throw std::runtime_error(path_ + ": " + key + " has no @{" + name + "}, which the report fills");
    out.append(begin, (*m)[0].first).append(filled);
    begin = (*m)[0].second;
  }
  return out.append(begin, text.cend());
}

}  // namespace plate
