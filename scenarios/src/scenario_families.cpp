#include "accsim/scenarios/scenario_families.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "accsim/env/road_map.h"

namespace accsim {
namespace {

constexpr double kSampleDt = 0.1;     // [s] reference trajectory resolution
constexpr double kAfterConflict = 5.0;  // [s] scenario time past the planned conflict
constexpr double kStartClearance = 30.0;  // [m] road behind the ego's start

using SpeedProfile = std::function<double(double)>;

// A vehicle moving along `path` from arc length s0 with speed v(t); past the
// path's end it keeps its heading (Trajectory extrapolates).
Trajectory AlongPath(const Polyline& path, double s0, double duration, const SpeedProfile& v) {
  std::vector<TrajectoryPoint> pts;
  double s = s0;
  for (int k = 0; k * kSampleDt <= duration + 1e-9; ++k) {
    const double t = k * kSampleDt;
    const Vec2 p = path.PointAt(s);
    pts.push_back({t, p.x(), p.y(), path.HeadingAt(s), v(t)});
    s += 0.5 * (v(t) + v(t + kSampleDt)) * kSampleDt;
  }
  return Trajectory(std::move(pts));
}

// Arc length travelled by time t under profile v (trapezoidal, same as AlongPath).
double Distance(const SpeedProfile& v, double t) {
  double s = 0.0;
  for (double u = 0.0; u < t - 1e-12; u += kSampleDt) {
    const double h = std::min(kSampleDt, t - u);
    s += 0.5 * (v(u) + v(u + h)) * h;
  }
  return s;
}

SpeedProfile Constant(double v) {
  return [v](double) { return v; };
}

// Arc length along `a` of the first point within `gap` of polyline `b`.
double FirstApproach(const Polyline& a, const Polyline& b, double gap, double from_s) {
  for (double s = from_s; s <= a.length(); s += 0.05) {
    if (b.Project(a.PointAt(s)).distance < gap) return s;
  }
  throw std::invalid_argument("family: the conflict paths never meet");
}

double HalfLength(VehicleClass c) { return Params(c).length / 2.0; }

struct Builder {
  const FamilyParams& p;
  Scenario s;
  RoadMapSpec spec;
  double duration = 0.0;  // [s] scenario time limit

  explicit Builder(const FamilyParams& params) : p(params) {
    s.family = p.family;
    s.seed = p.seed;
    s.name = std::string(ToString(p.family)) + "_" + std::string(ToString(p.count)) + "_" +
             std::to_string(p.seed);
    duration = p.time_to_conflict + kAfterConflict;
    s.time_limit = duration;
    spec.lanes_per_direction = p.lanes_per_direction;
    spec.divided = p.divided;
    spec.speed_limit = p.speed_limit;
    spec.surface = p.surface;
  }

  void SetEgo(const Polyline& route, double s0) {
    const Vec2 start = route.PointAt(s0);
    s.ego.vehicle_class = p.ego_class;
    s.ego.start = Pose2{start.x(), start.y(), route.HeadingAt(s0)};
    s.ego.speed = p.ego_speed;
    s.ego.target_speed = p.ego_speed;
    std::vector<Vec2> pts{start};
    for (size_t i = 0; i < route.points().size(); ++i) {
      if (route.arc_lengths()[i] > s0 + 0.5) pts.push_back(route.points()[i]);
    }
    s.ego.route = Polyline(std::move(pts));
  }

  Scenario Finish() {
    s.map = spec;
    return s;
  }

  void AddNpc(const std::string& id, VehicleClass cls, Trajectory ref) {
    s.npcs.push_back({id, cls, std::move(ref), PostCollisionSource::kPhysics, {}});
  }

