// The CSV files this repository writes into results/ and keeps in reference/, read back by column
// name: '#' lines are comments, the first other line names the columns, fields are separated by
// commas and never quoted (our writers refuse commas inside a field).
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace plate {

struct CsvTable {
  std::string path;  // for messages
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;

  // The index of a column; throws std::runtime_error naming the file and the column if absent.
  std::size_t column(const std::string& name) const;
  // A field as text, or as a number (throws naming file, row and column if it is not one).
  const std::string& text(std::size_t row, const std::string& name) const;
  double number(std::size_t row, const std::string& name) const;
  // The rows for which keep(row index) is true.
  std::vector<std::size_t> where(const std::function<bool(std::size_t)>& keep) const;
  // The rows whose field `name` equals `value`.
  std::vector<std::size_t> where(const std::string& name, const std::string& value) const;
};

// The fields of one line, split at every comma ("a,,b," gives four).
std::vector<std::string> split_csv_line(const std::string& line);

// The whole of s as a number; throws std::runtime_error with `where` (a file, a row) otherwise.
double parse_number(const std::string& s, const std::string& where);

// Throws std::runtime_error naming the path on a missing file, a missing header or a row whose
// number of fields differs from the header's.
CsvTable read_csv_table(const std::string& path);

}  // namespace plate
