// Crash reconstruction (AccidentSim Algorithm 1, condensed): from what a
// report says to two timed trajectories that meet as described, then a
// Bullet check that they really do.
//
//  Phase 1  the impact configuration from the crash type, movements and
//           damage areas (who strikes whom, with which faces, at what
//           approach angle) and the speeds (stated, else from the limit);
//  Phase 2  the map the report describes (road type, lanes, limit,
//           surface) and, per vehicle, the lanes its direction and
//           manoeuvre allow (through lanes, turn connectors);
//  Phase 3  paths along those lanes, with OMPL Dubins curves where a
//           vehicle leaves its lane (lane changes, drifting over the centre
//           line); constant-speed timing so both reach the impact together
//           at T = 5 s; the imminent-collision state S at T.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accsim/env/scenario.h"
#include "accsim/scenarios/accident_record.h"

namespace accsim {

// The planner's input: a normalised view of an AccidentRecord (or of
// investigators' codes).
struct CrashDescription {
  std::string source_id;
  RoadType road = RoadType::kStraight;
  int lanes_per_direction = 1;
  bool divided = false;
  double speed_limit = 13.41;  // [m/s]
  Surface surface = Surface::kDry;
  CrashType type = CrashType::kUnknown;
  int striker = 1, struck = 2;  // 1-based vehicle numbers
  DamageArea striker_area = DamageArea::kFront, struck_area = DamageArea::kUnknown;
  struct Vehicle {
    VehicleClass cls = VehicleClass::kCar;
    Movement movement = Movement::kStraight;
    double speed = 0.0;  // [m/s]; 0 = unknown
  };
  std::vector<Vehicle> vehicles;
};

// Throws std::invalid_argument naming the field when the record cannot be
// planned (no vehicles, contradictory roles).
CrashDescription DescriptionFromRecord(const AccidentRecord& r, std::optional<RoadType> road = std::nullopt);

struct ImminentCollisionState {
  double time = 0.0;  // [s]
  struct Body {
    std::string id;
    Pose2 pose;
    Vec2 velocity = Vec2::Zero();
    double yaw_rate = 0.0;
  };
  std::vector<Body> bodies;
};

struct Reconstruction {
  Scenario scenario;             // the struck vehicle is the ego
  ImminentCollisionState state;  // planned, at the impact
  std::string striker_id, struck_id;
  DamageArea striker_area = DamageArea::kUnknown, struck_area = DamageArea::kUnknown;  // as described
};

// Throws std::invalid_argument with the reason when the crash cannot be
// planned (e.g. "type: single-vehicle crashes are not reconstructed").
Reconstruction PlanReconstruction(const CrashDescription& d, uint64_t seed = 0);

struct ReconstructionCheck {
  bool success = false;
  std::string reason;        // why not, when it failed
  double contact_time = 0.0;
  DamageArea striker_face = DamageArea::kUnknown, struck_face = DamageArea::kUnknown;
};

// Simulates every vehicle tracking its planned trajectory in Bullet; success
// when the first contact is between the described vehicles, on the
// described faces, within +-0.5 s of the planned impact.
ReconstructionCheck CheckReconstruction(const Reconstruction& r);

struct SrrReport {
  std::map<std::string, int> attempted, succeeded;  // by road type
  std::vector<std::string> failures;                // "case: reason"
  int n = 0;
};
// Reconstructs every case of a labelled folder (labels.jsonl); the road type
// comes from the case's folder (crossing/, t/, straight/), the rest from the
// extracted narrative (from_labels = false) or the investigators' codes.
SrrReport EvaluateReconstruction(const std::string& dir, bool from_labels);
nlohmann::json ToJson(const SrrReport& r);

}  // namespace accsim
