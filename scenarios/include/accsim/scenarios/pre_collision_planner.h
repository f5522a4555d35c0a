// Pre-collision planning, AccidentSim Algorithm 1 (§III-B): from a
// CrashDescription to timed trajectories that bring the described vehicles
// together with the described areas, and the imminent-collision state S.
//
//  Phase 1  ResolveImpact: fill what the description leaves open (seeded
//           draws, each recorded in `notes`), the crash type, the physical
//           roles (the front that strikes), the approach angle, and the
//           speeds at the start and at the impact.
//  Phase 2  GatherLaneCombinations: the map the description names and, per
//           vehicle, lane paths compatible with its direction and manoeuvre
//           (through lanes, turn connectors, OMPL Dubins curves where it
//           leaves its lane: lane changes, drifts over the centre line),
//           with the arc length at which it is at the impact.
//  Phase 3  TimeParameterise: jerk-limited speed profiles so every vehicle
//           is at its impact pose at the same time; validation (on the
//           drivable area, kinematic limits, the first footprint overlap is
//           the described pair with the described faces); S at the impact.
//
// PreCollisionPlanner::Plan runs the phases and keeps the first lane
// combination that passes validation and the caller's acceptance test
// (the Bullet reconstruction check, see reconstruction.h). Deterministic:
// the same description and seed give the same plan.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "accsim/env/road_map.h"
#include "accsim/env/scenario.h"
#include "accsim/env/trajectory.h"
#include "accsim/scenarios/crash_description.h"

namespace accsim {

struct PlannerConfig {
  double impact_time = 5.0;        // [s] planned time from the scenario start to the impact
  double after_impact = 3.0;       // [s] references continue this long past the impact
  double dt = 0.05;                // [s] reference sample period
  double max_accel = 2.5;          // [m/s^2] planned acceleration (capped by 0.5 mu g)
  double max_decel = 6.0;          // [m/s^2] planned braking (capped by 0.8 mu g)
  double max_jerk = 6.0;           // [m/s^3]
  double max_lateral_accel = 4.0;  // [m/s^2] (capped by 0.8 mu g)
  double min_turn_radius = 12.0;   // [m] smallest Dubins radius for lane changes and drifts
  double pull_away_speed = 4.0;    // [m/s] a vehicle coded stopped in a junction crash crosses at this speed
  double min_approach_time = 1.5;  // [s] the vehicles may not touch before this
};

// Phase 1 output.
struct ImpactConfiguration {
  CrashDescription description;  // every attribute filled; `notes` say what was inferred or drawn
  CrashType type = CrashType::kUnknown;  // resolved
  int striker = 0, struck = 1;   // vehicle indices of the physical roles: the striker's front hits
  bool roles_swapped = false;    // the description names the other vehicle as the striker
  bool obstacle = false;         // single-vehicle crash: the struck object is the last body (id kObjectId)
  bool across_lane = false;      // angle crash off any junction: the struck vehicle stands across the striker's lane
  ImpactArea striker_area = ImpactArea::kFront, struck_area = ImpactArea::kUnknown;  // physical roles' areas
  double approach_angle = 0.0;   // [rad] struck heading minus striker heading at impact (0 rear-end, pi head-on)
  std::vector<double> start_speed;   // [m/s] per vehicle, at t = 0
  std::vector<double> impact_speed;  // [m/s] per vehicle, at the impact
};

// Throws std::invalid_argument naming the field when the description is
// invalid (Validate) or names no vehicle. A single-vehicle crash
// (CrashDescription::SingleVehicle) gets the struck object as a stationary
// body, appended to the vehicles with id kObjectId.
ImpactConfiguration ResolveImpact(const CrashDescription& d, uint64_t seed, const PlannerConfig& config = {});

// Phase 2 output: one way for the vehicles to meet.
struct VehiclePath {
  Polyline path;         // in the direction of travel, long enough for the whole reference
  double impact_s = 0;   // [m] arc length of the vehicle's centre at the impact
  std::string lanes;     // what the path follows, for reports ("north inbound 0 -> left connector")
  bool leaves_lane = false;  // part of the path is an OMPL Dubins curve off the lane centrelines
  bool off_road = false;     // a roadside departure or object: not held to the drivable area
  bool reverse = false;      // driven rear first (backing): heading against the path, speed negative
};
struct LaneCombination {
  RoadMapSpec map;
  std::vector<VehiclePath> paths;  // per vehicle of the description
  double striker_shift = 0.0;      // [s] the striker arrives this much later than nominal
  std::string label;
};

std::vector<LaneCombination> GatherLaneCombinations(const ImpactConfiguration& c, const PlannerConfig& config = {});

struct ImminentCollisionState {
  double time = 0.0;  // [s] planned impact time (first footprint overlap)
  struct Body {
    std::string id;
    Pose2 pose;
    Vec2 velocity = Vec2::Zero();  // [m/s] world frame
    double yaw_rate = 0.0;         // [rad/s]
  };
  std::vector<Body> bodies;  // every vehicle, in description order
};
nlohmann::json ToJson(const ImminentCollisionState& s);

// The face of a vehicle's box (centre `pose`) a world point lies on.
ImpactArea FaceAt(const Vec2& point, const Pose2& pose, VehicleClass cls);
// Whether a contact at `point` touches `area`: on one of its faces, or within
// 0.35 m of one (a corner hit counts for both of its faces).
bool TouchesArea(const Vec2& point, const Pose2& pose, VehicleClass cls, ImpactArea area);

struct PlannedCrash {
  Scenario scenario;  // family reconstructed; ego = the described struck vehicle
  ImminentCollisionState state;
  ImpactConfiguration impact;
  std::vector<std::string> ids;          // per vehicle of the description
  std::vector<VehicleClass> classes;
  std::vector<Trajectory> trajectories;  // planned references, per vehicle (the ego's too)
  std::string striker_id, struck_id;     // as described (checked by the reconstruction check)
  ImpactArea striker_area = ImpactArea::kUnknown, struck_area = ImpactArea::kUnknown;  // as described
  std::string combination;               // the lane combination's label
  double peak_lateral_accel = 0.0, peak_accel = 0.0, peak_jerk = 0.0;  // [m/s^2], [m/s^3] as planned
};

// Throws std::invalid_argument with the reason when the combination fails
// validation ("plan: V1 leaves the drivable area at 2.35 s").
PlannedCrash TimeParameterise(const ImpactConfiguration& c, const LaneCombination& combination,
                              const PlannerConfig& config = {}, uint64_t seed = 0);

class PreCollisionPlanner {
 public:
  // Returns "" to accept a plan, else the reason it is rejected.
  using Acceptor = std::function<std::string(const PlannedCrash&)>;

  explicit PreCollisionPlanner(PlannerConfig config = {}) : config_(config) {}
  const PlannerConfig& config() const { return config_; }

  // Algorithm 1. Throws std::invalid_argument naming the field or, when no
  // combination passes, listing why the first ones failed.
  PlannedCrash Plan(const CrashDescription& d, uint64_t seed = 0, const Acceptor& accept = {}) const;

 private:
  PlannerConfig config_;
};

}  // namespace accsim
