#include "accsim/scenarios/reconstruction.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include "accsim/scenarios/labelled_case.h"
#include "accsim/scenarios/narrative_extractor.h"

namespace accsim {
namespace {

CrashDescription Two(CrashType type, RoadType road, ImpactArea striker_area, ImpactArea struck_area, Manoeuvre ma,
                     Manoeuvre mb) {
  CrashDescription d;
  d.road.type.Set(road, Provenance::kStated);
  d.type.Set(type, Provenance::kStated);
  d.vehicles.resize(2);
  d.vehicles[0].id = "V1";
  d.vehicles[1].id = "V2";
  d.vehicles[0].movement.Set(ma, Provenance::kStated);
  d.vehicles[1].movement.Set(mb, Provenance::kStated);
  d.striker.Set("V1", Provenance::kStated);
  d.struck.Set("V2", Provenance::kStated);
  if (striker_area != ImpactArea::kUnknown) d.vehicles[0].impact_area.Set(striker_area, Provenance::kStated);
  if (struck_area != ImpactArea::kUnknown) d.vehicles[1].impact_area.Set(struck_area, Provenance::kStated);
  return d;
}

TEST(ReconstructionTest, EveryTwoVehicleCrashTypeReconstructsOnEveryRoad) {
  struct Case {
    CrashType type;
    ImpactArea a, b;
    Manoeuvre ma, mb;
  };
  const Case cases[] = {
      {CrashType::kRearEnd, ImpactArea::kFront, ImpactArea::kRear, Manoeuvre::kStraight, Manoeuvre::kStopped},
      {CrashType::kHeadOn, ImpactArea::kFront, ImpactArea::kFront, Manoeuvre::kStraight, Manoeuvre::kStraight},
      {CrashType::kSideswipeSame, ImpactArea::kUnknown, ImpactArea::kRight, Manoeuvre::kLaneChangeLeft, Manoeuvre::kStraight},
      {CrashType::kSideswipeSame, ImpactArea::kRight, ImpactArea::kLeft, Manoeuvre::kLaneChangeRight, Manoeuvre::kStraight},
      {CrashType::kSideswipeOpposite, ImpactArea::kLeft, ImpactArea::kLeft, Manoeuvre::kStraight, Manoeuvre::kStraight},
      {CrashType::kAngle, ImpactArea::kFront, ImpactArea::kLeft, Manoeuvre::kStraight, Manoeuvre::kStraight},
      {CrashType::kAngle, ImpactArea::kRight, ImpactArea::kFront, Manoeuvre::kStraight, Manoeuvre::kStopped},
      {CrashType::kTurnAcrossPath, ImpactArea::kFront, ImpactArea::kUnknown, Manoeuvre::kStraight, Manoeuvre::kTurnLeft},
      {CrashType::kTurnIntoPath, ImpactArea::kFront, ImpactArea::kUnknown, Manoeuvre::kStraight, Manoeuvre::kTurnLeft},
      {CrashType::kTurnIntoPath, ImpactArea::kFront, ImpactArea::kRear, Manoeuvre::kStraight, Manoeuvre::kTurnRight},
  };
  for (const RoadType road : {RoadType::kStraight, RoadType::kIntersection, RoadType::kTJunction}) {
    for (const Case& k : cases) {
      const Reconstruction r = Reconstruct(Two(k.type, road, k.a, k.b, k.ma, k.mb));
      EXPECT_TRUE(r.check.success) << ToString(road) << " " << ToString(k.type) << ": " << r.check.reason << " ["
                                   << r.plan.combination << "]";
      EXPECT_NEAR(r.check.contact_time, r.plan.state.time, 0.5);
    }
  }
}

TEST(ReconstructionTest, SideswipesMeetWithTheLaneChangersFrontCorner) {
  struct Case {
    CrashType type;
    ImpactArea a, b;
    Manoeuvre ma, mb;
  };
  // Investigators code a lane changer's front corner against the other's
  // side (or, pulling out from behind, against its back) as a sideswipe.
  const Case cases[] = {
      {CrashType::kSideswipeSame, ImpactArea::kFront, ImpactArea::kLeft, Manoeuvre::kLaneChangeRight, Manoeuvre::kStraight},
      {CrashType::kSideswipeSame, ImpactArea::kFrontLeft, ImpactArea::kRight, Manoeuvre::kLaneChangeLeft, Manoeuvre::kStraight},
      {CrashType::kSideswipeSame, ImpactArea::kLeft, ImpactArea::kRight, Manoeuvre::kStraight, Manoeuvre::kStopped},
      {CrashType::kSideswipeSame, ImpactArea::kRight, ImpactArea::kRear, Manoeuvre::kStraight, Manoeuvre::kStraight},
      {CrashType::kSideswipeOpposite, ImpactArea::kFrontLeft, ImpactArea::kLeft, Manoeuvre::kStraight, Manoeuvre::kStraight},
  };
  for (const Case& k : cases) {
    const Reconstruction r = Reconstruct(Two(k.type, RoadType::kStraight, k.a, k.b, k.ma, k.mb));
    EXPECT_TRUE(r.check.success) << ToString(k.type) << " " << ToString(k.a) << "/" << ToString(k.b) << ": "
                                 << r.check.reason << " [" << r.plan.combination << "]";
  }
}

CrashDescription One(ImpactArea area, std::optional<ObstaclePlace> place) {
  CrashDescription d;
  d.vehicles.resize(1);
  d.vehicles[0].id = "V1";
  d.vehicles[0].speed.Set(22.0, Provenance::kStated);
  d.vehicles[0].impact_area.Set(area, Provenance::kStated);
  d.road.lanes_per_direction.Set(2, Provenance::kStated);
  d.striker.Set("V1", Provenance::kStated);
  d.struck.Set(std::string(kObjectId), Provenance::kStated);
  if (place) d.obstacle.Set(*place, Provenance::kStated);
  return d;
}

TEST(ReconstructionTest, SingleVehiclesStrikeAStationaryObstacle) {
  struct Case {
    ImpactArea area;
    std::optional<ObstaclePlace> place;
  };
  const Case cases[] = {
      {ImpactArea::kFront, ObstaclePlace::kRightRoadside}, {ImpactArea::kFront, ObstaclePlace::kLeftRoadside},
      {ImpactArea::kFront, ObstaclePlace::kInLane},        {ImpactArea::kFrontLeft, std::nullopt},
      {ImpactArea::kLeft, std::nullopt},                   {ImpactArea::kRight, ObstaclePlace::kRightRoadside},
  };
  for (const Case& k : cases) {
    const Reconstruction r = Reconstruct(One(k.area, k.place));
    EXPECT_TRUE(r.check.success) << ToString(k.area) << ": " << r.check.reason << " [" << r.plan.combination << "]";
    EXPECT_EQ(r.plan.scenario.ego.id, "V1");  // the only traffic unit is the ego
    ASSERT_EQ(r.plan.scenario.npcs.size(), 1u);
    const Trajectory& object = r.plan.scenario.npcs.front().reference;
    EXPECT_EQ(object.Sample(0.0).x, object.Sample(r.plan.state.time).x);  // it stands still
  }
  // Beside the road means beside it: the object's centre is off the drivable area.
  const Reconstruction right = Reconstruct(One(ImpactArea::kFront, ObstaclePlace::kRightRoadside));
  EXPECT_FALSE(RoadMap(right.plan.scenario.map).OnRoad(right.plan.state.bodies[1].pose.position()));
  // Backing into an object is not planned; the error says so.
  try {
    Reconstruct(One(ImpactArea::kRear, std::nullopt));
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("backing"), std::string::npos) << e.what();
  }
}

TEST(ReconstructionTest, SavedScenarioChecksAgain) {
  const Reconstruction r = Reconstruct(Two(CrashType::kAngle, RoadType::kTJunction, ImpactArea::kFront,
                                           ImpactArea::kLeft, Manoeuvre::kStraight, Manoeuvre::kStraight));
  ASSERT_TRUE(r.check.success) << r.check.reason;
  const Scenario s = ScenarioFromJson(ToJson(r.plan.scenario));
  const ReconstructionCheck c = CheckReconstructedScenario(s);
  EXPECT_TRUE(c.success) << c.reason;
  EXPECT_DOUBLE_EQ(c.contact_time, r.check.contact_time);
  Scenario plain = s;
  plain.provenance = nlohmann::json::object();
  EXPECT_THROW(CheckReconstructedScenario(plain), std::invalid_argument);
}

TEST(ReconstructionTest, CheckRejectsTheWrongFaces) {
  // Plan a rear-end, then claim the struck vehicle was hit on its front.
  Reconstruction r = Reconstruct(Two(CrashType::kRearEnd, RoadType::kStraight, ImpactArea::kFront, ImpactArea::kRear,
                                     Manoeuvre::kStraight, Manoeuvre::kStraight));
  ASSERT_TRUE(r.check.success);
  r.plan.struck_area = ImpactArea::kFront;
  const ReconstructionCheck c = CheckReconstruction(r.plan);
  EXPECT_FALSE(c.success);
  EXPECT_NE(c.reason.find("hit on its rear"), std::string::npos) << c.reason;
}

TEST(ReconstructionTest, NarrativeToCheckedScenario) {
  const AccidentRecord rec = NarrativeExtractor{}.Extract(
      "V1 was traveling north at 40 mph. V2, a pickup, was stopped in the lane ahead waiting to turn left. "
      "The front of V1 struck the back of V2.");
  const Reconstruction r = Reconstruct(FromAccidentRecord(rec));
  EXPECT_TRUE(r.check.success) << r.check.reason;
  EXPECT_EQ(r.plan.scenario.npcs.front().id, "V1");
}

TEST(ReconstructionTest, ContradictionsArePlannedWithAWarningUnlessBothAreStated) {
  // An inferred sideswipe against stated crossing directions: the
  // directions win, the type is inferred again within them, and it plans.
  CrashDescription d = Two(CrashType::kSideswipeSame, RoadType::kTJunction, ImpactArea::kFront, ImpactArea::kLeft,
                           Manoeuvre::kStraight, Manoeuvre::kStraight);
  d.type.source = Provenance::kInferred;
  d.vehicles[0].travel.Set(Compass::kWest, Provenance::kStated);
  d.vehicles[1].travel.Set(Compass::kNorth, Provenance::kStated);
  const Reconstruction r = Reconstruct(d);
  EXPECT_TRUE(r.check.success) << r.check.reason;
  EXPECT_EQ(r.plan.impact.type, CrashType::kAngle);
  ASSERT_EQ(r.plan.impact.description.warnings.size(), 1u);
  EXPECT_EQ(r.plan.impact.description.warnings[0].rfind("type: ", 0), 0u);
  EXPECT_EQ(r.plan.scenario.provenance.at("warnings").size(), 1u);

  // Both stated: refused, naming the field.
  d.type.source = Provenance::kStated;
  try {
    Reconstruct(d);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("vehicles[1].travel: north contradicts", 0), 0u) << e.what();
  }
}

