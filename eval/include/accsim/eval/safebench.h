// SafeBench-style evaluation: run a driver over a suite and report the
// metrics per scenario family and vehicle count (the paper's 12 cells).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accsim/env/rollout.h"

namespace accsim {

// Metrics of one group of episodes (SafeBench names in brackets).
struct SafetyMetrics {
  int episodes = 0;
  double collision_rate = 0.0;      // [CR] fraction of episodes whose ego collided
  double off_road_rate = 0.0;       // fraction that left the drivable area
  double route_completion = 0.0;    // [RC] mean fraction of the route driven
  double goal_rate = 0.0;           // fraction that reached the end of the route
  double mean_min_ttc = 0.0;        // [s] mean over episodes of the smallest TTC (capped at 10 s)
  double mean_collision_speed = 0.0;  // [m/s] mean relative speed of the collisions
  double mean_return = 0.0;
};

struct EvaluationReport {
  std::string driver;
  SafetyMetrics overall;
  // Keyed by "family/vehicle_count", e.g. "right_turn/three".
  std::map<std::string, SafetyMetrics> cells;
};

// "two", "three" or "many" for a scenario (from its provenance when the
// generator recorded it, else from its vehicle count).
std::string VehicleCountCell(const Scenario& s);

// Runs `policy` once on every scenario (seed = scenario index).
EvaluationReport Evaluate(const std::vector<std::shared_ptr<const Scenario>>& scenarios, const PolicyFn& policy,
                          const std::string& driver_name, const CrashEnvConfig& config = {});

nlohmann::json ToJson(const EvaluationReport& r);
// A Markdown table: one row per cell plus the overall row.
std::string ToMarkdown(const std::vector<EvaluationReport>& reports);

}  // namespace accsim
