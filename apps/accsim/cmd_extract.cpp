// accsim extract / eval-extraction: narrative -> AccidentRecord, and its score.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>
#include <vector>

#include "accsim/scenarios/extraction_eval.h"
#include "accsim/scenarios/llm_extractor.h"
#include "accsim/scenarios/narrative_extractor.h"
#include "accsim/scenarios/narrative_rewrites.h"
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

struct BackendOptions {
  std::string backend = "rules";
  LlmConfig llm;
};

void AddBackendOptions(CLI::App* cmd, BackendOptions& o) {
  cmd->add_option("--backend", o.backend,
                  "rules: the offline rule extractor (default). llm: rules, then a local OpenAI-compatible chat "
                  "server (llama.cpp server, Ollama, vLLM) fills what the rules only inferred")
      ->check(CLI::IsMember({"rules", "llm"}));
  cmd->add_option("--llm-url", o.llm.url, "Base URL of the chat server (http only); /v1/chat/completions is appended")
      ->capture_default_str();
  cmd->add_option("--llm-model", o.llm.model, "Model name the server expects")->capture_default_str();
  cmd->add_option("--llm-timeout", o.llm.timeout_s, "Seconds to wait for one answer")->capture_default_str();
}

// One extraction function for both back ends; the LLM config is validated here.
ExtractFn MakeExtractor(const BackendOptions& o) {
  if (o.backend == "llm") {
    auto llm = std::make_shared<LlmExtractor>(o.llm);
    return [llm](std::string_view t) { return llm->Extract(t); };
  }
  auto rules = std::make_shared<NarrativeExtractor>();
  return [rules](std::string_view t) { return rules->Extract(t); };
}

}  // namespace

void AddExtractCommands(CLI::App& app) {
  struct ExtractOptions {
    std::string input;
    BackendOptions backend;
  };
  auto e = std::make_shared<ExtractOptions>();
  CLI::App* extract = app.add_subcommand(
      "extract",
      "Read a crash narrative (police / NHTSA style, or a short description such as 'my car was stopped when a "
      "pickup rear-ended me'; mph or km/h) and print its AccidentRecord as JSON "
      "(schema_version 1; every field says whether it was stated, inferred or defaulted; 'warnings' says what "
      "could not be read)");
  extract->add_option("file", e->input, "Narrative text file, or - for standard input")->required();
  AddBackendOptions(extract, e->backend);
  extract->callback([e] {
    const AccidentRecord r = MakeExtractor(e->backend)(ReadInput(e->input));
    std::cout << ToJson(r).dump(2) << "\n";
  });

  struct EvalOptions {
    std::string dir;
    bool json = false;
    bool verbose = false;
    std::string rewrite;
    BackendOptions backend;
  };
  auto o = std::make_shared<EvalOptions>();
  CLI::App* eval = app.add_subcommand(
      "eval-extraction",
      "Score extraction on a labelled folder (labels.jsonl in the NMVCCS or CIREN layout; the input is each "
      "row's full narrative) on the AccidentSim paper's six attributes: lane count, speed limit, collision "
      "location (relation to junction), driving actions, crash type, participant count. docs/extraction.md "
      "documents how each coded label maps to the record");
  eval->add_option("dir", o->dir, "Folder holding labels.jsonl")->required()->check(CLI::ExistingDirectory);
  eval->add_flag("--json", o->json,
                 "Print JSON: {\"attributes\": {...}, \"n\": N, \"scored\": {...}, \"extra\": {...}, \"groups\": {...}}");
  eval->add_flag("--verbose", o->verbose, "List every mismatch (case: attribute: want X, got Y)");
  std::string rewrites = "Rewrite each narrative first, keeping its facts, to check that the score does not hang on "
                         "one writer's wording:";
  std::vector<std::string> names;
  for (const auto& r : NarrativeRewrites()) {
    rewrites += "\n  " + r.name + ": " + r.description;
    names.push_back(r.name);
  }
  eval->add_option("--rewrite", o->rewrite, rewrites)->check(CLI::IsMember(names));
  AddBackendOptions(eval, o->backend);
  eval->callback([o] {
    ExtractFn read = MakeExtractor(o->backend);
    if (!o->rewrite.empty()) {
      read = [plain = std::move(read), name = o->rewrite](std::string_view t) {
        return plain(RewriteNarrative(t, name));
      };
    }
    const ExtractionScore s = EvaluateExtraction(o->dir, read);
    if (o->json) {
      std::cout << ToJson(s).dump(2) << "\n";
      return;
    }
    std::printf("%-20s %9s %7s", "attribute", "all", "scored");
    for (const auto& [g, n] : s.group_sizes) std::printf(" %10s", g.c_str());
    std::printf("\n");
    for (const auto& a : ExtractionAttributes()) {
      if (s.scored.at(a) == 0) {
        std::printf("%-20s %9s %7d", a.c_str(), "n/a", 0);  // no case codes it
      } else {
        std::printf("%-20s %8.2f%% %7d", a.c_str(), 100.0 * s.attributes.at(a), s.scored.at(a));
      }
      for (const auto& [g, n] : s.group_sizes) std::printf(" %9.2f%%", 100.0 * s.by_group.at(g).at(a));
      std::printf("\n");
    }
    for (const auto& [k, v] : s.extra) std::printf("%-20s %8.2f%%   (extra: damaged plane per vehicle)\n", k.c_str(), 100.0 * v);
    std::printf("%-20s %9d", "cases", s.n);
    std::printf(" %7s", "");
    for (const auto& [g, n] : s.group_sizes) std::printf(" %10d", n);
    std::printf("\n");
    if (o->verbose) {
      for (const auto& m : s.pairings) std::printf("  %s\n", m.c_str());
      for (const auto& m : s.mismatches) std::printf("  %s\n", m.c_str());
    }
  });
}

}  // namespace accsim::cli
