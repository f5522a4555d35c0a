// Scenario suites: balanced train/test sets over the 12 family x vehicle
// count cells, every scenario dangerous (an ego holding its course
// collides) and avoidable (some simple manoeuvre avoids all contact).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accsim/env/crash_env.h"
#include "accsim/scenarios/scenario_families.h"

namespace accsim {

// The outcome of checking one candidate scenario.
struct ScenarioCheck {
  bool dangerous = false;          // the holding ego collides
  bool avoidable = false;          // some manoeuvre avoids every contact
  std::string avoiding_manoeuvre;  // the first one that did ("" if none)
  int episodes = 0;                // simulations run
};

// Simple ego manoeuvres for the avoidability search: full or half braking
// at several onsets, swerving a lane left or right, accelerating.
struct Manoeuvre {
  std::string name;
  std::function<std::array<float, 2>(const CrashEnv&)> policy;
};
std::vector<Manoeuvre> AvoidanceManoeuvres();

// Simulates the scenario under the holding ego, then (when dangerous) each
// manoeuvre until one avoids contact and stays on the road.
ScenarioCheck CheckScenario(const Scenario& scenario, const CrashEnvConfig& config = {});

struct SuiteOptions {
  int train = 4000;
  int test = 1000;
  uint64_t seed = 0;
  double test_fraction_of_reports = 0.25;  // reports reserved for the test suite
  int threads = 0;                         // 0 = hardware concurrency
  int max_attempts_per_scenario = 50;      // candidates tried per kept scenario before giving up on a cell
  std::function<void(int done, int total)> progress;  // called from worker threads, serialised
};

struct CellStats {
  ScenarioFamily family;
  VehicleCount count;
  int kept = 0;
  int dropped_unavoidable = 0;
  int dropped_harmless = 0;
  int build_failures = 0;
};

struct SuiteSplit {
  std::vector<Scenario> scenarios;   // cells interleaved, so any prefix is balanced
  std::vector<CellStats> cells;      // 12 cells
  std::vector<std::string> reports;  // source reports this split drew from
};

struct Suite {
  SuiteSplit train, test;
  double seconds = 0.0;
  double seconds_per_scenario = 0.0;
};

// Deterministic for (reports, options.seed), whatever options.threads.
// Throws std::invalid_argument when there are fewer than 2 reports.
Suite GenerateSuite(const std::vector<ReportSeed>& reports, const SuiteOptions& options);

// A report seed from a reconstructed (or any) scenario: road, surface,
// the ego as the struck vehicle and the first NPC as the striking one.
ReportSeed ReportSeedFromScenario(const Scenario& s);

// Writes DIR/train.jsonl, DIR/test.jsonl and DIR/stats.json (each atomically).
void WriteSuite(const Suite& suite, const std::string& dir, const SuiteOptions& options);
nlohmann::json StatsJson(const Suite& suite, const SuiteOptions& options);
// Reads a JSONL suite; errors name the file, the line and the field.
std::vector<Scenario> LoadSuite(const std::string& path);
// Scenario files (.json) and suites (.jsonl), in order, as shared scenarios
// for environments; throws std::invalid_argument when none are given.
std::vector<std::shared_ptr<const Scenario>> LoadScenarioSet(const std::vector<std::string>& paths);

}  // namespace accsim