  // Two vehicles crash ahead on `path`: `wreck_a` waits stopped at arc length
  // `s_wreck`, `wreck_b` comes from behind at `v_b` and hits it at `t_hit`.
  // `min_start` keeps the second car clear of the ego at the start.
  void AddWreck(const Polyline& path, double s_wreck, double v_b, double t_hit, double min_start) {
    const VehicleClass a = VehicleClass::kCar, b = p.extra_class;
    const double s_b0 = s_wreck - HalfLength(a) - HalfLength(b) - v_b * t_hit;
    if (s_b0 < min_start) throw std::invalid_argument("wreck_lead: the wreck needs more road ahead");
    AddNpc("wreck_a", a, AlongPath(path, s_wreck, duration, Constant(0.0)));
    AddNpc("wreck_b", b, AlongPath(path, s_b0, duration, Constant(v_b)));
  }
};

Scenario StraightObstacle(const FamilyParams& p) {
  Builder b(p);
  const double travel = p.ego_speed * b.duration;
  b.spec.type = RoadType::kStraight;
  b.spec.length = std::clamp(2.0 * kStartClearance + travel + 60.0, 200.0, 2000.0);
  const RoadMap map(b.spec);
  const int idx = p.lanes_per_direction - 1;  // kerb lane
  const Polyline lane = map.lane(map.FindLane(Compass::kEast, false, idx)).centreline;
  const double s0 = kStartClearance;
  b.SetEgo(lane, s0);
  const double v_n = std::min(p.npc_speed, 0.6 * p.ego_speed);
  const double contact_gap = HalfLength(p.ego_class) + HalfLength(p.npc_class);
  if (p.count == VehicleCount::kMany) {
    // The wreck is the obstacle: a car runs into a stopped one ahead of the ego.
    const double v_b = p.ego_speed;
    const double t_hit = std::max(0.5, p.time_to_conflict - p.wreck_lead);
    const double s_wreck = s0 + p.ego_speed * p.time_to_conflict + contact_gap + 1.0;
    b.AddWreck(lane, s_wreck, v_b, t_hit, s0 + HalfLength(p.ego_class) + HalfLength(p.extra_class) + 1.0);
  } else {
    const double s_npc = s0 + contact_gap + (p.ego_speed - v_n) * p.time_to_conflict;
    b.AddNpc("obstacle", p.npc_class, AlongPath(lane, s_npc, b.duration, Constant(v_n)));
  }
  if (p.count != VehicleCount::kTwo) {
    // A car alongside that closes the escape lane: the next lane over, or
    // oncoming traffic on a single-lane road.
    if (p.lanes_per_direction > 1) {
      const Polyline next = map.lane(map.FindLane(Compass::kEast, false, idx - 1)).centreline;
      b.AddNpc("alongside", p.extra_class, AlongPath(next, s0 + 2.0, b.duration, Constant(p.ego_speed)));
    } else {
      const Polyline west = map.lane(map.FindLane(Compass::kWest, false, 0)).centreline;
      const double meet = b.spec.length - (s0 + p.ego_speed * p.time_to_conflict);
      const double v_o = p.speed_limit;
      b.AddNpc("oncoming", p.extra_class,
               AlongPath(west, std::max(0.0, meet - v_o * p.time_to_conflict), b.duration, Constant(v_o)));
    }
  }
  return b.Finish();
}

Scenario LaneChanging(const FamilyParams& p) {
  if (p.lanes_per_direction < 2) {
    throw std::invalid_argument("lanes_per_direction: lane changing needs at least 2 lanes");
  }
  Builder b(p);
  b.spec.type = RoadType::kStraight;
  b.spec.length = std::clamp(2.0 * kStartClearance + p.ego_speed * b.duration + 80.0, 200.0, 2000.0);
  const RoadMap map(b.spec);
  const int ego_idx = 0, npc_idx = 1;
  const Polyline ego_lane = map.lane(map.FindLane(Compass::kEast, false, ego_idx)).centreline;
  const Polyline npc_lane = map.lane(map.FindLane(Compass::kEast, false, npc_idx)).centreline;
  const double s0 = kStartClearance;
  b.SetEgo(ego_lane, s0);

  // The cut-in starts its lane change 2 s before the planned conflict, takes
  // 2.5 s, and brakes from the start of the change.
  const double T = p.time_to_conflict;
  const double t_lc = std::max(0.5, T - 2.0), t_lat = 2.5;
  const double v0 = p.npc_speed, decel = p.npc_decel, v_min = std::max(2.0, 0.3 * v0);
  const SpeedProfile v = [=](double t) { return t < t_lc ? v0 : std::max(v_min, v0 - decel * (t - t_lc)); };
  const double gap = HalfLength(p.ego_class) + HalfLength(p.npc_class);
  const Vec2 ego_start = ego_lane.PointAt(s0);
  const double x_npc0 = ego_start.x() + p.ego_speed * T - Distance(v, T) + gap;
  if (x_npc0 < ego_start.x() - 1.0) {
    throw std::invalid_argument("npc_speed: the cut-in would start behind the ego");
  }
  const double y_from = npc_lane.PointAt(0).y(), y_to = ego_lane.PointAt(0).y();
  std::vector<TrajectoryPoint> pts;
  double x = x_npc0;
  for (int k = 0; k * kSampleDt <= b.duration + 1e-9; ++k) {
    const double t = k * kSampleDt;
    const double u = std::clamp((t - t_lc) / t_lat, 0.0, 1.0);
    const double y = y_from + (y_to - y_from) * 0.5 * (1.0 - std::cos(kPi * u));
    const double vy = (u > 0.0 && u < 1.0) ? (y_to - y_from) * 0.5 * kPi * std::sin(kPi * u) / t_lat : 0.0;
    pts.push_back({t, x, y, std::atan2(vy, v(t)), std::hypot(v(t), vy)});
    x += 0.5 * (v(t) + v(t + kSampleDt)) * kSampleDt;
  }
  b.AddNpc("cut_in", p.npc_class, Trajectory(std::move(pts)));

  if (p.count != VehicleCount::kTwo) {
    // A car in the cut-in's lane beside the ego closes the escape to the right.
    b.AddNpc("alongside", p.extra_class, AlongPath(npc_lane, s0 - 8.0, b.duration, Constant(p.ego_speed)));
  }
  if (p.count == VehicleCount::kMany) {
    const double t_hit = std::max(0.5, T + 1.0 - p.wreck_lead);
    const double s_wreck = s0 + p.ego_speed * (T + 1.5) + 10.0;
    b.AddWreck(ego_lane, s_wreck, p.ego_speed + 2.0, t_hit, s0 + HalfLength(p.ego_class) + HalfLength(p.extra_class) + 1.0);
  }
  return b.Finish();
}

// The ego comes from the south and turns; the conflict NPC crosses its path.
Scenario Turning(const FamilyParams& p, bool left) {
  Builder b(p);
  b.spec.type = RoadType::kIntersection;
  const double T = p.time_to_conflict;
  // First with a nominal arm length, to find where the paths meet.
  auto build = [&](double arm_length) {
    b.spec.length = arm_length;
    return RoadMap(b.spec);
  };
  RoadMap map = build(100.0);
  const int lanes = p.lanes_per_direction;
  const int ego_idx = left ? 0 : lanes - 1;
  auto plan = [&](const RoadMap& m, Polyline& ego_route, Polyline& npc_path, int& exit_lane) {
    const int in = m.FindLane(Compass::kNorth, true, ego_idx);
    const int conn = m.FindConnector(in, left ? Turn::kLeft : Turn::kRight);
    exit_lane = m.lane(conn).to_lane;
    ego_route = m.RouteThrough({in, conn, exit_lane});
    const Compass npc_travel = left ? Compass::kSouth : Compass::kEast;
    const int npc_in = m.FindLane(npc_travel, true, left ? 0 : lanes - 1);
    const int npc_conn = m.FindConnector(npc_in, Turn::kStraight);
    npc_path = m.RouteThrough({npc_in, npc_conn, m.lane(npc_conn).to_lane});
  };
  Polyline ego_route, npc_path;
  int exit_lane = -1;
  plan(map, ego_route, npc_path, exit_lane);
  const double in_len = map.lane(map.FindLane(Compass::kNorth, true, ego_idx)).centreline.length();
  const double meet_gap = 0.5 * (Params(p.ego_class).width + Params(p.npc_class).width);
  double meet_ego = FirstApproach(ego_route, npc_path, meet_gap, 0.0) - in_len;  // past the inbound lane's end
  const double ego_reach = p.ego_speed * T;   // distance to the conflict
  const double npc_reach = p.npc_speed * (T + p.timing_offset);
  const double arm = std::clamp(std::max(ego_reach - meet_ego, npc_reach) + 40.0, 60.0, 2000.0);
  map = build(arm);
  plan(map, ego_route, npc_path, exit_lane);
  const double in_len2 = map.lane(map.FindLane(Compass::kNorth, true, ego_idx)).centreline.length();
  meet_ego = FirstApproach(ego_route, npc_path, meet_gap, std::max(0.0, in_len2 - 5.0));
  const double ego_s0 = meet_ego - ego_reach;
  if (ego_s0 < 0.0) throw std::invalid_argument("time_to_conflict: the ego would start off the map");
  b.SetEgo(ego_route, ego_s0);
  const double meet_npc = npc_path.Project(ego_route.PointAt(meet_ego)).s;
  const double npc_s0 = meet_npc - npc_reach;
  if (npc_s0 < 0.0) throw std::invalid_argument("npc_speed: the conflict NPC would start off the map");
  b.AddNpc(left ? "oncoming" : "crossing", p.npc_class, AlongPath(npc_path, npc_s0, b.duration, Constant(p.npc_speed)));

  if (p.count != VehicleCount::kTwo) {
    // A second car follows the conflict NPC, so the gap behind it is short too.
    const double s_follow = npc_s0 - p.npc_speed * p.extra_gap;
    if (s_follow >= 0.0) {
      b.AddNpc(left ? "oncoming_follower" : "crossing_follower", p.extra_class,
               AlongPath(npc_path, s_follow, b.duration, Constant(p.npc_speed)));
    } else {
      b.AddNpc(left ? "oncoming_follower" : "crossing_follower", p.extra_class,
               AlongPath(npc_path, 0.0, b.duration, Constant(p.npc_speed)));
    }
  }
  if (p.count == VehicleCount::kMany) {
    // Wreckage on the ego's exit lane, 25 m past the junction.
    const Polyline exit = map.lane(exit_lane).centreline;
    const double t_hit = std::max(0.5, T + 1.0 - p.wreck_lead);
    b.AddWreck(exit, std::min(exit.length() - 5.0, 25.0 + (p.ego_speed + 1.0) * t_hit), p.ego_speed + 1.0, t_hit, 0.0);
  }
  return b.Finish();
}

double Uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * (static_cast<double>(rng() >> 11) * 0x1.0p-53);
}

VehicleClass SampleClass(std::mt19937_64& rng, VehicleClass from_report) {
  // The report's class most of the time; otherwise the US fleet mix.
  if (Uniform(rng, 0, 1) < 0.7) return from_report;
  const double u = Uniform(rng, 0, 1);
  if (u < 0.45) return VehicleClass::kCar;
  if (u < 0.70) return VehicleClass::kSuv;
  if (u < 0.85) return VehicleClass::kPickup;
  if (u < 0.93) return VehicleClass::kVan;
  if (u < 0.97) return VehicleClass::kTruck;
  if (u < 0.985) return VehicleClass::kBus;
  return VehicleClass::kMotorcycle;
}

}  // namespace

