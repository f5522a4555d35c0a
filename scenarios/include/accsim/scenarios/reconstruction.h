// Crash reconstruction: a CrashDescription planned (pre_collision_planner.h)
// and checked in Bullet, and the Scenario Reconstruction Rate (SRR) over a
// labelled folder.
//
// The check simulates every vehicle, the ego too, tracking its planned
// trajectory in the Bullet World. A reconstruction succeeds when the first
// contact is between the described vehicles, on the described striking and
// struck areas (a contact within 0.35 m of a face touches it; an undescribed
// area is not checked), within +-0.5 s of the planned impact time.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accsim/env/scenario.h"
#include "accsim/scenarios/crash_description.h"
#include "accsim/scenarios/pre_collision_planner.h"

namespace accsim {

struct ReconstructionCheck {
  bool success = false;
  std::string reason;        // why not, when it failed
  double contact_time = 0.0; // [s] first contact in Bullet
  double planned_time = 0.0; // [s] planned impact
  ImpactArea striker_face = ImpactArea::kUnknown, struck_face = ImpactArea::kUnknown;  // where Bullet touched
};

// Checks a plan (its trajectories and the described roles).
ReconstructionCheck CheckReconstruction(const PlannedCrash& plan);
// Checks a saved reconstructed scenario from its provenance (ego_reference,
// planned_impact_time, striker/struck and their areas); throws
// std::invalid_argument naming the field when the scenario is not one.
ReconstructionCheck CheckReconstructedScenario(const Scenario& s);

struct Reconstruction {
  PlannedCrash plan;
  ReconstructionCheck check;
};
// Algorithm 1 with the Bullet check as the acceptance test: the first lane
// combination whose simulation meets the criteria. Throws
// std::invalid_argument (naming the field) when nothing can be planned.
Reconstruction Reconstruct(const CrashDescription& d, uint64_t seed = 0, const PlannerConfig& config = {});

enum class DescriptionSource { kLabels, kNarrative };

struct SrrReport {
  // By road type (intersection, t_junction, straight). Single-vehicle
  // crashes are reconstructed against a stationary obstacle and counted in
  // `attempted` like the others; `single_vehicle` says how many there were.
  std::map<std::string, int> attempted, succeeded, single_vehicle;
  std::vector<std::string> failures;  // "case: reason"
  int n = 0;
  double Rate(const std::string& road) const;
  // Reconstructs what `describe` returns with `seed` and counts it under
  // `group`; a failure (or a description that cannot be made) is recorded
  // as "id: reason".
  void Tally(const std::string& group, const std::string& id, uint64_t seed,
             const std::function<CrashDescription()>& describe);
};
// Reconstructs every case of a labelled folder (labels.jsonl, NMVCCS or
// CIREN layout). The road type comes from the labels (the folder for
// NMVCCS); the rest from the investigators' codes or the extracted narrative.
SrrReport EvaluateReconstruction(const std::string& dir, DescriptionSource from, uint64_t seed = 0);
nlohmann::json ToJson(const SrrReport& r);

// Described crash configurations for a sweep (reconstruction_sweep.cpp):
// every road type and crash type with the movements and damaged areas a
// report of that type gives; vehicle classes rotated by `seed`; directions
// and speeds left open for the planner's seeded draws.
std::vector<CrashDescription> SweepDescriptions(uint64_t seed);
// Reconstructs SweepDescriptions(s) for seeds first_seed .. first_seed +
// seeds - 1, with seed s; rates grouped "road/crash_type".
SrrReport SweepReconstruction(uint64_t first_seed, int seeds);

}  // namespace accsim