TEST(ReconstructionTest, LabelledObjectImpactsAreSingleVehicleCrashes) {
  // A CIREN-style row: one vehicle, a right roadside departure into a tree.
  const nlohmann::json row = nlohmann::json::parse(R"json({
    "file": "CIREN/1/crash_report.xml", "vehicle_summaries": [],
    "vehicles": [{"veh": "1", "pre_event_movement": "Going Straight", "crash_type": "1 1 DRIVE OFF ROAD",
                  "relation_to_junction": "Non-interchange area and non-junction", "travel_lanes": "Two",
                  "relation_to_flow": "Not physically divided (two way traffic)", "posted_speed_limit_kmph": "89"}],
    "events": [{"veh": "1", "event": "1", "area_of_damage": "Front", "contacted": "Tree(> 10 cm in diameter)",
                "contacted_area_of_damage": "Not a motor vehicle"}]})json");
  const CrashDescription d = DescriptionFromLabels(row);
  EXPECT_TRUE(d.SingleVehicle());
  EXPECT_EQ(d.struck.value, kObjectId);
  EXPECT_EQ(d.obstacle.value, ObstaclePlace::kRightRoadside);
  EXPECT_EQ(d.obstacle.source, Provenance::kStated);
  EXPECT_EQ(d.vehicles[0].impact_area.value, ImpactArea::kFront);
  EXPECT_TRUE(Reconstruct(d).check.success);
}