std::string_view ToString(VehicleCount c) {
  switch (c) {
    case VehicleCount::kTwo: return "two";
    case VehicleCount::kThree: return "three";
    case VehicleCount::kMany: return "many";
  }
  return "unknown";
}

VehicleCount VehicleCountFromString(std::string_view name) {
  if (name == "two") return VehicleCount::kTwo;
  if (name == "three") return VehicleCount::kThree;
  if (name == "many") return VehicleCount::kMany;
  throw std::invalid_argument("vehicle count: unknown '" + std::string(name) + "' (expected two, three, many)");
}

Scenario BuildFamilyScenario(const FamilyParams& p) {
  if (!(p.ego_speed > 0.5 && p.ego_speed <= 40.0)) throw std::invalid_argument("ego_speed: must be in (0.5, 40] m/s");
  if (!(p.npc_speed >= 0.0 && p.npc_speed <= 40.0)) throw std::invalid_argument("npc_speed: must be in [0, 40] m/s");
  if (!(p.time_to_conflict >= 1.0 && p.time_to_conflict <= 20.0)) {
    throw std::invalid_argument("time_to_conflict: must be in [1, 20] s");
  }
  Scenario s;
  switch (p.family) {
    case ScenarioFamily::kStraightObstacle: s = StraightObstacle(p); break;
    case ScenarioFamily::kLaneChanging: s = LaneChanging(p); break;
    case ScenarioFamily::kUnprotectedLeftTurn: s = Turning(p, true); break;
    case ScenarioFamily::kRightTurn:
      if (p.npc_speed < 1.0) throw std::invalid_argument("npc_speed: the crossing car must move");
      s = Turning(p, false);
      break;
    default: throw std::invalid_argument("family: only the four SafeBench families can be built");
  }
  s.provenance = {{"source_report", p.source_id},
                  {"generator", "family"},
                  {"vehicle_count_cell", std::string(ToString(p.count))},
                  {"parameters",
                   {{"ego_speed", p.ego_speed},
                    {"npc_speed", p.npc_speed},
                    {"time_to_conflict", p.time_to_conflict},
                    {"timing_offset", p.timing_offset},
                    {"npc_decel", p.npc_decel},
                    {"extra_gap", p.extra_gap},
                    {"wreck_lead", p.wreck_lead}}}};
  return s;
}

