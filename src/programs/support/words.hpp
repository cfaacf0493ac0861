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
// where the words are not yet put in. A key is letters, digits, '_', '.' and '-'; a name letters,
// digits and '_', each name once; a value may not hold '"', "--" or a line break. Anything else
// throws std::invalid_argument: a marker the renderer could not read would vanish from the page.
std::string words(const std::string& key, const WordValues& values = {});

}  // namespace plate
