// accsim extract / eval-extraction: narrative -> AccidentRecord.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>

#include "accsim/scenarios/extraction_eval.h"
#include "accsim/scenarios/narrative_extractor.h"
#include "commands.h"

namespace accsim::cli {
namespace {

std::string ReadInput(const std::string& path) {
  if (path == "-") return std::string(std::istreambuf_iterator<char>(std::cin), {});
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError(path + ": cannot open file");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

void AddExtractCommands(CLI::App& app) {
  auto input = std::make_shared<std::string>();
  CLI::App* extract = app.add_subcommand(
      "extract", "Read a crash narrative and print its AccidentRecord as JSON (each field says stated/inferred/defaulted)");
  extract->add_option("file", *input, "Narrative text file, or - for standard input")->required();
  extract->callback([input] {
    const AccidentRecord r = NarrativeExtractor{}.Extract(ReadInput(*input));
    std::cout << ToJson(r).dump(2) << "\n";
  });

  struct EvalOptions {
    std::string dir;
    bool json = false;
    bool verbose = false;
  };
  auto o = std::make_shared<EvalOptions>();
  CLI::App* eval = app.add_subcommand(
      "eval-extraction", "Score extraction on a labelled folder (labels.jsonl, NMVCCS layout) on six attributes");
  eval->add_option("dir", o->dir, "Folder holding labels.jsonl")->required()->check(CLI::ExistingDirectory);
  eval->add_flag("--json", o->json, "Print the accuracies as JSON");
  eval->add_flag("--verbose", o->verbose, "List every mismatch");
  eval->callback([o] {
    const ExtractionScore s = EvaluateExtraction(o->dir, NarrativeExtractor{});
    if (o->json) {
      std::cout << ToJson(s).dump(2) << "\n";
      return;
    }
    std::printf("%-20s %9s", "attribute", "all");
    for (const auto& [g, n] : s.group_sizes) std::printf(" %10s", g.c_str());
    std::printf("\n");
    for (const auto& a : ExtractionAttributes()) {
      std::printf("%-20s %8.2f%%", a.c_str(), 100.0 * s.attributes.at(a));
      for (const auto& [g, n] : s.group_sizes) std::printf(" %9.2f%%", 100.0 * s.by_group.at(g).at(a));
      std::printf("\n");
    }
    std::printf("%-20s %9d", "cases", s.n);
    for (const auto& [g, n] : s.group_sizes) std::printf(" %10d", n);
    std::printf("\n");
    if (o->verbose) {
      for (const auto& m : s.mismatches) std::printf("  %s\n", m.c_str());
    }
  });
}

}  // namespace accsim::cli
