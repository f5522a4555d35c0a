#include "accsim/scenarios/crash_description.h"

#include <gtest/gtest.h>

namespace accsim {
namespace {

CrashDescription Pair(CrashType type) {
  CrashDescription d;
  d.type.Set(type, Provenance::kStated);
  d.vehicles.resize(2);
  d.vehicles[0].id = "V1";
  d.vehicles[1].id = "V2";
  d.striker.Set("V1", Provenance::kStated);
  d.struck.Set("V2", Provenance::kStated);
  return d;
}

std::string ErrorOf(const CrashDescription& d) {
  try {
    Validate(d);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(CrashDescriptionTest, BadDescriptionsNameTheFieldAndReason) {
  CrashDescription d;
  EXPECT_EQ(ErrorOf(d).rfind("vehicles:", 0), 0u);

  d = Pair(CrashType::kRearEnd);
  d.vehicles[0].travel.Set(Compass::kNorth, Provenance::kStated);
  d.vehicles[1].travel.Set(Compass::kSouth, Provenance::kStated);
  EXPECT_EQ(ErrorOf(d).rfind("vehicles[1].travel: south contradicts crash type rear_end", 0), 0u) << ErrorOf(d);

  d = Pair(CrashType::kAngle);
  d.vehicles[0].travel.Set(Compass::kEast, Provenance::kStated);
  d.vehicles[1].travel.Set(Compass::kWest, Provenance::kStated);
  EXPECT_NE(ErrorOf(d).find("contradicts crash type angle"), std::string::npos);

  d = Pair(CrashType::kRearEnd);
  d.vehicles[0].speed.Set(120.0, Provenance::kStated);
  EXPECT_EQ(ErrorOf(d).rfind("vehicles[0].speed: ", 0), 0u);
  EXPECT_NE(ErrorOf(d).find("impossible"), std::string::npos);

  d = Pair(CrashType::kRearEnd);
  d.vehicles[1].movement.Set(Manoeuvre::kStopped, Provenance::kStated);
  d.vehicles[1].speed.Set(15.0, Provenance::kStated);
  EXPECT_NE(ErrorOf(d).find("contradicts movement stopped"), std::string::npos);

  d = Pair(CrashType::kRearEnd);
  d.struck.Set("V1", Provenance::kStated);
  EXPECT_EQ(ErrorOf(d).rfind("struck: the same vehicle", 0), 0u);

  d = Pair(CrashType::kRearEnd);
  d.striker.Set("V7", Provenance::kStated);
  EXPECT_EQ(ErrorOf(d).rfind("striker: no vehicle 'V7'", 0), 0u);

  d = Pair(CrashType::kRearEnd);
  d.road.lanes_per_direction.Set(9, Provenance::kStated);
  EXPECT_EQ(ErrorOf(d).rfind("road.lanes_per_direction:", 0), 0u);

  d = Pair(CrashType::kRearEnd);
  d.road.lanes_per_direction.Set(2, Provenance::kStated);
  d.vehicles[0].lane.Set(3, Provenance::kStated);
  EXPECT_EQ(ErrorOf(d).rfind("vehicles[0].lane: 3 is not a lane", 0), 0u) << ErrorOf(d);

  EXPECT_EQ(ErrorOf(Pair(CrashType::kHeadOn)), "");
}

// The one warning Reconcile recorded; "" when none.
std::string WarningOf(CrashDescription& d) {
  Reconcile(d);
  EXPECT_LE(d.warnings.size(), 1u);
  return d.warnings.empty() ? "" : d.warnings.front();
}

TEST(CrashDescriptionTest, ReconcileSetsTheWeakerFieldAsideAndSaysWhich) {
  // Stated directions over an inferred type.
  CrashDescription d = Pair(CrashType::kSideswipeSame);
  d.type.source = Provenance::kInferred;
  d.vehicles[0].travel.Set(Compass::kWest, Provenance::kStated);
  d.vehicles[1].travel.Set(Compass::kNorth, Provenance::kStated);
  EXPECT_EQ(WarningOf(d).rfind("type: inferred sideswipe_same_direction contradicts the stated directions", 0), 0u)
      << d.warnings.front();
  EXPECT_EQ(d.type.value, CrashType::kUnknown);
  EXPECT_EQ(ErrorOf(d), "");

  // A stated type over an inferred direction.
  d = Pair(CrashType::kRearEnd);
  d.vehicles[0].travel.Set(Compass::kNorth, Provenance::kStated);
  d.vehicles[1].travel.Set(Compass::kSouth, Provenance::kInferred);
  EXPECT_EQ(WarningOf(d).rfind("vehicles[1].travel: inferred south contradicts the stated crash type rear_end", 0), 0u)
      << d.warnings.front();
  EXPECT_FALSE(d.vehicles[1].travel.value.has_value());
  EXPECT_EQ(d.type.value, CrashType::kRearEnd);

  // A stated speed over an inferred stop, a stated stop over an inferred speed.
  d = Pair(CrashType::kRearEnd);
  d.vehicles[1].movement.Set(Manoeuvre::kStopped, Provenance::kInferred);
  d.vehicles[1].speed.Set(12.0, Provenance::kStated);
  EXPECT_EQ(WarningOf(d).rfind("vehicles[1].movement: inferred stopped", 0), 0u);
  EXPECT_EQ(d.vehicles[1].movement.value, Manoeuvre::kStraight);
  d = Pair(CrashType::kRearEnd);
  d.vehicles[1].movement.Set(Manoeuvre::kStopped, Provenance::kStated);
  d.vehicles[1].speed.Set(12.0, Provenance::kInferred);
  EXPECT_EQ(WarningOf(d).rfind("vehicles[1].speed: inferred", 0), 0u);
  EXPECT_FALSE(d.vehicles[1].speed.value.has_value());

  // A stated lane widens a defaulted lane count; an inferred lane gives way to a stated count.
  d = Pair(CrashType::kRearEnd);
  d.vehicles[0].lane.Set(2, Provenance::kStated);
  EXPECT_EQ(WarningOf(d).rfind("road.lanes_per_direction: defaulted 1 has no lane 2", 0), 0u);
  EXPECT_EQ(d.road.lanes_per_direction.value, 3);
  d = Pair(CrashType::kRearEnd);
  d.road.lanes_per_direction.Set(1, Provenance::kStated);
  d.vehicles[0].lane.Set(2, Provenance::kInferred);
  EXPECT_EQ(WarningOf(d).rfind("vehicles[0].lane: inferred 2", 0), 0u);
  EXPECT_FALSE(d.vehicles[0].lane.value.has_value());

  // Stated against stated is left for Validate to refuse, naming the field.
  d = Pair(CrashType::kRearEnd);
  d.vehicles[0].travel.Set(Compass::kNorth, Provenance::kStated);
  d.vehicles[1].travel.Set(Compass::kSouth, Provenance::kStated);
  EXPECT_EQ(WarningOf(d), "");
  EXPECT_EQ(ErrorOf(d).rfind("vehicles[1].travel: south contradicts crash type rear_end", 0), 0u);
}

TEST(CrashDescriptionTest, JsonRoundTripKeepsValuesAndProvenance) {
  CrashDescription d = Pair(CrashType::kTurnAcrossPath);
  d.source_id = "case 7";
  d.road.type.Set(RoadType::kIntersection, Provenance::kStated);
  d.road.speed_limit.Set(17.9, Provenance::kInferred);
  d.vehicles[0].movement.Set(Manoeuvre::kTurnLeft, Provenance::kStated);
  d.vehicles[0].speed.Set(6.5, Provenance::kStated);
  d.vehicles[1].travel.Set(Compass::kSouth, Provenance::kInferred);
  d.vehicles[1].impact_area.Set(ImpactArea::kFrontLeft, Provenance::kStated);
  d.notes = {"a note"};
  const CrashDescription r = CrashDescriptionFromJson(ToJson(d));
  EXPECT_EQ(ToJson(r), ToJson(d));
  EXPECT_EQ(r.road.speed_limit.source, Provenance::kInferred);
  EXPECT_EQ(*r.vehicles[1].travel.value, Compass::kSouth);
  EXPECT_FALSE(r.vehicles[0].travel.value.has_value());

  nlohmann::json bad = ToJson(d);
  bad["vehicles"][1]["movement"]["value"] = "flying";
  try {
    CrashDescriptionFromJson(bad);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("flying"), std::string::npos);
  }
}

TEST(CrashDescriptionTest, CornersIncludeBothFaces) {
  EXPECT_TRUE(AreaIncludes(ImpactArea::kFrontLeft, ImpactArea::kLeft));
  EXPECT_TRUE(AreaIncludes(ImpactArea::kFrontLeft, ImpactArea::kFront));
  EXPECT_FALSE(AreaIncludes(ImpactArea::kFrontLeft, ImpactArea::kRear));
  EXPECT_TRUE(AreaIncludes(ImpactArea::kUnknown, ImpactArea::kRear));
  EXPECT_EQ(ImpactAreaFrom(DamageArea::kLeft, "left-rear"), ImpactArea::kRearLeft);
  EXPECT_EQ(ImpactAreaFrom(DamageArea::kFront, ""), ImpactArea::kFront);
}

TEST(CrashDescriptionTest, FromAccidentRecordKeepsProvenanceAndMapsLayouts) {
  AccidentRecord r;
  EXPECT_THROW(FromAccidentRecord(r), std::invalid_argument);
  r.road.kind.Set(RoadKind::kDriveway, Provenance::kStated);
  r.vehicles.resize(2);
  r.vehicles[0].id = "V1";
  r.vehicles[1].id = "V2";
  r.vehicles[0].speed_mps.Set(20.0, Provenance::kStated);
  r.vehicles[1].movement.Set(Movement::kTurnLeft, Provenance::kStated);
  r.crash.striking.Set("V1", Provenance::kStated);
  r.crash.struck.Set("V2", Provenance::kStated);
  r.crash.struck_area.Set(DamageArea::kLeft, Provenance::kStated);
  const CrashDescription d = FromAccidentRecord(r);
  EXPECT_EQ(d.road.type.value, RoadType::kTJunction);
  EXPECT_EQ(d.road.type.source, Provenance::kInferred);
  EXPECT_NE(d.road.layout_note.find("driveway"), std::string::npos);
  EXPECT_EQ(*d.vehicles[0].speed.value, 20.0);
  EXPECT_FALSE(d.vehicles[1].speed.value.has_value());
  EXPECT_EQ(d.vehicles[1].movement.value, Manoeuvre::kTurnLeft);
  EXPECT_EQ(d.vehicles[1].impact_area.value, ImpactArea::kLeft);
  EXPECT_EQ(d.striker.value, "V1");
  EXPECT_NO_THROW(Validate(d));
}

}  // namespace
}  // namespace accsim
