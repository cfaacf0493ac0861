// The exit status of every program here, one table for all, so a script can tell a bad option
// from a run that did not converge.
#pragma once
#include <CLI/CLI.hpp>

#include <iostream>
#include <stdexcept>

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

// A program's work after parse_options, with the table above: an input it cannot use
// (std::invalid_argument) exits kBadInput, any other exception kFailure, each with one line that
// names the program, so that no failure leaves as a crash.
template <class Body>
int run_guarded(const char* program, Body body) {
  try {
    return body();
  } catch (const std::invalid_argument& e) {
    std::cerr << program << ": bad input: " << e.what() << "\n";
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << program << ": error: " << e.what() << "\n";
    return kFailure;
  }
}

}  // namespace plate
