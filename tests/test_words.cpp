// The reports' words live in reports/words.md and reach a report through a marker
// (src/programs/support/words.hpp). These tests hold the marker's rules: a value fills its slot, and
// every way a marker and its entry can disagree is an error that names them.
#include <gtest/gtest.h>

#include <fstream>

#include "scratch.hpp"
#include "words.hpp"

using namespace plate;

namespace {
// A words file with the given text, in a scratch folder that goes with the returned object.
struct WordsFile {
  Scratch dir{"words"};
  std::string path;
  explicit WordsFile(const std::string& text) : path(dir.path("words.md")) { std::ofstream(path) << text; }
};

std::string error_of(const Words& w, const std::string& text) {
  try {
    w.render(text);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Words, AMarkerBecomesItsEntryWithTheValuesInPlace) {
  const WordsFile f("# heading, not an entry\n\n## a.caption\nThe plate at n = @{n},\nread down (@{what}) in $\\lambda_{1h}$.\n\n## a.other\nOther.\n");
  const Words w(f.path);
  const std::string report = "| x |\n\nTable: " + words("a.caption", {{"n", "64"}, {"what", "max w"}}) + "\n" + words("a.other") + "\n";
  EXPECT_EQ(w.render(report), "| x |\n\nTable: The plate at n = 64, read down (max w) in $\\lambda_{1h}$.\nOther.\n");
  EXPECT_EQ(w.render("no marker here\n"), "no marker here\n");
}

TEST(Words, AMarkerAndItsEntryThatDisagreeAreErrorsNamingThem) {
  const WordsFile f("## a.caption\nThe plate at n = @{n}.\n");
  const Words w(f.path);
  EXPECT_NE(error_of(w, words("a.missing")).find("a.missing"), std::string::npos);
  EXPECT_NE(error_of(w, words("a.caption")).find("@{n}"), std::string::npos);  // a slot no value fills
  EXPECT_NE(error_of(w, words("a.caption", {{"n", "8"}, {"m", "9"}})).find("@{m}"), std::string::npos);  // a value no slot takes
  EXPECT_EQ(error_of(w, words("a.caption", {{"n", "8"}})), "");
}

TEST(Words, AValueThatWouldBreakItsMarkerIsRefused) {
  EXPECT_THROW(words("k", {{"v", "say \"this\""}}), std::invalid_argument);
  EXPECT_THROW(words("k", {{"v", "--edge"}}), std::invalid_argument);
  EXPECT_THROW(words("k", {{"v", "two\nlines"}}), std::invalid_argument);
}

TEST(Words, AFileWithAnEntryTwiceOrAnEmptyEntryIsRefused) {
  const WordsFile twice("## k\nOne.\n## k\nTwo.\n"), empty("## k\n\n## j\nJ.\n");
  EXPECT_THROW(Words{twice.path}, std::runtime_error);
  EXPECT_THROW(Words{empty.path}, std::runtime_error);
  EXPECT_THROW(Words{"/nonexistent/words.md"}, std::runtime_error);
}
