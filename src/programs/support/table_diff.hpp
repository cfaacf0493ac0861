// Whether two renderings of one results table say the same thing, number by number (the rule of
// deal.II's numdiff, with the tolerance read off the printed digits). A digit that round-off can
// flip flips on some machine, thread count or BLAS kernel, so no test compares tables byte for byte.
//
// The rule: the text between numbers is the same, and two numbers agree when they differ by at most
// one unit in the last digit printed. Every table here prints a digit only where it is at least ten
// times the round-off that could change it (fmt_above), so that unit is also at least the column's
// round-off bound. Printed to different depths (a machine whose round-off estimate left it fewer
// digits), they agree within half a unit of the coarser plus one of the finer. Integers (counts,
// flags, grid sizes) must be equal. A bound "< B" agrees with a number v when |v| < B plus one unit
// of v's last digit, and with another bound by the same rule as numbers.
#pragma once
#include <string>

namespace plate {

struct TableDiff {
  bool agrees = true;
  std::string first_difference;  // where and how, when they do not agree: line, both fields, tolerance
  int lines_compared = 0;
  int numbers_compared = 0;
};

// How lines are paired. Whole: line by line, the same count. Subset: `actual` comes from a shorter
// run (fewer grids); each of its data lines is paired with the line of `expected` that begins with
// the same first `key_fields` fields (split at ',' or '|'); a data line whose key the expected file
// lacks is a difference, and comments ('#') are not compared.
struct TablePairing {
  bool subset = false;
  int key_fields = 2;
};

TableDiff compare_tables(const std::string& expected, const std::string& actual, const TablePairing& pairing = {});

// Reads both files (throws std::runtime_error naming a file it cannot read).
TableDiff compare_table_files(const std::string& expected_path, const std::string& actual_path,
                              const TablePairing& pairing = {});

}  // namespace plate
