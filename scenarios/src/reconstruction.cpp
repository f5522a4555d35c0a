#include "accsim/scenarios/reconstruction.h"

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/DubinsStateSpace.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <stdexcept>

#include "accsim/env/road_map.h"
#include "accsim/env/world.h"
#include "accsim/scenarios/narrative_extractor.h"

namespace accsim {
namespace {

constexpr double kImpactTime = 5.0;     // [s] nominal time of the impact
constexpr double kAfterImpact = 3.0;    // [s] reference beyond the impact
constexpr double kDt = 0.05;            // [s] reference resolution
constexpr double kTimeTolerance = 0.5;  // [s] Bullet contact vs planned impact
constexpr double kFaceTolerance = 0.35; // [m] a contact this close to a face touches it
constexpr double kDubinsRadius = 40.0;  // [m] lane changes at urban speeds

using Profile = std::function<double(double)>;

double HalfLength(VehicleClass c) { return Params(c).length / 2; }

// Constant speed along `path` so that arc length `s_at_impact` is reached at
// kImpactTime; a stopped vehicle stays there.
Trajectory Timed(const Polyline& path, double s_at_impact, double v) {
  std::vector<TrajectoryPoint> pts;
  const double s0 = s_at_impact - v * kImpactTime;
  if (s0 < 0.0) throw std::invalid_argument("speed: the approach is longer than the planned road");
  for (int k = 0; k * kDt <= kImpactTime + kAfterImpact + 1e-9; ++k) {
    const double s = s0 + v * k * kDt;
    const Vec2 p = path.PointAt(s);
    pts.push_back({k * kDt, p.x(), p.y(), path.HeadingAt(s), v});
  }
  return Trajectory(std::move(pts));
}

// Straight line, then an OMPL Dubins curve to (to, yaw), then straight on.
Polyline DubinsDetour(const Vec2& start, const Vec2& from, const Vec2& to, double yaw, double end_x) {
  auto space = std::make_shared<ompl::base::DubinsStateSpace>(kDubinsRadius);
  ompl::base::ScopedState<ompl::base::DubinsStateSpace> a(space), b(space), s(space);
  a->setXY(from.x(), from.y());
  a->setYaw(yaw);
  b->setXY(to.x(), to.y());
  b->setYaw(yaw);
  std::vector<Vec2> pts{start};
  const int n = 60;
  for (int i = 0; i <= n; ++i) {
    space->interpolate(a.get(), b.get(), static_cast<double>(i) / n, s.get());
    pts.emplace_back(s->getX(), s->getY());
  }
  pts.emplace_back(end_x, to.y());
  return Polyline(pts);
}

struct Box {
  Vec2 c, u, v;  // centre, heading unit, left unit
  double hl, hw;
};
Box BoxOf(const TrajectoryPoint& p, VehicleClass cls) {
  const Vec2 u(std::cos(p.yaw), std::sin(p.yaw));
  return {Vec2(p.x, p.y), u, Vec2(-u.y(), u.x()), HalfLength(cls), Params(cls).width / 2};
}
bool Overlap(const Box& a, const Box& b) {
  const Vec2 d = b.c - a.c;
  for (const Vec2& n : {a.u, a.v, b.u, b.v}) {
    const double r = a.hl * std::abs(n.dot(a.u)) + a.hw * std::abs(n.dot(a.v)) + b.hl * std::abs(n.dot(b.u)) +
                     b.hw * std::abs(n.dot(b.v));
    if (std::abs(n.dot(d)) > r) return false;
  }
  return true;
}

// Which faces of a box a world point touches (corners touch two).
bool Touches(const Vec2& point, const Pose2& pose, VehicleClass cls, DamageArea face) {
  const Vec2 l = ToLocal(point - pose.position(), pose.yaw);
  const double hl = HalfLength(cls), hw = Params(cls).width / 2;
  switch (face) {
    case DamageArea::kFront: return l.x() > hl - kFaceTolerance;
    case DamageArea::kRear: return l.x() < -hl + kFaceTolerance;
    case DamageArea::kLeft: return l.y() > hw - kFaceTolerance;
    case DamageArea::kRight: return l.y() < -hw + kFaceTolerance;
    case DamageArea::kUnknown: return true;
  }
  return true;
}

DamageArea FaceOf(const Vec2& point, const Pose2& pose, VehicleClass cls) {
  const Vec2 l = ToLocal(point - pose.position(), pose.yaw);
  const double fx = std::abs(l.x()) / HalfLength(cls), fy = std::abs(l.y()) / (Params(cls).width / 2);
  if (fx >= fy) return l.x() > 0 ? DamageArea::kFront : DamageArea::kRear;
  return l.y() > 0 ? DamageArea::kLeft : DamageArea::kRight;
}

double SpeedOf(const CrashDescription& d, int vehicle, double fallback_fraction) {
  const auto& v = d.vehicles.at(static_cast<size_t>(vehicle - 1));
  if (v.movement == Movement::kStopped) return 0.0;
  if (v.speed > 0.5) return std::clamp(v.speed, 2.0, 40.0);
  double s = d.speed_limit * fallback_fraction;
  if (v.movement == Movement::kSlowing) s *= 0.5;
  if (v.movement == Movement::kTurnLeft || v.movement == Movement::kTurnRight) s = std::min(s, 8.0);
  return std::clamp(s, 2.0, 40.0);
}

}  // namespace

CrashDescription DescriptionFromRecord(const AccidentRecord& r, std::optional<RoadType> road) {
  CrashDescription d;
  if (r.vehicles.empty()) throw std::invalid_argument("vehicles: the record names no vehicle");
  switch (r.road.kind.value) {
    case RoadKind::kIntersection: d.road = RoadType::kIntersection; break;
    case RoadKind::kTJunction:
    case RoadKind::kDriveway: d.road = RoadType::kTJunction; break;
    default: d.road = RoadType::kStraight;
  }
  if (road) d.road = *road;
  d.lanes_per_direction = std::clamp(r.road.lanes_per_direction.value, 1, 4);
  d.divided = r.road.divided.value;
  d.speed_limit = std::clamp(r.road.speed_limit_mps.value, 4.0, 40.0);
  d.surface = r.road.surface.value;
  d.type = r.crash.type.value;
  auto number = [](const std::string& id) { return id.size() == 2 && id[0] == 'V' ? id[1] - '0' : 0; };
  d.striker = std::max(1, number(r.crash.striking.value));
  d.struck = number(r.crash.struck.value);
  if (d.struck == 0) d.struck = d.striker == 1 ? 2 : 1;
  if (d.striker == d.struck) throw std::invalid_argument("crash.struck: the same vehicle as the striker");
  d.striker_area = r.crash.striking_area.value;
  d.struck_area = r.crash.struck_area.known() ? r.crash.struck_area.value : DamageArea::kUnknown;
  for (const auto& v : r.vehicles) d.vehicles.push_back({v.vehicle_class.value, v.movement.value, v.speed_mps.value});
  while (static_cast<int>(d.vehicles.size()) < std::max(d.striker, d.struck)) d.vehicles.push_back({});
  return d;
}

namespace {

// One lane combination and timing of Algorithm 1's search: `variant` picks
// the other vehicle's direction (bit 0), which vehicle turns (bit 1) and a
// timing shift of the striker (variant / 4: 0, -0.35 s, +0.35 s).
Reconstruction PlanVariant(const CrashDescription& described, uint64_t seed, int variant) {
  const bool flip = variant & 1, swap_turner = variant & 2;
  const double shift = std::array<double, 3>{0.0, -0.35, 0.35}[static_cast<size_t>(variant / 4) % 3];
  CrashDescription d = described;
  // Investigators list the vehicle whose side or back was hit first when
  // it caused the crash (it ran the light, pulled out); physically the
  // other vehicle's front strikes. Plan the physics, check the description.
  const auto side_or_back = [](DamageArea a) {
    return a == DamageArea::kLeft || a == DamageArea::kRight || a == DamageArea::kRear;
  };
  if (side_or_back(d.striker_area) && (d.struck_area == DamageArea::kFront || d.struck_area == DamageArea::kUnknown)) {
    std::swap(d.striker, d.struck);
    std::swap(d.striker_area, d.struck_area);
    if (d.striker_area == DamageArea::kUnknown) d.striker_area = DamageArea::kFront;
  }
  if (d.vehicles.size() < 2) throw std::invalid_argument("vehicles: a reconstruction needs two vehicles");
  if (d.type == CrashType::kSingleVehicle) throw std::invalid_argument("type: single-vehicle crashes are not reconstructed");
  if (d.striker < 1 || d.struck < 1 || d.striker == d.struck ||
      d.striker > static_cast<int>(d.vehicles.size()) || d.struck > static_cast<int>(d.vehicles.size())) {
    throw std::invalid_argument("striker/struck: must name two different vehicles of the record");
  }
  const auto& A = d.vehicles[static_cast<size_t>(d.striker - 1)];
  const auto& B = d.vehicles[static_cast<size_t>(d.struck - 1)];
  RoadMapSpec spec;
  spec.lanes_per_direction = d.lanes_per_direction;
  spec.divided = false;
  spec.speed_limit = d.speed_limit;
  spec.surface = d.surface;
  Polyline path_a, path_b;
  double s_a = 0.0, s_b = 0.0;  // arc lengths at the impact
  double va = SpeedOf(d, d.striker, 0.9), vb = SpeedOf(d, d.struck, 0.9);
  CrashType type = d.type;
  if (type == CrashType::kUnknown) {
    type = (A.movement == Movement::kTurnLeft || B.movement == Movement::kTurnLeft) ? CrashType::kTurnAcrossPath
           : d.road == RoadType::kStraight                                          ? CrashType::kRearEnd
                                                                                    : CrashType::kAngle;
  }
  const bool junction_type =
      type == CrashType::kAngle || type == CrashType::kTurnAcrossPath || type == CrashType::kTurnIntoPath;
  if (junction_type) {
    spec.type = d.road == RoadType::kIntersection ? RoadType::kIntersection : RoadType::kTJunction;
    spec.length = 220.0;
  } else {
    spec.type = RoadType::kStraight;
    spec.length = 600.0;
    if (type == CrashType::kSideswipeSame) spec.lanes_per_direction = std::max(2, spec.lanes_per_direction);
  }
  // "Stopped" in a junction crash is coded for the wait at the stop line;
  // the vehicle then pulls into the junction, so it crosses at walking-pace
  // start-up speed rather than standing still (which could never meet).
  constexpr double kPullAwaySpeed = 4.0;  // [m/s]
  if (junction_type) {
    if (va <= 0.0) va = kPullAwaySpeed;
    if (vb <= 0.0) vb = kPullAwaySpeed;
  }
  const RoadMap map(spec);
  const double w = spec.lane_width;
  auto through = [&](Compass travel, int index) {
    const int in = map.FindLane(travel, true, index);
    const int conn = map.FindConnector(in, Turn::kStraight);
    if (in < 0 || conn < 0) throw std::invalid_argument("road: no straight path for that direction on this map");
    return map.RouteThrough({in, conn, map.lane(conn).to_lane});
  };
  auto turning = [&](Compass travel, int index, Turn turn) {
    const int in = map.FindLane(travel, true, index);
    const int conn = in < 0 ? -1 : map.FindConnector(in, turn);
    if (conn < 0) throw std::invalid_argument("road: no such turn on this map");
    return map.RouteThrough({in, conn, map.lane(conn).to_lane});
  };
  auto meet = [](const Polyline& p, const Polyline& q) {
    for (double s = 0; s <= p.length(); s += 0.05) {
      if (q.Project(p.PointAt(s)).distance < 0.05) return s;
    }
    throw std::invalid_argument("road: the planned paths do not cross");
  };
  const int kerb = spec.lanes_per_direction - 1;
  switch (type) {
    case CrashType::kRearEnd: {
      path_a = path_b = map.lane(map.FindLane(Compass::kEast, false, 0)).centreline;
      if (vb > 0.0 && va < vb + 3.0) va = vb + 3.0;
      s_b = 300.0;
      s_a = s_b - HalfLength(A.cls) - HalfLength(B.cls);
      break;
    }
    case CrashType::kHeadOn:
    case CrashType::kSideswipeOpposite: {
      path_b = map.lane(map.FindLane(Compass::kWest, false, 0)).centreline;
      const double overlap = type == CrashType::kHeadOn ? 0.0 : (Params(A.cls).width + Params(B.cls).width) / 2 - 0.4;
      const Vec2 start(-300.0, -w / 2);
      path_a = DubinsDetour(start, Vec2(-80.0, -w / 2), Vec2(-30.0, w / 2 - overlap), 0.0, 300.0);
      // Fronts meet at x = 0.
      s_b = path_b.Project(Vec2(HalfLength(B.cls), w / 2)).s;
      s_a = path_a.Project(Vec2(-HalfLength(A.cls), w / 2 - overlap)).s;
      break;
    }
    case CrashType::kSideswipeSame: {
      // Lane 0 is next to the centre line. The striker drifts into the
      // struck vehicle's lane from the side the damage says it came from:
      // a struck left side (or a striking right side) means from its left.
      const bool from_left = d.struck_area == DamageArea::kLeft || d.striker_area == DamageArea::kRight;
      path_b = map.lane(map.FindLane(Compass::kEast, false, from_left ? 1 : 0)).centreline;
      const double y_from = from_left ? -0.5 * w : -1.5 * w, y_to = from_left ? -1.5 * w : -0.5 * w;
      path_a = DubinsDetour(Vec2(-300.0, y_from), Vec2(-40.0, y_from), Vec2(10.0, y_to), 0.0, 300.0);
      if (va < vb + 2.0) va = vb + 2.0;
      s_b = path_b.Project(Vec2(0.0, y_to)).s;
      s_a = path_a.Project(Vec2(-HalfLength(A.cls), y_to)).s;
      break;
    }
    case CrashType::kAngle: {
      // The striker's front meets the struck vehicle's side; which side
      // decides where the striker comes from.
      const bool from_left = d.struck_area == DamageArea::kLeft;
      if (spec.type == RoadType::kIntersection) {
        path_b = through(flip ? Compass::kWest : Compass::kEast, kerb);
        path_a = through(from_left != flip ? Compass::kSouth : Compass::kNorth, kerb);
      } else {  // T-junction: the striker comes out of the stem, northbound
        const bool west = from_left != flip;
        path_b = through(west ? Compass::kWest : Compass::kEast, kerb);
        path_a = turning(Compass::kNorth, kerb, west ? Turn::kLeft : Turn::kRight);
      }
      s_a = meet(path_a, path_b);
      s_b = path_b.Project(path_a.PointAt(s_a)).s;
      s_a -= HalfLength(A.cls) + Params(B.cls).width / 2;
      break;
    }
    case CrashType::kTurnAcrossPath:
    case CrashType::kTurnIntoPath: {
      // One vehicle turns; the other goes straight.
      const bool a_turns = (A.movement == Movement::kTurnLeft || A.movement == Movement::kTurnRight ||
                            !(B.movement == Movement::kTurnLeft || B.movement == Movement::kTurnRight)) != swap_turner;
      const auto& turner = a_turns ? A : B;
      const Turn turn = turner.movement == Movement::kTurnRight ? Turn::kRight : Turn::kLeft;
      Polyline turn_path, straight_path;
      if (type == CrashType::kTurnAcrossPath) {
        if (spec.type == RoadType::kIntersection) {
          turn_path = turning(Compass::kNorth, turn == Turn::kLeft ? 0 : kerb, turn);
          straight_path = through(turn == Turn::kLeft ? Compass::kSouth : Compass::kNorth, turn == Turn::kLeft ? 0 : kerb);
        } else {  // westbound on the through road, turning left into the stem
          turn_path = turning(Compass::kWest, 0, Turn::kLeft);
          straight_path = through(Compass::kEast, 0);
        }
      } else {  // from the side road (south) into the main road; the other from the west (or east)
        turn_path = turning(Compass::kNorth, turn == Turn::kLeft ? 0 : kerb, turn);
        straight_path = flip ? through(Compass::kWest, 0) : through(Compass::kEast, turn == Turn::kLeft ? 0 : kerb);
      }
      path_a = a_turns ? turn_path : straight_path;
      path_b = a_turns ? straight_path : turn_path;
      s_a = meet(path_a, path_b);
      s_b = path_b.Project(path_a.PointAt(s_a)).s;
      s_a -= HalfLength(A.cls) + Params(B.cls).width / 2;
      break;
    }
    default: throw std::invalid_argument("type: cannot reconstruct this crash type");
  }

  s_a += shift * va;
  Reconstruction rec;
  Trajectory ta = Timed(path_a, s_a, va), tb = Timed(path_b, s_b, vb);
  // The impact is where the planned footprints first overlap.
  double t_impact = -1.0;
  size_t ca = 0, cb = 0;
  for (double t = 0.0; t <= kImpactTime + kAfterImpact; t += 0.01) {
    if (Overlap(BoxOf(ta.Sample(t, &ca), A.cls), BoxOf(tb.Sample(t, &cb), B.cls))) {
      t_impact = t;
      break;
    }
  }
  if (t_impact < 0.0) throw std::invalid_argument("plan: the planned paths never bring the vehicles together");
  if (t_impact < 1.0) throw std::invalid_argument("plan: the vehicles would touch before the planned approach");

  Scenario& s = rec.scenario;
  s.name = d.source_id.empty() ? "reconstruction" : "reconstruction_" + d.source_id;
  s.family = ScenarioFamily::kReconstructed;
  s.seed = seed;
  s.time_limit = kImpactTime + kAfterImpact;
  s.map = spec;
  const std::string ida = "V" + std::to_string(d.striker), idb = "V" + std::to_string(d.struck);
  // The struck vehicle is the ego: the one a policy should learn to save.
  const TrajectoryPoint b0 = tb.Sample(0.0);
  s.ego.id = idb;
  s.ego.vehicle_class = B.cls;
  s.ego.start = Pose2{b0.x, b0.y, b0.yaw};
  s.ego.speed = vb;
  s.ego.target_speed = vb;
  {
    std::vector<Vec2> route;
    const double s0 = s_b - vb * kImpactTime;
    for (double u = s0; u <= std::min(path_b.length(), s0 + 200.0); u += 2.0) route.push_back(path_b.PointAt(u));
    if (route.size() < 2) route.push_back(path_b.PointAt(s0 + 20.0));
    s.ego.route = Polyline(route);
  }
  s.npcs.push_back({ida, A.cls, ta, PostCollisionSource::kPhysics, {}});
  s.provenance = {{"source_report", d.source_id},
                  {"generator", "reconstruction"},
                  {"crash_type", std::string(ToString(type))},
                  {"planned_impact_time", t_impact},
                  // The ego's planned path, for the reconstruction check.
                  {"ego_reference", ToJson(tb)}};
  rec.state.time = t_impact;
  for (const auto& [id, traj] : {std::pair<std::string, const Trajectory*>{ida, &ta}, {idb, &tb}}) {
    const TrajectoryPoint p = traj->Sample(t_impact);
    rec.state.bodies.push_back({id, Pose2{p.x, p.y, p.yaw}, p.v * Vec2(std::cos(p.yaw), std::sin(p.yaw)), 0.0});
  }
  rec.striker_id = ida;
  rec.struck_id = idb;
  rec.striker_area = d.striker_area;
  rec.struck_area = d.struck_area;
  return rec;
}

constexpr int kVariants = 12;

}  // namespace

Reconstruction PlanReconstruction(const CrashDescription& d, uint64_t seed) {
  // Phase 3: the first lane combination whose simulated collision meets the
  // described criteria; if none does, the first that could be planned.
  std::optional<Reconstruction> first;
  std::string first_error;
  for (int v = 0; v < kVariants; ++v) {
    try {
      Reconstruction r = PlanVariant(d, seed, v);
      if (CheckReconstruction(r).success) return r;
      if (!first) first = std::move(r);
    } catch (const std::invalid_argument& e) {
      if (first_error.empty()) first_error = e.what();
    }
  }
  if (first) return *first;
  throw std::invalid_argument(first_error);
}

ReconstructionCheck CheckReconstruction(const Reconstruction& r) {
  ReconstructionCheck c;
  const Scenario& s = r.scenario;
  const Trajectory ego_ref = TrajectoryFromJson(s.provenance.at("ego_reference"), "ego_reference");
  std::vector<std::pair<std::string, VehicleClass>> ids{{s.ego.id, s.ego.vehicle_class}};
  std::vector<const Trajectory*> refs{&ego_ref};
  for (const auto& n : s.npcs) {
    ids.emplace_back(n.id, n.vehicle_class);
    refs.push_back(&n.reference);
  }
  WorldConfig wc;
  wc.tyre_friction = FrictionCoefficient(s.map.surface);
  World world(wc);
  for (size_t i = 0; i < refs.size(); ++i) {
    const TrajectoryPoint p = refs[i]->Sample(0.0);
    world.AddVehicle(Params(ids[i].second), Pose2{p.x, p.y, p.yaw}, p.v, BodyControl::kTracking);
  }
  world.Finalize();
  std::vector<size_t> cursor(refs.size(), 0);
  while (world.time() < s.time_limit && world.contact_log().empty()) {
    for (size_t i = 0; i < refs.size(); ++i) {
      const TrajectoryPoint p = refs[i]->Sample(world.time() + wc.physics_dt, &cursor[i]);
      world.SetTrackingTarget(static_cast<int>(i), Pose2{p.x, p.y, p.yaw});
    }
    world.Step();
  }
  if (world.contact_log().empty()) {
    c.reason = "no contact in simulation";
    return c;
  }
  const ContactEvent& e = world.contact_log().front();
  c.contact_time = e.time;
  const std::string a = ids[static_cast<size_t>(e.body_a)].first, b = ids[static_cast<size_t>(e.body_b)].first;
  if (!((a == r.striker_id && b == r.struck_id) || (a == r.struck_id && b == r.striker_id))) {
    c.reason = "first contact is between " + a + " and " + b;
    return c;
  }
  const int is = a == r.striker_id ? e.body_a : e.body_b, it = is == e.body_a ? e.body_b : e.body_a;
  const auto& cls_s = ids[static_cast<size_t>(is)].second;
  const auto& cls_t = ids[static_cast<size_t>(it)].second;
  c.striker_face = FaceOf(e.point, world.state(is).pose, cls_s);
  c.struck_face = FaceOf(e.point, world.state(it).pose, cls_t);
  const double planned = s.provenance.at("planned_impact_time").get<double>();
  if (std::abs(e.time - planned) > kTimeTolerance) {
    c.reason = "contact at " + std::to_string(e.time) + " s, planned " + std::to_string(planned) + " s";
    return c;
  }
  const auto matches = [&](int body, VehicleClass cls, DamageArea described, DamageArea face) {
    return described == DamageArea::kUnknown || face == described ||
           Touches(e.point, world.state(body).pose, cls, described);
  };
  if (!matches(is, cls_s, r.striker_area, c.striker_face)) {
    c.reason = "striker hit with its " + std::string(ToString(c.striker_face)) + ", described " +
               std::string(ToString(r.striker_area));
    return c;
  }
  if (!matches(it, cls_t, r.struck_area, c.struck_face)) {
    c.reason = "struck vehicle hit on its " + std::string(ToString(c.struck_face)) + ", described " +
               std::string(ToString(r.struck_area));
    return c;
  }
  c.success = true;
  return c;
}

namespace {

std::string Get(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : "";
}

DamageArea AreaCode(const std::string& s) {
  if (s == "Front") return DamageArea::kFront;
  if (s == "Back") return DamageArea::kRear;
  if (s == "Left Side") return DamageArea::kLeft;
  if (s == "Right Side") return DamageArea::kRight;
  return DamageArea::kUnknown;
}

// Investigators' codes -> description (the same mapping as extraction scoring).
CrashDescription FromLabels(const nlohmann::json& row, RoadType road) {
  CrashDescription d;
  d.road = road;
  const auto& v1 = row.at("vehicles").at(0);
  const int lanes = std::atoi(Get(v1, "num_travel_lanes_code").c_str());
  d.divided = Get(v1, "trafficway_flow").rfind("Divided", 0) == 0;
  d.lanes_per_direction = std::clamp(d.divided ? lanes : std::max(1, lanes / 2), 1, 4);
  const std::string limit = Get(v1, "speed_limit_kmph");
  if (!limit.empty() && std::isdigit(static_cast<unsigned char>(limit[0]))) d.speed_limit = std::stod(limit) / 3.6;
  const std::string surface = Get(v1, "surface_condition");
  d.surface = surface.rfind("Wet", 0) == 0 ? Surface::kWet
              : surface.find("Snow") != std::string::npos ? Surface::kSnow
              : surface.find("Ice") != std::string::npos  ? Surface::kIce
                                                          : Surface::kDry;
  const int code = std::atoi(Get(v1, "crash_type_code").c_str());
  d.type = code >= 1 && code <= 19    ? CrashType::kSingleVehicle
           : code >= 20 && code <= 43 ? CrashType::kRearEnd
           : code >= 44 && code <= 49 ? CrashType::kSideswipeSame
           : code >= 50 && code <= 63 ? CrashType::kHeadOn
           : code >= 64 && code <= 67 ? CrashType::kSideswipeOpposite
           : code >= 68 && code <= 75 ? CrashType::kTurnAcrossPath
           : code >= 76 && code <= 85 ? CrashType::kTurnIntoPath
           : code >= 86 && code <= 91 ? CrashType::kAngle
                                      : CrashType::kUnknown;
  for (const auto& v : row.at("vehicles")) {
    CrashDescription::Vehicle veh;
    const std::string m = Get(v, "pre_event_movement");
    veh.movement = m.rfind("Turning left", 0) == 0    ? Movement::kTurnLeft
                   : m.rfind("Turning right", 0) == 0 ? Movement::kTurnRight
                   : m.rfind("Stopped", 0) == 0       ? Movement::kStopped
                   : m.rfind("Decelerating", 0) == 0  ? Movement::kSlowing
                                                      : Movement::kStraight;
    const std::string body = Get(v, "body_type");
    veh.cls = body.find("pickup") != std::string::npos || body.find("Pickup") != std::string::npos ? VehicleClass::kPickup
              : body.find("van") != std::string::npos || body.find("Van") != std::string::npos       ? VehicleClass::kVan
              : body.find("utility") != std::string::npos || body.find("Utility") != std::string::npos
                  ? VehicleClass::kSuv
                  : VehicleClass::kCar;
    const double kmh = std::atof(Get(v, "police_travel_speed").c_str());
    veh.speed = kmh > 0 ? kmh / 3.6 : 0.0;
    d.vehicles.push_back(veh);
  }
  if (row.contains("events") && row["events"].is_array() && !row["events"].empty()) {
    // Events are not always listed in order; the crash being reconstructed is
    // the first harmful event between two vehicles, else the first at all.
    const nlohmann::json* first = &row["events"][0];
    int best = std::numeric_limits<int>::max();
    for (const auto& ev : row["events"]) {
      if (Get(ev, "object_hit").rfind("Vehicle#", 0) != 0) continue;
      const int n = std::atoi(Get(ev, "event_number").c_str());
      if (n < best) best = n, first = &ev;
    }
    const auto& e = *first;
    d.striker = std::max(1, std::atoi(Get(e, "striker_vehicle").c_str()));
    const std::string hit = Get(e, "object_hit");
    d.struck = hit.rfind("Vehicle#", 0) == 0 ? std::atoi(hit.substr(8).c_str()) : 0;
    d.striker_area = AreaCode(Get(e, "striker_area_damage"));
    d.struck_area = AreaCode(Get(e, "hit_area_damage"));
  }
  if (d.struck == 0) d.struck = d.striker == 1 ? 2 : 1;
  return d;
}

}  // namespace

SrrReport EvaluateReconstruction(const std::string& dir, bool from_labels) {
  const std::string path = dir + "/labels.jsonl";
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot open (expected labels.jsonl in the folder)");
  SrrReport rep;
  std::string line;
  const NarrativeExtractor extractor;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \r\t") == std::string::npos) continue;
    const nlohmann::json row = nlohmann::json::parse(line);
    const std::string file = Get(row, "file");
    const std::string folder = file.substr(0, file.find('/'));
    const RoadType road = folder == "crossing" ? RoadType::kIntersection
                          : folder == "t"      ? RoadType::kTJunction
                                               : RoadType::kStraight;
    const std::string group(ToString(road));
    ++rep.n;
    ++rep.attempted[group];
    try {
      CrashDescription d = from_labels ? FromLabels(row, road)
                                       : DescriptionFromRecord(extractor.Extract(Get(row, "narrative")), road);
      d.source_id = file;
      const Reconstruction r = PlanReconstruction(d);
      const ReconstructionCheck c = CheckReconstruction(r);
      if (c.success) {
        ++rep.succeeded[group];
      } else {
        rep.failures.push_back(file + ": " + c.reason);
      }
    } catch (const std::exception& e) {
      rep.failures.push_back(file + ": " + e.what());
    }
  }
  return rep;
}

nlohmann::json ToJson(const SrrReport& r) {
  nlohmann::json srr = nlohmann::json::object();
  for (const auto& [k, n] : r.attempted) srr[k] = n ? static_cast<double>(r.succeeded.count(k) ? r.succeeded.at(k) : 0) / n : 0.0;
  return {{"srr", srr}, {"n", r.n}, {"failures", r.failures}};
}

}  // namespace accsim
