// compare_tables: does a rebuilt results table say what the committed one says? Number by number,
// each within one unit of its last printed digit (table_diff.hpp), never byte for byte. Used by
// `make check-results`; `compare_tables --help`.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>

#include "exit_codes.hpp"
#include "table_diff.hpp"

using namespace plate;

int main(int argc, char** argv) {
  CLI::App app{"compare_tables: compares each FILE in --rebuilt with the one of the same name in --expected,\n"
               "number by number (one unit in the last printed digit), and prints 'agrees' or the first difference."};
  std::string expected = "results", rebuilt;
  std::vector<std::string> files;
  int subset = 0;
  app.add_option("--expected", expected, "folder of the committed tables")->check(CLI::ExistingDirectory)->capture_default_str();
  app.add_option("--rebuilt", rebuilt, "folder of the rebuilt tables")->required()->check(CLI::ExistingDirectory);
  app.add_option("--subset", subset,
                 "the rebuilt run was shorter: pair its data lines with the expected lines that begin with the "
                 "same K fields (0: compare the files whole, line by line)")
      ->check(CLI::Range(0, 20))
      ->capture_default_str();
  app.add_option("files", files, "file names, in both folders")->required();
  app.footer(kExitStatusHelp);
  if (const int status = parse_options(app, argc, argv, "compare_tables"); status >= 0) return status;
  namespace fs = std::filesystem;
  int status = kSuccess;
  for (const std::string& name : files) {
    const fs::path e = fs::path(expected) / name, a = fs::path(rebuilt) / name;
    for (const fs::path& p : {e, a})
      if (!fs::is_regular_file(p)) {
        std::cerr << "compare_tables: bad input: " << p.string() << " is not a file\n";
        return kBadInput;
      }
    try {
      const TableDiff d = compare_table_files(e.string(), a.string(), TablePairing{subset > 0, subset});
      if (d.agrees) {
        std::cout << name << ": agrees (" << d.numbers_compared << " numbers on " << d.lines_compared << " lines)\n";
      } else {
        std::cout << name << ": DIFFERS at " << d.first_difference << "\n";
        status = kNotConverged;
      }
    } catch (const std::exception& x) {
      std::cerr << "compare_tables: " << x.what() << "\n";
      return kFailure;
    }
  }
  return status;
}