TEST(ReconstructionTest, DevelopmentSetRatesFromLabels) {
  const SrrReport r =
      EvaluateReconstruction(std::string(ACCSIM_SHARED_DIR) + "/data/narratives/nmvccs", DescriptionSource::kLabels);
  EXPECT_EQ(r.n, 75);
  // Floors at the measured rates (docs/reconstruction.md): a drop is a regression.
  EXPECT_GE(r.Rate("intersection"), 0.98);
  EXPECT_GE(r.Rate("t_junction"), 0.98);
  EXPECT_GE(r.Rate("straight"), 0.98);

  // CIREN, single-vehicle crashes counted in: 20 of 20 (docs/reconstruction.md).
  const SrrReport c =
      EvaluateReconstruction(std::string(ACCSIM_SHARED_DIR) + "/data/narratives/ciren", DescriptionSource::kLabels);
  EXPECT_EQ(c.attempted.at("straight"), 14);
  EXPECT_EQ(c.single_vehicle.at("straight"), 2);
  EXPECT_GE(c.Rate("straight"), 0.99) << ToJson(c).dump();
}

TEST(ReconstructionSweepTest, DescriptionsCoverEveryRoadAndCrashTypeAndStateWhatOddSeedsDraw) {
  const auto open = SweepDescriptions(0), stated = SweepDescriptions(1);
  ASSERT_EQ(open.size(), stated.size());
  std::set<std::string> groups;
  for (const auto& d : open) {
    groups.insert(std::string(ToString(d.road.type.value)) + "/" + std::string(ToString(d.type.value)));
    for (const auto& v : d.vehicles) EXPECT_FALSE(v.travel.known()) << d.source_id;
  }
  // Five crash types on every road, angle and the two turning types at the
  // two junction layouts only.
  EXPECT_EQ(groups.size(), 5u * 3u + 3u * 2u);
  EXPECT_EQ(groups.count("straight/turn_across_path"), 0u);
  EXPECT_EQ(groups.count("straight/angle"), 0u);
  for (const auto& d : stated) {
    EXPECT_NO_THROW(Validate(d)) << d.source_id;
    for (const auto& v : d.vehicles) {
      EXPECT_TRUE(v.travel.known()) << d.source_id;
      if (v.movement.value != Manoeuvre::kStopped) {
        EXPECT_TRUE(v.speed.known()) << d.source_id;
      }
    }
    if (d.vehicles.size() == 2) {
      const auto course = CourseOf(d.vehicles[0], d.vehicles[1]);
      ASSERT_TRUE(course.has_value());
      EXPECT_TRUE(TypeFits(d.type.value, *course)) << d.source_id;
    }
  }
}

