// The exit status of every program here, one table for all, so a script can tell a bad option
// from a run that did not converge.
#pragma once
#include <CLI/CLI.hpp>

#include <iostream>

namespace plate {

constexpr int kSuccess = 0;
constexpr int kBadInput = 2;      // an option or an input file that cannot be used; nothing was run
constexpr int kNotConverged = 3;  // a solve or a check missed its target; the outputs say so
constexpr int kFailure = 4;       // anything else: a file that cannot be written, a child program that failed

constexpr const char* kExitStatusHelp =
    "Exit status: 0 done, 2 bad input, 3 not converged or a check failed (outputs are still written), "
    "4 other failure.";

// CLI11's parse with the table above: --help exits 0, an option CLI11 cannot use exits kBadInput
// with its message (CLI11's own codes would say 105, 109, ...). Returns -1 when the program goes on.
inline int parse_options(CLI::App& app, int argc, char** argv, const char* program) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << program << ": bad input: " << e.what() << "\n";
    return kBadInput;
  }
  return -1;
}

}  // namespace plate
