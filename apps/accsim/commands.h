// Subcommands of the `accsim` CLI. Each Add*Command registers one
// subcommand (with its --help) and the callback that runs it. Callbacks
// report user errors by throwing accsim::cli::UsageError or
// std::invalid_argument; main() prints them as "error: ..." and exits 2.
#pragma once

#include <CLI/CLI.hpp>
#include <stdexcept>
#include <string>

namespace accsim::cli {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void AddSimulateCommand(CLI::App& app);
void AddBenchCommand(CLI::App& app);
void AddGenerateSuiteCommand(CLI::App& app);
void AddEvaluateCommand(CLI::App& app);
void AddExtractCommands(CLI::App& app);  // extract, eval-extraction
void AddReconstructCommands(CLI::App& app);  // reconstruct, eval-reconstruction, sweep-reconstruction

}  // namespace accsim::cli
