// accsim reconstruct / eval-reconstruction: narrative -> planned crash -> Bullet check.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>

#include "accsim/scenarios/narrative_extractor.h"
#include "accsim/scenarios/reconstruction.h"
#include "commands.h"

namespace accsim::cli {

void AddReconstructCommands(CLI::App& app) {
  struct Options {
    std::string input, out, road;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* rec = app.add_subcommand(
      "reconstruct", "Narrative -> AccidentRecord -> planned pre-collision trajectories -> Bullet check -> scenario JSON");
  rec->add_option("narrative", o->input, "Narrative text file, or - for standard input")->required();
  rec->add_option("-o,--out", o->out, "Write the reconstructed scenario here")->required();
  rec->add_option("--road", o->road, "Override the road type: straight, intersection, t_junction")
      ->check(CLI::IsMember({"straight", "intersection", "t_junction"}));
  rec->add_flag("--json", o->json, "Print the outcome as JSON");
  rec->callback([o] {
    std::string text;
    if (o->input == "-") {
      text.assign(std::istreambuf_iterator<char>(std::cin), {});
    } else {
      std::ifstream in(o->input, std::ios::binary);
      if (!in) throw UsageError(o->input + ": cannot open file");
      std::stringstream ss;
      ss << in.rdbuf();
      text = ss.str();
    }
    const AccidentRecord record = NarrativeExtractor{}.Extract(text);
    std::optional<RoadType> road;
    if (!o->road.empty()) road = RoadTypeFromString(o->road);
    CrashDescription d = DescriptionFromRecord(record, road);
    d.source_id = o->input;
    const Reconstruction r = PlanReconstruction(d);
    const ReconstructionCheck c = CheckReconstruction(r);
    SaveJsonFile(ToJson(r.scenario), o->out);
    if (o->json) {
      std::cout << nlohmann::json{{"success", c.success}, {"reason", c.reason}, {"contact_time", c.contact_time},
                                  {"planned_impact_time", r.state.time}, {"crash_type", std::string(ToString(d.type))},
                                  {"out", o->out}}
                       .dump()
                << "\n";
      return;
    }
    std::printf("crash type  %s, %s strikes %s\n", std::string(ToString(d.type)).c_str(), r.striker_id.c_str(),
                r.struck_id.c_str());
    std::printf("planned     impact at %.2f s\n", r.state.time);
    std::printf("check       %s%s%s\n", c.success ? "reconstructed" : "FAILED", c.success ? "" : ": ",
                c.reason.c_str());
    std::printf("saved       %s\n", o->out.c_str());
  });

  struct EvalOptions {
    std::string dir;
    std::string from = "labels";
    bool json = false;
    bool verbose = false;
  };
  auto e = std::make_shared<EvalOptions>();
  CLI::App* eval = app.add_subcommand(
      "eval-reconstruction", "Scenario Reconstruction Rate per road type on a labelled folder (NMVCCS layout)");
  eval->add_option("dir", e->dir, "Folder holding labels.jsonl")->required()->check(CLI::ExistingDirectory);
  eval->add_option("--from", e->from, "Describe each crash from the investigators' codes (labels) or the extracted narrative")
      ->check(CLI::IsMember({"labels", "narrative"}))
      ->capture_default_str();
  eval->add_flag("--json", e->json, "Print the rates as JSON");
  eval->add_flag("--verbose", e->verbose, "List the reason for each failure");
  eval->callback([e] {
    const SrrReport r = EvaluateReconstruction(e->dir, e->from == "labels");
    if (e->json) {
      std::cout << ToJson(r).dump(2) << "\n";
      return;
    }
    std::printf("SRR from %s (%d cases)\n", e->from.c_str(), r.n);
    for (const auto& [road, n] : r.attempted) {
      const int ok = r.succeeded.count(road) ? r.succeeded.at(road) : 0;
      std::printf("  %-14s %6.2f%%  (%d of %d)\n", road.c_str(), 100.0 * ok / n, ok, n);
    }
    if (e->verbose) {
      for (const auto& f : r.failures) std::printf("  %s\n", f.c_str());
    }
  });
}

}  // namespace accsim::cli
