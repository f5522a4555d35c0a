// Writes the hand-made example scenarios in scenarios/examples/: one per
// family, each built so that an ego holding its speed is hit and an ego
// braking from the start is not. Geometry comes from the same RoadMap the
// environment uses, so routes sit on lane centrelines.
//
//   accsim_make_examples <output dir>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <string>

#include "accsim/env/road_map.h"
#include "accsim/env/scenario.h"

namespace accsim {
namespace {

constexpr double kSampleDt = 0.1;  // [s] reference trajectory resolution

// A vehicle moving along `path` from arc length s0 with speed profile v(t).
Trajectory AlongPath(const Polyline& path, double s0, double duration,
                     const std::function<double(double)>& speed) {
  std::vector<TrajectoryPoint> pts;
  double s = s0;
  for (double t = 0.0; t <= duration + 1e-9; t += kSampleDt) {
    const double v = speed(t);
    pts.push_back({t, path.PointAt(s).x(), path.PointAt(s).y(), path.HeadingAt(s), v});
    s += 0.5 * (v + speed(t + kSampleDt)) * kSampleDt;
  }
  return Trajectory(pts);
}

// Arc length along `a` of the first point within `gap` of polyline `b`.
double FirstApproach(const Polyline& a, const Polyline& b, double gap) {
  for (double s = 0.0; s <= a.length(); s += 0.05) {
    if (b.Project(a.PointAt(s)).distance < gap) return s;
  }
  throw std::runtime_error("paths never meet");
}

Scenario Base(std::string name, ScenarioFamily family, const RoadMapSpec& map) {
  Scenario s;
  s.name = std::move(name);
  s.family = family;
  s.map = map;
  s.seed = 0;
  s.time_limit = 10.0;
  s.provenance = {{"source", "hand-made example"}, {"generator", "tools/make_examples.cpp"}};
  return s;
}

void SetEgo(Scenario& s, const Polyline& route, double s0, double speed) {
  s.ego.start = Pose2{route.PointAt(s0).x(), route.PointAt(s0).y(), route.HeadingAt(s0)};
  s.ego.speed = speed;
  s.ego.target_speed = speed;
  std::vector<Vec2> pts{route.PointAt(s0)};
  for (size_t i = 0; i < route.points().size(); ++i) {
    if (route.arc_lengths()[i] > s0 + 0.5) pts.push_back(route.points()[i]);
  }
  s.ego.route = Polyline(pts);
}

// Straight obstacle: a car stopped in the ego's lane 60 m ahead.
Scenario StraightObstacle() {
  RoadMapSpec m;
  m.type = RoadType::kStraight;
  m.lanes_per_direction = 2;
  m.length = 300.0;
  Scenario s = Base("example_straight_obstacle", ScenarioFamily::kStraightObstacle, m);
  const RoadMap map(m);
  const Polyline lane = map.lane(map.FindLane(Compass::kEast, false, 1)).centreline;
  SetEgo(s, lane, 40.0, 13.0);
  s.npcs.push_back({"stopped_car", VehicleClass::kCar, AlongPath(lane, 100.0, 0.0, [](double) { return 0.0; }),
                    PostCollisionSource::kPhysics, {}});
  return s;
}

// Turning scenarios at a one-lane intersection: the ego approaches from the
// south and turns; the NPC arrives where their paths meet when the ego does.
Scenario Turning(bool left) {
  RoadMapSpec m;
  m.type = RoadType::kIntersection;
  m.lanes_per_direction = 1;
  m.length = 80.0;
  Scenario s = Base(left ? "example_unprotected_left_turn" : "example_right_turn",
                    left ? ScenarioFamily::kUnprotectedLeftTurn : ScenarioFamily::kRightTurn, m);
  const RoadMap map(m);
  const int ego_in = map.FindLane(Compass::kNorth, true, 0);
  const int ego_conn = map.FindConnector(ego_in, left ? Turn::kLeft : Turn::kRight);
  const int ego_out = map.lane(ego_conn).to_lane;
  const Polyline ego_route = map.RouteThrough({ego_in, ego_conn, ego_out});
  // Left turn: oncoming traffic from the north going straight. Right turn:
  // cross traffic from the west going straight into the ego's target lane.
  const Compass npc_travel = left ? Compass::kSouth : Compass::kEast;
  const int npc_in = map.FindLane(npc_travel, true, 0);
  const int npc_conn = map.FindConnector(npc_in, Turn::kStraight);
  const Polyline npc_path = map.RouteThrough({npc_in, npc_conn, map.lane(npc_conn).to_lane});

  const double ego_speed = 9.0, npc_speed = 12.0;
  const double ego_s0 = ego_route.Project(Vec2(map.lane(ego_in).centreline.PointAt(0).x(), -m.length + 30.0)).s;
  SetEgo(s, ego_route, ego_s0, ego_speed);
  const double meet_ego = FirstApproach(ego_route, npc_path, 1.5);
  const Vec2 meet = ego_route.PointAt(meet_ego);
  const double t_meet = (meet_ego - ego_s0) / ego_speed;
  const double meet_npc = npc_path.Project(meet).s;
  const double npc_s0 = meet_npc - npc_speed * t_meet;
  s.npcs.push_back({left ? "oncoming_car" : "crossing_car", VehicleClass::kCar,
                    AlongPath(npc_path, npc_s0, 12.0, [=](double) { return npc_speed; }),
                    PostCollisionSource::kPhysics, {}});
  return s;
}

// Lane changing: a car in the next lane cuts in just ahead of the ego and
// slows; a follower in that lane and an oncoming truck make four vehicles.
Scenario LaneChanging() {
  RoadMapSpec m;
  m.type = RoadType::kStraight;
  m.lanes_per_direction = 2;
  m.length = 400.0;
  Scenario s = Base("example_lane_changing", ScenarioFamily::kLaneChanging, m);
  const RoadMap map(m);
  const Polyline ego_lane = map.lane(map.FindLane(Compass::kEast, false, 0)).centreline;
  const Polyline kerb_lane = map.lane(map.FindLane(Compass::kEast, false, 1)).centreline;
  const Polyline west_lane = map.lane(map.FindLane(Compass::kWest, false, 0)).centreline;
  SetEgo(s, ego_lane, 60.0, 14.0);
  const double y_from = kerb_lane.PointAt(0).y(), y_to = ego_lane.PointAt(0).y();
  const double x0 = ego_lane.PointAt(60.0).x() + 15.0;
  std::vector<TrajectoryPoint> cut;
  double x = x0;
  for (double t = 0.0; t <= 12.0 + 1e-9; t += kSampleDt) {
    const double v = t < 1.0 ? 14.0 : t < 3.0 ? 14.0 - 4.0 * (t - 1.0) : 6.0;
    const double u = std::clamp((t - 1.0) / 2.5, 0.0, 1.0);  // lateral progress
    const double y = y_from + (y_to - y_from) * 0.5 * (1.0 - std::cos(kPi * u));
    const double vy = (y_to - y_from) * 0.5 * kPi * std::sin(kPi * u) / 2.5 * (u > 0 && u < 1);
    cut.push_back({t, x, y, std::atan2(vy, v), std::hypot(v, vy)});
    const double v_next = t + kSampleDt < 1.0 ? 14.0 : t + kSampleDt < 3.0 ? 14.0 - 4.0 * (t + kSampleDt - 1.0) : 6.0;
    x += 0.5 * (v + v_next) * kSampleDt;
  }
  s.npcs.push_back({"cut_in_car", VehicleClass::kCar, Trajectory(cut), PostCollisionSource::kPhysics, {}});
  s.npcs.push_back({"follower", VehicleClass::kSuv,
                    AlongPath(kerb_lane, 35.0, 12.0, [](double) { return 13.0; }),
                    PostCollisionSource::kPhysics, {}});
  s.npcs.push_back({"oncoming_truck", VehicleClass::kTruck,
                    AlongPath(west_lane, 150.0, 12.0, [](double) { return 12.0; }),
                    PostCollisionSource::kPhysics, {}});
  return s;
}

}  // namespace
}  // namespace accsim

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: accsim_make_examples <output dir>\n";
    return 2;
  }
  const std::string dir = argv[1];
  try {
    for (const accsim::Scenario& s : {accsim::StraightObstacle(), accsim::Turning(true),
                                      accsim::Turning(false), accsim::LaneChanging()}) {
      const std::string path = dir + "/" + std::string(accsim::ToString(s.family)) + ".json";
      accsim::SaveJsonFile(accsim::ToJson(s), path);
      std::cout << "wrote " << path << "\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
