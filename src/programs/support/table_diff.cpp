#include "table_diff.hpp"

#include <cctype>
#include <cfloat>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace plate {
namespace {

// A line cut into text and numbers. A number's unit is one in its last printed digit.
struct Token {
  bool number = false;
  bool bound = false;  // printed as "< value"
  std::string text;    // as printed (numbers too, for messages)
  double value = 0, unit = 0;
  bool integer = false;  // no point, no exponent: a count, a flag or a label, compared exactly
};

bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool is_word(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// Length of the number printed at s[i] (sign, digits, point, digits, exponent), 0 if none. A digit
// that continues a word (m12, w_0.5, (5a)'s 5 is not one) belongs to the word: column names compare
// as text.
size_t number_length(const std::string& s, size_t i) {
  if (i > 0 && (is_word(s[i - 1]) || s[i - 1] == '.')) return 0;
  size_t j = i;
  if (s[j] == '-' || s[j] == '+') ++j;
  const size_t digits_from = j;
  while (j < s.size() && is_digit(s[j])) ++j;
  size_t mantissa_digits = j - digits_from;
  if (j < s.size() && s[j] == '.') {
    size_t k = j + 1;
    while (k < s.size() && is_digit(s[k])) ++k;
    if (k - j - 1 > 0 || mantissa_digits > 0) mantissa_digits += k - j - 1, j = k;
  }
  if (mantissa_digits == 0) return 0;
  if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
    size_t k = j + 1;
    if (k < s.size() && (s[k] == '-' || s[k] == '+')) ++k;
    if (k < s.size() && is_digit(s[k])) {
      while (k < s.size() && is_digit(s[k])) ++k;
      j = k;
    }
  }
  return j - i;
}

// One in the last printed digit of a number as printed: 0.0976921 -> 1e-7, 2.1e-06 -> 1e-7, 39 -> 1.
double last_digit_unit(const std::string& t) {
  const size_t e = t.find_first_of("eE");
  const std::string mantissa = t.substr(0, e);
  const size_t point = mantissa.find('.');
  const int decimals = point == std::string::npos ? 0 : static_cast<int>(mantissa.size() - point - 1);
  const int exponent = e == std::string::npos ? 0 : std::stoi(t.substr(e + 1));
  return std::pow(10.0, exponent - decimals);
}

std::vector<Token> tokens(const std::string& line) {
  std::vector<Token> out;
  std::string text;
  auto flush = [&] {
    if (!text.empty()) out.push_back(Token{false, false, text, 0, 0, false});
    text.clear();
  };
  for (size_t i = 0; i < line.size();) {
    const size_t n = number_length(line, i);
    if (n == 0) {
      text += line[i++];
      continue;
    }
    // "< 3e-11" is a bound, whose "<" belongs to the number, not to the text before it.
    bool bound = false;
    size_t end = text.size();
    while (end > 0 && text[end - 1] == ' ') --end;
    if (end > 0 && text[end - 1] == '<') bound = true, text.resize(end - 1);
    flush();
    const std::string t = line.substr(i, n);
    out.push_back(Token{true, bound, t, std::stod(t), last_digit_unit(t), t.find_first_of(".eE") == std::string::npos});
    i += n;
  }
  flush();
  return out;
}

std::string quoted(const Token& t) { return "'" + std::string(t.bound ? "< " : "") + t.text + "'"; }

// Empty when the two tokens agree; otherwise what differs and by how much.
std::string disagreement(const Token& e, const Token& a) {
  if (e.number != a.number) return quoted(e) + " against " + quoted(a) + " (a number against text)";
  if (!e.number) return e.text == a.text ? "" : quoted(e) + " against " + quoted(a);
  // Printed to one depth: one unit of it. To two depths: the coarser was rounded, so half its unit,
  // and one unit of the finer for round-off. Counts and flags: exactly.
  double tolerance = e.unit == a.unit ? e.unit : 0.5 * std::max(e.unit, a.unit) + std::min(e.unit, a.unit);
  if (e.integer && a.integer) tolerance = 0;
  double difference = std::abs(e.value - a.value);
  if (e.bound != a.bound) {  // a bound against a value below it, give or take the value's last digit
    const Token& b = e.bound ? e : a;
    const Token& v = e.bound ? a : e;
    tolerance = v.unit;
    difference = std::max(0.0, std::abs(v.value) - b.value);
  }
  // The printed decimals are not the doubles read from them, nor is their difference exact.
  const double slack = 8 * DBL_EPSILON * std::max(std::abs(e.value), std::abs(a.value));
  if (difference <= tolerance + slack) return "";
  std::ostringstream m;
  m << quoted(e) << " against " << quoted(a) << ": they differ by " << difference << ", the tolerance is " << tolerance;
  return m.str();
}

std::vector<std::string> lines_of(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// The first `k` fields of a line split at ',' or '|' (a markdown row's leading '|' skipped), or
// empty if the line has no more than k fields or is a comment.
std::string key_of(const std::string& line, int k) {
  if (line.empty() || line[0] == '#') return "";
  const size_t start = line[0] == '|' ? 1 : 0;
  size_t at = start;
  for (int f = 0; f < k; ++f) {
    at = line.find_first_of(",|", at);
    if (at == std::string::npos) return "";
    ++at;
  }
  if (at >= line.size()) return "";
  return line.substr(start, at - start);
}

bool compare_line(const std::string& e, const std::string& a, int number, TableDiff& d) {
  const std::vector<Token> te = tokens(e), ta = tokens(a);
  ++d.lines_compared;
  std::string why;
  if (te.size() != ta.size()) why = "the lines do not have the same fields";
  for (size_t i = 0; why.empty() && i < te.size(); ++i) {
    why = disagreement(te[i], ta[i]);
    if (te[i].number) ++d.numbers_compared;
  }
  if (why.empty()) return true;
  d.agrees = false;
  d.first_difference = "line " + std::to_string(number) + ": " + why + "\n  expected: " + e + "\n  rebuilt:  " + a;
  return false;
}

}  // namespace

TableDiff compare_tables(const std::string& expected, const std::string& actual, const TablePairing& pairing) {
  const std::vector<std::string> e = lines_of(expected), a = lines_of(actual);
  TableDiff d;
  if (!pairing.subset) {
    for (size_t i = 0; i < std::min(e.size(), a.size()); ++i)
      if (!compare_line(e[i], a[i], static_cast<int>(i + 1), d)) return d;
    if (e.size() != a.size()) {
      d.agrees = false;
      d.first_difference = "the expected file has " + std::to_string(e.size()) + " lines, the rebuilt one " +
                           std::to_string(a.size());
    }
    return d;
  }
  std::map<std::string, size_t> by_key;
  for (size_t i = 0; i < e.size(); ++i)
    if (const std::string k = key_of(e[i], pairing.key_fields); !k.empty()) by_key.emplace(k, i);
  for (size_t i = 0; i < a.size(); ++i) {
    const std::string k = key_of(a[i], pairing.key_fields);
    if (k.empty()) continue;
    const auto found = by_key.find(k);
    if (found == by_key.end()) {
      d.agrees = false;
      d.first_difference = "line " + std::to_string(i + 1) + " of the rebuilt file has no line with its key in the "
                           "expected one: " + a[i];
      return d;
    }
    if (!compare_line(e[found->second], a[i], static_cast<int>(found->second + 1), d)) return d;
  }
  if (d.lines_compared == 0) {
    d.agrees = false;
    d.first_difference = "no line of the rebuilt file has a key (its first " + std::to_string(pairing.key_fields) +
                         " fields) that the expected file has";
  }
  return d;
}

TableDiff compare_table_files(const std::string& expected_path, const std::string& actual_path,
                              const TablePairing& pairing) {
  auto read = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  };
  return compare_tables(read(expected_path), read(actual_path), pairing);
}

}  // namespace plate
