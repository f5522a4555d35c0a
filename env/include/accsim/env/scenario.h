// A scenario as data: the map, the ego's start and route, the NPCs'
// reference trajectories and what happens to them after contact. Stored as
// versioned JSON; the loader validates every field and names the offending
// one ("npcs[1].reference[3].t: times must be strictly increasing").
#pragma once

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "accsim/env/geometry.h"
#include "accsim/env/physical_tables.h"
#include "accsim/env/road_map.h"
#include "accsim/env/trajectory.h"

namespace accsim {

constexpr int kScenarioSchemaVersion = 1;

enum class ScenarioFamily { kStraightObstacle, kUnprotectedLeftTurn, kRightTurn, kLaneChanging, kReconstructed };
std::string_view ToString(ScenarioFamily f);
ScenarioFamily ScenarioFamilyFromString(std::string_view name);  // throws naming "family"

enum class PostCollisionSource { kPhysics, kPredicted };

struct EgoSpec {
  std::string id = "ego";
  VehicleClass vehicle_class = VehicleClass::kCar;
  Pose2 start;                // chassis centre
  double speed = 0.0;         // [m/s] initial speed along the heading
  double target_speed = 0.0;  // [m/s] what a speed-holding driver keeps (defaults to speed)
  Polyline route;             // from near the start to the goal, in travel order
};

struct NpcSpec {
  std::string id;
  VehicleClass vehicle_class = VehicleClass::kCar;
  Trajectory reference;  // followed until the NPC's first contact
  PostCollisionSource post_collision = PostCollisionSource::kPhysics;
  Trajectory predicted;  // replayed after first contact when post_collision == kPredicted
};

struct Scenario {
  std::string name;
  ScenarioFamily family = ScenarioFamily::kReconstructed;
  uint64_t seed = 0;
  double time_limit = 15.0;  // [s]
  RoadMapSpec map;
  EgoSpec ego;
  std::vector<NpcSpec> npcs;
  nlohmann::json provenance = nlohmann::json::object();  // source report, generator, parameters

  int vehicle_count() const { return 1 + static_cast<int>(npcs.size()); }
};

// Throws FieldError (a std::invalid_argument) naming the field and reason.
Scenario ScenarioFromJson(const nlohmann::json& j);
nlohmann::json ToJson(const Scenario& s);
RoadMapSpec RoadMapSpecFromJson(const nlohmann::json& j, const std::string& path);
nlohmann::json ToJson(const RoadMapSpec& m);
Trajectory TrajectoryFromJson(const nlohmann::json& j, const std::string& path);
nlohmann::json ToJson(const Trajectory& t);

// Reads and validates a scenario file; errors name the file, then the field.
Scenario LoadScenarioFile(const std::string& path);
// Writes atomically (temporary file + rename) so a failure never leaves a
// half-written file where a good one was.
void SaveJsonFile(const nlohmann::json& j, const std::string& path, int indent = 2);

}  // namespace accsim
