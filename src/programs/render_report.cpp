// render_report: reports from results/ with their words put in (reports/words.md), printed to
// standard output. The document's include filter calls it on every report it splices in; a reader
// at a terminal calls it the same way: build/render_report results/liftoff.md | less
#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <sstream>

#include "exit_codes.hpp"
#include "words_file.hpp"

using namespace plate;

int main(int argc, char** argv) {
  CLI::App app{"render_report: print reports from results/ with their captions and sentences put in from the\n"
               "words file. Nothing is printed unless every report renders."};
  std::string words_path = PLATE_SOURCE_DIR "/reports/words.md";
  std::vector<std::string> reports;
  app.add_option("--words", words_path, "the words file")->check(CLI::ExistingFile)->capture_default_str();
  app.add_option("reports", reports, "report files (Markdown) to print")->required()->check(CLI::ExistingFile);
  app.footer("Exit status: 0 printed; 2 a report or the words file cannot be used (the message names it); "
             "4 other failure.");
  if (const int status = parse_options(app, argc, argv, "render_report"); status >= 0) return status;
  return run_guarded("render_report", [&] {
    const Words words(words_path);
    std::string out;
    for (const std::string& path : reports) {
      std::ifstream in(path);
      std::stringstream text;
      text << in.rdbuf();
      try {
        out += words.render(text.str());
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(path + ": " + e.what());
      }
    }
    std::cout << out;
    return kSuccess;
  });
}
