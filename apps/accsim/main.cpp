// accsim: one binary, one subcommand per pipeline stage.
#include <exception>
#include <iostream>

#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app{"accsim: crash reports reconstructed as physically simulated RL scenarios"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "accsim 0.1.0");
  accsim::cli::AddSimulateCommand(app);
  accsim::cli::AddBenchCommand(app);
  accsim::cli::AddGenerateSuiteCommand(app);
  accsim::cli::AddEvaluateCommand(app);
  accsim::cli::AddExtractCommands(app);
  accsim::cli::AddReconstructCommands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; a bad flag or value is a usage error (2),
    // like every other input error.
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
