#include "words.hpp"

#include <regex>
#include <set>
#include <stdexcept>

namespace plate {

std::string words(const std::string& key, const WordValues& values) {
  static const std::regex key_chars(kWordKeyChars), name_chars(kWordNameChars);
  if (!std::regex_match(key, key_chars) || key.find("--") != std::string::npos || key.back() == '-')
    throw std::invalid_argument("words: the key \"" + key + "\" is not letters, digits, '_', '.' or '-', or holds \"--\" or ends in '-'");
  std::string out = "<!--words " + key;
  std::set<std::string> names;
  for (const auto& [name, value] : values) {
    if (!std::regex_match(name, name_chars) || !names.insert(name).second)
      throw std::invalid_argument("words(" + key + "): the name \"" + name + "\" is not letters, digits and '_', or comes twice");
    if (value.find('\n') != std::string::npos || value.find('\r') != std::string::npos)
      throw std::invalid_argument("words(" + key + "): the value of " + name + " holds a line break: " + value);
    out += " " + name + "=\"" + escape_word_value(value) + "\"";
  }
  return out + "-->";
}

}  // namespace plate