FamilyParams SampleFamilyParams(ScenarioFamily family, VehicleCount count, const ReportSeed& seed,
                                std::mt19937_64& rng) {
  // Distributions (all uniform):
  //  speeds       the report's speed if stated, else speed limit x [0.8, 1.1]
  //               (ego) or [0.8, 1.2] (NPC); then x [0.9, 1.1]; in [4, 30] m/s
  //  surface      the report's 80 % of the time, else dry / wet / snow / ice
  //  classes      the report's 70 % of the time, else the US fleet mix
  //  lanes        the report's, in [1, 3] (lane changing: at least 2)
  //  timing       time to conflict [3.5, 5.5] s, NPC arrival offset [-0.3, 0.3] s
  //  obstacle     stopped half the time, else [0.2, 0.6] x the ego's speed
  //  cut-in       [0.9, 1.2] x the ego's speed, braking [3, 6] m/s^2; extras: headway [1.5, 3] s, wreck [1, 2] s ahead
  FamilyParams p;
  p.family = family;
  p.count = count;
  p.source_id = seed.source_id;
  p.seed = rng();
  p.speed_limit = std::clamp(seed.speed_limit, 5.0, 35.0);
  p.lanes_per_direction = std::clamp(seed.lanes_per_direction, 1, 3);
  if (family == ScenarioFamily::kLaneChanging) p.lanes_per_direction = std::max(2, p.lanes_per_direction);
  p.divided = seed.divided;
  if (Uniform(rng, 0, 1) < 0.8) {
    p.surface = seed.surface;
  } else {
    const Surface all[] = {Surface::kDry, Surface::kWet, Surface::kSnow, Surface::kIce};
    p.surface = all[static_cast<int>(Uniform(rng, 0, 4)) % 4];
  }
  p.ego_class = SampleClass(rng, seed.struck_class);
  p.npc_class = SampleClass(rng, seed.striking_class);
  p.extra_class = SampleClass(rng, VehicleClass::kCar);
  const double ego_base = seed.struck_speed > 0 ? seed.struck_speed : p.speed_limit * Uniform(rng, 0.8, 1.1);
  const double npc_base = seed.striking_speed > 0 ? seed.striking_speed : p.speed_limit * Uniform(rng, 0.8, 1.2);
  p.ego_speed = std::clamp(ego_base * Uniform(rng, 0.9, 1.1), 4.0, 30.0);
  p.npc_speed = std::clamp(npc_base * Uniform(rng, 0.9, 1.1), 4.0, 30.0);
  p.time_to_conflict = Uniform(rng, 3.5, 5.5);
  p.timing_offset = Uniform(rng, -0.3, 0.3);
  if (family == ScenarioFamily::kLaneChanging) {
    // A cut-in comes from slightly ahead, so it is at most a little faster.
    p.npc_speed = p.ego_speed * Uniform(rng, 0.9, 1.2);
  }
  if (family == ScenarioFamily::kStraightObstacle) {
    p.npc_speed = Uniform(rng, 0, 1) < 0.5 ? 0.0 : p.ego_speed * Uniform(rng, 0.2, 0.6);
  }
  p.npc_decel = Uniform(rng, 3.0, 6.0);
  p.extra_gap = Uniform(rng, 1.5, 3.0);
  p.wreck_lead = Uniform(rng, 1.0, 2.0);
  return p;
}

}  // namespace accsim