TEST(ReconstructionSweepTest, StatedConfigurationsReconstructAtTheirStatedSpeedsAndDeterministically) {
  // Two seeds: one leaving directions and speeds open, one stating them.
  const SrrReport a = SweepReconstruction(0, 2), b = SweepReconstruction(0, 2);
  EXPECT_EQ(a.failures, b.failures);
  EXPECT_EQ(a.succeeded, b.succeeded);
  int ok = 0;
  for (const auto& [group, n] : a.succeeded) ok += n;
  EXPECT_GE(ok, a.n * 95 / 100) << (a.failures.empty() ? "" : a.failures.front());
  // A stated speed is the speed at the planned impact, unless the plan says
  // why not (a turn too tight for it, a striker that must close on the
  // vehicle ahead).
  int honoured = 0, noted = 0;
  for (const CrashDescription& d : SweepDescriptions(1)) {
    if (d.SingleVehicle()) continue;
    const Reconstruction r = Reconstruct(d, 1);
    if (!r.check.success) continue;
    for (size_t k = 0; k < d.vehicles.size(); ++k) {
      if (!d.vehicles[k].speed.known() || !d.vehicles[k].speed.value) continue;
      if (std::abs(r.plan.state.bodies[k].velocity.norm() - *d.vehicles[k].speed.value) < 0.5) {
        ++honoured;
        continue;
      }
      ++noted;
      const auto& notes = r.plan.impact.description.notes;
      const bool said = std::any_of(notes.begin(), notes.end(), [&](const std::string& n) {
        return n.rfind(d.vehicles[k].id + ".speed:", 0) == 0;
      });
      EXPECT_TRUE(said) << d.source_id << " " << d.vehicles[k].id << " changed without a note";
    }
  }
  EXPECT_GT(honoured, noted);
}

TEST(ReconstructionTest, ChainCrashesQueueTheStoppedAndSpaceTheFollowers) {
  // A rear-end into a queue of three stopped vehicles: they wait ahead of the
  // struck one, and the striker's front meets the struck vehicle's back first.
  auto queue = Two(CrashType::kRearEnd, RoadType::kStraight, ImpactArea::kFront, ImpactArea::kRear,
                   Manoeuvre::kStraight, Manoeuvre::kStopped);
  for (const char* id : {"V3", "V4"}) {
    queue.vehicles.push_back({});
    queue.vehicles.back().id = id;
    queue.vehicles.back().movement.Set(Manoeuvre::kStopped, Provenance::kStated);
  }
  const Reconstruction q = Reconstruct(queue);
  EXPECT_TRUE(q.check.success) << q.check.reason;
  const double struck_x = q.plan.trajectories[1].Sample(0.0).x;
  for (size_t i : {2u, 3u}) {
    EXPECT_NEAR(q.plan.trajectories[i].Sample(0.0).v, 0.0, 1e-12);
    EXPECT_GT(q.plan.trajectories[i].Sample(0.0).x, struck_x);  // ahead of the struck vehicle (eastbound)
  }
  EXPECT_GT(q.plan.trajectories[3].Sample(0.0).x, q.plan.trajectories[2].Sample(0.0).x);
  // Two moving vehicles outside a head-on follow the striker a gap apart each,
  // not in one place.
  auto head_on = Two(CrashType::kHeadOn, RoadType::kStraight, ImpactArea::kFront, ImpactArea::kFront,
                     Manoeuvre::kStraight, Manoeuvre::kStraight);
  for (const char* id : {"V3", "V4"}) {
    head_on.vehicles.push_back({});
    head_on.vehicles.back().id = id;
  }
  const Reconstruction h = Reconstruct(head_on);
  EXPECT_TRUE(h.check.success) << h.check.reason;
  const auto p3 = h.plan.trajectories[2].Sample(0.0), p4 = h.plan.trajectories[3].Sample(0.0);
  EXPECT_GT(std::hypot(p3.x - p4.x, p3.y - p4.y), 10.0);
}

