// accsim generate-suite: balanced, checked train/test scenario suites.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "accsim/scenarios/suite_generator.h"
#include "commands.h"
#include "progress.h"

namespace accsim::cli {
namespace {

struct GenerateSuiteOptions {
  SuiteOptions suite;
  std::string out;
  std::vector<std::string> sources;
  bool json = false;
};

// Report seeds from scenario files, folders of them, or JSONL suites.
std::vector<ReportSeed> LoadSeeds(const std::vector<std::string>& sources) {
  std::vector<ReportSeed> seeds;
  auto add_file = [&](const std::filesystem::path& p) {
    if (p.extension() == ".jsonl") {
      for (const auto& s : LoadSuite(p.string())) seeds.push_back(ReportSeedFromScenario(s));
    } else {
      ReportSeed r = ReportSeedFromScenario(LoadScenarioFile(p.string()));
      if (r.source_id.empty()) r.source_id = p.stem().string();
      seeds.push_back(r);
    }
  };
  for (const auto& src : sources) {
    const std::filesystem::path p(src);
    if (std::filesystem::is_directory(p)) {
      std::vector<std::filesystem::path> files;
      for (const auto& e : std::filesystem::directory_iterator(p)) {
        if (e.path().extension() == ".json" || e.path().extension() == ".jsonl") files.push_back(e.path());
      }
      std::sort(files.begin(), files.end());
      for (const auto& f : files) add_file(f);
    } else if (std::filesystem::exists(p)) {
      add_file(p);
    } else {
      throw UsageError("--sources: no such file or folder: " + src);
    }
  }
  return seeds;
}

std::string DefaultSources() {
  if (const char* dir = std::getenv("ACCSIM_DATA_DIR")) return std::string(dir) + "/scenarios/examples";
  return std::string(ACCSIM_SOURCE_DIR) + "/scenarios/examples";
}

void PrintCells(const char* name, const SuiteSplit& split) {
  std::printf("%s: %zu scenarios from %zu source reports\n", name, split.scenarios.size(), split.reports.size());
  std::printf("  %-22s %-6s %6s %12s %10s %8s\n", "family", "count", "kept", "unavoidable", "harmless", "failed");
  for (const auto& c : split.cells) {
    std::printf("  %-22s %-6s %6d %12d %10d %8d\n", std::string(ToString(c.family)).c_str(),
                std::string(ToString(c.count)).c_str(), c.kept, c.dropped_unavoidable, c.dropped_harmless,
                c.build_failures);
  }
}

void RunGenerateSuite(GenerateSuiteOptions& o) {
  if (o.sources.empty()) o.sources.push_back(DefaultSources());
  const std::vector<ReportSeed> seeds = LoadSeeds(o.sources);
  ProgressBar bar("generating");
  o.suite.progress = [&bar](int done, int total) { bar.Update(done, total); };
  const Suite suite = GenerateSuite(seeds, o.suite);
  bar.Finish();
  WriteSuite(suite, o.out, o.suite);
  if (o.json) {
    std::cout << StatsJson(suite, o.suite).dump(2) << "\n";
    return;
  }
  PrintCells("train", suite.train);
  PrintCells("test", suite.test);
  std::printf("%.1f s in all, %.3f s per kept scenario; wrote %s/{train,test}.jsonl and stats.json\n",
              suite.seconds, suite.seconds_per_scenario, o.out.c_str());
}

}  // namespace

void AddGenerateSuiteCommand(CLI::App& app) {
  auto o = std::make_shared<GenerateSuiteOptions>();
  CLI::App* cmd = app.add_subcommand(
      "generate-suite",
      "Generate balanced train/test suites over the 12 family x vehicle-count cells; every scenario is "
      "dangerous (a speed-holding ego collides) and avoidable (a simple manoeuvre avoids it)");
  cmd->add_option("--train", o->suite.train, "Scenarios in the train suite")->check(CLI::Range(0, 10000000))->capture_default_str();
  cmd->add_option("--test", o->suite.test, "Scenarios in the test suite")->check(CLI::Range(0, 10000000))->capture_default_str();
  cmd->add_option("--seed", o->suite.seed, "Seed; the same seed and sources give the same suites")->capture_default_str();
  cmd->add_option("-o,--out", o->out, "Output folder (train.jsonl, test.jsonl, stats.json)")->required();
  cmd->add_option("--sources", o->sources,
                  "Scenario files, folders or JSONL suites whose reports seed the suites (default: the bundled "
                  "example scenarios)");
  cmd->add_option("--threads", o->suite.threads, "Worker threads (0 = all cores)")->check(CLI::Range(0, 256))->capture_default_str();
  cmd->add_flag("--json", o->json, "Print the statistics as JSON");
  cmd->callback([o] { RunGenerateSuite(*o); });
}

}  // namespace accsim::cli
