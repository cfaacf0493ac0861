// The words of the reports (captions, standing and verdict sentences) live in reports/words.md,
// apart from the programs that compute the numbers. A program writes a marker where the words go,
// naming the entry and the values it fills in; build/render_report puts the words in
// (words_file.hpp), for the document (include.lua calls it) and for a reader at a terminal. Mending
// a caption therefore rebuilds the document and reruns no solver.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace plate {

using WordValues = std::vector<std::pair<std::string, std::string>>;

// What a marker's key and a value's name may hold: words() checks them, and the renderer's patterns
// (words_file.cpp) take only these, so the writer and the reader cannot drift apart.
inline const std::string kWordKeyChars = R"([A-Za-z0-9_.\-]+)", kWordNameChars = "[A-Za-z0-9_]+";

// <!--words key name="value" ...-->: an HTML comment, so that a Markdown viewer shows nothing false
// where the words are not yet put in. A key is letters, digits, '_', '.' and '-', with no "--" and
// not ending in '-' (an HTML comment may hold neither); a name letters, digits and '_', each name
// once; a value any one line. Anything else throws std::invalid_argument: a marker the renderer
// could not read would vanish from the page.
std::string words(const std::string& key, const WordValues& values = {});

// A value may quote a program's message or an option, but inside the marker it may hold neither '"'
// (which ends it) nor "--" (which an HTML comment may not hold). So '&' -> &amp;, '"' -> &quot;, and
// a '-' that follows a '-' -> &#45;; a value without '&', '"' or "--" is written as it is, so the
// numbers in a marker stay plain for compare_tables. unescape_word_value() is the exact inverse.
// Both are here, in the header, because the writer (platesupport) and the reader (platewords) are
// two libraries that must not link each other.
inline std::string escape_word_value(const std::string& value) {
  std::string out;
  for (size_t i = 0; i < value.size(); ++i) {
    const char c = value[i];
    if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else if (c == '-' && i > 0 && value[i - 1] == '-') out += "&#45;";
    else out += c;
  }
  return out;
}

inline std::string unescape_word_value(const std::string& value) {
  static const std::pair<std::string, char> kEntities[] = {{"&amp;", '&'}, {"&quot;", '"'}, {"&#45;", '-'}};
  std::string out;
  for (size_t i = 0; i < value.size();) {
    bool entity = false;
    for (const auto& [text, c] : kEntities)
      if (value.compare(i, text.size(), text) == 0) {
        out += c, i += text.size(), entity = true;
        break;
      }
    if (!entity) out += value[i++];
  }
  return out;
}

}  // namespace plate
