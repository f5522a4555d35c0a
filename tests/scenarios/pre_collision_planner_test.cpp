#include "accsim/scenarios/pre_collision_planner.h"

#include <gtest/gtest.h>

#include <cmath>

namespace accsim {
namespace {

CrashDescription Two(CrashType type, RoadType road, ImpactArea striker_area, ImpactArea struck_area) {
  CrashDescription d;
  d.road.type.Set(road, Provenance::kStated);
  d.type.Set(type, Provenance::kStated);
  d.vehicles.resize(2);
  d.vehicles[0].id = "V1";
  d.vehicles[1].id = "V2";
  d.vehicles[1].vehicle_class.Set(VehicleClass::kSuv, Provenance::kStated);
  d.vehicles[0].speed.Set(15.0, Provenance::kStated);
  d.vehicles[1].speed.Set(10.0, Provenance::kStated);
  d.striker.Set("V1", Provenance::kStated);
  d.struck.Set("V2", Provenance::kStated);
  if (striker_area != ImpactArea::kUnknown) d.vehicles[0].impact_area.Set(striker_area, Provenance::kStated);
  if (struck_area != ImpactArea::kUnknown) d.vehicles[1].impact_area.Set(struck_area, Provenance::kStated);
  return d;
}

TEST(PreCollisionPlannerTest, Phase1FillsGapsWithSeededDrawsAndSaysSo) {
  auto d = Two(CrashType::kAngle, RoadType::kIntersection, ImpactArea::kFront, ImpactArea::kLeft);
  d.vehicles[1].speed = {};
  const ImpactConfiguration a = ResolveImpact(d, 1), b = ResolveImpact(d, 1), c = ResolveImpact(d, 2);
  EXPECT_EQ(a.impact_speed, b.impact_speed);  // seeded
  EXPECT_NE(a.impact_speed[1], c.impact_speed[1]);
  EXPECT_EQ(a.description.vehicles[1].speed.source, Provenance::kDefaulted);
  const double limit = d.road.speed_limit.value;
  EXPECT_GE(a.impact_speed[1], 0.8 * limit);
  EXPECT_LE(a.impact_speed[1], 1.0 * limit);
  bool noted = false;
  for (const auto& n : a.description.notes) noted |= n.rfind("V2.speed: not stated", 0) == 0;
  EXPECT_TRUE(noted);
  EXPECT_NEAR(a.approach_angle, kPi / 2, 1e-12);  // from the struck vehicle's left
}

TEST(PreCollisionPlannerTest, Phase1PlansTheFrontThatStrikes) {
  // Coded with V1 (which ran the light) first, hit on its right side by V2's front.
  auto d = Two(CrashType::kAngle, RoadType::kIntersection, ImpactArea::kRight, ImpactArea::kFront);
  const ImpactConfiguration c = ResolveImpact(d, 0);
  EXPECT_TRUE(c.roles_swapped);
  EXPECT_EQ(c.striker, 1);
  EXPECT_EQ(c.struck_area, ImpactArea::kRight);
  EXPECT_NEAR(c.approach_angle, -kPi / 2, 1e-12);
}

TEST(PreCollisionPlannerTest, Phase1InfersTheTypeAndGivesSingleVehiclesAnObstacle) {
  auto d = Two(CrashType::kUnknown, RoadType::kStraight, ImpactArea::kFront, ImpactArea::kRear);
  d.type = {};
  const ImpactConfiguration c = ResolveImpact(d, 0);
  EXPECT_EQ(c.type, CrashType::kRearEnd);
  EXPECT_EQ(c.description.type.source, Provenance::kInferred);
  // The striker must close on the vehicle ahead.
  EXPECT_GE(c.impact_speed[0], c.impact_speed[1] + 3.0 - 1e-9);

  // One traffic unit: the struck object is a stationary body on the side
  // the damage faces.
  auto one = Two(CrashType::kSingleVehicle, RoadType::kStraight, ImpactArea::kLeft, ImpactArea::kUnknown);
  one.vehicles.resize(1);
  one.struck = {};
  const ImpactConfiguration o = ResolveImpact(one, 0);
  EXPECT_TRUE(o.obstacle);
  ASSERT_EQ(o.description.vehicles.size(), 2u);
  EXPECT_EQ(o.description.vehicles[1].id, kObjectId);
  EXPECT_EQ(o.impact_speed[1], 0.0);
  EXPECT_EQ(o.striker, 0);  // a side impact on an object does not swap the roles
  EXPECT_EQ(o.description.obstacle.value, ObstaclePlace::kLeftRoadside);
  EXPECT_EQ(o.description.obstacle.source, Provenance::kInferred);
  auto zero = one;
  zero.vehicles.clear();
  zero.striker = {};
  EXPECT_THROW(ResolveImpact(zero, 0), std::invalid_argument);
}

TEST(PreCollisionPlannerTest, Phase2KeepsLanesCompatibleWithTheManoeuvres) {
  auto d = Two(CrashType::kTurnAcrossPath, RoadType::kIntersection, ImpactArea::kFront, ImpactArea::kFront);
  d.vehicles[1].movement.Set(Manoeuvre::kTurnLeft, Provenance::kStated);
  const ImpactConfiguration c = ResolveImpact(d, 0);
  const auto ks = GatherLaneCombinations(c);
  ASSERT_FALSE(ks.empty());
  const LaneCombination& k = ks.front();
  EXPECT_EQ(k.map.type, RoadType::kIntersection);
  EXPECT_NE(k.paths[1].lanes.find("turning left"), std::string::npos) << k.label;
  EXPECT_NE(k.paths[0].lanes.find("straight on"), std::string::npos) << k.label;
  // Opposite approaches: V2 turns left across V1 coming the other way.
  EXPECT_NEAR(std::abs(WrapAngle(k.paths[0].path.HeadingAt(0) - k.paths[1].path.HeadingAt(0))), kPi, 1e-6);

  // A lane change leaves its lane on an OMPL Dubins curve whose curvature
  // keeps within the lateral limit at the planned speed.
  auto s = Two(CrashType::kSideswipeSame, RoadType::kStraight, ImpactArea::kRight, ImpactArea::kLeft);
  s.vehicles[0].movement.Set(Manoeuvre::kLaneChangeRight, Provenance::kStated);
  const auto ss = GatherLaneCombinations(ResolveImpact(s, 0));
  EXPECT_TRUE(ss.front().paths[0].leaves_lane);
  EXPECT_GE(ss.front().map.lanes_per_direction, 2);
}

// The combinations whose label contains `what`, planned.
std::vector<PlannedCrash> PlansWith(const CrashDescription& d, const std::string& what) {
  const ImpactConfiguration c = ResolveImpact(d, 0);
  std::vector<PlannedCrash> out;
  for (const LaneCombination& k : GatherLaneCombinations(c)) {
    if (k.label.find(what) != std::string::npos && k.striker_shift == 0.0) out.push_back(TimeParameterise(c, k));
  }
  return out;
}

TEST(PreCollisionPlannerTest, Phase2SideswipesMeetWithTheFrontCorner) {
  // V1 swerves left round V2 ahead and clips V2's back with its right front
  // corner (coded a sideswipe, CIREN 105203).
  auto pull_out = Two(CrashType::kSideswipeSame, RoadType::kStraight, ImpactArea::kRight, ImpactArea::kRear);
  const auto out = PlansWith(pull_out, "pulling out left from behind, front corner first");
  ASSERT_FALSE(out.empty());
  // The corner touches at the planned time, with V1 already in the left lane's direction.
  EXPECT_NEAR(out.front().state.time, PlannerConfig{}.impact_time, 0.05);
  EXPECT_GT(out.front().state.bodies[0].pose.yaw, 0.0);

  // A lane changer's front corner on the other's side, from the side the damage names.
  auto into = Two(CrashType::kSideswipeSame, RoadType::kStraight, ImpactArea::kFront, ImpactArea::kLeft);
  const auto in = PlansWith(into, "changing lanes right, front corner first");
  ASSERT_FALSE(in.empty());
  EXPECT_NEAR(in.front().state.time, PlannerConfig{}.impact_time, 0.05);
  EXPECT_LT(in.front().state.bodies[0].pose.yaw, 0.0);

  // The damaged areas rule the corner out: a struck right side cannot meet a
  // changer coming from its left.
  auto wrong = Two(CrashType::kSideswipeSame, RoadType::kStraight, ImpactArea::kRight, ImpactArea::kRight);
  EXPECT_TRUE(PlansWith(wrong, "front corner first").empty());
}

TEST(PreCollisionPlannerTest, Phase3MeetsAtThePlannedTimeWithinLimits) {
  const PlannerConfig cfg;
  for (const CrashType t : {CrashType::kRearEnd, CrashType::kHeadOn, CrashType::kAngle}) {
    const ImpactArea struck = t == CrashType::kRearEnd ? ImpactArea::kRear
                              : t == CrashType::kHeadOn ? ImpactArea::kFront
                                                        : ImpactArea::kLeft;
    auto d = Two(t, t == CrashType::kAngle ? RoadType::kIntersection : RoadType::kStraight, ImpactArea::kFront, struck);
    const PlannedCrash p = PreCollisionPlanner(cfg).Plan(d, 3);
    EXPECT_NEAR(p.state.time, cfg.impact_time, 0.6) << ToString(t);
    EXPECT_LE(p.peak_lateral_accel, cfg.max_lateral_accel * 1.1);
    EXPECT_LE(p.peak_accel, cfg.max_accel + 1e-9);
    EXPECT_LE(p.peak_jerk, cfg.max_jerk + 1e-9);
    ASSERT_EQ(p.state.bodies.size(), 2u);
    EXPECT_EQ(p.scenario.ego.id, "V2");  // the struck vehicle is the ego
    EXPECT_EQ(p.scenario.family, ScenarioFamily::kReconstructed);
    EXPECT_GE(p.scenario.npcs.front().reference.end_time(), p.state.time + 2.0);  // continues past the impact
    EXPECT_NO_THROW(ScenarioFromJson(ToJson(p.scenario)));
  }
}

TEST(PreCollisionPlannerTest, Phase3SlowsAndPullsAwayWithinJerkLimits) {
  auto d = Two(CrashType::kAngle, RoadType::kTJunction, ImpactArea::kFront, ImpactArea::kRight);
  d.vehicles[0].movement.Set(Manoeuvre::kStopped, Provenance::kStated);
  d.vehicles[0].speed = {};
  const PlannedCrash p = PreCollisionPlanner().Plan(d, 0);
  const Trajectory& v1 = p.trajectories[0];
  EXPECT_NEAR(v1.Sample(0.0).v, 0.0, 1e-9);  // waits at the stop line
  EXPECT_NEAR(v1.Sample(p.state.time).v, PlannerConfig{}.pull_away_speed, 0.5);
  EXPECT_LE(p.peak_jerk, PlannerConfig{}.max_jerk + 1e-9);
}

TEST(PreCollisionPlannerTest, SlowingOnIceStartsNoFasterThanTheSurfaceCanShed) {
  // A lead vehicle "began to slow down" on an icy road, its speed not stated:
  // the drawn start speed is lowered to what ice lets it brake away.
  auto d = Two(CrashType::kRearEnd, RoadType::kStraight, ImpactArea::kFront, ImpactArea::kRear);
  d.road.surface.Set(Surface::kIce, Provenance::kStated);
  d.vehicles[1].movement.Set(Manoeuvre::kSlowing, Provenance::kStated);
  d.vehicles[1].speed = {};
  d.vehicles[0].speed = {};
  const PlannedCrash p = PreCollisionPlanner().Plan(d, 0);
  const Trajectory& v2 = p.trajectories[1];
  EXPECT_GT(v2.Sample(0.0).v, v2.Sample(p.state.time).v);  // still slowing
  EXPECT_LE(p.peak_accel, PlannerConfig{}.max_accel + 1e-9);
}

TEST(PreCollisionPlannerTest, ExtraVehiclesStayOutOfTheImpact) {
  auto d = Two(CrashType::kRearEnd, RoadType::kStraight, ImpactArea::kFront, ImpactArea::kRear);
  d.vehicles.push_back({});
  d.vehicles[2].id = "V3";
  const PlannedCrash p = PreCollisionPlanner().Plan(d, 0);
  EXPECT_EQ(p.scenario.vehicle_count(), 3);
  EXPECT_EQ(p.state.bodies.size(), 3u);
}

TEST(PreCollisionPlannerTest, DeterministicForASeed) {
  auto d = Two(CrashType::kTurnIntoPath, RoadType::kTJunction, ImpactArea::kFront, ImpactArea::kUnknown);
  d.vehicles[1].movement.Set(Manoeuvre::kTurnLeft, Provenance::kStated);
  d.vehicles[0].speed = {};
  const PlannedCrash a = PreCollisionPlanner().Plan(d, 9), b = PreCollisionPlanner().Plan(d, 9);
  EXPECT_EQ(ToJson(a.scenario), ToJson(b.scenario));
  // The front-corner sideswipes and single-vehicle obstacles too.
  auto pull_out = Two(CrashType::kSideswipeSame, RoadType::kStraight, ImpactArea::kRight, ImpactArea::kRear);
  pull_out.vehicles[0].speed = {};
  const auto p1 = PlansWith(pull_out, "front corner first"), p2 = PlansWith(pull_out, "front corner first");
  ASSERT_FALSE(p1.empty());
  EXPECT_EQ(ToJson(p1.front().scenario), ToJson(p2.front().scenario));
  auto one = Two(CrashType::kSingleVehicle, RoadType::kStraight, ImpactArea::kFront, ImpactArea::kUnknown);
  one.vehicles.resize(1);
  one.struck = {};
  one.vehicles[0].speed = {};
  EXPECT_EQ(ToJson(PreCollisionPlanner().Plan(one, 4).scenario), ToJson(PreCollisionPlanner().Plan(one, 4).scenario));
}

}  // namespace
}  // namespace accsim