TEST(ReconstructionTest, AStrikerBackingOutOfADriveMeetsTheSideWithItsBack) {
  for (const ImpactArea side : {ImpactArea::kLeft, ImpactArea::kRight}) {
    for (const CrashType type : {CrashType::kAngle, CrashType::kSideswipeSame, CrashType::kUnknown}) {
      auto d = Two(type, RoadType::kStraight, ImpactArea::kRear, side, Manoeuvre::kBacking, Manoeuvre::kStraight);
      if (type == CrashType::kUnknown) d.type = {};
      const Reconstruction r = Reconstruct(d);
      EXPECT_TRUE(r.check.success) << ToString(type) << " " << ToString(side) << ": " << r.check.reason;
      // Backing: facing against its motion, at walking-to-jogging speed.
      const TrajectoryPoint p = r.plan.trajectories[0].Sample(r.plan.state.time);
      EXPECT_LT(p.v, 0.0);
      EXPECT_GE(-p.v, 1.5 - 1e-9);
      EXPECT_LE(-p.v, 3.0 + 1e-9);
      // The saved scenario, reversing reference and all, loads again.
      EXPECT_NO_THROW(ScenarioFromJson(ToJson(r.plan.scenario)));
    }
  }
  // Into a parked car across the street.
  auto parked = Two(CrashType::kSingleVehicle, RoadType::kStraight, ImpactArea::kRear, ImpactArea::kLeft,
                    Manoeuvre::kBacking, Manoeuvre::kStopped);
  parked.vehicles[1].parked = true;
  const Reconstruction p = Reconstruct(parked);
  EXPECT_TRUE(p.check.success) << p.check.reason;
}

TEST(ReconstructionTest, AVehicleStoppedAcrossTheLaneOffAJunctionIsStruckWhereItStands) {
  // Spun out and stalled crosswise on a straight road, hit in the side.
  for (const ImpactArea side : {ImpactArea::kLeft, ImpactArea::kRight}) {
    auto d = Two(CrashType::kAngle, RoadType::kStraight, ImpactArea::kFront, side, Manoeuvre::kStraight,
                 Manoeuvre::kStopped);
    d.location.Set(CrashLocation::kSegment, Provenance::kStated);
    const Reconstruction r = Reconstruct(d);
    ASSERT_TRUE(r.check.success) << ToString(side) << ": " << r.check.reason;
    EXPECT_EQ(r.plan.scenario.map.type, RoadType::kStraight);
    // It stands still, crosswise to the striker, the whole run.
    const Trajectory& t = r.plan.trajectories[1];
    for (const double time : {0.0, r.plan.state.time}) {
      const TrajectoryPoint p = t.Sample(time);
      EXPECT_EQ(p.v, 0.0);
      EXPECT_NEAR(std::abs(std::remainder(p.yaw - r.plan.trajectories[0].Sample(time).yaw, 2 * kPi)), kPi / 2, 1e-6);
    }
    EXPECT_EQ(t.Sample(0.0).x, t.Sample(r.plan.state.time).x);
  }
  // At a junction, stopped is the wait at the stop line: it pulls away.
  auto j = Two(CrashType::kAngle, RoadType::kIntersection, ImpactArea::kFront, ImpactArea::kLeft,
               Manoeuvre::kStraight, Manoeuvre::kStopped);
  j.location.Set(CrashLocation::kJunction, Provenance::kStated);
  const Reconstruction rj = Reconstruct(j);
  ASSERT_TRUE(rj.check.success) << rj.check.reason;
  EXPECT_GT(rj.plan.trajectories[1].Sample(rj.plan.state.time).v, 0.5);
}

}  // namespace
}  // namespace accsim
