// accsim reconstruct / eval-reconstruction: narrative (or description) ->
// planned crash -> Bullet check -> scenario JSON; SRR over a labelled folder.
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

void AddReconstructCommands(CLI::App& app) {
  struct Options {
    std::string input, out, road, description_out;
    bool json = false, description = false;
    uint64_t seed = 0;
  };
  auto o = std::make_shared<Options>();
  CLI::App* rec = app.add_subcommand(
      "reconstruct", "Narrative -> AccidentRecord -> planned pre-collision trajectories -> Bullet check -> scenario JSON");
  rec->add_option("narrative", o->input, "Narrative text file (or a crash description JSON with --description), - for stdin")
      ->required();
  rec->add_option("-o,--out", o->out, "Write the reconstructed scenario here")->required();
  rec->add_option("--road", o->road, "Override the road type: straight, intersection, t_junction")
      ->check(CLI::IsMember({"straight", "intersection", "t_junction"}));
  rec->add_flag("--description", o->description, "The input is a crash description (JSON), not a narrative");
  rec->add_option("--description-out", o->description_out, "Also write the filled crash description (JSON) here");
  rec->add_option("--seed", o->seed, "Seed for attributes the report leaves open")->capture_default_str();
  rec->add_flag("--json", o->json, "Print the outcome as JSON");
  rec->callback([o] {
    const std::string text = ReadInput(o->input);
    std::optional<RoadType> road;
    if (!o->road.empty()) road = RoadTypeFromString(o->road);
    CrashDescription d;
    if (o->description) {
      nlohmann::json j;
      try {
        j = nlohmann::json::parse(text);
      } catch (const nlohmann::json::exception& e) {
        throw UsageError(o->input + ": not JSON (" + e.what() + ")");
      }
      d = CrashDescriptionFromJson(j);
      if (road) d.road.type.Set(*road, Provenance::kStated);
    } else {
      d = FromAccidentRecord(NarrativeExtractor{}.Extract(text), road);
    }
    if (d.source_id.empty()) d.source_id = o->input;
    const Reconstruction r = Reconstruct(d, o->seed);
    SaveJsonFile(ToJson(r.plan.scenario), o->out);
    if (!o->description_out.empty()) SaveJsonFile(ToJson(r.plan.impact.description), o->description_out);
    const ReconstructionCheck& c = r.check;
    if (o->json) {
      std::cout << nlohmann::json{{"success", c.success},
                                  {"reason", c.reason},
                                  {"contact_time", c.contact_time},
                                  {"planned_impact_time", r.plan.state.time},
                                  {"crash_type", std::string(ToString(r.plan.impact.type))},
                                  {"striker", r.plan.striker_id},
                                  {"struck", r.plan.struck_id},
                                  {"combination", r.plan.combination},
                                  {"imminent_collision_state", ToJson(r.plan.state)},
                                  {"notes", r.plan.impact.description.notes},
                                  {"warnings", r.plan.impact.description.warnings},
                                  {"out", o->out}}
                       .dump()
                << "\n";
      return;
    }
    std::printf("crash type  %s, %s strikes %s\n", std::string(ToString(r.plan.impact.type)).c_str(),
                r.plan.striker_id.c_str(), r.plan.struck_id.c_str());
    std::printf("paths       %s\n", r.plan.combination.c_str());
    std::printf("planned     impact at %.2f s\n", r.plan.state.time);
    for (const auto& b : r.plan.state.bodies) {
      std::printf("  %-4s x %7.2f  y %7.2f  yaw %6.3f  v %5.2f m/s  yaw rate %6.3f rad/s\n", b.id.c_str(), b.pose.x,
                  b.pose.y, b.pose.yaw, b.velocity.norm(), b.yaw_rate);
    }
    for (const auto& w : r.plan.impact.description.warnings) std::printf("warning     %s\n", w.c_str());
    for (const auto& n : r.plan.impact.description.notes) std::printf("note        %s\n", n.c_str());
    std::printf("check       %s%s%s\n", c.success ? "reconstructed" : "FAILED", c.success ? "" : ": ",
                c.reason.c_str());
    std::printf("saved       %s\n", o->out.c_str());
  });

  struct EvalOptions {
    std::string dir;
    std::string from = "labels";
    bool json = false;
    bool verbose = false;
    uint64_t seed = 0;
  };
  auto e = std::make_shared<EvalOptions>();
  CLI::App* eval = app.add_subcommand(
      "eval-reconstruction", "Scenario Reconstruction Rate per road type on a labelled folder (NMVCCS or CIREN layout)");
  eval->add_option("dir", e->dir, "Folder holding labels.jsonl")->required()->check(CLI::ExistingDirectory);
  eval->add_option("--from", e->from, "Describe each crash from the investigators' codes (labels) or the extracted narrative")
      ->check(CLI::IsMember({"labels", "narrative"}))
      ->capture_default_str();
  eval->add_option("--seed", e->seed, "Seed for attributes the reports leave open")->capture_default_str();
  eval->add_flag("--json", e->json, "Print the rates as JSON");
  eval->add_flag("--verbose", e->verbose, "List the reason for each failure");
  eval->callback([e] {
    const SrrReport r = EvaluateReconstruction(
        e->dir, e->from == "labels" ? DescriptionSource::kLabels : DescriptionSource::kNarrative, e->seed);
    if (e->json) {
      std::cout << ToJson(r).dump(2) << "\n";
      return;
    }
    std::printf("SRR from %s (%d cases)\n", e->from.c_str(), r.n);
    for (const auto& [road, n] : r.attempted) {
      const int ok = r.succeeded.count(road) ? r.succeeded.at(road) : 0;
      std::printf("  %-14s %6.2f%%  (%d of %d)\n", road.c_str(), 100.0 * r.Rate(road), ok, n);
    }
    for (const auto& [road, n] : r.single_vehicle) {
      std::printf("  %-14s %d single-vehicle crash(es) among them, against a stationary obstacle\n", road.c_str(), n);
    }
    if (e->verbose || r.failures.size() <= 10) {
      for (const auto& f : r.failures) std::printf("  %s\n", f.c_str());
    }
  });

  struct SweepOptions {
    uint64_t seed = 0;
    int seeds = 4;
    bool json = false, verbose = false;
  };
  auto w = std::make_shared<SweepOptions>();
  CLI::App* sweep = app.add_subcommand(
      "sweep-reconstruction",
      "Reconstruct described crash configurations no report set covers in full: every road type x crash type with "
      "the movements and damaged areas such reports give, vehicle classes rotated by seed, directions and speeds "
      "drawn; the rate per road type and crash type");
  sweep->add_option("--seed", w->seed, "First seed")->capture_default_str();
  sweep->add_option("--seeds", w->seeds, "Number of seeds (each one sweeps every configuration)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  sweep->add_flag("--json", w->json, "Print the rates as JSON");
  sweep->add_flag("--verbose", w->verbose, "List the reason for each failure");
  sweep->callback([w] {
    const SrrReport r = SweepReconstruction(w->seed, w->seeds);
    if (w->json) {
      std::cout << ToJson(r).dump(2) << "\n";
      return;
    }
    int ok_all = 0;
    std::printf("Reconstruction sweep, seeds %llu..%llu (%d descriptions)\n",
                static_cast<unsigned long long>(w->seed), static_cast<unsigned long long>(w->seed + w->seeds - 1), r.n);
    for (const auto& [group, n] : r.attempted) {
      const int ok = r.succeeded.count(group) ? r.succeeded.at(group) : 0;
      ok_all += ok;
      std::printf("  %-40s %6.2f%%  (%d of %d)\n", group.c_str(), 100.0 * r.Rate(group), ok, n);
    }
    std::printf("  %-40s %6.2f%%  (%d of %d)\n", "all", r.n ? 100.0 * ok_all / r.n : 0.0, ok_all, r.n);
    if (w->verbose || r.failures.size() <= 10) {
      for (const auto& f : r.failures) std::printf("  %s\n", f.c_str());
    }
  });
}

}  // namespace accsim::cli
