// The four SafeBench-style scenario families, each with two, three or many
// vehicles (12 cells), built parametrically on the environment's road maps.
//
// Every family puts the ego on a route and times one "conflict" NPC so that
// an ego holding its speed meets it; the extra vehicles of the larger cells
// narrow the ego's escape (a car alongside, a follower) and, in the "many"
// cell, two other vehicles crash ahead of the ego so that their wreckage
// blocks its way.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "accsim/env/scenario.h"

namespace accsim {

enum class VehicleCount { kTwo, kThree, kMany };
std::string_view ToString(VehicleCount c);
VehicleCount VehicleCountFromString(std::string_view name);  // "two", "three", "many"

// What a real crash report contributes to the scenarios it seeds.
struct ReportSeed {
  std::string source_id;             // report identifier, recorded in provenance
  double speed_limit = 13.89;        // [m/s]
  int lanes_per_direction = 2;
  bool divided = false;
  Surface surface = Surface::kDry;
  VehicleClass struck_class = VehicleClass::kCar;    // becomes the ego
  VehicleClass striking_class = VehicleClass::kCar;  // becomes the conflict NPC
  double struck_speed = 0.0;         // [m/s]; 0 = unknown
  double striking_speed = 0.0;       // [m/s]; 0 = unknown
};

// Everything that decides one scenario of a family.
struct FamilyParams {
  ScenarioFamily family = ScenarioFamily::kStraightObstacle;
  VehicleCount count = VehicleCount::kTwo;
  std::string source_id;
  uint64_t seed = 0;
  // Road.
  int lanes_per_direction = 2;
  bool divided = false;
  double speed_limit = 13.89;  // [m/s]
  Surface surface = Surface::kDry;
  // Ego and the conflict NPC.
  VehicleClass ego_class = VehicleClass::kCar;
  double ego_speed = 12.0;           // [m/s]
  double time_to_conflict = 4.0;     // [s] for an ego holding its speed
  VehicleClass npc_class = VehicleClass::kCar;
  double npc_speed = 10.0;           // [m/s] (straight obstacle: 0 = stopped)
  double timing_offset = 0.0;        // [s] NPC arrival at the conflict minus the ego's
  double npc_decel = 4.0;            // [m/s^2] lane changing: the cut-in's braking
  // Extra vehicles.
  VehicleClass extra_class = VehicleClass::kSuv;
  double extra_gap = 2.0;            // [s] time headway of extra vehicles
  double wreck_lead = 1.5;           // [s] the NPC crash happens this long before the ego arrives
};

// Builds the scenario; throws std::invalid_argument naming the parameter
// when it cannot be built (e.g. lane changing with one lane).
Scenario BuildFamilyScenario(const FamilyParams& p);

// Draws the parameters of one scenario of a cell around a real report:
// its road, surface and vehicle classes, and speeds near its speeds, with
// timing and distances from documented ranges (see the .cpp).
FamilyParams SampleFamilyParams(ScenarioFamily family, VehicleCount count, const ReportSeed& seed,
                                std::mt19937_64& rng);

}  // namespace accsim
