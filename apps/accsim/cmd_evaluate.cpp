// accsim evaluate: SafeBench-style metrics of scripted drivers on a suite.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "accsim/env/scripted_drivers.h"
#include "accsim/eval/safebench.h"
#include "accsim/scenarios/suite_generator.h"
#include "commands.h"

namespace accsim::cli {
namespace {

struct EvaluateOptions {
  std::vector<std::string> inputs;
  std::vector<std::string> drivers{"hold", "rule"};
  std::string config;
  std::string markdown;
  bool json = false;
};

PolicyFn Driver(const std::string& name) {
  if (name == "hold") return [](const CrashEnv& e) { return HoldPolicy(e); };
  if (name == "brake") return [](const CrashEnv& e) { return BrakePolicy(e, 0.0); };
  return [](const CrashEnv& e) { return RuleBasedPolicy(e); };
}

void RunEvaluate(const EvaluateOptions& o) {
  const auto scenarios = LoadScenarioSet(o.inputs);
  const CrashEnvConfig config = o.config.empty() ? CrashEnvConfig{} : LoadCrashEnvConfig(o.config);
  std::vector<EvaluationReport> reports;
  for (const auto& d : o.drivers) reports.push_back(Evaluate(scenarios, Driver(d), d, config));
  const std::string table = ToMarkdown(reports);
  if (!o.markdown.empty()) {
    std::ofstream(o.markdown) << "# Evaluation on " << scenarios.size() << " scenarios\n\n"
                              << "CR = collision rate, RC = route completion.\n\n" << table;
  }
  if (o.json) {
    nlohmann::json j = nlohmann::json::array();
    for (const auto& r : reports) j.push_back(ToJson(r));
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::printf("%zu scenarios; CR = collision rate, RC = route completion\n\n%s", scenarios.size(), table.c_str());
}

}  // namespace

void AddEvaluateCommand(CLI::App& app) {
  auto o = std::make_shared<EvaluateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "evaluate", "Collision rate and other SafeBench metrics of drivers, per family and vehicle count");
  cmd->add_option("inputs", o->inputs, "Suites (.jsonl) or scenario files (.json)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--ego", o->drivers, "Drivers to evaluate: hold, brake, rule")
      ->check(CLI::IsMember({"hold", "brake", "rule"}))
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--config", o->config, "Environment config YAML")->check(CLI::ExistingFile);
  cmd->add_option("--markdown", o->markdown, "Also write the table to this Markdown file");
  cmd->add_flag("--json", o->json, "Print the metrics as JSON");
  cmd->callback([o] { RunEvaluate(*o); });
}

}  // namespace accsim::cli
