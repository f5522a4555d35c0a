#include "accsim/scenarios/narrative_extractor.h"

#include <gtest/gtest.h>

#include <atomic>
#include <random>
#include <string>
#include <thread>
#include <tuple>

namespace accsim {
namespace {

const NarrativeExtractor kExtractor;

// The speed limit read, in mph.
double LimitMph(const std::string& text) { return kExtractor.Extract(text).road.speed_limit_mps.value / 0.44704; }

// The pre-event movement of vehicle `i` in a report naming `vehicles`
// vehicles (kUnknown, and a failure, if the count is not that).
Movement PreEventOf(const std::string& text, size_t vehicles, size_t i) {
  const AccidentRecord r = kExtractor.Extract(text);
  EXPECT_EQ(r.vehicles.size(), vehicles) << text;
  return i < r.vehicles.size() ? r.vehicles[i].pre_event.value : Movement::kUnknown;
}

TEST(NarrativeExtractorTest, RearEndWithMphAndVehicleWords) {
  const auto r = kExtractor.Extract(
      "The crash happened on a two-lane, two-way road with a posted speed limit of 35 mph. Vehicle one, a 2004 "
      "Ford F-150 pickup, was traveling northbound at about 45 mph. Vehicle two, a 1999 Honda Civic, was stopped "
      "in the lane ahead. The front of V1 struck the back of V2. The driver of V2 was a 30-year old male who was "
      "transported to a hospital.");
  EXPECT_EQ(r.participant_count.value, 2);
  EXPECT_EQ(r.participant_count.source, Provenance::kStated);
  EXPECT_NEAR(r.road.speed_limit_mps.value, 35 * 0.44704, 1e-6);
  EXPECT_EQ(r.road.speed_limit_unit.value, "mph");
  EXPECT_EQ(r.road.lanes_total.value, 2);
  EXPECT_EQ(r.vehicles[0].vehicle_class.value, VehicleClass::kPickup);
  EXPECT_EQ(r.vehicles[0].travel.value, Compass::kNorth);
  EXPECT_NEAR(r.vehicles[0].speed_mps.value, 45 * 0.44704, 1e-6);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kStopped);
  EXPECT_EQ(r.crash.striking.value, "V1");
  EXPECT_EQ(r.crash.struck.value, "V2");
  EXPECT_EQ(r.crash.striking_area.value, DamageArea::kFront);
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kRear);
  EXPECT_EQ(r.crash.type.value, CrashType::kRearEnd);
}

TEST(NarrativeExtractorTest, PassiveVoiceAndKmh) {
  const auto r = kExtractor.Extract(
      "This crash occurred at a four-leg intersection of two undivided roads, each with 2 lanes in each "
      "direction; the posted speed limit was 56 km/h (35 mph). V1, a 2001 Toyota Camry, was eastbound going "
      "straight. V2, a Chevrolet Suburban, was southbound. V1 was struck on the left side by the front of V2 in "
      "the intersection.");
  EXPECT_NEAR(r.road.speed_limit_mps.value * 3.6, 56.0, 1e-9);
  EXPECT_EQ(r.road.speed_limit_unit.value, "km/h");
  EXPECT_EQ(r.road.lanes_per_direction.value, 2);
  EXPECT_EQ(r.road.lanes_total.value, 4);
  EXPECT_EQ(r.road.kind.value, RoadKind::kIntersection);
  EXPECT_EQ(r.vehicles[1].vehicle_class.value, VehicleClass::kSuv);
  EXPECT_EQ(r.crash.striking.value, "V2");
  EXPECT_EQ(r.crash.struck.value, "V1");
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kLeft);
  EXPECT_EQ(r.crash.type.value, CrashType::kAngle);
  EXPECT_EQ(r.crash.location.value, CrashLocation::kJunction);
}

TEST(NarrativeExtractorTest, LeftTurnAcrossOncomingTraffic) {
  const auto r = kExtractor.Extract(
      "Vehicle #1 was traveling west and turned left at the intersection. Vehicle #2 was traveling east "
      "through the intersection. The front of Vehicle #2 impacted the right side of Vehicle #1.");
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kStraight);
  EXPECT_EQ(r.crash.type.value, CrashType::kTurnAcrossPath);
  EXPECT_EQ(r.crash.striking.value, "V2");
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kRight);
}

TEST(NarrativeExtractorTest, WaitingToTurnIsStoppedNotTurning) {
  const auto r = kExtractor.Extract(
      "V2 was stopped in the eastbound lane waiting to turn left. V1, traveling east, did not see it and the "
      "front of V1 struck the back of V2.");
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kStopped);
  EXPECT_EQ(r.crash.type.value, CrashType::kRearEnd);
}

TEST(NarrativeExtractorTest, HeadOnInfersTheStruckFront) {
  const auto r = kExtractor.Extract(
      "V1 was northbound and drifted over the center line. V2 was southbound. V1 impacted V2 with its front.");
  EXPECT_EQ(r.crash.type.value, CrashType::kHeadOn);
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kFront);
  EXPECT_EQ(r.crash.struck_area.source, Provenance::kInferred);
}

TEST(NarrativeExtractorTest, BadInputNeverThrowsAndSaysWhatWasDefaulted) {
  for (const std::string& text :
       {std::string(""), std::string("   \n\t "), std::string("The weather was nice and we had lunch."),
        std::string("El vehiculo uno choco contra el vehiculo dos en la interseccion."),
        std::string("\x00\x01\xff\xfe binary \x80", 14), std::string("{\"limit\": 00. \"stopped_car\"}")}) {
    AccidentRecord r;
    ASSERT_NO_THROW(r = kExtractor.Extract(text)) << text;
    EXPECT_FALSE(r.warnings.empty()) << text;
    EXPECT_EQ(r.crash.striking.source, Provenance::kDefaulted);
    EXPECT_NO_THROW(ToJson(r).dump());
    EXPECT_NO_THROW(AccidentRecordFromJson(ToJson(r))) << text;  // "limit: 00" is no limit of 0
  }
  std::mt19937_64 rng(1);
  std::string junk(100000, ' ');
  for (auto& c : junk) c = static_cast<char>(rng() & 0xff);
  EXPECT_NO_THROW(ToJson(kExtractor.Extract(junk)).dump());
}

TEST(NarrativeExtractorTest, HugeTextIsCappedWithAWarning) {
  std::string text;
  while (text.size() < 10'000'000) text += "V1 was traveling north and struck the rear of V2. ";
  const auto r = kExtractor.Extract(text);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings.front().find("only the start was read"), std::string::npos);
  EXPECT_EQ(r.crash.type.value, CrashType::kRearEnd);
}

TEST(NarrativeExtractorTest, JsonCarriesProvenanceOnEveryField) {
  const auto j = ToJson(kExtractor.Extract("V1 struck V2."));
  EXPECT_EQ(j["schema_version"], 1);
  EXPECT_EQ(j["crash"]["striking"]["source"], "stated");
  EXPECT_EQ(j["road"]["speed_limit_mps"]["source"], "defaulted");
  EXPECT_EQ(j["vehicles"][0]["movement"]["source"], "inferred");
}


TEST(NarrativeExtractorTest, MakeAliasesNumberWordsAndInjuryParagraphs) {
  const auto r = kExtractor.Extract(
      "The crash occurred on a four lane undivided roadway. The posted speed limit was forty-five mph. Vehicle one, "
      "a 1998 Ford Taurus, was traveling westbound in the second lane. Vehicle two, a 2003 Honda motorcycle, was "
      "traveling eastbound. The Ford turned left at the intersection in front of the motorcycle. The front of the "
      "motorcycle struck the right side of the Ford. The 43-year old driver of the Ford was stopped by police and "
      "transported to a hospital with injuries.");
  EXPECT_NEAR(r.road.speed_limit_mps.value, 45 * 0.44704, 1e-6);
  EXPECT_EQ(r.road.lanes_total.value, 4);
  EXPECT_EQ(r.vehicles[1].vehicle_class.value, VehicleClass::kMotorcycle);
  EXPECT_EQ(r.vehicles[0].lane.value, 2);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnLeft);  // "stopped by police" is about people
  EXPECT_EQ(r.crash.striking.value, "V2");
  EXPECT_EQ(r.crash.struck.value, "V1");
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kRight);
  EXPECT_EQ(r.crash.type.value, CrashType::kTurnAcrossPath);
  EXPECT_EQ(r.crash.location.value, CrashLocation::kJunction);
}

TEST(NarrativeExtractorTest, OneWayAndPerDirectionLanesOfV1sRoad) {
  const auto r = kExtractor.Extract(
      "This crash occurred at the intersection of an east-west roadway with two lanes in each direction, and a "
      "one-way northbound roadway. Vehicle # 1 was traveling westbound on the left lane. Vehicle # 2 was traveling "
      "northbound. At the intersection, the front of Vehicle # 2 contacted the left side of Vehicle # 1.");
  EXPECT_EQ(r.road.lanes_per_direction.value, 2);
  EXPECT_EQ(r.road.lanes_total.value, 4);
  EXPECT_FALSE(r.road.one_way.value);
  EXPECT_EQ(r.crash.type.value, CrashType::kAngle);
  EXPECT_EQ(r.AreaOf("V1"), DamageArea::kLeft);
  EXPECT_EQ(r.AreaOf("V2"), DamageArea::kFront);
}

TEST(NarrativeExtractorTest, ParkedVehicleIsAnObject) {
  const auto r = kExtractor.Extract(
      "Vehicle #1 was traveling south when it went over the right lane line and its right front impacted the left "
      "rear of a parked and unoccupied Oldsmobile Ciera.");
  EXPECT_EQ(r.participant_count.value, 2);
  EXPECT_TRUE(r.vehicles[1].parked.value);
  EXPECT_EQ(r.crash.type.value, CrashType::kSingleVehicle);
}

TEST(NarrativeExtractorTest, CameraHintOnlyWhenAsked) {
  EXPECT_FALSE(kExtractor.Extract("V1 struck the rear of V2.").camera_hint.known());
  const auto r = kExtractor.Extract("V1 struck the rear of V2. Show the crash from behind V2.");
  EXPECT_EQ(r.camera_hint.value, "behind V2");
  EXPECT_EQ(kExtractor.Extract("V1 hit V2 head-on; render a bird's-eye view.").camera_hint.value, "overhead");
}

TEST(NarrativeExtractorTest, RecordJsonRoundTripsAndBadJsonNamesTheField) {
  const auto r = kExtractor.Extract(
      "V1, a 2004 Ford F-150 pickup, was traveling north at 45 mph. V2 was stopped. V1 rear-ended V2.");
  const nlohmann::json j = ToJson(r);
  const AccidentRecord back = AccidentRecordFromJson(j);
  EXPECT_EQ(ToJson(back), j);
  nlohmann::json bad = j;
  bad["vehicles"][1]["movement"]["value"] = "flying";
  try {
    AccidentRecordFromJson(bad);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("vehicles[1].movement.value"), std::string::npos) << e.what();
  }
}

TEST(NarrativeExtractorTest, SameTextSameRecordAcrossThreads) {
  const std::string text =
      "V1 was eastbound and turned left. V2 was westbound at 40 mph. The front of V2 struck the right side of V1.";
  const nlohmann::json want = ToJson(kExtractor.Extract(text));
  std::vector<std::thread> threads;
  std::atomic<int> same{0};
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&] { same += ToJson(kExtractor.Extract(text)) == want; });
  }
  for (auto& t : threads) t.join();
  EXPECT_EQ(same, 4);
}

// Invented reports, one per rule; none is taken from the labelled sets.

TEST(NarrativeExtractorTest, StopThenTurnIsStoppedBeforeTheTurn) {
  const auto r = kExtractor.Extract(
      "V1, a 2003 Buick Century driven by a 52-year old female, was traveling north on a side street with one "
      "occupant. She stopped at the stop sign and then began to turn left onto the main road. V2, a 2006 Kia "
      "Rio, was traveling west on the main road. The front of V2 struck the left side of V1.");
  // The manoeuvre into the crash is the turn; the pre-event movement is the stop.
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStopped);
  EXPECT_EQ(r.vehicles[0].travel.value, Compass::kNorth);  // "driven by ..., with one occupant" is still motion
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, RollingStopBeforeTurnIsSlowing) {
  const auto r = kExtractor.Extract(
      "Vehicle one rolled through the stop sign and turned right into the path of vehicle two, which was "
      "traveling east. Vehicle two struck vehicle one in the left side.");
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnRight);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kSlowing);
}

TEST(NarrativeExtractorTest, WhatAnotherDriverSawIsAboutTheSeenVehicle) {
  const auto r = kExtractor.Extract(
      "V1 was traveling south in lane two. V2 was traveling north and turned left across the southbound lanes. "
      "The front of V1 struck the right side of V2. The driver of V1 said she saw V2 waiting to turn and "
      "thought it would yield.");
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kStopped);
}

TEST(NarrativeExtractorTest, CodedCriticalEventsNameTheCrashType) {
  // Front to front, yet the investigators' events say the turner crossed
  // the path of a vehicle from the opposite direction.
  const auto across = kExtractor.Extract(
      "V1 was eastbound and made a left turn at the intersection. V2 was westbound. The front of V1 struck the "
      "front of V2. The critical precrash event for V1 was this vehicle traveling, turning left at "
      "intersection. The critical precrash event for V2 was other vehicle encroachment from opposite "
      "direction over left lane line.");
  EXPECT_EQ(across.crash.type.value, CrashType::kTurnAcrossPath);
  EXPECT_EQ(across.crash.type.source, Provenance::kStated);
  const auto into = kExtractor.Extract(
      "V1 pulled out from the side road. V2 was traveling south. V2 struck V1. The critical pre-crash event for "
      "V2 was other vehicle encroachment from crossing street, turning into same direction.");
  EXPECT_EQ(into.crash.type.value, CrashType::kTurnIntoPath);
  const auto crossing = kExtractor.Extract(
      "V1 was northbound. V2 was eastbound. The front of V2 struck the left side of V1 in the intersection. The "
      "critical precrash event for V1 was other vehicle encroaching from crossing street, across her path.");
  EXPECT_EQ(crossing.crash.type.value, CrashType::kAngle);
  const auto lead = kExtractor.Extract(
      "V1 and V2 were westbound. V1 struck V2. The critical precrash event for V1 was other motor vehicle in "
      "lane, other vehicle stopped.");
  EXPECT_EQ(lead.crash.type.value, CrashType::kRearEnd);
}

TEST(NarrativeExtractorTest, StatedCrashTypeOverridesAContradictoryDirection) {
  const auto r = kExtractor.Extract(
      "V1 was traveling south when it struck the rear of V2 with its front. V2 had been stopped in the northbound "
      "lane. The critical precrash event for V1 was other motor vehicle in lane, other vehicle stopped.");
  EXPECT_EQ(r.crash.type.value, CrashType::kRearEnd);
  EXPECT_EQ(r.vehicles[1].travel.value, Compass::kSouth);
  EXPECT_EQ(r.vehicles[1].travel.source, Provenance::kInferred);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings.back().find("vehicles[1].travel"), std::string::npos);
}

TEST(NarrativeExtractorTest, TravelVerbBeatsTheDirectionOfTheLane) {
  const auto r = kExtractor.Extract(
      "V1 was traveling west when the driver saw V2, a motorcycle, in the westbound lane traveling east. V1 "
      "struck V2 with its front.");
  EXPECT_EQ(r.vehicles[1].travel.value, Compass::kEast);
}

TEST(NarrativeExtractorTest, OneWayAndTwoWayRoadsAtOneIntersection) {
  const auto one_way = kExtractor.Extract(
      "The intersection joins a two-way road with one lane in each direction and a one-lane, one-way street. V1 "
      "was traveling north on the one-way street. V2 was traveling east on the two-way road. V2 struck V1.");
  EXPECT_TRUE(one_way.road.one_way.value);
  EXPECT_EQ(one_way.road.lanes_total.value, 1);
  const auto two_way = kExtractor.Extract(
      "The intersection joins a two-way road with one lane in each direction and a one-lane, one-way street. V1 "
      "was traveling east on the two-way road. V2 was traveling north on the one-way street. V2 struck V1.");
  EXPECT_FALSE(two_way.road.one_way.value);
  EXPECT_EQ(two_way.road.lanes_total.value, 2);
}

TEST(NarrativeExtractorTest, LeavingADrivewayPutsTheCrashAtTheDriveway) {
  const auto r = kExtractor.Extract(
      "The crash occurred at a four-leg intersection of a four-lane undivided road. V1 was exiting a parking lot "
      "driveway and turned left. V2 was traveling north in lane two. V2 struck V1 in the left side.");
  EXPECT_EQ(r.crash.location.value, CrashLocation::kDriveway);
  EXPECT_EQ(r.road.lanes_total.value, 2);  // the drive V1 was on
  EXPECT_EQ(r.road.lanes_total.source, Provenance::kInferred);
}

TEST(NarrativeExtractorTest, RoadClassGivesAnInferredLimitOnlyWhenNoneIsPosted) {
  const auto rural = kExtractor.Extract("V1 was traveling east on a two-lane rural road. V1 struck V2.");
  EXPECT_NEAR(rural.road.speed_limit_mps.value, 55 * 0.44704, 1e-9);
  EXPECT_EQ(rural.road.speed_limit_mps.source, Provenance::kInferred);
  const auto posted = kExtractor.Extract(
      "V1 was traveling east on a two-lane rural road; the posted speed limit was 45 mph. V1 struck V2.");
  EXPECT_NEAR(posted.road.speed_limit_mps.value, 45 * 0.44704, 1e-9);
  EXPECT_EQ(posted.road.speed_limit_mps.source, Provenance::kStated);
  const auto unnamed = kExtractor.Extract("V1 was traveling east. V1 struck V2.");
  EXPECT_FALSE(unnamed.road.speed_limit_mps.known());
}

TEST(NarrativeExtractorTest, UnpostedLimitFollowsTheRoadClassAndSize) {
  auto limit_mph = [](const char* text) {
    const auto r = kExtractor.Extract(text);
    EXPECT_EQ(r.road.speed_limit_mps.source, Provenance::kInferred) << text;
    return r.road.speed_limit_mps.value / 0.44704;
  };
  // A described road with no class named: the usual limit outside towns.
  EXPECT_NEAR(limit_mph("V1 was traveling east in the eastbound lane of a two-lane, two-way roadway. V2 was traveling "
                        "west. The front of V2 struck the front of V1."),
              55.0, 1e-9);
  // Urban: a multi-lane arterial is faster than a two-lane street.
  EXPECT_NEAR(limit_mph("V1 was traveling north in the left lane of a four-lane, two-way urban roadway. V1 struck V2."),
              45.0, 1e-9);
  EXPECT_NEAR(limit_mph("V1 was traveling north on a two-lane urban street. V1 struck V2."), 30.0, 1e-9);
  EXPECT_NEAR(limit_mph("V1 was traveling south in the right lane of a limited access freeway. V2 struck V1."), 70.0,
              1e-9);
  EXPECT_NEAR(limit_mph("V1 was traveling east in the eastbound lane of a three-lane, two-way suburban road. V2 was "
                        "traveling west. The front of V2 struck the front of V1."),
              45.0, 1e-9);
  // V1's own road's class, not the other road's ("a residential street
  // that meets the east-west road").
  EXPECT_NEAR(limit_mph("V1 was traveling west in the right westbound lane of a four-lane, two-way urban road and was "
                        "approaching a T-intersection. V2 was traveling south on a two-lane, two-way residential "
                        "street that meets the east-west road from the north. The front of V1 struck the left side "
                        "of V2."),
              45.0, 1e-9);
}

TEST(NarrativeExtractorTest, WhatTheTextTellsLaterOfTheTimeBeforeTheTurnCounts) {
  const auto r = kExtractor.Extract(
      "V1 was traveling north and made a left turn at the intersection. V2 was traveling south. The front of V2 struck "
      "the right side of V1. V1 was driven by a 40-year old male who was not injured. He did not stop before making "
      "the turn.");
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kSlowing);
  const auto stopped = kExtractor.Extract(
      "V1 was traveling north and turned left at the intersection. V2 was traveling south. The front of V2 struck the "
      "right side of V1. The driver of V1 had stopped at the stop sign for several seconds.");
  EXPECT_EQ(stopped.vehicles[0].pre_event.value, Movement::kStopped);
}

TEST(NarrativeExtractorTest, AParkedVehicleStruckIsNotTheStriker) {
  const auto r = kExtractor.Extract(
      "Vehicle 1 was traveling west. The driver veered to the left and the front of Vehicle 1 impacted the left side "
      "of a legally parked and unoccupied Ford van.");
  ASSERT_GE(r.vehicles.size(), 1u);
  EXPECT_FALSE(r.vehicles[0].parked.value);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kStraight);
  EXPECT_EQ(r.crash.type.value, CrashType::kSingleVehicle);
  const auto intro = kExtractor.Extract("V2, a parked and unoccupied 1998 Ford van, was struck by V1.");
  ASSERT_GE(intro.vehicles.size(), 2u);
  EXPECT_TRUE(intro.vehicles[1].parked.value);
}

TEST(NarrativeExtractorTest, AVehicleCrossingTheThroughRoadsAxisIsOnTheCrossStreet) {
  const auto r = kExtractor.Extract(
      "The crash occurred at a T-intersection on a two way six lane roadway. The roadway consists of three westbound "
      "and three eastbound lanes. The cross street is a two way, one lane asphalt roadway. V1 was traveling "
      "southbound approaching the through street, stopped for the stop sign and turned left. V2 was traveling east. "
      "The front of V2 struck the left side of V1.");
  EXPECT_EQ(r.road.lanes_total.value, 2);  // one lane each way on the cross street
  EXPECT_EQ(r.road.lanes_per_direction.value, 1);
  const auto through = kExtractor.Extract(
      "The crash occurred at a T-intersection on a two way six lane roadway. The roadway consists of three westbound "
      "and three eastbound lanes. The cross street is a two way, one lane asphalt roadway. V1 was traveling east. V2 "
      "was traveling south and turned left. The front of V1 struck the left side of V2.");
  EXPECT_EQ(through.road.lanes_total.value, 6);
}

TEST(NarrativeExtractorTest, AQuotedWitnessIsNotTheNarrator) {
  const auto r = kExtractor.Extract(
      "A pickup heading west on Route 9 crossed the center line and struck a sedan head-on. \"I saw it coming,\" a "
      "witness said.");
  EXPECT_EQ(r.participant_count.value, 2);
  EXPECT_EQ(r.crash.type.value, CrashType::kHeadOn);
  const auto claim = kExtractor.Extract("I was stopped at the light when a pickup hit me from behind.");
  EXPECT_EQ(claim.participant_count.value, 2);
  EXPECT_EQ(claim.crash.struck.value, "V1");
}

TEST(NarrativeExtractorTest, PreEventMovementRoundTripsThroughJson) {
  const auto r = kExtractor.Extract(
      "V1 stopped at the stop sign and then turned left. V2 was traveling east. V2 struck V1.");
  const AccidentRecord back = AccidentRecordFromJson(ToJson(r));
  EXPECT_EQ(back.vehicles[0].pre_event.value, r.vehicles[0].pre_event.value);
  EXPECT_EQ(back.vehicles[0].movement.value, r.vehicles[0].movement.value);
}

TEST(NarrativeExtractorTest, TheDriverOfAVehicleIsNotItsLeftSide) {
  const auto r = kExtractor.Extract(
      "V1 was traveling east. V2 was traveling west. The driver of V1 tried to avoid V2 by steering right but the "
      "front of V2 struck the front of V1.");
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kFront);
  EXPECT_EQ(r.crash.type.value, CrashType::kHeadOn);
  const auto door = kExtractor.Extract("V1 was traveling east. V2 struck V1 in the driver's door.");
  EXPECT_EQ(door.crash.struck_area.value, DamageArea::kLeft);
}

TEST(NarrativeExtractorTest, CouldNotAvoidStrikingIsNotTheImpactSentence) {
  const auto r = kExtractor.Extract(
      "V1 was southbound. V2 was northbound. V1 drifted into the northbound lane. The driver of V2 steered right "
      "but could not avoid striking V1. The front of V1 struck the front of V2 on the east shoulder.");
  EXPECT_EQ(r.crash.striking.value, "V1");
  EXPECT_EQ(r.crash.struck.value, "V2");
  EXPECT_EQ(r.crash.type.value, CrashType::kHeadOn);
}

TEST(NarrativeExtractorTest, AReportedSentenceThatNamesThePlanesIsTheImpact) {
  const auto r = kExtractor.Extract(
      "V1 was traveling west. V2 was also traveling west, ahead of V1. V3 was traveling east. The driver of V1 reported that "
      "he steered to the left, but the right side of V1 struck the rear of V2. Then the front of V1 struck the "
      "left side of V3.");
  EXPECT_EQ(r.crash.struck.value, "V2");
  EXPECT_EQ(r.crash.striking_area.value, DamageArea::kRight);
  EXPECT_EQ(r.crash.type.value, CrashType::kSideswipeSame);
}

TEST(NarrativeExtractorTest, WaitingToTurnThenEnteringTheRoadIsATurn) {
  const auto r = kExtractor.Extract(
      "V1 was stopped in a driveway, waiting to make a left turn onto the road. V2 was traveling north. V1 began "
      "to enter the roadway with the intention of turning left, and the front of V2 struck the left side of V1.");
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStopped);
  EXPECT_EQ(r.crash.type.value, CrashType::kTurnIntoPath);
}

TEST(NarrativeExtractorTest, AParkedVehicleThatPullsOutIsATrafficUnit) {
  const auto r = kExtractor.Extract(
      "V1 was parked off the right side of the road. V2 was traveling north. V1 entered the roadway from the "
      "right to make a U-turn. V2 struck V1 in the left side with its front.");
  EXPECT_FALSE(r.vehicles[0].parked.value);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kMerging);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_NE(r.crash.type.value, CrashType::kSingleVehicle);
  const auto parked = kExtractor.Extract(
      "V1 was traveling north. V2 was parked and unoccupied on the shoulder. V1 struck the rear of V2.");
  EXPECT_TRUE(parked.vehicles[1].parked.value);
  EXPECT_EQ(parked.crash.type.value, CrashType::kSingleVehicle);
}

TEST(NarrativeExtractorTest, AVehicleNotInTheFirstHarmfulEventMakesItSingleVehicle) {
  const auto r = kExtractor.Extract(
      "V1 ran off the left side of the road and struck the trailer of V2 with its top. No critical precrash "
      "event was coded to the driver of V2 because he was not involved in the first harmful event.");
  EXPECT_EQ(r.crash.type.value, CrashType::kSingleVehicle);
}

TEST(NarrativeExtractorTest, ATurnLaneIsNotATurn) {
  const auto r = kExtractor.Extract(
      "V1 was stopped at the exit of a parking lot. V2 was traveling east in the two-way left turn lane. V1 pulled "
      "out to turn left and the front of V1 struck the front of V2.");
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, PastPerfectAfterTheImpactStillDescribesBeforeIt) {
  const auto r = kExtractor.Extract(
      "V1 was traveling west when it struck the left side of V2. V2 had been southbound on the side road and had "
      "stopped at the stop sign before it began its left turn.");
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kStopped);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kTurnLeft);
}

TEST(NarrativeExtractorTest, OthersStoppedTrafficIsNotThisVehiclesStop) {
  const auto r = kExtractor.Extract(
      "V1 was traveling north. V2 was traveling south. The driver of V1 recognized slowing or stopped traffic "
      "ahead and swerved left. The front of V1 struck the front of V2.");
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, AVehicleOnAnEntranceRampIsMerging) {
  const auto r = kExtractor.Extract(
      "V1 was traveling on a one-way entrance ramp toward the right westbound lane of a freeway. V2 was traveling "
      "west in the right lane. The front of V2 struck the left side of V1.");
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kMerging);
}

TEST(NarrativeExtractorTest, ShortDescriptionsWithoutVehicleNumbers) {
  const auto tbone = kExtractor.Extract(
      "A red sedan ran a red light and T-boned a white SUV that was crossing the intersection. The sedan was "
      "going about 40 mph.");
  ASSERT_EQ(tbone.participant_count.value, 2);
  EXPECT_EQ(tbone.vehicles[1].vehicle_class.value, VehicleClass::kSuv);
  EXPECT_NEAR(tbone.vehicles[0].speed_mps.value, 40 * 0.44704, 1e-9);  // "the sedan" is V1
  EXPECT_EQ(tbone.crash.striking.value, "V1");
  EXPECT_EQ(tbone.crash.type.value, CrashType::kAngle);
  EXPECT_EQ(tbone.crash.location.value, CrashLocation::kJunction);

  const auto mine = kExtractor.Extract(
      "My car was stopped at a red light when a pickup truck rear-ended me at around 30 km/h.");
  ASSERT_EQ(mine.participant_count.value, 2);
  EXPECT_EQ(mine.vehicles[0].movement.value, Movement::kStopped);
  EXPECT_EQ(mine.vehicles[1].vehicle_class.value, VehicleClass::kPickup);
  EXPECT_NEAR(mine.vehicles[1].speed_mps.value * 3.6, 30.0, 1e-9);
  EXPECT_EQ(mine.crash.striking.value, "V2");
  EXPECT_EQ(mine.crash.type.value, CrashType::kRearEnd);

  const auto side = kExtractor.Extract(
      "I was driving north on Elm Street when a van ran the stop sign and hit my car on the driver side.");
  EXPECT_EQ(side.vehicles[0].travel.value, Compass::kNorth);
  EXPECT_EQ(side.crash.struck.value, "V1");
  EXPECT_EQ(side.crash.struck_area.value, DamageArea::kLeft);
  EXPECT_EQ(side.crash.location.value, CrashLocation::kJunction);
}

TEST(NarrativeExtractorTest, AShortDescriptionOfOneUnintroducedVehicleNamesItV1) {
  // Nobody says "a car": the car is told as "his car" or "the car", its
  // driver as "he" or "she"; both are the one vehicle of the crash.
  const auto driven = kExtractor.Extract(
      "He was driving his car north on Main Street when he lost control and struck a tree.");
  ASSERT_EQ(driven.participant_count.value, 1);
  EXPECT_EQ(driven.vehicles[0].travel.value, Compass::kNorth);
  EXPECT_EQ(driven.crash.striking.value, "V1");
  EXPECT_EQ(driven.crash.type.value, CrashType::kSingleVehicle);

  const auto driver = kExtractor.Extract(
      "The driver of the car was westbound on Route 5 at night when she ran off the road and hit a utility pole.");
  EXPECT_EQ(driver.vehicles[0].travel.value, Compass::kWest);
  EXPECT_EQ(driver.crash.striking.value, "V1");
}

TEST(NarrativeExtractorTest, AReportThatNamesItsVehiclesByMakeNumbersThemInOrder) {
  // No V1 or V2 anywhere: a make with its model year in brackets, then an
  // indefinite one with a direction before the year; later "the tundra".
  const auto r = kExtractor.Extract(
      "The Escape (2009 Ford Escape) was eastbound in the left lane of a divided highway. It crossed the "
      "median and struck a westbound 2012 Toyota Tundra pickup head-on. The Tundra's driver braked. A car "
      "behind the Tundra was not struck and its driver stopped to help.");
  ASSERT_EQ(r.participant_count.value, 2);
  EXPECT_EQ(r.vehicles[0].travel.value, Compass::kEast);
  EXPECT_EQ(r.vehicles[1].vehicle_class.value, VehicleClass::kPickup);
  EXPECT_EQ(r.crash.striking.value, "V1");
  EXPECT_EQ(r.crash.struck.value, "V2");
}

TEST(NarrativeExtractorTest, ACaseVehicleReportNamesTheOtherVehicleAfterIt) {
  // "The case vehicle" is V1; "the other vehicle, a ..." and "a 2014 ram
  // 1500 pickup was westbound" are V2, with what they did.
  const auto other = kExtractor.Extract(
      "The case vehicle, a 2008 Buick Lucerne, was traveling south in the southbound lane. The other vehicle, a "
      "2013 Hyundai Accent sedan, had stopped in a parking lot exit facing east. The Hyundai's driver pulled out "
      "to turn left, and the front of the Buick struck the left side of the Hyundai.");
  ASSERT_EQ(other.participant_count.value, 2);
  EXPECT_EQ(other.vehicles[1].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(other.crash.struck.value, "V2");
  EXPECT_EQ(other.crash.struck_area.value, DamageArea::kLeft);

  const auto pickup = kExtractor.Extract(
      "The case vehicle, a 2015 Mazda CX-5, was northbound on a rural road and stopped at a stop sign. A 2014 Ram "
      "1500 pickup was westbound on the through road. The case vehicle pulled into the intersection and the front "
      "of the Ram struck its right side.");
  ASSERT_EQ(pickup.participant_count.value, 2);
  EXPECT_EQ(pickup.vehicles[1].travel.value, Compass::kWest);
  EXPECT_EQ(pickup.crash.striking.value, "V2");
}

TEST(NarrativeExtractorTest, AnUnnumberedVehicleOnlyAtTheSceneAfterwardTookNoPart) {
  const auto r = kExtractor.Extract(
      "The case vehicle was westbound on a wet two-lane road at night when it slid off the road. The left side of "
      "the vehicle struck a utility pole. No other vehicles were involved, and a car that had been following at a "
      "distance stopped and its occupants called 911.");
  EXPECT_EQ(r.participant_count.value, 1);
  EXPECT_EQ(r.crash.type.value, CrashType::kSingleVehicle);
}

TEST(NarrativeExtractorTest, AParkedVehicleNumberedAtTheEndMakesItASingleVehicleCrash) {
  // "The parked Ranger (V2)" keeps how it stood; "a second car" that "was
  // not involved" is one more car, not V2.
  const auto parked = kExtractor.Extract(
      "A 1997 Ford Ranger pickup had been left on the shoulder. V1, a 2001 Dodge Caravan, was northbound. The van "
      "drifted onto the shoulder and its front struck the back of the parked Ranger. The parked Ranger (V2) was not "
      "in transport.");
  ASSERT_EQ(parked.participant_count.value, 2);
  EXPECT_TRUE(parked.vehicles[1].parked.value);
  EXPECT_EQ(parked.crash.type.value, CrashType::kSingleVehicle);
  EXPECT_EQ(parked.crash.struck_area.value, DamageArea::kRear);

  const auto alone = kExtractor.Extract(
      "Vehicle one was northbound on a county road when it left the road in a curve and the front struck a tree. A "
      "second car carrying friends, which had been following, was not involved.");
  EXPECT_EQ(alone.participant_count.value, 1);
  EXPECT_EQ(alone.crash.type.value, CrashType::kSingleVehicle);
  EXPECT_EQ(alone.crash.striking.value, "V1");
}

TEST(NarrativeExtractorTest, AnErrandStopOnTheWayIsNoPreCrashStop) {
  const auto r = kExtractor.Extract(
      "V1 was northbound negotiating a curve when it drifted over the centerline. V2 was southbound in its lane. The "
      "front of V1 struck the front of V2. The driver of V1 had stopped at a convenience store about 20 minutes "
      "before the crash to buy coffee.");
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
  // A stop in a station's exit before pulling out is still the stop.
  const auto exit = kExtractor.Extract(
      "V2 had stopped at the gas station exit and then pulled out to turn left. V1 was eastbound. V1 struck V2.");
  EXPECT_EQ(exit.vehicles[1].pre_event.value, Movement::kStopped);
}

TEST(NarrativeExtractorTest, ALimitToldAsANumberBeforeTheWordIsRead) {
  const auto r = kExtractor.Extract(
      "A car turned left onto Highway 50 and got hit by a pickup. Highway 50 is four lanes with no median and a 55 "
      "limit.");
  EXPECT_NEAR(r.road.speed_limit_mps.value, 55 * 0.44704, 1e-9);
  const auto zone = kExtractor.Extract("V1 was northbound in a 25 zone when it struck V2, which was parked.");
  EXPECT_NEAR(zone.road.speed_limit_mps.value, 25 * 0.44704, 1e-9);
}

TEST(NarrativeExtractorTest, AShortDescriptionNamesARelativesCarAndAModel) {
  const auto kin = kExtractor.Extract(
      "A car crossed the center line on Route 12 and hit my son's Silverado head on.");
  ASSERT_EQ(kin.participant_count.value, 2);
  EXPECT_EQ(kin.crash.striking.value, "V1");
  EXPECT_EQ(kin.crash.struck.value, "V2");

  const auto model = kExtractor.Extract(
      "A van ran the stop sign and hit a Camry that was crossing the intersection. The Camry was pushed into a pole.");
  ASSERT_EQ(model.participant_count.value, 2);
  EXPECT_EQ(model.crash.struck.value, "V2");
  EXPECT_EQ(model.crash.type.value, CrashType::kAngle);
}

TEST(NarrativeExtractorTest, AnAreaBelongsToTheNearestVehicle) {
  const auto r = kExtractor.Extract("V1 was driving north. V2 hit V1 on the left side.");
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kLeft);
  EXPECT_EQ(r.crash.striking_area.value, DamageArea::kFront);
}

TEST(NarrativeExtractorTest, AStreetAbbreviationDoesNotJoinTwoVehiclesSentences) {
  const auto r = kExtractor.Extract(
      "Unit 1 was westbound on Main St. Unit 2 was eastbound and turned left in front of Unit 1 at the "
      "intersection with 5th Ave. Unit 1 struck Unit 2 on the passenger side.");
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kStraight);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(r.vehicles[1].travel.value, Compass::kEast);
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kRight);
  EXPECT_EQ(r.crash.type.value, CrashType::kTurnAcrossPath);
}

TEST(NarrativeExtractorTest, ATurnFromTheWrongLaneWasPrecededByDrivingOn) {
  // A right turn across the lane of a vehicle going the same way (the
  // real crossing/17, 19 and 21): going straight before the critical turn.
  const auto r = kExtractor.Extract(
      "V1 was traveling east in the left lane and turned right at the intersection. V2 was traveling east in the "
      "right lane. The front of V2 struck the right side of V1. The critical precrash event for V1 was this vehicle "
      "traveling, turning right at intersection.");
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnRight);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
  const auto oncoming = kExtractor.Extract(
      "V1 was traveling east and turned left at the intersection. V2 was traveling west. The front of V2 struck "
      "the right side of V1. The critical precrash event for V1 was this vehicle traveling, turning left at "
      "intersection.");
  EXPECT_EQ(oncoming.vehicles[0].pre_event.value, Movement::kTurnLeft);
}

TEST(NarrativeExtractorTest, AStopOnSeeingTheOtherIsTheAvoidanceNotThePreEvent) {
  const auto r = kExtractor.Extract(
      "V1 was traveling north around the bend. V1 saw V2 coming over the center line and stopped. The front of "
      "V2 struck the left side of V1.");
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
  const auto waited = kExtractor.Extract(
      "V1 was stopped in the northbound lane waiting for traffic. The front of V2 struck the rear of V1.");
  EXPECT_EQ(waited.vehicles[0].pre_event.value, Movement::kStopped);
}

TEST(NarrativeExtractorTest, WithTheRearOfTheOtherIsNotTheStrikersRear) {
  const auto r = kExtractor.Extract("Vehicle #1 impacted with the rear of Vehicle #2 with its front.");
  EXPECT_EQ(r.crash.striking_area.value, DamageArea::kFront);
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kRear);
  const auto side = kExtractor.Extract("Vehicle #1 impacted with the left side of Vehicle #2 with its front.");
  EXPECT_EQ(side.crash.striking_area.value, DamageArea::kFront);
  EXPECT_EQ(side.crash.struck_area.value, DamageArea::kLeft);
}

TEST(NarrativeExtractorTest, PoliceStyleVehicleNamesAndSpeedZones) {
  const auto cars = kExtractor.Extract(
      "Car 1 was traveling east. Car 2 was traveling north. Car 2 struck the left side of Car 1 in the "
      "intersection.");
  ASSERT_EQ(cars.participant_count.value, 2);
  EXPECT_EQ(cars.crash.striking.value, "V2");
  EXPECT_EQ(cars.crash.type.value, CrashType::kAngle);
  const auto ordinals = kExtractor.Extract(
      "The first vehicle was traveling west when it was struck by the second vehicle, which was turning left.");
  ASSERT_EQ(ordinals.participant_count.value, 2);
  EXPECT_EQ(ordinals.vehicles[1].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(ordinals.crash.striking.value, "V2");
  const auto zone = kExtractor.Extract(
      "Driver 1 was traveling north on Route 9 in a 45 mph zone. Vehicle 2 pulled out of a private driveway and "
      "Vehicle 1 struck Vehicle 2 on the driver side door. The trip was 3 miles long.");
  EXPECT_NEAR(zone.road.speed_limit_mps.value, 45 * 0.44704, 1e-9);
  EXPECT_EQ(zone.road.speed_limit_mps.source, Provenance::kStated);
  EXPECT_EQ(zone.participant_count.value, 2);  // "3 miles" is no vehicle
  EXPECT_EQ(zone.crash.location.value, CrashLocation::kDriveway);
  EXPECT_EQ(zone.crash.type.value, CrashType::kAngle);
}

TEST(NarrativeExtractorTest, BothVehiclesDirectionAndTheStrikersSideInASideswipe) {
  const auto r = kExtractor.Extract(
      "V2 was changing lanes to the left when its left side sideswiped the right side of V1, which was traveling "
      "in the left lane. Both vehicles were eastbound on the interstate.");
  EXPECT_EQ(r.vehicles[0].travel.value, Compass::kEast);
  EXPECT_EQ(r.vehicles[1].travel.value, Compass::kEast);
  EXPECT_EQ(r.crash.striking.value, "V2");
  EXPECT_EQ(r.crash.striking_area.value, DamageArea::kLeft);
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kRight);
  EXPECT_EQ(r.crash.type.value, CrashType::kSideswipeSame);
}

TEST(NarrativeExtractorTest, BackingIsAVehiclesQueuedTrafficIsNot) {
  const auto r = kExtractor.Extract(
      "V1 was backing out of a parking space when its rear struck the left side of V2, which was traveling "
      "through the lot. Traffic was backed up on the street.");
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kBacking);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, TheyCollidedThenTheRolesInTheNextSentence) {
  const auto r = kExtractor.Extract(
      "Vehicle 1 was traveling south at 50 mph and Vehicle 2 was traveling east at 30 mph when they collided in "
      "the intersection; the front of Vehicle 1 hit the right side of Vehicle 2.");
  EXPECT_EQ(r.crash.striking.value, "V1");
  EXPECT_EQ(r.crash.struck.value, "V2");
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kRight);
  EXPECT_EQ(r.crash.type.value, CrashType::kAngle);
}

TEST(NarrativeExtractorTest, AttemptingToPassIsPassing) {
  const auto r = kExtractor.Extract(
      "V2 was attempting to pass V1 on the left when V1 began a left turn into a driveway. The front of V2 struck "
      "the left side of V1.");
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kPassing);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnLeft);
}

TEST(NarrativeExtractorTest, ModelYearIntroductionsAndTheStrikersOwnFront) {
  const auto pole = kExtractor.Extract(
      "The driver of a 2010 Honda Accord lost control on a wet curve, left the road to the right and struck a "
      "utility pole with the front of the car.");
  ASSERT_EQ(pole.participant_count.value, 1);
  EXPECT_EQ(pole.vehicles[0].description.value, "2010 honda accord");
  EXPECT_EQ(pole.crash.striking.value, "V1");
  EXPECT_EQ(pole.crash.struck.value, "object");
  EXPECT_EQ(pole.crash.type.value, CrashType::kSingleVehicle);
  const auto light = kExtractor.Extract(
      "A 2004 Ford Taurus was traveling north when it was struck by a 2008 Chevrolet Silverado pickup that ran "
      "the red light.");
  ASSERT_EQ(light.participant_count.value, 2);
  EXPECT_EQ(light.vehicles[1].vehicle_class.value, VehicleClass::kPickup);
  EXPECT_EQ(light.crash.striking.value, "V2");
  EXPECT_EQ(light.crash.type.value, CrashType::kAngle);
  EXPECT_EQ(light.crash.location.value, CrashLocation::kJunction);
}

TEST(NarrativeExtractorTest, AListOfVehiclesSharesADirection) {
  const auto r = kExtractor.Extract(
      "V1, V2 and V3 were northbound in lane one. V3 stopped for traffic. V2 stopped behind V3. V1 struck the "
      "rear of V2, pushing V2 into the rear of V3.");
  ASSERT_EQ(r.vehicles.size(), 3u);
  for (const auto& v : r.vehicles) EXPECT_EQ(v.travel.value, Compass::kNorth) << v.id;
  EXPECT_EQ(r.crash.type.value, CrashType::kRearEnd);
}

TEST(NarrativeExtractorTest, WhatMakesARoadDivided) {
  const auto freeway = kExtractor.Extract(
      "V1 was traveling south in the right southbound lane of a 4-lane, divided, limited access freeway (two lanes "
      "southbound, two lanes northbound). V1 struck the rear of V2.");
  EXPECT_TRUE(freeway.road.divided.value);
  EXPECT_EQ(freeway.road.lanes_per_direction.value, 2);
  const auto paint = kExtractor.Extract(
      "The two-lane two-way roadway was divided by two solid yellow lines. V1 was traveling east. V1 struck V2.");
  EXPECT_FALSE(paint.road.divided.value);
  const auto nearby = kExtractor.Extract(
      "V1 was traveling north on a 3-lane roadway toward a nearby interstate. V1 struck V2.");
  EXPECT_FALSE(nearby.road.divided.value);
}

TEST(NarrativeExtractorTest, FrontToFrontNamesBothPlanes) {
  const auto r = kExtractor.Extract(
      "V1 was traveling north about 30 MPH. V2 was traveling south. V1 and V2 collided front to front.");
  EXPECT_EQ(r.crash.striking.value, "V1");
  EXPECT_EQ(r.crash.struck.value, "V2");
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kFront);
  EXPECT_EQ(r.crash.type.value, CrashType::kHeadOn);
}

TEST(NarrativeExtractorTest, UnitAndDriverShorthandNameTheVehicles) {
  const auto r = kExtractor.Extract(
      "U1 WAS WESTBOUND ON PINE RD. U2 WAS STOPPED AHEAD OF U1 FOR A TRAIN. D1 SAID HE LOOKED AWAY. FRONT OF U1 "
      "STRUCK REAR OF U2.");
  ASSERT_EQ(r.participant_count.value, 2);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kStopped);
  EXPECT_EQ(r.crash.striking.value, "V1");
  EXPECT_EQ(r.crash.struck.value, "V2");
  EXPECT_EQ(r.crash.type.value, CrashType::kRearEnd);
}

TEST(NarrativeExtractorTest, LetteredVehiclesAndAJunctionToldOnlyByItsSignal) {
  // "Vehicle A", "car B": lettered in order.
  const auto r = kExtractor.Extract(
      "Vehicle A was northbound and Vehicle B was eastbound. Vehicle A ran the red light and struck the left side of "
      "Vehicle B.");
  ASSERT_EQ(r.participant_count.value, 2);
  EXPECT_EQ(r.vehicles[0].travel.value, Compass::kNorth);
  EXPECT_EQ(r.vehicles[1].travel.value, Compass::kEast);
  EXPECT_EQ(r.crash.striking.value, "V1");
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kLeft);
  EXPECT_EQ(r.crash.type.value, CrashType::kAngle);
  // No sentence names the intersection: the red light places the crash at
  // one, and the roads cross there.
  EXPECT_EQ(r.crash.location.value, CrashLocation::kJunction);
  EXPECT_EQ(r.road.kind.value, RoadKind::kIntersection);
  // A letter without a second one is a word: one vehicle.
  EXPECT_EQ(kExtractor.Extract("He drove the car a short distance and struck a tree.").participant_count.value, 1);
  // A turn made at a green light is a turn at a junction.
  const auto t =
      kExtractor.Extract("I was turning left at a green light when an oncoming SUV hit my passenger side.");
  EXPECT_EQ(t.crash.type.value, CrashType::kTurnAcrossPath);
  EXPECT_EQ(t.crash.location.value, CrashLocation::kJunction);
  EXPECT_EQ(t.road.kind.value, RoadKind::kIntersection);
}

TEST(NarrativeExtractorTest, ThePairThatCollidedIsBothVehicles) {
  for (const char* contact : {"The two collided front to front", "Both vehicles then collided",
                              "The two vehicles collided"}) {
    const auto r = kExtractor.Extract(std::string("Vehicle #1, a pickup, was westbound on a two-lane road. Vehicle #2, "
                                                  "a sedan, was eastbound. ") +
                                      contact + " in the eastbound lane, head-on. Both drivers were injured.");
    ASSERT_EQ(r.participant_count.value, 2) << contact;
    EXPECT_EQ(r.crash.type.value, CrashType::kHeadOn) << contact;
    EXPECT_EQ(r.crash.striking.value, "V1") << contact;
    EXPECT_EQ(r.crash.struck.value, "V2") << contact;
  }
}

TEST(NarrativeExtractorTest, AParkedCarTheOtherDriverSawPullOutFromTheCurbLeftItsPosition) {
  const auto r = kExtractor.Extract(
      "Vehicle 1 (1999 Mercury Grand Marquis) and Vehicle 2 (2005 Dodge Ram van) collided on a downtown street with "
      "one travel lane in each direction. The Mercury had been parallel-parked along the south curb facing east. The "
      "van was eastbound in the travel lane. According to the van's driver, the Mercury's turn signal was not on and "
      "the car \"just came out from the curb\" when he was nearly alongside. The van's right front struck the "
      "Mercury's left front fender.");
  ASSERT_EQ(r.participant_count.value, 2);
  EXPECT_FALSE(r.vehicles[0].parked.value);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kMerging);
  EXPECT_EQ(r.crash.type.value, CrashType::kTurnAcrossPath);
}

TEST(NarrativeExtractorTest, AMakeDescribedBeforeItsNumberAndTheParkedCarAVehiclePasses) {
  const auto r = kExtractor.Extract(
      "The Volvo, a 1996 850 sedan (Vehicle 2), had been parallel-parked along the south curb facing east. Its "
      "driver signaled and pulled out of the space. The Jeep, a 2005 Wrangler (Vehicle 1), was eastbound in the "
      "travel lane and was passing the parked Volvo. The left front of the Volvo struck the right side of the Jeep.");
  ASSERT_EQ(r.participant_count.value, 2);
  EXPECT_FALSE(r.vehicles[0].parked.value);  // the one passing is not the parked one
  EXPECT_NE(r.vehicles[0].pre_event.value, Movement::kStopped);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kMerging);
  EXPECT_EQ(r.crash.striking.value, "V2");
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kRight);
}

TEST(NarrativeExtractorTest, AVehicleThatOnlyComesByAfterTheCrashTookNoPart) {
  const auto r = kExtractor.Extract(
      "Vehicle two (V2), a Chevrolet Malibu, was traveling east. Vehicle one (V1), a Ford Ranger, was traveling west "
      "and lost control on the ice. The front of V1 struck the left side of V2. Both vehicles came to rest in the "
      "eastbound lane. A third vehicle, a snowplow traveling east about 400 meters behind V2, stopped and the "
      "operator radioed for assistance. Both vehicles were towed.");
  EXPECT_EQ(r.participant_count.value, 2);
  // One pushed into, or damaged, did take part.
  const auto chain = kExtractor.Extract(
      "V1 struck the rear of V2, which was stopped in traffic. V2 was then pushed into the rear of V3.");
  EXPECT_EQ(chain.participant_count.value, 3);
}

TEST(NarrativeExtractorTest, SheIsTheDriverToldAsAWoman) {
  const auto r = kExtractor.Extract(
      "V1, a 1998 Buick LeSabre driven by a 79-year-old female, was exiting the parking lot of a store on the south "
      "side of an east-west road. She was facing north in the mouth of the driveway intending to turn left. V2, a "
      "GMC Envoy, was eastbound in the right lane approaching the driveway. A westbound tractor-trailer had slowed "
      "and flashed its headlights, which the V1 driver interpreted as a signal to proceed. She pulled out across the "
      "eastbound lanes. The front of V2 struck the left side of V1. The 35-year-old driver of V2 was not injured.");
  ASSERT_EQ(r.participant_count.value, 2);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kStraight);
  // A trucker who stopped after the crash is not the vehicle last named.
  const auto t = kExtractor.Extract(
      "Vehicle 1 pulled into the westbound lane to pass a line of traffic. Vehicle 2, a minivan, came over the crest "
      "westbound. The front of Vehicle 1 struck the front of Vehicle 2. The minivan was driven by a 40-year-old "
      "female. She said Vehicle 1 came out of nowhere. She was transported. The trucker, who stopped, said Vehicle 1 "
      "passed on the double yellow.");
  EXPECT_EQ(t.vehicles[1].pre_event.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, TheDriversTurnToldAfterAVanThatBlockedHerView) {
  const auto r = kExtractor.Extract(
      "Vehicle #1, a 2005 Honda CR-V, was northbound in the inside lane and was stopped at the stop bar waiting to "
      "turn left onto the side street. Vehicle #2, a 1999 Ford Crown Victoria, was southbound in the inside lane "
      "approaching the same intersection. The driver of the Honda stated to the researcher that a southbound "
      "delivery van waiting to turn left had blocked her view, and when the van turned she began her turn believing "
      "the lanes beyond it were clear. As the Honda crossed the southbound lanes the front of the Ford struck the "
      "right side of the Honda.");
  ASSERT_EQ(r.participant_count.value, 2);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(r.crash.type.value, CrashType::kTurnAcrossPath);
}

TEST(NarrativeExtractorTest, PoliceAbbreviationsForDirectionLanesAndIntersection) {
  const auto r = kExtractor.Extract(
      "V1 WAS NB ON A 4 LN UNDIVIDED RDWY, POSTED 40 MPH. V2 WAS EB ON BIRCH ST. FRONT OF V2 STRUCK LEFT SIDE OF "
      "V1 IN THE INTX.");
  EXPECT_EQ(r.vehicles[0].travel.value, Compass::kNorth);
  EXPECT_EQ(r.vehicles[1].travel.value, Compass::kEast);
  EXPECT_EQ(r.road.lanes_total.value, 4);
  EXPECT_EQ(r.crash.location.value, CrashLocation::kJunction);
  EXPECT_EQ(r.crash.type.value, CrashType::kAngle);
}

TEST(NarrativeExtractorTest, ShortDescriptionsNameNarratorMakesRidersAndAppositives) {
  const auto narrator = kExtractor.Extract(
      "I was waiting at a red light on Cole Street when a green van struck me from behind.");
  ASSERT_EQ(narrator.participant_count.value, 2);
  EXPECT_EQ(narrator.vehicles[1].vehicle_class.value, VehicleClass::kVan);
  EXPECT_EQ(narrator.crash.striking.value, "V2");
  const auto make = kExtractor.Extract(
      "A red Honda Fit was stopped at the light when a Dodge Ram hit it from behind.");
  ASSERT_EQ(make.participant_count.value, 2);
  EXPECT_EQ(make.vehicles[1].vehicle_class.value, VehicleClass::kPickup);
  const auto rider = kExtractor.Extract(
      "A motorcyclist was thrown on Dover Lane when a taxi turned left across his path. The motorcycle struck the "
      "right side of the taxi.");
  ASSERT_EQ(rider.participant_count.value, 2);
  EXPECT_EQ(rider.vehicles[0].vehicle_class.value, VehicleClass::kMotorcycle);
  EXPECT_EQ(rider.crash.striking.value, "V1");
  const auto appositive = kExtractor.Extract(
      "A van heading north struck a hatchback heading west. The hatchback, a 2015 Mazda 3, spun into a hedge.");
  EXPECT_EQ(appositive.participant_count.value, 2);
  const auto behind = kExtractor.Extract(
      "I was stopped at a crosswalk when the car behind me hit me. It was a black Audi A4.");
  ASSERT_EQ(behind.participant_count.value, 2);
  EXPECT_EQ(behind.crash.type.value, CrashType::kRearEnd);
}

TEST(NarrativeExtractorTest, TheOtherWayAndThePassengerSideAreNotAboutPeople) {
  const auto r = kExtractor.Extract(
      "V1 was northbound on Elm Road. V2, coming the other way, drifted over and struck the front passenger side "
      "of V1.");
  EXPECT_EQ(r.crash.striking.value, "V2");
  EXPECT_EQ(r.crash.struck.value, "V1");
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kRight);
}

TEST(NarrativeExtractorTest, LanesEachWayDualCarriagewayAndSingleLane) {
  const auto each_way = kExtractor.Extract(
      "Harbour Road has three lanes each way. V1 was westbound in the left lane. V1 struck the rear of V2.");
  EXPECT_EQ(each_way.road.lanes_per_direction.value, 3);
  EXPECT_EQ(each_way.road.lanes_total.value, 6);
  const auto dual = kExtractor.Extract(
      "V1 was travelling north on a dual carriageway at 60 mph. V1 struck the rear of V2.");
  EXPECT_TRUE(dual.road.divided.value);
  const auto ramp = kExtractor.Extract(
      "V1 was on a single-lane ramp behind V2. V2 braked and V1 struck the rear of V2.");
  EXPECT_EQ(ramp.road.lanes_total.value, 1);
}

TEST(NarrativeExtractorTest, AJunctionAtADistanceIsNotTheCrashLocation) {
  const auto away = kExtractor.Extract(
      "V1 WAS SB ON MAPLE AVE ABOUT 200 FT NORTH OF THE NEXT CROSS STREET. FRONT OF V1 STRUCK REAR OF V2.");
  EXPECT_EQ(away.crash.location.value, CrashLocation::kSegment);
  const auto between = kExtractor.Extract(
      "V2 was stopped in traffic midway between two cross streets when V1 struck the rear of V2.");
  EXPECT_EQ(between.crash.location.value, CrashLocation::kSegment);
  const auto meets = kExtractor.Extract(
      "V1 was waiting at the lights where the B210 meets Mill Lane. V2 struck the rear of V1.");
  EXPECT_EQ(meets.crash.location.value, CrashLocation::kJunction);
  const auto junction = kExtractor.Extract(
      "V1 was travelling north at the junction. V2 struck the left side of V1.");
  EXPECT_EQ(junction.crash.location.value, CrashLocation::kJunction);
  const auto petrol = kExtractor.Extract(
      "V2 turned right into the entrance of a petrol station across the path of V1. V1 struck the left side of "
      "V2.");
  EXPECT_EQ(petrol.crash.location.value, CrashLocation::kDriveway);
}

TEST(NarrativeExtractorTest, LeavingTheRoadOntoAnotherAcrossOncomingTrafficIsTurnAcrossPath) {
  const auto across = kExtractor.Extract(
      "V1 was northbound on Lark Street. V2 was southbound on Lark Street and turned left onto Fern Road in front "
      "of V1. The front of V1 struck the right side of V2.");
  EXPECT_EQ(across.crash.type.value, CrashType::kTurnAcrossPath);
  const auto oncoming = kExtractor.Extract(
      "I turned left from Lark Street onto Fern Road. A van coming the other way struck the right side of my car.");
  EXPECT_EQ(oncoming.crash.type.value, CrashType::kTurnAcrossPath);
  const auto into = kExtractor.Extract(
      "V2 was stopped at the stop sign on Fern Road. V2 pulled out to turn left onto northbound Lark Street and was "
      "struck on the left side by V1, which was traveling southbound on Lark Street.");
  EXPECT_EQ(into.crash.type.value, CrashType::kTurnIntoPath);
}

TEST(NarrativeExtractorTest, OvertakingWordsAndAMoveBetweenNamedLanes) {
  const auto began = kExtractor.Extract(
      "V1 was travelling north. V2 was travelling south and began overtaking a bus. V2 collided head-on with V1.");
  EXPECT_EQ(began.vehicles[1].movement.value, Movement::kPassing);
  const auto slower = kExtractor.Extract(
      "V2 pulled out to pass a slower van and struck V1, which was travelling the other way.");
  EXPECT_EQ(slower.vehicles[1].movement.value, Movement::kPassing);
  const auto lanes = kExtractor.Extract(
      "V1 was eastbound in the offside lane. V2 moved from the nearside lane into the offside lane and its front "
      "struck the left side of V1.");
  EXPECT_EQ(lanes.vehicles[1].movement.value, Movement::kChangingLanes);
  EXPECT_EQ(lanes.crash.type.value, CrashType::kSideswipeSame);
}

TEST(NarrativeExtractorTest, ACoordinatedSubjectSharesItsState) {
  const auto r = kExtractor.Extract(
      "Unit 1 was westbound in the left lane. Unit 2 and Unit 3 were ahead of Unit 1 and were slowing for a red "
      "signal. Unit 1 struck the rear of Unit 2, pushing it into Unit 3.");
  ASSERT_EQ(r.vehicles.size(), 3U);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kStraight);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kSlowing);
  EXPECT_EQ(r.vehicles[2].movement.value, Movement::kSlowing);
  const auto listed = kExtractor.Extract(
      "Vehicle 1, Vehicle 2 and Vehicle 3 were northbound. Vehicle 2 and Vehicle 3 were stationary in a queue. "
      "Vehicle 1 struck the rear of Vehicle 2.");
  EXPECT_EQ(listed.vehicles[1].movement.value, Movement::kStopped);
  EXPECT_EQ(listed.vehicles[2].movement.value, Movement::kStopped);
  EXPECT_EQ(listed.vehicles[0].movement.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, AReportedClauseHasItsOwnSubject) {
  const auto r = kExtractor.Extract(
      "V1 was eastbound on Maple Drive. V2 was in a private driveway. D1 stated V2 backed out directly in front "
      "of him. The front of V1 struck the left side of V2.");
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kStraight);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kBacking);
}

TEST(NarrativeExtractorTest, AStateInARelativeClauseAfterTheImpactIsFromBefore) {
  const auto r = kExtractor.Extract(
      "V1 was westbound. V2 was northbound and entered the intersection against a red signal. The front of V2 "
      "struck the left side of V1. V1 was redirected into V3, a 2011 Honda Pilot, which was stopped facing south.");
  ASSERT_EQ(r.vehicles.size(), 3U);
  EXPECT_EQ(r.vehicles[2].movement.value, Movement::kStopped);
  // Told after the impact without a relative clause, a stop is the outcome.
  const auto after = kExtractor.Extract("V1 was northbound. V2 was southbound. V1 struck V2 head-on. V2 stopped in the ditch.");
  EXPECT_EQ(after.vehicles[1].movement.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, AValueThatDescribesTheRoadIsItsLimit) {
  const auto comma = kExtractor.Extract(
      "I was driving south on Ridge Road when I hit ice on a bend and slid into a tree. The road is two lanes, 45 "
      "mph.");
  EXPECT_NEAR(comma.road.speed_limit_mps.value, 45 * 0.44704, 1e-6);
  EXPECT_EQ(comma.road.speed_limit_mps.source, Provenance::kStated);
  const auto adjective = kExtractor.Extract(
      "V1 was northbound on a 35 mph two-lane road at about 50 mph when it struck V2, which was stopped.");
  EXPECT_NEAR(adjective.road.speed_limit_mps.value, 35 * 0.44704, 1e-6);
  // A vehicle's speed on the road is not its limit.
  const auto speed = kExtractor.Extract(
      "V1 was traveling 60 mph on the highway when it struck the rear of V2. V2 was slowing for traffic.");
  EXPECT_NE(speed.road.speed_limit_mps.source, Provenance::kStated);
}

TEST(NarrativeExtractorTest, APronounObjectAndFromBehindMakeARearEnd) {
  const auto r = kExtractor.Extract(
      "A motorcycle was northbound on the ramp. The motorcycle had slowed for a queue when a sedan, a Kia Optima, "
      "struck it from behind.");
  ASSERT_EQ(r.vehicles.size(), 2U);
  EXPECT_EQ(r.crash.striking.value, "V2");
  EXPECT_EQ(r.crash.struck.value, "V1");
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kRear);
  EXPECT_EQ(r.crash.type.value, CrashType::kRearEnd);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kSlowing);
  // Two vehicles before an intransitive verb are still striker and struck in order.
  const auto collided = kExtractor.Extract("V1 was eastbound. V2 was westbound. V1 and V2 collided head-on.");
  EXPECT_EQ(collided.crash.striking.value, "V1");
  EXPECT_EQ(collided.crash.struck.value, "V2");
}

TEST(NarrativeExtractorTest, TheVehiclesRunIntoWereTheStoppedTraffic) {
  const auto r = kExtractor.Extract(
      "A tractor-trailer failed to slow for stopped traffic on eastbound Interstate 80, striking a Toyota Corolla, "
      "which was pushed into a Chevy Malibu, state police said.");
  ASSERT_EQ(r.vehicles.size(), 3U);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kStraight);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kStopped);
  EXPECT_EQ(r.vehicles[2].movement.value, Movement::kStopped);
  EXPECT_EQ(r.crash.type.value, CrashType::kRearEnd);
  // Slowing traffic makes the vehicles ahead slowing; a vehicle with its own state keeps it.
  const auto slowing = kExtractor.Extract(
      "V1 did not slow for slowing traffic and struck the rear of V2. V3 was parked on the shoulder and was struck by "
      "V2.");
  EXPECT_EQ(slowing.vehicles[1].movement.value, Movement::kSlowing);
  EXPECT_EQ(slowing.vehicles[2].movement.value, Movement::kStopped);
  EXPECT_TRUE(slowing.vehicles[2].parked.value);
}

TEST(NarrativeExtractorTest, V1AcrossEveryDescribedRoadWasOnAnUndescribedTwoLaneRoad) {
  const auto stem = kExtractor.Extract(
      "The crash occurred in the westbound lanes of a five-lane roadway with a T-intersection. V1 was southbound "
      "approaching the stop sign. V2 was westbound in the right lane. V1 turned left and the front of V2 struck the "
      "left side of V1.");
  EXPECT_EQ(stem.road.lanes_total.value, 2);
  EXPECT_EQ(stem.road.lanes_total.source, Provenance::kInferred);
  // V1 on the described road keeps its count.
  const auto through = kExtractor.Extract(
      "The crash occurred in the westbound lanes of a five-lane roadway with a T-intersection. V2 was southbound "
      "approaching the stop sign. V1 was westbound in the right lane. V2 turned left and the front of V1 struck the "
      "left side of V2.");
  EXPECT_EQ(through.road.lanes_total.value, 5);
  EXPECT_EQ(through.road.lanes_total.source, Provenance::kStated);
  // A road's axis is the one named before its lane count, not the next road's.
  const auto axes = kExtractor.Extract(
      "This crash occurred at the intersection of an east-west roadway with two lanes in each direction, and a "
      "one-way northbound roadway. V1 was traveling westbound in the left lane. V2 was traveling northbound. The "
      "front of V2 contacted the left side of V1.");
  EXPECT_EQ(axes.road.lanes_total.value, 4);
  EXPECT_EQ(axes.road.lanes_per_direction.value, 2);
}

TEST(NarrativeExtractorTest, APastPerfectSentenceAfterTheImpactPlacesTheCrash) {
  const auto r = kExtractor.Extract(
      "This crash occurred on a two lane undivided straight roadway. V1 was traveling south when it impacted the rear "
      "of V2. V1 came to rest on the shoulder. V2 had been stopped in the northbound lane waiting to make a left turn "
      "into a parking lot.");
  EXPECT_EQ(r.crash.location.value, CrashLocation::kDriveway);
  // Where a vehicle came to rest after the crash does not place it.
  const auto rest = kExtractor.Extract(
      "This crash occurred on a two lane undivided straight roadway. V1 was traveling south when it impacted the rear "
      "of V2, which was stopped. V2 came to rest in a parking lot.");
  EXPECT_EQ(rest.crash.location.value, CrashLocation::kSegment);
}

TEST(NarrativeExtractorTest, LanesThatHeadOneWayAreNotTheRoadsTotal) {
  const auto r = kExtractor.Extract(
      "This crash occurred in the eastbound lanes (two lanes head east and one heads west) of a three lane "
      "undivided roadway. V1 was traveling east in lane two. V2 was traveling east in lane one. V1 struck the left "
      "side of V2.");
  EXPECT_EQ(r.road.lanes_total.value, 3);
  EXPECT_EQ(r.road.lanes_per_direction.value, 2);
}

TEST(NarrativeExtractorTest, AnIntroductionAfterTheImpactIsBackground) {
  const auto r = kExtractor.Extract(
      "This crash occurred on a two-lane roadway at a T intersection. V1 was a 2005 Toyota Tundra, traveling "
      "southbound. V1 struck V2 in the center of its rear bumper. V1 was towed. V2 was a 1997 Dodge 2500 pickup that "
      "was traveling southbound and was stopped to make a left turn at the intersection.");
  ASSERT_EQ(r.vehicles.size(), 2U);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kStopped);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, TheVehicleAsASubjectIsTheOneNamedBeforeIt) {
  const auto r = kExtractor.Extract(
      "V1 was a 1988 Mercedes stopped at the signal. V2 was a 2002 Mercury driving eastbound in the right lane. The "
      "light for V1 turned green and the vehicle started turning left when the front of V2 struck the left-front "
      "corner of V1.");
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kStraight);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStopped);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnLeft);
}

TEST(NarrativeExtractorTest, CoordinatedSubjectsWithTheirDescriptions) {
  const auto r = kExtractor.Extract(
      "Vehicle #1, a 1990 Cadillac DeVille, was traveling westbound. Vehicle #2, a 2003 Volkswagen Passat, and "
      "Vehicle #3, a 1999 Mazda 626, were legally parked and unoccupied along the north curb. Vehicle #1 drifted into "
      "the parking lane, where its front struck the back of Vehicle #2.");
  ASSERT_EQ(r.vehicles.size(), 3U);
  EXPECT_TRUE(r.vehicles[1].parked.value);
  EXPECT_TRUE(r.vehicles[2].parked.value);
  // NASS codes striking a parked vehicle as a single-driver crash.
  EXPECT_EQ(r.crash.type.value, CrashType::kSingleVehicle);
  const auto queue = kExtractor.Extract(
      "Vehicle #3, a 2006 Hyundai Accent, and Vehicle #2, a 2002 Chevrolet Suburban, were stopped in the queue. The "
      "front of Vehicle #1 struck the back of Vehicle #2.");
  EXPECT_EQ(queue.vehicles[1].movement.value, Movement::kStopped);
  EXPECT_EQ(queue.vehicles[2].movement.value, Movement::kStopped);
  // "V2, a 1997 Ford Mustang, 2-door coupe and V3, ... were traveling south":
  // V2 is southbound too, so its front into V1's front is a head-on.
  const auto pass = kExtractor.Extract(
      "Vehicle one (V1), a 2004 Honda Civic, 4-door sedan was traveling north on a two-lane road. Vehicle two (V2), a "
      "1997 Ford Mustang, 2-door coupe and vehicle three (V3), a 2001 Dodge Ram, 2-door pickup truck were traveling "
      "south in the southbound lane, with V2 following V3. The driver of V2 pulled into the northbound lane to pass "
      "V3. The front of V2 struck the front of V1.");
  ASSERT_EQ(pass.vehicles.size(), 3u);
  EXPECT_EQ(pass.vehicles[1].travel.value, Compass::kSouth);
  EXPECT_EQ(pass.crash.type.value, CrashType::kHeadOn);
}

TEST(NarrativeExtractorTest, QueueWordsPassingAndMovingOff) {
  const auto pass = kExtractor.Extract(
      "V1 was westbound behind a slow truck. The driver of V1 pulled into the eastbound lane to pass the truck. V2 "
      "was eastbound. The front of V1 struck the front of V2.");
  EXPECT_EQ(pass.vehicles[0].movement.value, Movement::kPassing);
  const auto line = kExtractor.Extract(
      "V3 was first in line and V2 was stopped behind it. V1 came over the rise and its driver was not able to stop in "
      "time. The front of V1 struck the back of V2.");
  EXPECT_EQ(line.vehicles[2].movement.value, Movement::kStopped);
  EXPECT_EQ(line.vehicles[0].movement.value, Movement::kStraight);
  const auto moving = kExtractor.Extract(
      "V1 was eastbound, stopped for a red signal. When the signal turned green, V1 began moving forward into the "
      "intersection. V2 was southbound and did not stop for the red signal. The front of V2 struck the left side of "
      "V1.");
  EXPECT_EQ(moving.vehicles[0].movement.value, Movement::kStraight);
  // A witness waiting at a bus stop is not the vehicle the text was about.
  const auto witness = kExtractor.Extract(
      "V1 was southbound and entered the intersection against a red signal. V2 was eastbound. The front of V2 struck "
      "the right side of V1. He said the light was yellow. A witness waiting at a bus stop stated the signal was red.");
  EXPECT_EQ(witness.vehicles[0].movement.value, Movement::kStraight);
  // What a driver did not realize another vehicle did is about that vehicle.
  const auto realize = kExtractor.Extract(
      "V2 was northbound and had stopped for pedestrians. V1 was northbound behind V2. The front of V1 struck the back "
      "of V2. The driver of V1 stated she did not realize V2 had stopped.");
  EXPECT_EQ(realize.vehicles[0].movement.value, Movement::kStraight);
  EXPECT_EQ(realize.vehicles[1].movement.value, Movement::kStopped);
}

TEST(NarrativeExtractorTest, TravelLanesOneWayInTheSentenceBeforeAndRoadAxes) {
  const auto travel = kExtractor.Extract(
      "The north/south street had four travel lanes, two in each direction. V1 was northbound behind V2. The front of "
      "V1 struck the back of V2.");
  EXPECT_EQ(travel.road.lanes_total.value, 4);
  const auto one_way = kExtractor.Extract(
      "This crash occurred on a one-way northbound street. The street had three northbound travel lanes. V1 was "
      "northbound in lane three behind V2. The front of V1 struck the back of V2.");
  EXPECT_TRUE(one_way.road.one_way.value);
  EXPECT_EQ(one_way.road.lanes_total.value, 3);
  const auto legs = kExtractor.Extract(
      "The crash occurred at a three-leg intersection. The east/west roadway was a four-lane road with two lanes in "
      "each direction. The north/south roadway, which formed the south leg of the intersection, was a two-lane, "
      "two-way road. V1 was northbound on the south leg and stopped for the stop sign. V2 was eastbound. The front of "
      "V2 struck the left side of V1.");
  EXPECT_EQ(legs.road.lanes_total.value, 2);
}

TEST(NarrativeExtractorTest, MidblockAndTheNextIntersectionAreNotTheJunction) {
  const auto mid = kExtractor.Extract(
      "V1 was eastbound in lane two. V2 was eastbound in lane one. The crash occurred at a midblock location. The "
      "driver of V1 changed lanes to the right to turn at the next intersection, and the right side of V1 struck the "
      "left side of V2.");
  EXPECT_EQ(mid.crash.location.value, CrashLocation::kSegment);
  const auto next = kExtractor.Extract(
      "V1 was eastbound in lane two. V2 was eastbound in lane one. V1 moved right to prepare for a right turn at the "
      "next intersection, and the right side of V1 struck the left side of V2.");
  EXPECT_EQ(next.crash.location.value, CrashLocation::kSegment);
}

TEST(NarrativeExtractorTest, DirectionsAfterTheImpactAndTheFirstPairsCoding) {
  // Where V1 went after the impact is not its course; "following" it is.
  const auto after = kExtractor.Extract(
      "V2 was northbound and was slowing to turn right into a gas station driveway. V1 was following it. The front of "
      "V1 struck the back of V2. V1 continued into the southbound lane.");
  EXPECT_EQ(after.vehicles[0].travel.value, Compass::kNorth);
  EXPECT_EQ(after.crash.type.value, CrashType::kRearEnd);
  // A later pair's coding ("other vehicle stopped" for the third car) does not type the first harmful event.
  const auto chain = kExtractor.Extract(
      "V1 was northbound. V2 was southbound, followed by V3. V1 drifted across the centerline, and its front struck "
      "the front of V2. The front of V3 struck the back of V2. The critical precrash event for V1 was this vehicle "
      "traveling over the lane line on the left side of travel lane. The driver of V3 was not injured. His critical "
      "precrash event was other vehicle stopped in lane ahead.");
  EXPECT_EQ(chain.crash.type.value, CrashType::kHeadOn);
}

TEST(NarrativeExtractorTest, TurnsOffTheRoadAcrossAVehicleGoingTheSameWay) {
  const auto onto = kExtractor.Extract(
      "V1 and V2 were northbound on a two-lane highway. V2 moved into the southbound lane to pass V1. V1 began to turn "
      "left onto a gravel road, and the front of V2 struck the left side of V1.");
  EXPECT_EQ(onto.crash.type.value, CrashType::kTurnAcrossPath);
  const auto drive = kExtractor.Extract(
      "V1 and V2 were traveling north. V2 was ahead of V1. V2 attempted to cross over into a driveway on the west "
      "side of the roadway. V1 struck V2 in the left side with its front.");
  EXPECT_EQ(drive.vehicles[1].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(drive.crash.type.value, CrashType::kTurnAcrossPath);
}

TEST(NarrativeExtractorTest, TheNarratorsPossessionsAndWithoutSignalling) {
  const auto r = kExtractor.Extract(
      "I was driving west in the middle lane. A white Ford Explorer in the lane to my right suddenly moved into my "
      "lane without signalling and hit my passenger side.");
  ASSERT_EQ(r.vehicles.size(), 2U);
  EXPECT_EQ(r.crash.striking.value, "V2");
  EXPECT_EQ(r.crash.struck.value, "V1");
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kRight);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kChangingLanes);
  EXPECT_EQ(r.crash.type.value, CrashType::kSideswipeSame);
  // Across the centre line into the narrator's lane is not a lane change.
  const auto across = kExtractor.Extract(
      "I was driving north. A pickup coming the other way crossed the center line into my lane and hit my car "
      "head-on.");
  EXPECT_NE(across.vehicles[1].movement.value, Movement::kChangingLanes);
  EXPECT_EQ(across.crash.type.value, CrashType::kHeadOn);
}

TEST(NarrativeExtractorTest, TheOtherRoadsMedianDoesNotDivideV1sRoad) {
  const auto r = kExtractor.Extract(
      "V1 was southbound on a three-lane, two-way collector street that formed the north leg of a signalized "
      "T-intersection. The through roadway ran east/west and was a divided highway with three lanes in each "
      "direction separated by a raised median. V2 was westbound in the middle lane. V1 turned left and the front of "
      "V2 struck the left side of V1. V1 came to rest against the median curb.");
  EXPECT_FALSE(r.road.divided.value);
  EXPECT_EQ(r.road.lanes_total.value, 3);
  // V1 on the divided road: divided.
  const auto on = kExtractor.Extract(
      "V1 was westbound on the through roadway, which ran east/west and was a divided highway with three lanes in "
      "each direction. V2 was southbound at the T-intersection. V2 turned left and the front of V1 struck the left "
      "side of V2.");
  EXPECT_TRUE(on.road.divided.value);
}

TEST(NarrativeExtractorTest, AnInvertedSentenceGivesItsVehiclesTheDirection) {
  const auto r = kExtractor.Extract(
      "V1 was northbound on a two-lane highway. Southbound on the same road were V2, followed by V3, and then V4. V1 "
      "drifted across the centerline and its front struck the front of V2.");
  ASSERT_EQ(r.vehicles.size(), 4U);
  for (size_t i = 1; i < 4; ++i) EXPECT_EQ(r.vehicles[i].travel.value, Compass::kSouth) << i;
  EXPECT_EQ(r.vehicles[0].travel.value, Compass::kNorth);
  EXPECT_EQ(r.crash.type.value, CrashType::kHeadOn);
}

TEST(NarrativeExtractorTest, TwoRoadJunctionsTellV1sRoadByItsName) {
  // "no median" is undivided; the county road's lanes and limit are V1's.
  const auto county = kExtractor.Extract(
      "This crash occurred at the four-leg intersection of a north/south rural highway and an east/west county road. "
      "The highway has four travel lanes, two in each direction, with no median, and a posted speed limit of 55 mph. "
      "The county road is a two-lane, two-way road posted at 35 mph. V1 was eastbound on the county road and turned "
      "left. V2 was southbound on the highway. The front of V2 struck the left side of V1.");
  EXPECT_FALSE(county.road.divided.value);
  EXPECT_EQ(county.road.lanes_total.value, 2);
  EXPECT_NEAR(county.road.speed_limit_mps.value, 35 * 0.44704, 1e-6);
  // The stem is the cross street; its limit is the one said of the side street V1 is on.
  const auto stem = kExtractor.Extract(
      "The through road runs east/west and has four lanes, two in each direction, posted 40 MPH. The stem is a "
      "two-lane, two-way street entering from the south. The side street is posted at 25 MPH. V1 was northbound on "
      "the side street and turned left. V2 was eastbound. The front of V2 struck the left side of V1.");
  EXPECT_EQ(stem.road.lanes_total.value, 2);
  EXPECT_NEAR(stem.road.speed_limit_mps.value, 25 * 0.44704, 1e-6);
  // "The road" is no road in particular: the axis decides.
  const auto generic = kExtractor.Extract(
      "The north/south road is a two-lane highway posted 55 MPH. The east/west road is a two-lane road posted 45 "
      "MPH. V1 was eastbound on the east/west road. V2 was northbound. The front of V1 struck the left side of V2.");
  EXPECT_NEAR(generic.road.speed_limit_mps.value, 45 * 0.44704, 1e-6);
}

TEST(NarrativeExtractorTest, ListedLanesAndRampLanes) {
  const auto listed = kExtractor.Extract(
      "V1 was northbound approaching a four-leg intersection. At the intersection the roadway had one northbound "
      "lane, one southbound lane and a northbound left-turn lane. V1 turned left. V2 was southbound. The front of V2 "
      "struck the right side of V1.");
  EXPECT_EQ(listed.road.lanes_total.value, 3);
  // A stated total stands: the centre lane is among the five.
  const auto five = kExtractor.Extract(
      "The arterial is a five-lane roadway with two northbound lanes, two southbound lanes, and a center two-way "
      "left-turn lane. V1 was southbound and turned left. V2 was northbound. The front of V2 struck the right side of "
      "V1.");
  EXPECT_EQ(five.road.lanes_total.value, 5);
  const auto ramp = kExtractor.Extract(
      "The crash occurred where a single-lane entrance ramp joins the eastbound lanes of a freeway. The freeway has "
      "three eastbound lanes. V1 was entering the freeway from the ramp. V2 was eastbound in lane one. The left side "
      "of V1 contacted the right side of V2.");
  EXPECT_EQ(ramp.road.lanes_total.value, 1);
  EXPECT_TRUE(ramp.road.one_way.value);
}

TEST(NarrativeExtractorTest, StopsSlowingsAndUTurnsInOtherWords) {
  const auto brought = kExtractor.Extract(
      "V1 was northbound and its driver intended to turn left. The driver brought V1 to a complete stop to wait for a "
      "gap. V2 was southbound. V1 started its turn, and the front of V2 struck the right side of V1.");
  EXPECT_EQ(brought.vehicles[0].pre_event.value, Movement::kStopped);
  const auto never = kExtractor.Extract(
      "V1 was southbound. The driver of V1 slowed as she approached but never came to a stop, and began a left turn. "
      "V2 was northbound. The front of V2 struck the right side of V1.");
  EXPECT_EQ(never.vehicles[0].pre_event.value, Movement::kSlowing);
  const auto coasted = kExtractor.Extract(
      "V2 had run out of fuel and coasted to a stop in the right lane. V1 was northbound behind it. The front of V1 "
      "struck the back of V2.");
  EXPECT_EQ(coasted.vehicles[1].movement.value, Movement::kStopped);
  const auto slowed_to = kExtractor.Extract(
      "V1 was eastbound and its driver intended to turn left. He slowed to about 20 km/h with his left turn signal "
      "on. V2 was passing. The front of V2 struck the left side of V1.");
  EXPECT_EQ(slowed_to.vehicles[0].pre_event.value, Movement::kSlowing);
  // A turn signal is not a turn.
  const auto signal = kExtractor.Extract(
      "V1 was eastbound with its right turn signal on and began slowing. V2 was eastbound behind V1. The front of V2 "
      "struck the back of V1.");
  EXPECT_EQ(signal.vehicles[0].movement.value, Movement::kSlowing);
  const auto u_turn = kExtractor.Extract(
      "V1 was eastbound in the right lane. Without stopping, she steered left to make a U-turn. V2 was eastbound in "
      "the left lane. The front of V2 struck the left side of V1.");
  EXPECT_EQ(u_turn.vehicles[0].pre_event.value, Movement::kTurnLeft);
}

TEST(NarrativeExtractorTest, WhoAClauseIsAbout) {
  // "while it was slowing" after the object is the object's.
  const auto object = kExtractor.Extract(
      "V1 and V2 were northbound. V2 braked for a yellow signal. V1, which had been following closely, struck the "
      "back of V2 while it was slowing.");
  EXPECT_EQ(object.vehicles[1].movement.value, Movement::kSlowing);
  EXPECT_EQ(object.vehicles[0].movement.value, Movement::kStraight);
  // Every word of a model names it; "the stopped jetta" is the Jetta.
  const auto sonoma = kExtractor.Extract(
      "V1, a 1997 GMC Sonoma pickup, was eastbound. V2, a 2004 Dodge Neon, was passing the Sonoma when the Sonoma "
      "began its left turn. The front of V2 struck the left side of the stopped Sonoma.");
  EXPECT_EQ(sonoma.vehicles[1].movement.value, Movement::kPassing);
  EXPECT_EQ(sonoma.crash.struck.value, "V1");
  // What an observer only believed is not what the other did; a parked van it saw is not it.
  const auto belief = kExtractor.Extract(
      "V1 was stopped, waiting to turn left. V2 was southbound. She stated that she saw V2 coming but thought it was "
      "slowing to turn. A delivery van parked along the curb limited the view. The front of V2 struck the right side "
      "of V1.");
  EXPECT_EQ(belief.vehicles[1].movement.value, Movement::kStraight);
  EXPECT_FALSE(belief.vehicles[1].parked.value);
  const auto between = kExtractor.Extract(
      "V1 was backing out of a driveway. V2 was eastbound. The back of V1 struck the left side of V2. He said V1 shot "
      "out between 2 parked cars.");
  EXPECT_EQ(between.vehicles[0].movement.value, Movement::kBacking);
  // "Parked cars lined the curb": others, not the vehicle coming out of the alley.
  const auto alley = kExtractor.Extract(
      "V2 came out of an alley. The driver stopped at the sidewalk line, then pulled out to turn right. Parked cars "
      "lined the curb on both sides. V1 was westbound. The front of V1 hit the left side of V2.");
  EXPECT_FALSE(alley.vehicles[1].parked.value);
  EXPECT_EQ(alley.vehicles[1].pre_event.value, Movement::kStopped);
}

TEST(NarrativeExtractorTest, RampsAndMidblockPlaceTheCrash) {
  const auto ramp = kExtractor.Extract(
      "This crash occurred on a two-lane exit ramp leading to a signalized intersection. V2 was in the left lane of "
      "the ramp, moving slowly with the queue. V1 came onto the ramp behind V2, and its front struck the back of V2.");
  EXPECT_EQ(ramp.crash.location.value, CrashLocation::kRamp);
  // The signal where the ramp meets the street is not where the queue was hit.
  const auto queue = kExtractor.Extract(
      "V3 was exiting on an off-ramp that widens to two lanes as it approaches a signal where it meets a surface "
      "street. V1 was stopped in the right lane of the ramp, and V2 was stopped behind V1. The front of V3 struck the "
      "back of V2.");
  EXPECT_EQ(queue.crash.location.value, CrashLocation::kRamp);
  const auto missed = kExtractor.Extract(
      "The crash occurred mid-block. V1 had missed the entrance to a restaurant and made a U-turn. V2 was eastbound. "
      "The front of V2 struck the left side of V1.");
  EXPECT_EQ(missed.crash.location.value, CrashLocation::kSegment);
}

TEST(NarrativeExtractorTest, WhereAVehicleCameToRestIsNotItsCourse) {
  const auto r = kExtractor.Extract(
      "V1 was stopped at the signal intending to turn left. V2 was eastbound in the right lane. V1 started turning "
      "left when the front of V2 struck the left side of V1. V1 rotated and its final rest was facing east in the "
      "eastbound lane.");
  EXPECT_NE(r.vehicles[0].travel.value, std::optional<Compass>(Compass::kEast));
  EXPECT_EQ(r.vehicles[1].travel.value, Compass::kEast);
}

TEST(NarrativeExtractorTest, ALaneChangeThatIsTheCodedCriticalEventFollowedDrivingOn) {
  const char* kCrash =
      "V1 was eastbound in the center lane. V2 was eastbound in the left lane. V1 changed lanes to the left and its "
      "left side struck the right side of V2.";
  const auto plain = kExtractor.Extract(kCrash);
  EXPECT_EQ(plain.vehicles[0].movement.value, Movement::kChangingLanes);
  EXPECT_EQ(plain.vehicles[0].pre_event.value, Movement::kChangingLanes);
  const auto coded = kExtractor.Extract(std::string(kCrash) +
                                        " The Critical Precrash Event for V1 was this vehicle traveling over the lane "
                                        "line on the left side of travel lane.");
  EXPECT_EQ(coded.vehicles[0].movement.value, Movement::kChangingLanes);  // the path into the crash
  EXPECT_EQ(coded.vehicles[0].pre_event.value, Movement::kStraight);       // what NASS codes before it
  EXPECT_EQ(coded.crash.type.value, CrashType::kSideswipeSame);
}

TEST(NarrativeExtractorTest, ThirdSetWordingsForLanesLimitsAndQueues) {
  const auto bay = kExtractor.Extract(
      "The east-west road is a divided boulevard with a raised median, two through lanes plus a left-turn bay in each "
      "direction. V1 was westbound in the inside through lane. V2 was eastbound and turned left. The front of V1 hit "
      "the right side of V2.");
  EXPECT_EQ(bay.road.lanes_per_direction.value, 3);
  const auto zone = kExtractor.Extract(
      "V2 was traveling east on a two-lane undivided road in a 35-mph zone. V1 was traveling east behind V2 and hit "
      "V2 in the back.");
  EXPECT_NEAR(zone.road.speed_limit_mps.value, 35 * 0.44704, 1e-6);
  // "driven by a 17-year-old male with a provisional license" and "the 19-year-old male driver" do not make
  // a motion sentence one about people.
  const auto license = kExtractor.Extract(
      "Vehicle #1, a 1998 Honda Civic driven by a 17-year-old male with a provisional license, was northbound on a "
      "two-lane residential street posted at 25 mph and came to a complete stop at the stop sign. V2 was eastbound on "
      "the arterial. The front of V2 struck the left rear of V1.");
  EXPECT_NEAR(license.road.speed_limit_mps.value, 25 * 0.44704, 1e-6);
  EXPECT_EQ(license.road.lanes_total.value, 2);
  // Where it meant to go is not where it came from.
  const auto meant = kExtractor.Extract(
      "V1 was a 2003 Saturn. The 19-year-old male driver stopped at the stop sign, intending to turn left and travel "
      "west on the arterial. V2 was eastbound. The front of V2 hit the left side of V1.");
  EXPECT_NE(meant.vehicles[0].travel.value, std::optional<Compass>(Compass::kWest));
  EXPECT_EQ(meant.vehicles[0].pre_event.value, Movement::kStopped);
  // A queue listed after a colon shares its state; "passenger vehicles" are not people; a parked pickup is
  // another road user.
  const auto queue = kExtractor.Extract(
      "Veh. 1 was a box truck, northbound. Four passenger vehicles were stopped in the right lane, nose to tail: Veh. "
      "4, a Cobalt, at the front; then Veh. 3, a Sienna; then Veh. 2, a Civic at the back. The truck's front hit the "
      "back of the Civic. A large pickup was parked on the shoulder.");
  ASSERT_EQ(queue.vehicles.size(), 4U);
  for (size_t i = 1; i < 4; ++i) EXPECT_EQ(queue.vehicles[i].movement.value, Movement::kStopped) << i;
  EXPECT_EQ(queue.vehicles[0].movement.value, Movement::kStraight);
  EXPECT_FALSE(queue.vehicles[0].parked.value);
}

TEST(NarrativeExtractorTest, CrossingsFrontToFrontOffsetsAndPullingOutOfAParkingSpace) {
  const auto crossing = kExtractor.Extract(
      "V2 was eastbound on a two-lane road and had stopped at the stop sign where that road crosses a state route. "
      "V1 was southbound on the state route. The front of V1 impacted the left side of V2.");
  EXPECT_EQ(crossing.crash.location.value, CrashLocation::kJunction);
  // A creek crossed is no junction.
  const auto creek = kExtractor.Extract(
      "A concrete barrier begins where the interstate crosses a creek. V1 drifted right and its front struck the end "
      "of the barrier.");
  EXPECT_EQ(creek.crash.location.value, CrashLocation::kSegment);
  // "front to front, offset toward the driver's side" is head-on; "its driver, a 47-year-old female," does not
  // make the sentence one about people.
  const auto offset = kExtractor.Extract(
      "V2 was northbound and drifted left across the centerline. V1 was southbound. Its driver, a 47-year-old female, "
      "braked and steered right, but V1 and V2 collided front to front, offset toward the driver's side of each.");
  EXPECT_EQ(offset.crash.type.value, CrashType::kHeadOn);
  // Pulling out of a parallel parking space into a lane, midblock away from any alley: turn across path.
  const auto parked = kExtractor.Extract(
      "The crash happened mid-block, away from any intersection or alley. Vehicle 1 was traveling east in the right "
      "travel lane. Vehicle 2 had been parallel parked along the right curb. Its driver pulled out of the space into "
      "the right travel lane. The front of Vehicle 1 struck the left side of Vehicle 2.");
  EXPECT_EQ(parked.crash.location.value, CrashLocation::kSegment);
  EXPECT_EQ(parked.vehicles[1].pre_event.value, Movement::kMerging);
  EXPECT_EQ(parked.crash.type.value, CrashType::kTurnAcrossPath);
}

TEST(NarrativeExtractorTest, ASummaryOpeningTheReportIsNotTheImpact) {
  const auto r = kExtractor.Extract(
      "Contact occurred between a 1996 Jeep Grand Cherokee (V1) and a 2004 Honda Accord (V2) at a signalized "
      "intersection on a six-lane divided highway. The highway has three through lanes and a single left-turn lane in "
      "each direction. V2 was northbound and was stopped in the left-turn lane, waiting for a gap. V1 was southbound. "
      "The front of the Jeep impacted the right side of the Accord.");
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kStopped);
  EXPECT_EQ(r.crash.striking.value, "V1");
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kRight);
  EXPECT_EQ(r.road.lanes_per_direction.value, 4);
  // "the vehicles were stopped" are others; "slowed and turned" is slowing before the turn.
  const auto others = kExtractor.Extract(
      "V1 was northbound approaching the line of traffic. The turn bay begins north of where the vehicles were "
      "stopped. V2 slowed and turned right. The front of V1 struck the right side of V2.");
  EXPECT_EQ(others.vehicles[0].movement.value, Movement::kStraight);
  EXPECT_EQ(others.vehicles[1].pre_event.value, Movement::kSlowing);
}

TEST(NarrativeExtractorTest, FourthSetLaneWordings) {
  const auto each_has = kExtractor.Extract(
      "Vehicle one was traveling east on Route 30, a divided state highway. At the intersection each direction of "
      "Route 30 has two through lanes plus a left-turn bay. Vehicle one turned left. Vehicle two was westbound. The "
      "front of vehicle two struck the right side of vehicle one.");
  EXPECT_EQ(each_has.road.lanes_per_direction.value, 3);
  const auto centre = kExtractor.Extract(
      "V1 was westbound on Brennan Boulevard, an urban arterial with two through lanes in each direction separated "
      "by a continuous two-way left-turn lane. V2 was eastbound. V1 turned left and the front of V2 struck the right "
      "side of V1.");
  EXPECT_EQ(centre.road.lanes_total.value, 5);
  const auto each_direction = kExtractor.Extract(
      "Elm Street runs north-south, one lane each direction, and is posted 30 mph. V1 was northbound on Elm. V2 was "
      "eastbound. The front of V1 struck the right side of V2.");
  EXPECT_EQ(each_direction.road.lanes_total.value, 2);
  // The other road's median crossover, and a median V1 waited in, do not divide V1's road; a median wall does.
  const auto crossover = kExtractor.Extract(
      "TR 114 is a two-lane north-south road with stop signs at both roadways of US 20, including one in the median "
      "crossover. V1 was northbound on TR 114 and stopped again in the median. V2 was westbound. The front of V2 "
      "struck the right side of V1.");
  EXPECT_FALSE(crossover.road.divided.value);
  const auto wall = kExtractor.Extract(
      "V1 lost control and crossed two lanes before contacting V2. V1 then contacted the center median wall.");
  EXPECT_TRUE(wall.road.divided.value);
}

TEST(NarrativeExtractorTest, DriversFoldedIntoTheCrashSentenceAndMakeFirstDescriptions) {
  const auto folded = kExtractor.Extract(
      "Vehicle one was heading south on a green signal. Vehicle two had come to a stop for the red signal. The "
      "17-year-old male driving vehicle two, who had three teenage passengers, pulled forward into the intersection, "
      "and the front of vehicle two struck the right side of vehicle one.");
  EXPECT_EQ(folded.crash.striking.value, "V2");
  EXPECT_EQ(folded.crash.struck_area.value, DamageArea::kRight);
  const auto make_first = kExtractor.Extract(
      "The Volkswagen, a 2001 Jetta (V1), was westbound and stopped for the red light. The Honda, a 2003 CR-V (V2), "
      "was northbound in the curb lane. The front of the Honda struck the left side of the Volkswagen.");
  EXPECT_EQ(make_first.crash.striking.value, "V2");
  EXPECT_EQ(make_first.crash.struck.value, "V1");
}

TEST(NarrativeExtractorTest, LanesCountedByDirectionAfterTheCount) {
  const auto listed = kExtractor.Extract(
      "V1, a 2001 Ford Taurus, was northbound on a roadway with two lanes northbound and one lane southbound. V2 was "
      "stopped ahead of V1. The front of V1 struck the back of V2.");
  EXPECT_EQ(listed.road.lanes_total.value, 3);
  const auto for_traffic = kExtractor.Extract(
      "V1 was northbound on a road that has three lanes for northbound traffic and two for southbound traffic. V2 "
      "was stopped ahead of V1. The front of V1 struck the back of V2.");
  EXPECT_EQ(for_traffic.road.lanes_total.value, 5);
  const auto one_way = kExtractor.Extract(
      "V1 was northbound on a one-way road with 3 lanes northbound. V2 was stopped ahead of V1. The front of V1 "
      "struck the back of V2.");
  EXPECT_EQ(one_way.road.lanes_total.value, 3);
  // The sentence that splits a road's lanes by direction outranks the one
  // before it, which counted two roads.
  const auto two_roads = kExtractor.Extract(
      "The crash occurred in a T-intersection of a five-lane two-way roadway and a three-lane two-way roadway. The "
      "five-lane roadway had two lanes eastbound and two lanes westbound with a center two-way left turn lane. The "
      "three-lane roadway had two lanes northbound and one lane southbound. V1 was traveling northbound attempting "
      "to turn left. V2 was traveling in the second eastbound lane. The front of V1 struck the left side of V2.");
  EXPECT_EQ(two_roads.road.lanes_total.value, 3);
}

TEST(NarrativeExtractorTest, UncountedDividedRoadHasTwoLanesEachWay) {
  const auto r = kExtractor.Extract(
      "The crash occurred on a divided highway with a grass median. V1 was eastbound. V2 was stopped ahead of V1. "
      "The front of V1 struck the back of V2.");
  EXPECT_TRUE(r.road.divided.value);
  EXPECT_EQ(r.road.lanes_per_direction.value, 2);
  EXPECT_EQ(r.road.lanes_per_direction.source, Provenance::kInferred);
}

TEST(NarrativeExtractorTest, LimitSynonymsAndSingularMiles) {
  for (const char* limit : {"The roadway was a 45 mile per hour zone.", "The maximum speed allowed is 45 mph.",
                            "The legal speed was 45 mph."}) {
    const auto r = kExtractor.Extract(std::string("V1 was northbound on a two-lane road. ") + limit +
                                      " V2 was stopped ahead of V1. The front of V1 struck the back of V2.");
    EXPECT_NEAR(r.road.speed_limit_mps.value, 45 * 0.44704, 1e-6) << limit;
    EXPECT_TRUE(r.road.speed_limit_mps.known()) << limit;
  }
  // "40kph (25mph) on the residential street": the unit written onto the
  // number, and the road after the conversion.
  EXPECT_NEAR(LimitMph("A two-lane residential street ends at a four-lane east/west roadway. The posted speed limit "
                       "was 40kph (25mph) on the residential street and 56kph (35mph) on the east/west roadway. V1 "
                       "was traveling south on the residential street and turned right. V2 was traveling west. The "
                       "front of V2 struck the back of V1."),
              25.0, 0.5);
}

TEST(NarrativeExtractorTest, MakeNamedDriverSentencesAndUnnumberedTrucksKeepTheirVehicle) {
  // "The Pontiac was driven by ..." is V1's paragraph: what its driver said
  // follows V1, not the vehicle named last.
  const auto driven = kExtractor.Extract(
      "Vehicle 1, a 2000 Pontiac Grand Am, was westbound and turned left at the intersection. Vehicle 2, a 2005 Jeep "
      "Liberty, was eastbound, going straight. The front of Vehicle 2 struck the right side of Vehicle 1. The Pontiac "
      "was driven by a belted 17-year-old male. He estimated that he had slowed from 35 mph to 15 mph for the turn.");
  ASSERT_EQ(driven.vehicles.size(), 2u);
  EXPECT_EQ(driven.vehicles[1].pre_event.value, Movement::kStraight);
  // "A northbound box truck that had stopped ..." is another road user, not
  // the vehicle of the sentence before.
  const auto truck = kExtractor.Extract(
      "V1 was southbound and turning left. V2 was northbound approaching on the green signal. A northbound box truck "
      "that had stopped in the curb lane partially blocked the view. The front of V2 struck the right side of V1.");
  ASSERT_EQ(truck.vehicles.size(), 2u);
  EXPECT_EQ(truck.vehicles[1].pre_event.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, DriveLeftAtItsMouthAndOneLaneDrives) {
  // V1 waiting at the mouth of a drive was on the drive: two lanes.
  const auto mouth = kExtractor.Extract(
      "The arterial was a five-lane roadway. Vehicle #1 had stopped at the mouth of the driveway facing west, waiting "
      "to turn left. Vehicle #2 was traveling north in the curb lane. The front of Vehicle #2 struck the left side of "
      "Vehicle #1.");
  EXPECT_EQ(mouth.road.lanes_total.value, 2);
  // A one-way, exit-only drive or a 1-lane alley: one lane.
  const auto exit_only = kExtractor.Extract(
      "Mill Road is a two-lane road. The station has a one-way, exit-only driveway onto Mill Road. V1 drove south "
      "through the exit driveway to turn right. V2 was westbound. The front of V2 struck the left side of V1.");
  EXPECT_EQ(exit_only.road.lanes_total.value, 1);
  const auto alley = kExtractor.Extract(
      "V1 was backing out of an alley onto Lincoln Street. The alley is a narrow, one-lane paved alley. Lincoln "
      "Street has two travel lanes. V2 was northbound. The back of V1 struck the right side of V2.");
  EXPECT_EQ(alley.road.lanes_total.value, 1);
  // "was westbound in the driveway", "stopped at the plaza exit facing north".
  const auto in_drive = kExtractor.Extract(
      "The roadway was a three-lane, two-way road. Vehicle #1 was westbound in the driveway and stopped at the edge "
      "of the roadway. Vehicle #2 was northbound. The front of Vehicle #2 struck the left side of Vehicle #1.");
  EXPECT_EQ(in_drive.road.lanes_total.value, 2);
  const auto plaza = kExtractor.Extract(
      "The collector was a three-lane, two-way roadway. Vehicle #1 stopped at the plaza exit facing north, intending "
      "to drive straight across. Vehicle #2 was traveling west. As Vehicle #1 crossed the westbound lane, the front "
      "of Vehicle #2 struck the right side of Vehicle #1. Vehicle #1 was pushed to the west.");
  EXPECT_EQ(plaza.road.lanes_total.value, 2);
  ASSERT_FALSE(plaza.vehicles.empty());
  EXPECT_EQ(plaza.vehicles[0].travel.value, Compass::kNorth);
  EXPECT_EQ(plaza.crash.type.value, CrashType::kAngle);
}

TEST(NarrativeExtractorTest, ParkedCarsAfterAVehicleAreNotIt) {
  for (const char* parked : {"Vehicles parked along the south curb limited the view to the left.",
                             "Parked cars lined the curb on both sides."}) {
    const auto r = kExtractor.Extract(
        std::string("V1 was northbound on the one-way street and stopped at the stop sign, intending to turn left. ") +
        parked + " V2 was eastbound. The front of V2 struck the left side of V1.");
    ASSERT_EQ(r.vehicles.size(), 2u) << parked;
    EXPECT_FALSE(r.vehicles[0].parked.value) << parked;
    EXPECT_NE(r.crash.type.value, CrashType::kSingleVehicle) << parked;
  }
}

TEST(NarrativeExtractorTest, OneDirectionsLanesAndTheNearestRamp) {
  // "the eastbound roadway had 3 travel lanes" on a divided freeway counts
  // one direction; "the nearest ramp was 700 meters away" is not the place.
  const auto freeway = kExtractor.Extract(
      "This crash occurred on the eastbound roadway of an urban freeway divided by a concrete barrier. The eastbound "
      "roadway had three travel lanes. The nearest ramp was about 700 meters away. V1, a 2006 Dodge Charger, was "
      "eastbound in the center lane. V2, a 2001 Honda CR-V, was eastbound in the right lane. The driver of V1 moved "
      "to the right, and the right side of the Charger contacted the left side of the CR-V. Both vehicles stopped on "
      "the right shoulder.");
  EXPECT_TRUE(freeway.road.divided.value);
  EXPECT_EQ(freeway.road.lanes_per_direction.value, 3);
  EXPECT_EQ(freeway.crash.location.value, CrashLocation::kSegment);
  // "the eastbound side had 2 through lanes and a left-turn bay": three.
  const auto bay = kExtractor.Extract(
      "V1 was eastbound on a divided boulevard. At the intersection the eastbound side had two through lanes and a "
      "left-turn bay, separated from the westbound side by a raised median. V2 was westbound. The front of V2 struck "
      "the right side of V1.");
  EXPECT_EQ(bay.road.lanes_per_direction.value, 3);
  // "on the southbound lanes of a five-lane undivided highway" is the total.
  const auto total = kExtractor.Extract(
      "This crash occurred on the southbound lanes of a five-lane undivided urban highway. V1 was southbound. V2 was "
      "stopped ahead. The front of V1 struck the back of V2.");
  EXPECT_EQ(total.road.lanes_total.value, 5);
}

TEST(NarrativeExtractorTest, HadComeToAStopIsAStop) {
  const auto r = kExtractor.Extract(
      "V1 was traveling westbound approaching a four-way stop. V2 was eastbound. V1 had come to a stop at its stop "
      "line, intending to turn left. The driver of V1 began the left turn, and the front of V2 struck the right side "
      "of V1.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStopped);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnLeft);
}

TEST(NarrativeExtractorTest, ClausesAfterASemicolonAndOtherRoadsMedians) {
  // "...; it had a stop sign and a posted speed limit of 40 kmph" is about
  // the north/south road the sentence began with, V1's.
  const auto limit = kExtractor.Extract(
      "The east/west roadway was a three-lane road; its posted speed limit was 64 kmph (40 mph). The north/south "
      "roadway was a two-lane, two-way street that ended at the east/west road; it had a stop sign and a posted speed "
      "limit of 40 kmph (25 mph). V1 was southbound on the side street and stopped at the stop sign. V2 was "
      "westbound. The front of V2 struck the left side of V1.");
  EXPECT_NEAR(limit.road.speed_limit_mps.value * 3.6, 40.0, 0.5);
  // The raised median of the crossing road does not divide V1's street.
  const auto median = kExtractor.Extract(
      "Vehicle #1 was northbound on Linden Street, a two-lane city street with a 30 mph speed limit, approaching its "
      "intersection with Grand Avenue. Grand Avenue is a divided east-west arterial. At Linden each direction has "
      "three through lanes plus a left-turn bay next to the raised median, and the limit on Grand is 40 mph. Vehicle "
      "#2 was eastbound on Grand. The front of Vehicle #2 struck the right side of Vehicle #1.");
  EXPECT_FALSE(median.road.divided.value);
  EXPECT_EQ(median.road.lanes_total.value, 2);
}

TEST(NarrativeExtractorTest, IntendedTurnsMadeByPullingAwayOrBeginningTheTurn) {
  // "intended to turn left ..., and began the turn": a left turn across V2.
  const auto began = kExtractor.Extract(
      "Vehicle one (V1 - case vehicle) was traveling west in the left westbound lane and was approaching a four-leg "
      "intersection. Vehicle two (V2) was traveling east in the left eastbound lane of the same roadway. The driver "
      "of V1 intended to turn left and travel south, and began the turn on a circular green signal. The driver of V2 "
      "continued straight through the intersection and the front of V2 struck the right side of V1.");
  ASSERT_EQ(began.vehicles.size(), 2u);
  EXPECT_EQ(began.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(began.crash.type.value, CrashType::kTurnAcrossPath);
  // "pulled away from the stop sign intending to turn left": it turned.
  const auto pulled = kExtractor.Extract(
      "Vehicle one (V1) was traveling east on a two-lane state highway approaching a T-intersection. Vehicle two (V2) "
      "was traveling north on the intersecting road and had stopped at the stop sign. The driver of V2 pulled away "
      "from the stop sign intending to turn left and travel west. The front of V2 struck the right side of V1.");
  ASSERT_EQ(pulled.vehicles.size(), 2u);
  EXPECT_EQ(pulled.vehicles[1].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(pulled.crash.type.value, CrashType::kTurnIntoPath);
}

TEST(NarrativeExtractorTest, StruckInTheBackJustAfterTurningOntoTheRoadIsATurnIntoPath) {
  const auto r = kExtractor.Extract(
      "Vehicle one (V1) was traveling north in the northbound lane of a two-lane rural highway and was approaching a "
      "T-intersection with a road that entered from the east. Vehicle two (V2) was traveling west on the "
      "intersecting road and was approaching a yield sign. The driver of V2 did not yield and turned right onto the "
      "highway, directly in front of V1. The front of V1 struck the rear of V2.");
  EXPECT_EQ(r.crash.type.value, CrashType::kTurnIntoPath);
  // Without the turn it stays a rear-end.
  const auto rear = kExtractor.Extract(
      "V1 was traveling north on a two-lane rural highway. V2 was traveling north ahead of V1 and slowed for traffic. "
      "The front of V1 struck the rear of V2.");
  EXPECT_EQ(rear.crash.type.value, CrashType::kRearEnd);
}

TEST(NarrativeExtractorTest, RoadsNamedAfterTheirLimitsOneWayDirectionsAndCentreLanes) {
  // The road named after a limit is that limit's road.
  const auto after = kExtractor.Extract(
      "The crash occurred at a four-leg intersection. The posted speed limit was 64 kmph (40 mph) on the "
      "north/south roadway and 40 kmph (25 mph) on the east/west roadway. V1 was westbound and stopped at the stop "
      "sign. V2 was northbound. The front of V2 struck the left side of V1.");
  EXPECT_NEAR(after.road.speed_limit_mps.value * 3.6, 40.0, 0.5);
  const auto own = kExtractor.Extract(
      "V1 was eastbound approaching a T-intersection. The posted speed limit was 48 kmph (30 mph) on V1's roadway "
      "and 72 kmph (45 mph) on the north/south roadway. V2 was southbound. The front of V2 struck the left side of "
      "V1.");
  EXPECT_NEAR(own.road.speed_limit_mps.value * 3.6, 48.0, 0.5);
  // "the northbound roadway had 3 travel lanes" of a northbound one-way road: its total.
  const auto one_way = kExtractor.Extract(
      "The crash occurred in the intersection of a northbound one-way roadway and a westbound one-way roadway. The "
      "northbound roadway had three travel lanes and the westbound roadway had a single travel lane. Vehicle # 1 was "
      "traveling northbound in the middle lane. Vehicle # 2 was traveling westbound. The front of Vehicle # 1 "
      "impacted the left side of Vehicle # 2.");
  EXPECT_TRUE(one_way.road.one_way.value);
  EXPECT_EQ(one_way.road.lanes_total.value, 3);
  // The centre lane belongs to the road whose phrase names it.
  const auto centre = kExtractor.Extract(
      "The crash occurred at the intersection of a north/south two-way roadway with one lane in each direction and "
      "an east/west two-way roadway with one lane in each direction and a center two-way left turn lane. Vehicle # 1 "
      "was traveling southbound and stopped at the stop sign. Vehicle # 2 was traveling westbound. The front of "
      "Vehicle # 2 contacted the left side of Vehicle # 1.");
  EXPECT_EQ(centre.road.lanes_total.value, 2);
}

TEST(NarrativeExtractorTest, HadNotComeToAStopAndTheCodedLaneLineCrossing) {
  // "had braked ... but had not come to a stop": not stopped.
  const auto braked = kExtractor.Extract(
      "V2 was traveling west when its driver saw a deer and braked hard. V1 was traveling west behind V2. The front "
      "of V1 struck the back of V2. The driver of V2 stated she had braked for the deer but had not come to a stop.");
  ASSERT_EQ(braked.vehicles.size(), 2u);
  EXPECT_NE(braked.vehicles[1].pre_event.value, Movement::kStopped);
  // A lane change that is the vehicle's own critical event ("when she began to
  // travel over the lane line") was preceded by going straight.
  const auto lane = kExtractor.Extract(
      "V1 was traveling westbound in lane one behind a slow truck. V2 was traveling westbound in lane two. The driver "
      "of V1 began to change lanes to the left to pass the truck, and the left side of V1 contacted the right side of "
      "V2. The Critical Precrash Event for the driver of V1 was when she began to travel over the lane line on the "
      "left side of the travel lane.");
  ASSERT_EQ(lane.vehicles.size(), 2u);
  EXPECT_EQ(lane.vehicles[0].pre_event.value, Movement::kStraight);
  EXPECT_EQ(lane.vehicles[0].movement.value, Movement::kChangingLanes);
}

TEST(NarrativeExtractorTest, LaneStatementsInTheOrderToldAndStopThenAttempt) {
  const auto r = kExtractor.Extract(
      "Vehicle one (V1 - case vehicle) was traveling north in the northbound lane of a two-lane, two-way county road "
      "and was approaching a four-leg intersection with a four-lane, two-way rural highway (two lanes eastbound, two "
      "lanes westbound). Vehicle two (V2) was traveling west in the right westbound lane of the highway. The driver of "
      "V1 stopped at the stop sign and then attempted to drive straight across the highway. The front of V2 struck "
      "the right side of V1.");
  EXPECT_EQ(r.road.lanes_total.value, 2);
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, NamedRoadsGiveV1ItsLanesAndLimit) {
  // V1 on Tower Road: the road named, not the highway described first.
  const auto tower = kExtractor.Extract(
      "The crash occurred on US-41 at its intersection with Tower Road. US-41 is a four-lane divided highway with two "
      "eastbound and two westbound lanes. The posted speed on US-41 is 55 mph. Tower Road is a two-lane, two-way road "
      "posted at 30 mph. V1 was northbound on Tower Road and stopped at the stop sign. V2 was eastbound on US-41. The "
      "front of V2 struck the left side of V1.");
  EXPECT_EQ(tower.road.lanes_total.value, 2);
  EXPECT_NEAR(tower.road.speed_limit_mps.value * 3.6, 48.3, 0.5);
  // "Kessler Lane, a two-lane road with a 25 mph speed zone": a limit; the
  // route named after "with" is a place, not the clause's road.
  const auto kessler = kExtractor.Extract(
      "Kessler Lane, a two-lane road with a 25 mph speed zone, runs east to a T-intersection with Route 202. Route "
      "202 is a north-south highway with one lane in each direction and a 50 mph limit. V1 was eastbound on Kessler "
      "Lane. V2 was southbound on Route 202. The front of V2 struck the left side of V1.");
  EXPECT_NEAR(kessler.road.speed_limit_mps.value * 3.6, 40.2, 0.5);
  // "V1 and V2 were both westbound on Route 9"; "...; the limit was 50" is Route 9's.
  const auto route9 = kExtractor.Extract(
      "V1 (2003 Kia Optima) and V2 (1995 Volvo 850) were both westbound on Route 9 in the left lane. Route 9 is "
      "divided by a concrete barrier and has two lanes in each direction; the limit was 50. Both vehicles had been "
      "stopped for the red signal at Tilden Avenue, a two-lane street with a 25 mph limit. The front of V1 struck "
      "the back of V2.");
  EXPECT_NEAR(route9.road.speed_limit_mps.value * 3.6, 80.5, 0.5);
  // "a 2-way road" names no road.
  const auto unnamed = kExtractor.Extract(
      "Harper Road is an east-west, two-lane, two-way road posted at 45 mph. The crash occurred at a driveway east of "
      "Harper's intersection with Route 16, a four-lane highway posted at 55 mph. V1 stopped at the edge of Harper "
      "Road and then started a left turn. V2 was eastbound on Harper. The front of V2 struck the left side of V1.");
  EXPECT_NEAR(unnamed.road.speed_limit_mps.value * 3.6, 72.4, 0.5);
}

TEST(NarrativeExtractorTest, DividedSaidOfTheOtherRoadsPhrase) {
  const auto r = kExtractor.Extract(
      "This crash occurred at a rural four-leg intersection of a north/south divided highway and an east/west county "
      "road. The county road was a two-lane, two-way roadway with a posted speed limit of 55 mph. Vehicle #1 was "
      "traveling east on the county road and stopped at the stop sign. Vehicle #2 was traveling south. The front of "
      "Vehicle #2 struck the left side of Vehicle #1.");
  EXPECT_FALSE(r.road.divided.value);
  EXPECT_EQ(r.road.lanes_total.value, 2);
}

TEST(NarrativeExtractorTest, APassIsPrecededByGoingStraight) {
  const auto r = kExtractor.Extract(
      "V1 was traveling east in the right lane. V2 was traveling east in the center lane and was overtaking V1. V1 "
      "began a left turn across the center lane. The front of V2 struck the left side of V1.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kPassing);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, AUTurnOutOfAParkingSpaceIsATurnAcrossPath) {
  const auto r = kExtractor.Extract(
      "Vehicle # 1 was a 1995 Lincoln Town Car that was parked in the eastbound parking lane. Vehicle # 2 was a 2003 "
      "Chevrolet Trailblazer that was traveling eastbound in the eastbound lane. Vehicle # 1 pulled out of the "
      "parking space and attempted to make a U-turn to go westbound, and the front of Vehicle # 2 impacted the left "
      "side of Vehicle # 1.");
  EXPECT_EQ(r.crash.type.value, CrashType::kTurnAcrossPath);
}

TEST(NarrativeExtractorTest, CirenWordingsOfTurnsContactsAndTows) {
  // "...controlled by traffic signals, waiting to turn left" keeps its
  // intention (traffic signals are not traffic); "On a circular green signal
  // the driver of the Mazda began the turn" is the Mazda's sentence.
  const auto turn = kExtractor.Extract(
      "The case vehicle (V1), a 2001 Mazda Protege, was northbound and had stopped in the left-turn lane at an "
      "intersection controlled by traffic signals, waiting to turn left and travel west. V2, a 2005 GMC Yukon, was "
      "southbound in the inside through lane. On a circular green signal the driver of the Mazda began the turn "
      "across the southbound lanes and the front of the Yukon struck the right side of the Mazda.");
  EXPECT_EQ(turn.crash.type.value, CrashType::kTurnAcrossPath);
  ASSERT_EQ(turn.vehicles.size(), 2u);
  EXPECT_EQ(turn.vehicles[0].movement.value, Movement::kTurnLeft);
  // "engaged" is a contact; "moved to the right to reach an upcoming exit"
  // a lane change; what a tractor is pulling is its own.
  const auto engaged = kExtractor.Extract(
      "Vehicle one (V1), a 2005 Chrysler 300, was traveling south in the center southbound lane of a six-lane freeway. "
      "Vehicle two (V2), a 2004 Mack tractor pulling a flatbed semi-trailer was traveling south in the right "
      "southbound lane. The driver of V1 moved to the right to reach an upcoming exit and did not see V2. The left "
      "front corner of the Mack's tractor engaged the right rear quarter of the Chrysler.");
  EXPECT_EQ(engaged.crash.type.value, CrashType::kSideswipeSame);
  ASSERT_EQ(engaged.vehicles.size(), 2u);
  EXPECT_EQ(engaged.vehicles[1].travel.value, Compass::kSouth);
  // "an exit ramp approximately 5 km to the east" is not where it crashed.
  const auto wrong_way = kExtractor.Extract(
      "V1 was eastbound in the left lane of a divided interstate highway. V2 was traveling west in the left eastbound "
      "lane, the wrong way, having entered the interstate by way of an exit ramp approximately 5 km to the east. The "
      "front of V2 struck the front of V1.");
  EXPECT_EQ(wrong_way.crash.location.value, CrashLocation::kSegment);
}

TEST(NarrativeExtractorTest, UndividedSaidOfTheCrossRoadAndV1sRoadDescribedLater) {
  // V1's east/west road, described after the vehicles, is divided; the
  // north/south road's "undivided" is not about it.
  const auto r = kExtractor.Extract(
      "Vehicle 1, a 2007 Ford Fusion, was westbound in lane two, the middle of three westbound lanes, approaching a "
      "four-leg intersection on a green signal. Vehicle 2 was northbound. The front of Vehicle 2 struck the left side "
      "of Vehicle 1. Vehicle 1 came to rest facing south. The east/west road was a divided roadway with a 6-meter "
      "raised median and three travel lanes in each direction. The north/south road was a two-lane, two-way "
      "undivided road posted at 56 km/h.");
  EXPECT_TRUE(r.road.divided.value);
  EXPECT_EQ(r.road.lanes_per_direction.value, 3);
}

TEST(NarrativeExtractorTest, EachDirectionFirstAndAStrikeAtTheMouthOfADrive) {
  // "and, in each direction, 2 through lanes and a left-turn lane": 3 each way.
  const auto each = kExtractor.Extract(
      "Vehicle 1 was northbound in lane one of a divided roadway. Vehicle 2 was southbound and turned left. The front "
      "of Vehicle 1 struck the right side of Vehicle 2. The divided roadway had a grass median and, in each "
      "direction, two through lanes and a left-turn lane at the intersection.");
  EXPECT_EQ(each.road.lanes_per_direction.value, 3);
  // V1 striking a vehicle "at the mouth of the driveway" was not on the drive.
  const auto mouth = kExtractor.Extract(
      "This crash occurred in the eastbound lanes of a four-lane, two-way, undivided roadway with two lanes in each "
      "direction. Vehicle #2 was eastbound and beginning to turn right into a driveway. Vehicle #1 was eastbound "
      "behind it. The front of Vehicle #1 struck the back of Vehicle #2 at the mouth of the driveway.");
  EXPECT_EQ(mouth.road.lanes_total.value, 4);
}

TEST(NarrativeExtractorTest, TheContactsClauseNamesTheStruckArea) {
  // After "where", and after ", and": V1's right side, not the rear that
  // slid out before it (nor the back that later hit a tree).
  for (const char* text :
       {"Vehicle #1, a 1998 Acura Integra, was westbound negotiating the curve. Vehicle #2, a 2005 Chevrolet Tahoe, "
        "was eastbound negotiating the same curve. The rear of the Acura slid out and the car rotated "
        "counterclockwise across the center line into the eastbound lane, where the front of the Tahoe struck the "
        "right side of the Acura.",
        "The crash occurred on a two-lane rural road in a curve. V1, a 1996 Mitsubishi Eclipse, was eastbound. V2, a "
        "2001 Ford Explorer, was westbound. The rear of V1 slid out to the right, V1 rotated counterclockwise and "
        "crossed the centerline, and the front of V2 struck the right side of V1 in the westbound lane. V1 then "
        "went off the road and the back of V1 struck a tree."}) {
    SCOPED_TRACE(text);
    const auto r = kExtractor.Extract(text);
    EXPECT_EQ(r.crash.striking.value, "V2");
    EXPECT_EQ(r.crash.struck_area.value, DamageArea::kRight);
  }
}

TEST(NarrativeExtractorTest, RoadsNamedByTheirKindSingleTravelLanesAndACrossedDividedHighway) {
  // V1 "on a residential street"; the arterial is described first.
  const auto residential = kExtractor.Extract(
      "Vehicle 1 was northbound on a residential street and stopped at the stop sign where the street ended at a "
      "T-intersection with an east/west arterial. Vehicle 2 was eastbound in lane one of the arterial. The front of "
      "Vehicle 2 struck the left side of Vehicle 1. The arterial was a four-lane, two-way roadway with two lanes in "
      "each direction and a posted speed limit of 89 km/h (55 mph). The residential street was a two-lane, two-way "
      "road with a posted speed limit of 56 km/h (35 mph).");
  EXPECT_EQ(residential.road.lanes_total.value, 2);
  EXPECT_NEAR(residential.road.speed_limit_mps.value * 3.6, 56.0, 0.5);
  // "two one-way streets, each with a single travel lane".
  const auto single = kExtractor.Extract(
      "The crash occurred in the intersection of two one-way urban streets, each with a single travel lane. Vehicle "
      "#1 was southbound. Vehicle #2 was eastbound and its front struck the right side of Vehicle #1.");
  EXPECT_EQ(single.road.lanes_total.value, 1);
  // "a two-lane county road crosses a divided highway": V1 on the county road.
  const auto crossed = kExtractor.Extract(
      "The crash occurred at an intersection where a two-lane county road crosses a divided highway. The highway ran "
      "east and west with two travel lanes in each direction separated by a grass median. The county road had one "
      "lane in each direction. V1 was northbound on the county road. V2 was westbound. The front of V2 struck the "
      "right side of V1.");
  EXPECT_FALSE(crossed.road.divided.value);
  EXPECT_EQ(crossed.road.lanes_total.value, 2);
}

TEST(NarrativeExtractorTest, LaneWidthsTurnLanesFirstAndTrafficsLanes) {
  // "three 3.7-meter travel lanes" on one side of a divided interstate.
  const auto widths = kExtractor.Extract(
      "This crash occurred in the northbound lanes of an interstate highway. The northbound side had three "
      "3.7-meter travel lanes and was separated from the southbound lanes by a concrete median barrier. V2 was "
      "stopped in lane two. V1 was traveling north in lane two behind V2. The front of V1 struck the back of V2.");
  EXPECT_EQ(widths.road.lanes_per_direction.value, 3);
  // "The southbound approach had a left-turn lane and two through lanes, and
  // the northbound approach was configured the same way": 6, undivided.
  const auto approach = kExtractor.Extract(
      "The southbound approach had a left-turn lane and two through lanes, and the northbound approach was "
      "configured the same way; the two directions were separated only by painted double yellow lines. V1 was "
      "southbound in the left-turn lane. V2 was northbound in the left through lane. V1 turned left and the front "
      "of V2 struck the right side of V1.");
  EXPECT_EQ(approach.road.lanes_total.value, 6);
  // "Eastbound traffic had two travel lanes" of a divided highway.
  const auto traffic = kExtractor.Extract(
      "The crash occurred in the eastbound lanes of a divided highway. Eastbound traffic had two travel lanes, "
      "separated from the westbound lanes by a median with a W-beam guardrail. V1 was eastbound in lane one. V2 was "
      "eastbound in lane two. The right side of V2 struck the left side of V1.");
  EXPECT_EQ(traffic.road.lanes_per_direction.value, 2);
  // V1 "southbound leaving the plaza" was on its drive.
  const auto plaza = kExtractor.Extract(
      "This crash occurred at the exit of a shopping plaza onto a five-lane urban arterial. V1 was southbound leaving "
      "the plaza. V2 was westbound. The front of V2 struck the left side of V1.");
  EXPECT_EQ(plaza.road.lanes_total.value, 2);
}

TEST(NarrativeExtractorTest, TheRoadTurnedOntoRestingLanesAndOthersLanesAreNotV1s) {
  // V1 on the two-way street turned onto the one-way street, came to rest
  // in lane 3 of it: its road is the two-way street's 2 lanes.
  const auto r = kExtractor.Extract(
      "The crash occurred at a T-intersection of a westbound one-way street and a two-way street. The one-way street "
      "carried three lanes of westbound traffic. The two-way street had one lane in each direction. Vehicle #1 was "
      "northbound on the two-way street. It stopped at the stop sign and then turned left to travel west on the "
      "one-way street. Vehicle #2 was westbound in the middle lane. The front of Vehicle #2 struck the right side of "
      "Vehicle #1. Vehicle #1 came to rest in lane three facing southwest. The driver of Vehicle #1 stated that she "
      "thought Vehicle #2 was in lane two.");
  EXPECT_FALSE(r.road.one_way.value);
  EXPECT_EQ(r.road.lanes_total.value, 2);
  ASSERT_FALSE(r.vehicles.empty());
  EXPECT_FALSE(r.vehicles[0].lane.known());
}

TEST(NarrativeExtractorTest, PresentTenseReadsAsThePast) {
  // Police narratives are often in the present tense.
  const auto queue = kExtractor.Extract(
      "The crash occurs on a two lane undivided roadway. V1 is traveling south when it impacts the rear of V2 with "
      "its front. V2 has been stopped in the southbound lane waiting for traffic to pass.");
  ASSERT_EQ(queue.vehicles.size(), 2u);
  EXPECT_EQ(queue.vehicles[1].pre_event.value, Movement::kStopped);
  EXPECT_EQ(queue.crash.type.value, CrashType::kRearEnd);
  const auto stop = kExtractor.Extract(
      "The crash occurs at a T-intersection. V1 is traveling west on the main street. V2 is traveling south on the "
      "north/south street. The driver of V2 comes to a complete stop at her stop sign. The driver of V2 then enters "
      "the intersection and attempts to turn left. Its left side is struck by the front of V1.");
  ASSERT_EQ(stop.vehicles.size(), 2u);
  EXPECT_EQ(stop.vehicles[1].pre_event.value, Movement::kStopped);
  // "each direction of route 30 has two through lanes plus a left-turn bay".
  const auto bay = kExtractor.Extract(
      "V1 was traveling east on Route 30, a divided highway, approaching the signalized intersection with Maple "
      "Street. At the intersection each direction of Route 30 has two through lanes plus a left-turn bay. Maple "
      "Street is a two-lane street. V1 turned left and its right side was struck by the front of V2, which was "
      "westbound.");
  EXPECT_EQ(bay.road.lanes_per_direction.value, 3);
}

TEST(NarrativeExtractorTest, OneDirectionsLanesWhateverTheRoadIsCalled) {
  // "the southbound road had two through lanes" of a divided road, as
  // "the southbound roadway" would.
  const auto road = kExtractor.Extract(
      "The crash occurred in the southbound lanes of a divided road approaching an intersection. The southbound road "
      "had two through lanes and was separated from the northbound lanes by a raised median. V2 was stopped in the "
      "right lane. V1 was traveling south behind it. The front of V1 struck the rear of V2.");
  EXPECT_TRUE(road.road.divided.value);
  EXPECT_EQ(road.road.lanes_per_direction.value, 2);
  // "southbound there were three lanes: two through lanes and the left-turn lane".
  const auto there = kExtractor.Extract(
      "V1 was southbound in the left-turn lane of a state highway intending to turn left. V2 was northbound in the "
      "left through lane. The front of V2 struck the right side of V1. The highway is divided by a raised median. "
      "Southbound there were three lanes at the intersection: two through lanes and the left-turn lane. Northbound "
      "there were two through lanes.");
  EXPECT_EQ(there.road.lanes_per_direction.value, 3);
  // "an east/west road" is not a road named "west road".
  const auto axis = kExtractor.Extract(
      "The east/west road was a four-lane, two-way, undivided road with two lanes in each direction and a posted "
      "speed limit of 45 mph (72 kph). The north/south road was a two-lane, two-way road with a posted speed limit of "
      "30 mph (48 kph) and was controlled by stop signs on the north and south legs. V1, a 2001 Hyundai Sonata "
      "sedan, was traveling southbound on the north leg and stopped at the stop sign, intending to turn right to "
      "travel westbound. V1 pulled out and began its right turn, and the front of V2 struck the left side of V1 in "
      "lane one of the westbound lanes. Both vehicles came to final rest on the west leg facing west.");
  EXPECT_EQ(axis.road.lanes_total.value, 2);
  EXPECT_NEAR(axis.road.speed_limit_mps.value * 3.6, 48.3, 0.5);
}

TEST(NarrativeExtractorTest, LeavingADriveOntoACountedRoadIsOnTheDrive) {
  // V1's own sentence counts the road the drive comes out on, not the drive.
  const auto r = kExtractor.Extract(
      "V1 was leaving a shopping center parking lot through a driveway on the north side of a five-lane roadway (two "
      "lanes each way with a center two-way left-turn lane). The roadway was posted at 40 mph. The driver stopped at "
      "the end of the driveway and then pulled out to turn left. V2 was westbound in the curb lane. The front of V2 "
      "struck the left side of V1.");
  EXPECT_EQ(r.road.lanes_total.value, 2);
}

TEST(NarrativeExtractorTest, V1sOwnDirectionsCountAndTheRoadItsStopSignControls) {
  // "giving three westbound lanes", V1 westbound: its side has 3, not the 2
  // each way the sentence before counts.
  const auto bay = kExtractor.Extract(
      "The east/west roadway was a divided arterial with a raised median. Each direction had two through lanes; the "
      "westbound approach also had a left-turn bay, giving three westbound lanes at the intersection. V1 was "
      "westbound in the left-turn bay and stopped, waiting to turn left. V2 was eastbound in the inside through lane. "
      "V1 began its turn and the front of V2 struck the right side of V1.");
  EXPECT_EQ(bay.road.lanes_per_direction.value, 3);
  EXPECT_EQ(bay.road.lanes_total.value, 5);
  // "three southbound travel lanes" of a one-way southbound avenue: its total.
  const auto avenue = kExtractor.Extract(
      "The crash occurred at the intersection of a one-way southbound avenue and a two-way east/west street. The "
      "avenue had three southbound travel lanes, and the street had one travel lane in each direction. V1 was stopped "
      "for the red signal in the middle lane of the avenue. V2 was traveling eastbound on the street. V1 accelerated "
      "into the intersection and the front of V2 impacted the right side of V1.");
  EXPECT_TRUE(avenue.road.one_way.value);
  EXPECT_EQ(avenue.road.lanes_total.value, 3);
  // V1 stopped at the stop sign, and only the residential street has one:
  // its lanes and limit, not the state route's (two sentences before).
  const auto sign = kExtractor.Extract(
      "This crash occurred at a T-intersection where a residential street ends at a four-lane state route. The state "
      "route ran east/west with two lanes in each direction and a posted speed limit of 45 mph. The residential "
      "street approached from the south, had one lane in each direction with a posted limit of 25 mph, and was "
      "controlled by a stop sign. V1 stopped at the stop sign intending to turn left and travel west. V1 pulled out "
      "and into lane two, where it was struck on the left side by the front of V2, which was traveling east.");
  EXPECT_EQ(sign.road.lanes_total.value, 2);
  EXPECT_NEAR(sign.road.speed_limit_mps.value * 3.6, 40.2, 0.5);
}

TEST(NarrativeExtractorTest, CaseSummariesCodeAStopThenTurnByTheTurn) {
  // A CIREN case summary: the stop before the turn is not what is coded.
  const auto summary = kExtractor.Extract(
      "Vehicle one (V1 - case vehicle), a 1999 Chevrolet Malibu, 4-door sedan was stopped in the mouth of a "
      "commercial driveway facing west, waiting to make a left turn onto a north-south two-lane, two-way road. "
      "Vehicle two (V2), a 2003 Saturn Ion, 4-door sedan was traveling north in the northbound lane. The driver of V1 "
      "began to enter the roadway with the intention of turning left and the front of V2 struck the left side of V1. "
      "The 88-year-old female driver of V1 (case occupant) was using the available three-point seat belt.");
  ASSERT_EQ(summary.vehicles.size(), 2u);
  EXPECT_EQ(summary.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(summary.vehicles[0].pre_event.value, Movement::kTurnLeft);
  // An NMVCCS report quoting the coded critical event codes the stop.
  const auto report = kExtractor.Extract(
      "V1, a 1999 Chevrolet Malibu, was stopped in the mouth of a commercial driveway facing west, waiting to make a "
      "left turn onto a north-south two-lane, two-way road. V2, a 2003 Saturn Ion, was traveling north in the "
      "northbound lane. The driver of V1 began to enter the roadway with the intention of turning left and the front "
      "of V2 struck the left side of V1. The Critical Precrash Event for V1 was this vehicle traveling, turning left "
      "at intersection.");
  ASSERT_EQ(report.vehicles.size(), 2u);
  EXPECT_EQ(report.vehicles[0].pre_event.value, Movement::kStopped);
}

TEST(NarrativeExtractorTest, NotStoppedAndSlowingLeadsAndRampCurves) {
  // "had not stopped" is no stop.
  const auto ran = kExtractor.Extract(
      "V1 was traveling east on a two-lane road. V2 was traveling north toward the stop sign and did not slow down. "
      "The front of V1 struck the left side of V2. The driver of V2 had not stopped.");
  ASSERT_EQ(ran.vehicles.size(), 2u);
  EXPECT_EQ(ran.vehicles[1].pre_event.value, Movement::kStraight);
  // A lead struck from behind while slowing is coded going straight; its
  // path into the crash is still the slowing.
  const auto lead = kExtractor.Extract(
      "V1 was traveling east behind V2 on a two-lane road. V2 slowed for traffic ahead that was turning into a "
      "driveway. The front of V1 struck the back of V2.");
  ASSERT_EQ(lead.vehicles.size(), 2u);
  EXPECT_EQ(lead.crash.type.value, CrashType::kRearEnd);
  EXPECT_EQ(lead.vehicles[1].movement.value, Movement::kSlowing);
  EXPECT_EQ(lead.vehicles[1].pre_event.value, Movement::kStraight);
  // Lost in the entrance ramp's curve before the merge: negotiating the
  // curve, not merging, before the critical event.
  const auto ramp = kExtractor.Extract(
      "Vehicle one (V1 - case vehicle), a 2001 Pontiac Sunfire, was traveling on a one-lane entrance ramp that curves "
      "to the left to join the southbound lanes of a freeway. Vehicle two (V2) was traveling south in the right lane "
      "of the freeway. The driver of V1 entered the left curve at too great a speed and lost control, and V1 slid "
      "into the right southbound lane, where the front of V2 struck the right side of V1.");
  ASSERT_EQ(ramp.vehicles.size(), 2u);
  EXPECT_EQ(ramp.vehicles[0].movement.value, Movement::kMerging);
  EXPECT_EQ(ramp.vehicles[0].pre_event.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, TheOtherNamedRoadsDivisionAndDottedInitials) {
  // "a four-lane divided US route and a two-lane township road", V1 on the
  // township road: the division and the four lanes are the route's.
  const auto named = kExtractor.Extract(
      "This crash occurred at the intersection of a four-lane divided US route and a two-lane township road. V1 was "
      "northbound on the township road and stopped at the stop sign. V2 was eastbound in lane two. V1 pulled away "
      "from the stop sign and the front of V2 struck the left side of V1.");
  EXPECT_FALSE(named.road.divided.value);
  EXPECT_EQ(named.road.lanes_total.value, 2);
  // "U.S." ends no sentence.
  const auto dotted = kExtractor.Extract(
      "This crash occurred at the intersection of a four-lane divided U.S. route and a two-lane township road. The "
      "township road was a two-lane, two-way roadway and was controlled by stop signs. V1 was northbound on the "
      "township road and stopped at the stop sign. V2 was eastbound in lane two. V1 pulled away from the stop sign "
      "and the front of V2 struck the left side of V1.");
  EXPECT_FALSE(dotted.road.divided.value);
  EXPECT_EQ(dotted.road.lanes_total.value, 2);
}

TEST(NarrativeExtractorTest, TheRoadTurnedOntoAndOneDirectionsBay) {
  // "waiting to turn left onto the collector road": the two lanes counted
  // for the collector road are not V1's.
  const auto onto = kExtractor.Extract(
      "The crash occurred at a four-leg intersection of a divided highway and a two-lane collector road. The highway "
      "had a grass median approximately 12 meters wide. Each direction of the highway had two through lanes and a "
      "left turn lane at the intersection. V1 was traveling south in the left turn lane and had stopped at the stop "
      "line waiting to turn left onto the collector road. V2 was traveling north. V1 began its left turn and was "
      "struck in the right side by the front of V2.");
  EXPECT_EQ(onto.road.lanes_per_direction.value, 3);
  // "... two through lanes in each direction, with a left-turn lane for
  // southbound traffic", V1 southbound: three on its side.
  const auto bay = kExtractor.Extract(
      "The highway ran north/south and had two through lanes in each direction, separated by a raised grass median, "
      "with a left-turn lane for southbound traffic at the intersection. V1 was stopped in the southbound left-turn "
      "lane, waiting to turn left. V2 was traveling north in lane two. V1 began its left turn and its right side was "
      "struck by the front of V2.");
  EXPECT_EQ(bay.road.lanes_per_direction.value, 3);
  EXPECT_EQ(bay.road.lanes_total.value, 5);
}

TEST(NarrativeExtractorTest, CarsCrossedLanesAndExclusiveBaysAreNotMiscounted) {
  // "three westbound cars went by" counts cars, not lanes.
  const auto cars = kExtractor.Extract(
      "The crash occurred on State Route 9, a two-lane rural highway with one lane in each direction. Vehicle 1, a "
      "2006 Nissan Altima, was eastbound behind Vehicle 2. The front of Vehicle 1 struck the back of Vehicle 2. He "
      "stated that he had been stopped with his signal on for \"maybe ten seconds\" while three westbound cars went "
      "by.");
  EXPECT_EQ(cars.road.lanes_total.value, 2);
  // "Vehicle 1 crossed the two eastbound lanes" of the highway it then
  // turned onto: not its own road's count.
  const auto crossed = kExtractor.Extract(
      "This crash occurred at a four-leg rural intersection of a four-lane undivided state highway and a two-lane "
      "township road. The highway ran east-west with two lanes in each direction. Vehicle 1 was northbound on the "
      "township road and stopped at the stop sign intending to turn left. Vehicle 2 was westbound in the left lane "
      "of the highway. After stopping, Vehicle 1 crossed the two eastbound lanes and began to turn into the westbound "
      "lanes, where the front of Vehicle 2 struck the right side of Vehicle 1.");
  EXPECT_EQ(crossed.road.lanes_total.value, 2);
  EXPECT_EQ(crossed.road.lanes_per_direction.value, 1);
  // "two through lanes plus an exclusive left-turn lane" each way; V1 turns
  // onto "the cross street", the "two-lane east-west street".
  const auto exclusive = kExtractor.Extract(
      "The crash occurred at a signalized four-leg intersection of a north-south divided highway and a two-lane "
      "east-west street. The highway was divided by a raised grass median. Each direction of the highway had two "
      "through lanes plus an exclusive left-turn lane at the intersection. The posted speed limit on the highway was "
      "45 mph. V1 was northbound in the left-turn lane intending to turn left onto the cross street. V2 was "
      "southbound. V1 turned left and the front of V2 struck the right side of V1.");
  EXPECT_EQ(exclusive.road.lanes_per_direction.value, 3);
}

TEST(NarrativeExtractorTest, NoTrafficIsNobody) {
  // "did not see any traffic, and began her left turn": the clause after
  // "any traffic" is still the driver's own.
  const auto r = kExtractor.Extract(
      "Vehicle one (V1 - case vehicle), a 2000 Mercury Grand Marquis, 4-door sedan was traveling east on a two-lane, "
      "two-way road and had stopped at a stop sign at a four-leg intersection with a state highway. Vehicle two (V2), "
      "a 2005 Jeep Liberty, was traveling south on the state highway. The driver of V1 stated that she looked to her "
      "left, did not see any traffic, and began her left turn to travel north. The front of V2 struck the left side "
      "of V1. The driver of V1 (case occupant) was belted.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(r.crash.type.value, CrashType::kTurnIntoPath);
}

TEST(NarrativeExtractorTest, ABayInAdditionToTheThroughLanes) {
  // "The southbound side had a left-turn lane ... in addition to its two
  // through lanes", V1 southbound: three on its side.
  const auto r = kExtractor.Extract(
      "The crash occurred at the intersection of Route 1 and Quarry Road. Route 1 was a four-lane divided highway, "
      "two lanes in each direction, separated by a 15-meter grass median with an opening at the intersection. The "
      "southbound side had a left-turn lane leading into the median opening in addition to its two through lanes. "
      "Quarry Road was a two-lane road entering from the east and was controlled by a stop sign. V1 was southbound "
      "in the left-turn lane and stopped at the end of the lane, intending to turn left onto Quarry Road. V2 was "
      "northbound. V1 began its turn and the front of V2 struck the right side of V1.");
  EXPECT_TRUE(r.road.divided.value);
  EXPECT_EQ(r.road.lanes_per_direction.value, 3);
}

TEST(NarrativeExtractorTest, TheRoadNamedByItsCountsOwnNoun) {
  // Both counts are in one sentence about the junction; V1 is placed on
  // "the county road", which only the second count's noun names.
  const auto r = kExtractor.Extract(
      "The crash happened at a junction of a six-lane divided parkway and a two-lane gravel county road that came in "
      "from the west. The parkway had three lanes each way split by a grass median. V1, a 2004 Buick Century, was "
      "eastbound on the county road and stopped at its stop sign before turning left. V2, a 2001 Dodge Neon, was "
      "northbound on the parkway. The front of V2 struck the left side of V1.");
  EXPECT_EQ(r.road.lanes_total.value, 2);
  EXPECT_EQ(r.road.lanes_per_direction.value, 1);
  EXPECT_FALSE(r.road.divided.value);
}

TEST(NarrativeExtractorTest, TheLaneOfTheRoadIsTheRoadTravelledOn) {
  // "in the right lane (lane one) of the highway": V1 is on the highway,
  // not the county road the other vehicle came from.
  const auto r = kExtractor.Extract(
      "The crash happened at a signalized intersection of a divided highway and a two-lane county road. The highway "
      "had two lanes in each direction separated by a raised median. V1, a 2003 Chrysler PT Cruiser, was westbound "
      "in the right lane (lane one) of the highway. V2, a 1991 Chevrolet pickup, was northbound on the county road "
      "and entered the intersection against the red signal. The front of V2 struck the left side of V1.");
  EXPECT_TRUE(r.road.divided.value);
  EXPECT_EQ(r.road.lanes_per_direction.value, 2);
}

TEST(NarrativeExtractorTest, AMidSentenceDriverIsTheSubjectAndALaneChangeForATurnIsALaneChange) {
  // "just past the light the driver of V1 began to change lanes ... for a
  // right turn into a plaza": V1's lane change, not V2's, and not a turn.
  const auto r = kExtractor.Extract(
      "The sideswipe happened on a four-lane undivided street with two lanes each way. V1, a 2001 Mazda MPV, was "
      "southbound in the left lane. V2, a 2005 Kia Rio, was southbound in the right lane. Just past the light the "
      "driver of V1 began to change lanes to the right to get into position for a right turn into a plaza. The right "
      "front of V1 contacted the left side of V2.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kChangingLanes);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kStraight);
  EXPECT_EQ(r.crash.type.value, CrashType::kSideswipeSame);
}

TEST(NarrativeExtractorTest, BeganToMoveIntoTheLaneIsALaneChange) {
  // An expectation ("expected it to move over to the left lane") is not one.
  const auto r = kExtractor.Extract(
      "V1, a 2004 Toyota Camry, was northbound in the left lane of a four-lane divided highway. V2, a 1995 Ford F-150, "
      "was northbound in the right lane. The driver of V1 began to move back into the right lane and the right rear "
      "of V1 contacted the left front of V2. The driver of V2 stated she expected V1 to move over to the left lane.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kChangingLanes);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, LaneCountsAtTheApproach) {
  auto lanes = [](const char* road) {
    const auto r = kExtractor.Extract(std::string(road) +
                                      " V1, a 2002 Ford Focus, was westbound. V2, a 2004 Jeep Liberty, was northbound. "
                                      "The front of V1 struck the right side of V2.");
    return std::tuple(r.road.lanes_total.value, r.road.lanes_per_direction.value, r.road.one_way.value);
  };
  // The count where the road widens at the junction replaces the road's.
  EXPECT_EQ(std::get<0>(lanes("The crash happened at a signalized intersection. The east/west road was a two-lane "
                              "undivided road that widened to three lanes at the intersection: one eastbound lane, one "
                              "westbound lane and a center left turn lane.")),
            3);
  // "each approach ... had 2 through lanes and a left-turn bay".
  EXPECT_EQ(std::get<1>(lanes("The crash happened at an intersection of a four-lane divided boulevard and a two-lane "
                              "side street. On the east/west boulevard each approach to the intersection had two "
                              "through lanes and a left-turn bay.")),
            3);
  // "two moving lanes each way" on an avenue a one-way street leaves.
  const auto avenue = lanes("The crash happened on an undivided avenue, two moving lanes each way, where a one-way "
                            "northbound street leaves it to the left.");
  EXPECT_EQ(std::get<0>(avenue), 4);
  EXPECT_FALSE(std::get<2>(avenue));
  // "a one-way westbound roadway with three travel lanes and a two-way ...".
  const auto one_way = lanes("The crash happened at the intersection of a one-way westbound roadway with three travel "
                             "lanes and a two-way north/south roadway.");
  EXPECT_EQ(std::get<0>(one_way), 3);
  EXPECT_TRUE(std::get<2>(one_way));
}

TEST(NarrativeExtractorTest, EachLimitBelongsToTheRoadItsClauseNames) {
  // The road named after the value.
  EXPECT_NEAR(LimitMph("V1, a 2000 GMC Yukon, was westbound on a two-lane, two-way asphalt roadway, approaching a "
                       "T-intersection with a road from the north. The posted speed limit was 72 kmph (45 mph) on the "
                       "through road and 48 kmph (30 mph) on the side road. V2, a 1996 Ford Escort, was southbound on "
                       "the side road and turned left. The front of V1 struck the left side of V2."),
              44.7, 0.5);
  // A second road with its own verb starts its own clause.
  EXPECT_NEAR(LimitMph("The crash happened where a two-lane side road ends at a four-lane highway. The highway had a "
                       "posted speed limit of 50 mph and the side road had a posted speed limit of 25 mph. V1, a 1993 "
                       "Chevrolet Astro, was southbound on the side road and stopped at the stop sign before turning "
                       "right. V2, a 2004 Honda Odyssey, was westbound on the highway. The front of V2 struck the left "
                       "side of V1."),
              25.0, 0.5);
  // No limit stated; street parking on both sides is a town's street.
  EXPECT_NEAR(LimitMph("The crash occurred on a two-way roadway with one lane in each direction and parking lanes on "
                       "both sides. V1, a 2003 Honda CR-V, was northbound. V2, a 2000 box truck, was southbound and "
                       "crossed the center line. The left side of V2 struck the left side of V1."),
              30.0, 0.5);
}

TEST(NarrativeExtractorTest, ACodedTurnWithNothingBeforeItIsItsOwnPreEventMovement) {
  auto pre_event = [](const std::string& road, const std::string& v2) {
    const auto r = kExtractor.Extract(
        road + " V1, a 1991 Volkswagen Jetta, was traveling southbound approaching the T-intersection intending on "
               "turning left. " + v2 + " V1 made the left turn and the front of V2 struck the front-right of V1. The "
               "critical precrash event for V1 was this vehicle turning left at the intersection.");
    return r.vehicles.at(0).pre_event.value;
  };
  const std::string v2_oncoming = "V2, a 1994 Ford Taurus, was traveling northbound intending on going straight.";
  EXPECT_EQ(pre_event("The crash occurred on a two-lane roadway with a T-intersection.", v2_oncoming),
            Movement::kTurnLeft);
  // On a curve: negotiating it (coded going straight).
  EXPECT_EQ(pre_event("The crash occurred on a two-lane roadway with a T-intersection on a curve to the left.",
                      v2_oncoming),
            Movement::kStraight);
  // Across a lane of its own direction (from the wrong lane): going straight.
  EXPECT_EQ(pre_event("The crash occurred on a four-lane roadway with a T-intersection.",
                      "V2, a 1994 Ford Taurus, was traveling southbound in the lane to the left of V1."),
            Movement::kStraight);
}

TEST(NarrativeExtractorTest, SlowedToTurnIsSlowing) {
  const auto r = kExtractor.Extract(
      "The crash occurred on a two lane undivided roadway at a T-intersection. V1, a 2004 Suzuki motorcycle, was "
      "traveling north. V2, a 1998 Jeep Cherokee, was traveling south and slowed to turn left onto the residential "
      "street. V2 turned across the northbound lane and was struck in the right side by the front of V1.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kSlowing);
}

TEST(NarrativeExtractorTest, WhatCameLastBeforeTheCrashStoppedOrSlowing) {
  // Moved up, then stopped again: stopped; the follower that had stopped
  // and then accelerated into it: started (going straight).
  const auto queue = kExtractor.Extract(
      "The side street was controlled by a stop sign. V2, a 1996 Ford Taurus, was stopped at the stop sign. V1, a "
      "2004 Nissan Sentra, had stopped behind V2. V2 moved forward to the edge of the route and then stopped again "
      "for an approaching car. The driver of V1, who was looking to the left, accelerated, and the front of V1 struck "
      "the back of V2.");
  ASSERT_EQ(queue.vehicles.size(), 2u);
  EXPECT_EQ(queue.vehicles[0].pre_event.value, Movement::kStraight);
  EXPECT_EQ(queue.vehicles[1].pre_event.value, Movement::kStopped);
  // "was northbound and slowing ... to turn into the driveway", "almost
  // stopped": a lead that meant to turn, slowing, not stopped.
  const auto lead = kExtractor.Extract(
      "V2, a 2004 Saturn Ion, was northbound and slowing with its right turn signal on to turn into the driveway of "
      "a store. V1, a 1999 GMC Sierra, was northbound behind V2. The front of V1 struck the back of V2. V2 was almost "
      "stopped when it was hit.");
  ASSERT_EQ(lead.vehicles.size(), 2u);
  EXPECT_EQ(lead.vehicles[1].pre_event.value, Movement::kSlowing);
  // "slowed but did not stop for its stop sign": slowing.
  const auto rolled = kExtractor.Extract(
      "V1, a 1996 Chevrolet Cavalier, was northbound and stopped at the stop sign and then started across the "
      "intersection. V2, a 2003 GMC Sierra, was eastbound and slowed but did not stop for its stop sign. The front of "
      "V2 struck the left side of V1.");
  ASSERT_EQ(rolled.vehicles.size(), 2u);
  EXPECT_EQ(rolled.vehicles[1].pre_event.value, Movement::kSlowing);
}

TEST(NarrativeExtractorTest, LanesSeparatedFromTheOtherDirectionByAMedian) {
  // Said in V1's own sentence: "with two westbound lanes separated from the
  // two eastbound lanes by a wide grass median".
  const auto r = kExtractor.Extract(
      "Vehicle one (V1 - case vehicle), a 2005 Honda Civic, was traveling west in the right lane of a limited "
      "access interstate with two westbound lanes separated from the two eastbound lanes by a wide depressed grass "
      "median. Vehicle two (V2), a 2004 Chevrolet Suburban, was traveling west in the left lane. V1 drifted to the "
      "left and the left side of V1 contacted the right side of V2.");
  EXPECT_TRUE(r.road.divided.value);
  EXPECT_EQ(r.road.lanes_per_direction.value, 2);
}

TEST(NarrativeExtractorTest, ALimitAfterItsRoadAndARoadAfterCommas) {
  // "and on the side road 48 KMPH": the road just before the value.
  EXPECT_NEAR(LimitMph("The crash occurred at a T-intersection of a four lane roadway and a two lane side road. The "
                       "posted speed limit on the four lane roadway was 72 KMPH (45 MPH) and on the side road 48 KMPH "
                       "(30 MPH). Vehicle #1 was traveling west on the side road and turned left. Vehicle #2 was "
                       "traveling north on the four lane roadway. The front of Vehicle #2 struck Vehicle #1."),
              30.0, 0.5);
  // "on a two-lane, two-way residential street": V1's road through commas.
  EXPECT_NEAR(LimitMph("V1, a 2001 Ford Focus, was stopped at a stop sign facing north on a two-lane, two-way "
                       "residential street at a T-intersection with an east/west five-lane roadway. The posted speed "
                       "limit was 64 kmph (40 mph) on the five-lane roadway and 40 kmph (25 mph) on the residential "
                       "street. V2 was traveling east. V1 pulled out and the front of V2 struck the left side of V1."),
              25.0, 0.5);
}

TEST(NarrativeExtractorTest, TheRoadAPostedStopSignControlsIsTheOneV1StoppedAt) {
  // "The residential street is controlled by a posted stop sign", V1
  // stopped at it: V1's road is the residential street, and its limit.
  EXPECT_NEAR(LimitMph("A two way, two lane residential street ends at a two way, two lane collector roadway. The "
                       "residential street is controlled by a posted stop sign for southbound traffic. The speed "
                       "limit on the collector roadway is posted 72 kmph (45 mph). The speed limit on the "
                       "residential street is posted 48 kmph (30 mph). V1 was traveling southbound and stopped at "
                       "the stop sign, intending to turn left. V2 was traveling westbound. V1 pulled out and the "
                       "front of V2 struck the left side of V1."),
              30.0, 0.5);
}

TEST(NarrativeExtractorTest, ATelegraphicLimitListGoesOnAfterASemicolon) {
  // "; side road 40 km/h": the list's second road has its own limit without
  // the limit word again.
  EXPECT_NEAR(LimitMph("T-intersection of a two-lane north/south highway and a two-lane road that ends at it from the "
                       "west. Stop sign for the side road. Highway posted 72 km/h (45 mph); side road 40 km/h (25 "
                       "mph). V1 (1993 Toyota Camry) stopped at the stop sign on the side road and then began a left "
                       "turn. V2 (2002 Chevrolet Trailblazer) was southbound on the highway. The front of V2 struck "
                       "the left side of V1."),
              25.0, 0.5);
  // A speed in the next sentence is no limit: "the car 60 km/h" follows no
  // road noun.
  EXPECT_NEAR(LimitMph("V1 was northbound on a two-lane highway posted 72 km/h (45 mph); the driver estimated 60 "
                       "km/h. V2 pulled out of a driveway and the front of V1 struck the left side of V2."),
              45.0, 0.5);
}

TEST(NarrativeExtractorTest, AVehicleNamedBeforeItsNumberIsNamedWithinItsSentence) {
  // "the northbound lanes. The Mercury Sable (Vehicle #1)": the name is
  // "the mercury sable", not everything from the previous sentence's "the".
  const AccidentRecord r = kExtractor.Extract(
      "Vehicle #1, a 1996 Mercury Sable, was traveling west and rolled through the stop sign while attempting a left "
      "turn. Vehicle #2, a 2003 Jeep Liberty, was traveling north. The front of Vehicle #2 impacted the left side of "
      "Vehicle #1. Both vehicles came to rest in the northbound lanes. The Mercury Sable (Vehicle #1) was driven by a "
      "belted 34 year old female. She stated she slowed down but did not come to a complete stop. The Jeep Liberty "
      "(Vehicle #2) was driven by a 58 year old male.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kSlowing);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kStraight);
  EXPECT_EQ(r.crash.striking_area.value, DamageArea::kFront);
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kLeft);
  // "The 2002 Dodge Caravan (V1) was southbound": its description, so "the
  // dodge" later is V1.
  const AccidentRecord d = kExtractor.Extract(
      "The 2002 Dodge Caravan (V1) was southbound on a two-lane county road. The 2004 Ford Escape (V2) was eastbound "
      "on the highway. The Dodge's driver, a 40-year-old woman taking her mother to an appointment, stopped at the "
      "stop sign and then turned left to travel east. As the Dodge entered the eastbound lane the front of the Ford "
      "struck its right side. The Ford stopped in the eastbound lane.");
  ASSERT_EQ(d.vehicles.size(), 2u);
  EXPECT_EQ(d.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(d.vehicles[0].pre_event.value, Movement::kStopped);
  EXPECT_EQ(d.vehicles[1].pre_event.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, WhatADriverSawAnotherVehicleDoIsNotTheirOwnMovement) {
  const AccidentRecord r = kExtractor.Extract(
      "V1 was a 2000 Buick Century traveling eastbound intending to turn left into the parking lot. V2, a 1995 Honda "
      "Accord, was traveling westbound. V1 slowed and began to turn left into the parking lot and the front of V2 "
      "struck the right side of V1. V2 was driven by a 26-year-old female. She stated that she was traveling about "
      "40 MPH and the car turned right in front of her.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, ASlowingOrStopThatEndedBeforeTheCrashIsNotThePreEventMovement) {
  // "had slowed ... but it turned green so she ... continued".
  const AccidentRecord slowed = kExtractor.Extract(
      "V1 was pulling out of a driveway. V2 was traveling south. V2's driver stated that she had slowed as she "
      "approached the traffic light, but it turned green so she did not come to a complete stop and continued. The "
      "front of V2 struck the left side of V1.");
  ASSERT_EQ(slowed.vehicles.size(), 2u);
  EXPECT_EQ(slowed.vehicles[1].pre_event.value, Movement::kStraight);
  // A long stop told before the vehicle went on: started, not stopped.
  const AccidentRecord stopped = kExtractor.Extract(
      "V1 was traveling north through the intersection. V2 was traveling east. The front of V1 struck the left side "
      "of V2. The driver of V2 stated that he stopped for the stop sign for approximately 5 seconds and looked both "
      "directions before proceeding through the intersection.");
  ASSERT_EQ(stopped.vehicles.size(), 2u);
  EXPECT_NE(stopped.vehicles[1].pre_event.value, Movement::kStopped);
}

TEST(NarrativeExtractorTest, ATurnerPassedFromTheNextLaneIsCodedGoingStraight) {
  // straight/0 of the development set: stopped before turning, passed on the
  // left, coded going straight (the passer's move is the critical event).
  const AccidentRecord r = kExtractor.Extract(
      "V1, a 1995 Chevrolet Lumina was traveling eastbound. V2, a 2004 Chevrolet Trailblazer was also traveling "
      "eastbound on the same roadway. V2 was attempting to make a left-hand turn into a private drive. While "
      "turning V1 attempted to pass V2 on the left-hand side contacting its front to the left side of V2. The "
      "driver of V2 was a 41-year old female who reported that she had stopped prior to turning. The Critical "
      "Precrash Event for the driver of V1 was this vehicle traveling over left lane line on the left side of "
      "travel. The Critical Precrash Event for the driver of V2 was other vehicle encroachment from adjacent lane "
      "over left lane line.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kStraight);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, AnUnstatedLimitInTownIsTheStatutoryOneWhereReportsStateTheirLimits) {
  const std::string scene =
      "The crash occurred at a signalized intersection in a downtown area. The east/west street was a one-way "
      "westbound roadway with three travel lanes. V1 was westbound in the middle lane. V2 was westbound in the right "
      "lane. V1 began a right turn from the middle lane and the front of V2 struck the right side of V1.";
  // A report quoting the NASS coding gives its posted limits: silence is
  // the unposted town street's 30 mph, however many lanes.
  EXPECT_NEAR(LimitMph(scene + " The Critical Precrash Event for V1 was this vehicle traveling, turning right at "
                                "intersection."),
              30.0, 0.5);
  // A summary that never states limits keeps the arterial's prior.
  EXPECT_NEAR(LimitMph(scene), 45.0, 0.5);
}

TEST(NarrativeExtractorTest, ALocalStreetAndARoadPostedByName) {
  // "the local street" is V1's road, told apart from the arterial.
  EXPECT_NEAR(LimitMph("The crash occurred at a T-intersection where a two-lane local street ends at an east/west "
                       "arterial. The arterial had three lanes and a posted speed limit of 72 km/h (45 mph). The local "
                       "street was posted at 48 km/h (30 mph) and controlled by a stop sign. V1 was northbound on the "
                       "local street and stopped at the stop sign. V2 was westbound on the arterial. V1 turned left "
                       "and the front of V2 struck the left side of V1."),
              30.0, 0.5);
  // "meets a four-lane undivided arterial posted at 64 km/h": the
  // arterial's, not the first road of the sentence.
  EXPECT_NEAR(LimitMph("The crash occurred where a two-lane side street from the south meets an east/west four-lane "
                       "undivided arterial posted at 64 km/h (40 mph). The side street was posted at 48 km/h (30 mph). "
                       "V1 was northbound on the side street and turned right. V2 was eastbound on the arterial. The "
                       "front of V2 struck the rear of V1."),
              30.0, 0.5);
}

TEST(NarrativeExtractorTest, TheTrafficADriverWatchedIsNotANewSubject) {
  const AccidentRecord r = kExtractor.Extract(
      "Vehicle 2, a 2003 Volkswagen Jetta, was northbound on the local street, stopped at the stop sign and waiting "
      "to turn left. Vehicle 1, a 1998 Toyota 4Runner, was stopped behind it. The Jetta started forward, then "
      "stopped again for a westbound car. The driver of the Toyota, who was watching traffic to his left, started "
      "forward at the same time and struck the rear of the Jetta.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_NE(r.vehicles[0].pre_event.value, Movement::kStopped);
}

TEST(NarrativeExtractorTest, AStopThatEndedInMovingOffOrACodedDecelerationIsGoingStraight) {
  // "had been stopped ... and was moving into the intersection": moving off.
  EXPECT_EQ(PreEventOf("The crash occurred at a signalized intersection of two two-lane roads. V1 was traveling "
                       "west. V2 had been stopped in the northbound lane for a red signal and was moving into the "
                       "intersection after the signal turned green. The front of V1 struck the right side of V2.",
                       2, 1),
            Movement::kStraight);
  // The follower's coded event says the lead was still decelerating when
  // struck, whatever the driver says of her stop.
  const std::string lead =
      "The crash occurred on a two-lane road approaching a signal. V2 was traveling east when the signal turned "
      "yellow, and the driver of V2 braked to stop for the signal. V1 was traveling east behind V2. The front of V1 "
      "struck the back of V2. The driver of V2 stated that she stopped for the light.";
  EXPECT_EQ(PreEventOf(lead + " The Critical Precrash Event for V1 was other motor vehicle in lane, traveling in "
                              "same direction while decelerating.",
                       2, 1),
            Movement::kStraight);
  // Coded as stopped, it stays stopped.
  EXPECT_EQ(PreEventOf(lead + " The Critical Precrash Event for V1 was other motor vehicle in lane, other vehicle "
                              "stopped.",
                       2, 1),
            Movement::kStopped);
}

TEST(NarrativeExtractorTest, WhatWasLongPastOrSomeoneElsesIsNotThePreCrashMovement) {
  // "to go around the stopped vehicle": the stopped one is another.
  const std::string around =
      "The crash occurred mid-block on a four-lane city street with two lanes in each direction. V1 was traveling "
      "east in lane two. A vehicle ahead of V1 in lane two had stopped to turn left into an alley. V1 moved to the "
      "right to go around the stopped vehicle, and the right front of V1 struck the left side of V2, which was "
      "traveling east in lane one.";
  EXPECT_NE(PreEventOf(around, 2, 0), Movement::kStopped);
  // ... and the alley it was turning into does not put the crash there.
  EXPECT_EQ(kExtractor.Extract(around).crash.location.value, CrashLocation::kSegment);
  // A lane change a block earlier.
  EXPECT_EQ(PreEventOf("The crash occurred at a T-intersection of a four-lane road and a residential street. V1 "
                       "stopped at the stop sign on the street and pulled out to turn right. V2 was traveling east in "
                       "lane one with its right turn signal on. The front of V2 struck the left side of V1. The driver "
                       "of V2 stated that he was going straight and that his signal was still on from moving into the "
                       "right lane a block earlier.",
                       2, 1),
            Movement::kStraight);
  // A speed kept down for the ice.
  EXPECT_EQ(PreEventOf("The crash occurred on a two-lane rural road. V1 was westbound in a curve when it lost traction "
                       "on the ice and slid into the eastbound lane. V2 was eastbound. The front of V2 struck the "
                       "right side of V1. The driver of V2 said he had slowed for the ice and was traveling about 35 "
                       "mph.",
                       2, 1),
            Movement::kStraight);
  // "slowed down and began to weave within its lane": no slowing to turn.
  EXPECT_EQ(PreEventOf("The crash occurred on a two-lane undivided highway. V1 was traveling west. Witnesses stated "
                       "that it slowed down and began to weave within its lane. V1 then drifted left across the center "
                       "line. V2 was traveling east. The front of V1 struck the front of V2.",
                       2, 0),
            Movement::kStraight);
  // "moved to the right to prepare for a right turn at the next block" is
  // a lane change, not the turn.
  const AccidentRecord shift = kExtractor.Extract(
      "The crash occurred on a four-lane undivided arterial. V1 was northbound in the left lane. V2 was northbound "
      "in the right lane, slightly behind V1. The driver of V1 moved to the right to prepare for a right turn at the "
      "next block, and the right side of V1 struck the left front of V2.");
  ASSERT_EQ(shift.vehicles.size(), 2u);
  EXPECT_EQ(shift.vehicles[0].movement.value, Movement::kChangingLanes);
  EXPECT_EQ(shift.crash.type.value, CrashType::kSideswipeSame);
}

TEST(NarrativeExtractorTest, DividedOrUndividedBelongsToTheRoadItQualifies) {
  auto lanes = [](const std::string& text) { return kExtractor.Extract(text).road; };
  const std::string v1 =
      " The boulevard had two eastbound and two westbound lanes separated by a grass median. V1 was traveling east "
      "in the right lane of the boulevard. V2 was traveling north on the city street. The front of V1 struck the "
      "left side of V2.";
  const RoadRecord first = lanes(
      "The crash occurred at the signalized intersection of a four-lane divided boulevard and a two-lane undivided "
      "city street." + v1);
  EXPECT_TRUE(first.divided.value);
  EXPECT_EQ(first.lanes_per_direction.value, 2);
  const RoadRecord second = lanes(
      "The crash occurred at the signalized intersection of a two-lane undivided city street and a four-lane divided "
      "boulevard." + v1);
  EXPECT_TRUE(second.divided.value);
  // Said of V1's own road, it holds.
  EXPECT_FALSE(lanes("The crash occurred at the intersection of a four-lane undivided boulevard and a two-lane city "
                     "street. V1 was traveling east on the boulevard. V2 was traveling north on the city street. The "
                     "front of V1 struck the left side of V2.")
                   .divided.value);
  // "Of a six-lane, divided, limited access interstate": the words that say
  // it name V1's road themselves.
  EXPECT_TRUE(lanes("V1 was traveling west in the center westbound lane of a six-lane, divided, limited access "
                    "interstate highway (three lanes westbound, concrete median barrier, three lanes eastbound). V2 "
                    "was ahead of V1 in the same lane. The front of V1 struck the rear of V2.")
                  .divided.value);
}

TEST(NarrativeExtractorTest, ADriftOutOfTheLaneIsGoingStraightBeforeIt) {
  const std::string scene =
      "V1 was traveling west in the center lane of a six-lane freeway with three lanes in each direction. V2 was "
      "westbound in the left lane, slightly behind V1. ";
  const AccidentRecord drift = kExtractor.Extract(
      scene + "The driver of V1 reached for a phone and V1 drifted to the left into the left lane. The front of V2 "
              "struck the left side of V1.");
  ASSERT_EQ(drift.vehicles.size(), 2u);
  EXPECT_EQ(drift.vehicles[0].movement.value, Movement::kChangingLanes);  // the path the planner drives
  EXPECT_EQ(drift.vehicles[0].pre_event.value, Movement::kStraight);
  // A lane change the driver made stays one.
  EXPECT_EQ(PreEventOf(scene + "The driver of V1 signaled and moved into the left lane. The front of V2 struck "
                               "the left side of V1.",
                       2, 0),
            Movement::kChangingLanes);
}

TEST(NarrativeExtractorTest, CaseSummaryWordingOfVehiclesAndTheirCourses) {
  // "a 2003 honda cr-v 4-door utility vehicle" names no fourth vehicle.
  const AccidentRecord body = kExtractor.Extract(
      "Vehicle one (V1, case vehicle), a 2005 Chevrolet Cobalt 4-door sedan, was traveling west. Vehicle two (V2), "
      "a 2003 Honda CR-V 4-door utility vehicle, was stopped ahead of V1 in the same lane. The front of V1 struck "
      "the back of V2.");
  EXPECT_EQ(body.vehicles.size(), 2u);
  // "waiting for westbound traffic to clear" is not V2's course.
  const AccidentRecord waiting = kExtractor.Extract(
      "The case vehicle (V1) was traveling east in the eastbound lane of a two-lane rural road. V2 was stopped "
      "ahead of V1 in the eastbound lane with its left turn signal on, waiting for westbound traffic to clear so "
      "that it could turn left. The front of V1 struck the back of V2.");
  ASSERT_EQ(waiting.vehicles.size(), 2u);
  EXPECT_EQ(waiting.vehicles[1].travel.value, Compass::kEast);
  EXPECT_EQ(waiting.crash.type.value, CrashType::kRearEnd);
  // A case vehicle never numbered is V1.
  const AccidentRecord unnumbered = kExtractor.Extract(
      "The case vehicle, a 2002 Toyota Camry four-door sedan, was traveling eastbound on a two-lane rural highway. "
      "V2, a 2000 Ford F-150 pickup, was westbound. The Camry drifted left across the centerline into the westbound "
      "lane. The front of the Camry struck the front of V2.");
  ASSERT_EQ(unnumbered.vehicles.size(), 2u);
  EXPECT_EQ(unnumbered.vehicles[0].travel.value, Compass::kEast);
  EXPECT_EQ(unnumbered.crash.type.value, CrashType::kHeadOn);
  // Who rode along does not hide the course: "was southbound on vine street
  // with a 17-year-old male driver and two passengers".
  const AccidentRecord riders = kExtractor.Extract(
      "The crash occurred where Vine Street, a north-south two-lane street with a 25 mph limit, ends at Commercial "
      "Avenue, which has two lanes in each direction and a 35 mph limit. The case vehicle, a 2004 Mazda Tribute, "
      "was southbound on Vine Street with a 17-year-old male driver and two passengers. It slid across Commercial "
      "Avenue and its front struck a utility pole.");
  ASSERT_EQ(riders.vehicles.size(), 1u);
  EXPECT_EQ(riders.vehicles[0].travel.value, Compass::kSouth);
  EXPECT_NEAR(riders.road.speed_limit_mps.value / 0.44704, 25.0, 0.5);
}

TEST(NarrativeExtractorTest, TheCaseVehicleOnceNumberedAndMovesOnlyMeant) {
  // "the driver of the case vehicle stated ... then pulled out to turn
  // left": the case vehicle is V1, and CIREN codes its turn.
  EXPECT_EQ(PreEventOf("The case vehicle (V1), a 2000 Buick LeSabre, was northbound on a two-lane county road "
                       "approaching a four-leg intersection with a state highway. Vehicle two (V2), a 2004 Chevrolet "
                       "TrailBlazer, was traveling east on the state highway. The driver of the case vehicle stated "
                       "that she stopped at the stop sign, looked both ways, and then pulled out to turn left and "
                       "proceed west on the highway. The front of V2 struck the left side of V1.",
                       2, 0),
            Movement::kTurnLeft);
  // "looked over his shoulder to change lanes": no lane change made.
  const AccidentRecord meant = kExtractor.Extract(
      "Traffic in both eastbound lanes of the interstate had come to a stop. V2 was stopped in the right lane. V1 "
      "(case vehicle) was traveling east in the right lane. The driver of V1 stated that he had looked over his "
      "shoulder to change lanes and did not see that traffic had stopped. The front of V1 struck the back of V2.");
  ASSERT_EQ(meant.vehicles.size(), 2u);
  EXPECT_EQ(meant.vehicles[0].pre_event.value, Movement::kStraight);
  EXPECT_EQ(meant.crash.type.value, CrashType::kRearEnd);
  // Nor "checking his mirror before changing lanes".
  const AccidentRecord before = kExtractor.Extract(
      "Northbound traffic was moving at about 10 mph because of congestion, and V1 was moving with that traffic. "
      "V2, a box truck, was also northbound in the right lane behind V1. The driver of V2 stated he was checking his "
      "mirror before changing lanes and did not notice that traffic ahead had slowed. The front of V2 struck the back "
      "of V1.");
  ASSERT_EQ(before.vehicles.size(), 2u);
  EXPECT_EQ(before.vehicles[1].pre_event.value, Movement::kStraight);
  EXPECT_EQ(before.crash.type.value, CrashType::kRearEnd);
  // What she believed the other would do is not her own intent: "she thought
  // V1 was going to turn onto Carver Road and she began a left turn".
  const AccidentRecord belief = kExtractor.Extract(
      "V1 was driving south on Harrison Avenue. V2 was eastbound on Carver Road and was stopped at the stop sign "
      "where Carver Road forms a T-intersection with Harrison Avenue. The 16-year-old driver of V2 stated that she "
      "thought V1 was going to turn onto Carver Road and she began a left turn to go north. The front of V2 struck "
      "the right side of V1.");
  ASSERT_EQ(belief.vehicles.size(), 2u);
  EXPECT_EQ(belief.vehicles[1].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(belief.crash.type.value, CrashType::kTurnIntoPath);
  // One that spun across the centerline and was broadsided by an oncoming
  // vehicle is in the opposite-direction group, not an angle crash.
  const AccidentRecord spun = kExtractor.Extract(
      "V1 was traveling northbound on a two-lane undivided state highway. V2 was southbound on the same road. The "
      "rear of V1 began to slide to the left and V1 rotated clockwise as it crossed the centerline into the "
      "southbound lane. The front of V2 struck the left side of V1 in a broadside configuration.");
  ASSERT_EQ(spun.vehicles.size(), 2u);
  EXPECT_EQ(spun.crash.type.value, CrashType::kSideswipeOpposite);
}

TEST(NarrativeExtractorTest, CodedWordingsOfALaneLineCrossingAndAnUnpostedCountedRoad) {
  // "the critical pre-crash event for v1 was when it traveled over the lane
  // line": driving straight before it, though it changed lanes.
  const AccidentRecord lane = kExtractor.Extract(
      "The southbound roadway of the interstate had three travel lanes. V1 was traveling south in lane two. V2 was "
      "traveling south in lane one, slightly behind V1. The driver of V1 changed lanes to the right to get in "
      "position for the exit, and the right side of V1 contacted the left side of V2. The Critical Pre-crash Event "
      "for V1 was when it traveled over the lane line on the right side of the travel lane.");
  ASSERT_EQ(lane.vehicles.size(), 2u);
  EXPECT_EQ(lane.vehicles[0].movement.value, Movement::kChangingLanes);
  EXPECT_EQ(lane.vehicles[0].pre_event.value, Movement::kStraight);
  // A report that gives its limits as a rule and gives none here, on a road
  // named by no class: the unposted town street's 30 mph.
  const std::string scene =
      "The crash occurred in the intersection of two two-way roadways, each with two lanes in each direction, "
      "controlled by traffic signals. Vehicle # 1 was traveling eastbound in the left lane. Vehicle # 2 was "
      "traveling eastbound in the right lane and attempted to make a left turn. The front of Vehicle # 1 impacted "
      "the left side of Vehicle # 2.";
  const AccidentRecord told = kExtractor.Extract(
      scene + " The Critical Pre-crash Event for Vehicle # 2 was coded as: This vehicle traveling, turning left at "
              "intersection.");
  EXPECT_NEAR(told.road.speed_limit_mps.value / 0.44704, 30.0, 0.5);
  EXPECT_NEAR(LimitMph(scene), 55.0, 0.5);
}

TEST(NarrativeExtractorTest, VehiclesNamedByMakeRoleOrLoadAreFollowed) {
  // A make glued to its model number ("mazda3") still names "the mazda".
  EXPECT_EQ(PreEventOf("The Mazda (V2), a 2004 Mazda3 sedan, was traveling in the left lane and was slowing with the "
                       "traffic. The Jeep (V1), a 2001 Jeep Grand Cherokee, was following the Mazda. The front of "
                       "the Jeep struck the rear of the Mazda. The driver of the Mazda, a 50-year-old female, said "
                       "she was slowing down because the traffic ahead had nearly stopped.",
                       2, 0),
            Movement::kStraight);
  // The make before the number, the model after it.
  const AccidentRecord made = kExtractor.Extract(
      "The Toyota (V2), a 2005 Prius, was traveling north in the curb lane and braked for the yellow signal. The "
      "Mitsubishi (V1), a 2000 Eclipse coupe, was following in the same lane. The front of the Mitsubishi struck "
      "the rear of the Toyota. The Mitsubishi stopped just behind it.");
  ASSERT_EQ(made.vehicles.size(), 2u);
  EXPECT_EQ(made.vehicles[0].pre_event.value, Movement::kStraight);
  EXPECT_EQ(made.crash.striking_area.value, DamageArea::kFront);
  // Roles named once ("the striking vehicle, a ... (v2)") and a report that
  // opens with the collision: the impact is where the roles are told.
  const AccidentRecord roles = kExtractor.Extract(
      "The striking vehicle, a 2002 Chevrolet Tahoe (V2), and the turning vehicle, a 2004 Kia Spectra (V1), "
      "collided at the signalized intersection of Harbor Boulevard and Seaview Drive. V1 was westbound and was "
      "the first vehicle stopped at the red signal, intending to turn left. V2 was eastbound and entered the "
      "intersection on the green. The front of V2 struck the right side of V1. The driver of the turning vehicle "
      "said he had been stopped for about a minute.");
  ASSERT_EQ(roles.vehicles.size(), 2u);
  EXPECT_EQ(roles.crash.striking.value, "V2");
  EXPECT_EQ(roles.crash.struck_area.value, DamageArea::kRight);
  EXPECT_EQ(roles.vehicles[1].travel.value, Compass::kEast);
  // A tractor's trailer is the tractor; "the slow-moving truck" is a vehicle named.
  const AccidentRecord towing = kExtractor.Extract(
      "V1, a 2002 Buick LeSabre, was westbound on an interstate highway. V2, a 2001 International 9200 tractor "
      "pulling a loaded van semitrailer, was ahead of V1 in the same lane, traveling slowly. The driver of V1 did "
      "not recognize the slow-moving truck, and the front of V1 struck and underrode the rear of the semitrailer.");
  EXPECT_EQ(towing.crash.type.value, CrashType::kRearEnd);
  EXPECT_EQ(towing.crash.struck_area.value, DamageArea::kRear);
}

TEST(NarrativeExtractorTest, QueuesRollingStopsAndLanesEnteredAreNotTheSubjectsMoves) {
  // A stop sign rolled through after slowing: decelerating.
  EXPECT_EQ(PreEventOf("V1 was northbound and stopped at the all-way stop sign. V2 was westbound. The driver of V2 "
                       "slowed, coasting up to the stop line, but did not stop before continuing straight into the "
                       "intersection. The front of V2 struck the right side of V1.",
                       2, 1),
            Movement::kSlowing);
  // "the third vehicle in a queue" is a place in line, and the queue's stop
  // is not the follower's.
  const std::string queue =
      "V2 was stopped in the center lane, the third vehicle in a queue waiting for the red signal. V1 was "
      "approaching in the same lane. The driver of V1 did not recognize that the queue had stopped until he was "
      "close to it, and the front of V1 struck the back of V2.";
  EXPECT_EQ(kExtractor.Extract(queue).participant_count.value, 2);
  EXPECT_EQ(PreEventOf(queue, 2, 0), Movement::kStraight);
  EXPECT_EQ(PreEventOf(queue, 2, 1), Movement::kStopped);
  // Moving into a turn lane is no turn begun: it struck the car ahead.
  EXPECT_EQ(PreEventOf("V2 was southbound in the center lane and had stopped waiting to turn left. V1 was also "
                       "southbound; its driver had entered the center lane about 60 meters back, also intending to "
                       "turn left, and was coasting toward the intersection. The front of V1 struck the rear of V2.",
                       2, 0),
            Movement::kStraight);
  // ... but entering the road's lane from a drive is.
  EXPECT_EQ(PreEventOf("V1 was stopped in the mouth of the driveway, waiting to turn left onto the roadway. V2 was "
                       "eastbound. As V1 entered the eastbound lane, the front of V2 struck the left side of V1.",
                       2, 0),
            Movement::kStopped);
  // A swerve away from the crash is no lane change.
  EXPECT_EQ(PreEventOf("V1 was southbound in the curb lane. V2 pulled out of a gas station driveway across the "
                       "southbound lanes in front of V1. The driver of V1 steered left into the inside lane, but the "
                       "front of V1 struck the left side of V2.",
                       2, 0),
            Movement::kStraight);
  // A back out of a stall before the coded turn out of the lot.
  const AccidentRecord lot = kExtractor.Extract(
      "V2 was westbound on Center Street. The driver of V1 backed out of a parking stall, drove through the lot to "
      "the exit and turned left to go east. The front of V2 struck V1's left side. The Critical Precrash Event for "
      "V1 was this vehicle traveling, turning left at intersection.");
  ASSERT_EQ(lot.vehicles.size(), 2u);
  EXPECT_NE(lot.vehicles[0].pre_event.value, Movement::kBacking);
  EXPECT_EQ(lot.vehicles[0].movement.value, Movement::kTurnLeft);
}

TEST(NarrativeExtractorTest, WherePlacesAndRoadsAreToldInPassing) {
  auto location = [](const std::string& text) { return kExtractor.Extract(text).crash.location.value; };
  const std::string rear =
      " V2 was stopped at the end of the queue. V1 was traveling in the same lane behind V2. The front of V1 struck "
      "the back of V2.";
  // A queue for the light at the next intersection, 30 meters on, is at it.
  EXPECT_EQ(location("Traffic in the left lane was stopped for a red signal at the next intersection, approximately "
                     "30 meters ahead." + rear),
            CrashLocation::kJunction);
  EXPECT_EQ(location("V1 began a lane change to the right to prepare for a right turn at the next intersection, and "
                     "the right side of V1 struck the left side of V2."),
            CrashLocation::kSegment);
  // A plaza's or a yard's entrance is an access; a drive children got off
  // at, or one driven past, is not.
  EXPECT_EQ(location("V1 had moved into the two-way left turn lane, intending to turn left into the entrance of a "
                     "shopping plaza. V2 was eastbound. The front of V2 struck the right side of V1."),
            CrashLocation::kDriveway);
  EXPECT_EQ(location("A school bus had stopped to let two children off at their driveway. V2 had come to a stop "
                     "behind the bus." + rear),
            CrashLocation::kSegment);
  EXPECT_EQ(location("V1 had passed the entrance to a shopping plaza and began a U-turn at a location with no "
                     "median opening or intersection. The front of V2 struck the left side of V1."),
            CrashLocation::kSegment);
  // "where a road crosses US-29", "the intersecting street".
  EXPECT_EQ(location("The crash took place where Carter's Mill Road crosses US-29. V2 pulled out to cross the "
                     "northbound lanes. The front of V1 struck the right side of V2."),
            CrashLocation::kJunction);
  EXPECT_EQ(location("V1 was southbound on the highway. V2 was stopped at the stop sign of the intersecting two-lane "
                     "residential street. V2 pulled away and the front of V1 struck the right side of V2."),
            CrashLocation::kJunction);
  // Lanes: a barrier between the directions divides the road; "lanes of
  // traffic in each direction"; a turn lane after the through lanes; the
  // one-way avenue counted in the next sentence.
  const AccidentRecord barrier = kExtractor.Extract(
      "V1 was southbound in lane two of an urban highway with three southbound lanes, separated from the northbound "
      "lanes by a concrete barrier. V2 was southbound in lane one. The right side of V1 struck the left side of V2.");
  EXPECT_TRUE(barrier.road.divided.value);
  EXPECT_EQ(barrier.road.lanes_per_direction.value, 3);
  const AccidentRecord avenue = kExtractor.Extract(
      "The crash took place on a north/south avenue carrying two lanes of traffic in each direction with no "
      "median. V1 was northbound. V2 was northbound. The left front of V1 struck the right side of V2.");
  EXPECT_EQ(avenue.road.lanes_total.value, 4);
  const AccidentRecord bay = kExtractor.Extract(
      "Route 202 is a divided highway with a grass median; at the intersection the southbound side consists of two "
      "through lanes and a long left-turn lane. V2 was stopped in the left-turn lane. V1 was southbound behind V2. "
      "The front of V1 struck the back of V2.");
  EXPECT_EQ(bay.road.lanes_per_direction.value, 3);
  const AccidentRecord one_way = kExtractor.Extract(
      "The crash occurred at the intersection of a southbound one-way avenue and a two-way east/west street. The "
      "avenue had three travel lanes with parking along both curbs. V1 was southbound in the middle lane of the "
      "avenue and turned right. V2 was southbound in the right lane. The front of V2 struck the right side of V1.");
  EXPECT_TRUE(one_way.road.one_way.value);
  EXPECT_EQ(one_way.road.lanes_total.value, 3);
}

TEST(NarrativeExtractorTest, WhatWasStruckAndTheLimitAreReadCloseBy) {
  // A sapling struck, then "the vehicle rolled": one vehicle.
  const AccidentRecord tree = kExtractor.Extract(
      "Vehicle 1, a 2005 Jeep Liberty, was southbound. The Jeep drifted off the right edge of the pavement. The "
      "front of the Jeep struck a small sapling (about 8 cm in diameter), then the vehicle rolled over down the "
      "embankment. She estimated her speed at 72-80 kmph (45-50 mph) and said she thought the limit on the road "
      "was 55 mph.");
  EXPECT_EQ(tree.participant_count.value, 1);
  EXPECT_EQ(tree.crash.type.value, CrashType::kSingleVehicle);
  EXPECT_NEAR(tree.road.speed_limit_mps.value / 0.44704, 55.0, 0.5);  // not her 80 km/h
  // A front into the back corner of a car stalled in the lane: a rear-end.
  const AccidentRecord stalled = kExtractor.Extract(
      "V1 was northbound on a two-lane rural road. V2 had run out of fuel and was stopped in the northbound lane "
      "with its hazard lamps flashing. The front of V1 struck the left rear of V2.");
  EXPECT_EQ(stalled.crash.type.value, CrashType::kRearEnd);
  // A turn signal tells the turn: the pass around it crosses a turner's path.
  const AccidentRecord signal = kExtractor.Extract(
      "V2 was westbound and slowed with its left turn signal on to turn into a residential driveway. V1 was "
      "westbound behind V2. V1's driver, who said he did not see the turn signal, steered left across the double "
      "yellow to go around the slowing pickup just as V2 began its turn. The front of V1 struck the left side of "
      "V2. The Critical Precrash Event for V1 was this vehicle traveling over the lane line on the left side of the "
      "travel lane.");
  EXPECT_EQ(signal.crash.type.value, CrashType::kTurnAcrossPath);
}

TEST(NarrativeExtractorTest, TrafficLookedForOrWavingIsNotTheSubject) {
  // "looked to her right for westbound traffic and then pulled out to turn
  // left": her turn, not the traffic's (a CIREN summary codes the turn).
  const AccidentRecord looked = kExtractor.Extract(
      "V1, a 2002 Saturn SL (case vehicle), was stopped at a stop sign at the end of a northbound township road "
      "where it forms a T-intersection with a state highway. V2 was eastbound on the highway. The Saturn's driver "
      "reported that she looked to her right for westbound traffic and then pulled out to turn left toward the "
      "west. The front of V2 struck the left side of V1.");
  ASSERT_EQ(looked.vehicles.size(), 2u);
  EXPECT_EQ(looked.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(looked.crash.type.value, CrashType::kTurnIntoPath);
  // The direction of the traffic that waved it out is not its own.
  const AccidentRecord waved = kExtractor.Extract(
      "Vehicle #2 was exiting a gasoline station on the west side of the road, intending to turn left to travel "
      "north. Southbound traffic in the curb lane was stopped, and a driver in that lane waved Vehicle #2 out. "
      "Vehicle #1 was traveling south in lane two. Vehicle #2 pulled out between the stopped vehicles and began "
      "its left turn, and the front of Vehicle #1 impacted the left side of Vehicle #2.");
  ASSERT_EQ(waved.vehicles.size(), 2u);
  EXPECT_EQ(waved.vehicles[1].pre_event.value, Movement::kTurnLeft);
  EXPECT_EQ(waved.crash.location.value, CrashLocation::kDriveway);  // a gasoline station's drive
  // A lane change he could not make is none.
  EXPECT_EQ(PreEventOf("V1 stopped at the stop sign and then began a right turn. V2 was northbound in lane one. The "
                       "front of V2 contacted the left rear of V1. The driver of V2 stated that he braked hard, but "
                       "he could not change lanes because of traffic.",
                       2, 1),
            Movement::kStraight);
  // A private residential driveway is no residential street: the rural
  // highway's 55 mph.
  EXPECT_NEAR(LimitMph("V1 was leaving a private residential driveway on the east side of a two-lane rural highway, "
                       "intending to turn left. V2 was northbound. The front of V2 struck the left side of V1."),
              55.0, 0.5);
}

TEST(NarrativeExtractorTest, ClausesAboutTheDriverAndAboutBothVehicles) {
  // The driver's own clause after another road user in the same sentence.
  const AccidentRecord bus = kExtractor.Extract(
      "V1, a 2001 Ford Focus, was leaving the lot of a hardware store on the south side of a two-lane road and its "
      "driver intended to turn left to go west. V2, a 1998 Buick Regal, was traveling west. The driver of V1 said "
      "that a delivery truck parked at the curb hid the westbound lane, and she pulled out beyond the truck's "
      "front. The front of V2 struck the left side of V1.");
  ASSERT_EQ(bus.vehicles.size(), 2u);
  EXPECT_EQ(bus.vehicles[0].movement.value, Movement::kTurnLeft);
  // What both vehicles did together is each one's: a queue starting on green.
  EXPECT_EQ(PreEventOf("V1, a 1999 Ford Escort, and V2, a 2002 Honda Civic, were stopped in the right lane of a "
                       "one-way street at a red light. V2 was first in line and V1 was behind it. When the light "
                       "changed, both vehicles started to move forward. V2 stopped suddenly for a dog, and the front "
                       "of V1 struck the back of V2.",
                       2, 0),
            Movement::kStraight);
  // A merge from an entrance ramp in an NMVCCS report is a turn into path;
  // a CIREN case summary codes it as a sideswipe.
  const std::string merge =
      "V1 was on the entrance ramp, merging into the right lane of the interstate. V2 was eastbound in the right "
      "lane. The left side of V1 contacted the right side of V2. The Critical Precrash Event for V1 was this "
      "vehicle traveling over the lane line on the left side of travel lane.";
  EXPECT_EQ(kExtractor.Extract(merge).crash.type.value, CrashType::kTurnIntoPath);
  EXPECT_EQ(kExtractor.Extract("Vehicle one (V1, the case vehicle) was on the entrance ramp, merging into the right "
                               "lane of the interstate. V2 was eastbound in the right lane. The left side of V1 "
                               "contacted the right side of V2.")
                .crash.type.value,
            CrashType::kSideswipeSame);
}

TEST(NarrativeExtractorTest, RoadsToldByRouteAndBySign) {
  // "U.S. 22" is a route's name (V1's road: divided, two lanes each way).
  const AccidentRecord us = kExtractor.Extract(
      "The crash occurred at the intersection of U.S. 22, a divided highway, and a four-lane undivided street. U.S. "
      "22 has two lanes in each direction. V1 was northbound on U.S. 22. V2 was eastbound on the street. The front "
      "of V1 struck the left side of V2.");
  EXPECT_TRUE(us.road.divided.value);
  EXPECT_EQ(us.road.lanes_per_direction.value, 2);
  // The road a stop sign is "for" is the one V1 stopped on.
  EXPECT_NEAR(LimitMph("A two-lane side road meets a two-lane highway. Stop sign for the side road. The highway had "
                       "a posted speed limit of 55 mph; the side road had a posted speed limit of 35 mph. V1 stopped "
                       "at the stop sign and pulled out. V2 was southbound on the highway. The front of V2 struck "
                       "the left side of V1."),
              35.0, 0.5);
}

TEST(NarrativeExtractorTest, AccountsRollsAndParkingSpaces) {
  // A junction far ahead does not place the crash.
  EXPECT_EQ(kExtractor
                .Extract("V1 and V2 were eastbound on a four-lane divided highway. Traffic was slowing for a signalized "
                         "intersection about 500 meters ahead. The front of V1 struck the back of V2.")
                .crash.location.value,
            CrashLocation::kSegment);
  // In a driver's account of another vehicle, her own braking is not its.
  EXPECT_EQ(PreEventOf("V1, a 2003 Chevrolet Malibu, was traveling north. V2, a 1997 Ford Escort, stopped at the "
                       "stop sign on the side street. V2 then proceeded to turn left. The front of V1 struck the left "
                       "side of V2. The Malibu's driver stated that the Ford pulled out right in front of her and she "
                       "braked but could not stop.",
                       2, 1),
            Movement::kStopped);
  // "Did not come to a complete stop" is no stop.
  EXPECT_EQ(PreEventOf("V1 was westbound approaching a stop sign. V2 was southbound on the through road. V1 slowed "
                       "but did not come to a complete stop and rolled into the intersection, where the front of V2 "
                       "struck the left side of V1.",
                       2, 0),
            Movement::kSlowing);
  // Backing out of a parking space is leaving a parking position.
  const AccidentRecord backed = kExtractor.Extract(
      "V1 had been parked in an angled space on the north side of the street. V2 was traveling west. The driver of "
      "V1 backed out of the parking space into the westbound lane, and the front of V2 struck the back of V1.");
  ASSERT_EQ(backed.vehicles.size(), 2u);
  EXPECT_EQ(backed.vehicles[0].pre_event.value, Movement::kMerging);
  EXPECT_EQ(backed.vehicles[0].movement.value, Movement::kBacking);
}

TEST(NarrativeExtractorTest, RoadsListedInOneSentence) {
  // ", and Pine Street, a two-lane north/south street": the count is Pine
  // Street's, and Route 4's two lanes each way (undivided) are V1's.
  const AccidentRecord listed = kExtractor.Extract(
      "The crash occurred at the intersection of Route 4, an east/west undivided roadway with two lanes in each "
      "direction, and Pine Street, a two-lane north/south street. V1 was westbound on Route 4. V2 was northbound on "
      "Pine Street. The front of V1 struck the right side of V2.");
  EXPECT_EQ(listed.road.lanes_total.value, 4);
  // "Two southbound lanes and a single northbound lane": three in all.
  EXPECT_EQ(kExtractor
                .Extract("Elm Avenue had two southbound lanes and a single northbound lane and was undivided. V1 was "
                         "southbound on Elm Avenue. V2 was northbound. The front of V2 struck the left side of V1.")
                .road.lanes_total.value,
            3);
  // "45 mph on Cedar Road and 25 mph on Aspen Lane": each limit its road.
  EXPECT_NEAR(LimitMph("Aspen Lane ends at Cedar Road. The posted speed limit was 45 mph on Cedar Road and 25 mph on "
                       "Aspen Lane. V1 was northbound on Aspen Lane and stopped at the stop sign. V2 was eastbound on "
                       "Cedar Road. The front of V2 struck the left side of V1."),
              25.0, 0.5);
  // A report that tells its limits and gives none here: an unposted town
  // street's 30 mph, residential or not.
  EXPECT_NEAR(LimitMph("The crash occurred at the intersection of two residential streets. V1 was northbound. V2 "
                       "was eastbound. The front of V1 struck the left side of V2. The Critical Precrash Event for V1 "
                       "was this vehicle traveling, crossing over (passing through) intersection."),
              30.0, 0.5);
}

TEST(NarrativeExtractorTest, WhereCrashesHappenAtAccessesRampsAndCrossovers) {
  auto location = [](const std::string& text) { return kExtractor.Extract(text).crash.location.value; };
  // "Where County Road 7 crosses ...": a junction; the next sentence about
  // "the highway" is not County Road 7's.
  const std::string crossing =
      "This crash occurred where County Road 7 crosses US Highway 20. The highway ran east/west with a posted speed "
      "limit of 55 mph. County Road 7 was a two-lane road with a posted speed limit of 35 mph. V1 was northbound on "
      "County Road 7 and stopped at the stop sign. V2 was eastbound. The front of V2 struck the left side of V1.";
  EXPECT_EQ(location(crossing), CrashLocation::kJunction);
  EXPECT_NEAR(LimitMph(crossing), 35.0, 0.5);
  // "There was no intersection or traffic control device at the crash
  // location": a U-turn on the segment.
  EXPECT_EQ(location("The crash occurred on the northbound lanes of a two-way roadway with two lanes in each "
                     "direction. There was no intersection or traffic control device at the crash location. V1 was "
                     "traveling northbound in the right lane. V2 was traveling northbound in the left lane. V1 "
                     "attempted to make a U-turn from the right lane, and the front of V2 impacted the left side of "
                     "V1."),
            CrashLocation::kSegment);
  // The intersection an exit ramp ends at is not where a crash in its loop was.
  EXPECT_EQ(location("The crash occurred on a 1-lane exit ramp that curves to the right and ends at a signalized "
                     "intersection. Traffic was backed up on the ramp. V2 was slowing on the ramp. V1 was behind V2. "
                     "The front of V1 struck the back of V2 in the curve."),
            CrashLocation::kRamp);
  // "Stopped at the car wash exit": a driveway, and "the car wash" is no
  // vehicle even when one vehicle is the only car.
  EXPECT_EQ(location("V1, a 2001 Toyota Corolla, was stopped at the car wash exit waiting to turn left. V2, a 2004 "
                     "Ford F-150 pickup, was westbound. V1 pulled out and the front of V2 struck the left side of "
                     "V1."),
            CrashLocation::kDriveway);
  // A median crossover is coded as an intersection.
  EXPECT_EQ(location("The crash occurred at a median crossover on a divided highway. V1 was stopped in the left-turn "
                     "lane and then pulled into the crossover. V2 was southbound. The front of V2 struck the right "
                     "side of V1."),
            CrashLocation::kJunction);
  // "One through lane in each direction and an additional northbound
  // right-turn lane", V1 northbound: three lanes.
  EXPECT_EQ(kExtractor
                .Extract("The north/south street had one through lane in each direction and an additional "
                         "northbound right-turn lane. V1 was northbound in the right-turn lane. V2 was eastbound on "
                         "the cross street. The front of V2 struck the left side of V1.")
                .road.lanes_total.value,
            3);
}

TEST(NarrativeExtractorTest, ACarLeavingADriveCountsTheDriveInNmvccsAndTheRoadInCiren) {
  const std::string road =
      "a parking lot on the south side of a five-lane, two-way road (two lanes each way and a center two-way "
      "left-turn lane) and intended to turn left. V2 was traveling east in the left eastbound lane. The front of V2 "
      "struck the left side of V1.";
  // NMVCCS (a report quoting the coded events): the drive, one lane each way.
  EXPECT_EQ(kExtractor
                .Extract("V1 was exiting " + road +
                         " The Critical Precrash Event for V1 was this vehicle traveling, turning left at "
                         "intersection.")
                .road.lanes_total.value,
            2);
  // A CIREN case summary: the road it enters ...
  EXPECT_EQ(kExtractor.Extract("Vehicle one (V1 - case vehicle) was exiting " + road).road.lanes_total.value, 5);
  // ... unless it counts the drive's own lanes.
  EXPECT_EQ(kExtractor
                .Extract("Vehicle one (V1 - case vehicle) was exiting " + road +
                         " The parking lot driveway is a two-lane, two-way driveway.")
                .road.lanes_total.value,
            2);
}

TEST(NarrativeExtractorTest, ApproachesToldByTheirTurnLanes) {
  // "Its southbound approach had a left-turn lane and a right-turn lane, and
  // it had one northbound lane", V1 southbound: three lanes.
  EXPECT_EQ(kExtractor
                .Extract("Oak Street ended at the avenue from the north; its southbound approach had a left-turn "
                         "lane and a right-turn lane, and it had one northbound lane. V1 was southbound on Oak "
                         "Street in the left-turn lane. V2 was westbound on the avenue. The front of V2 struck the "
                         "left side of V1.")
                .road.lanes_total.value,
            3);
  // "The northbound side had two through lanes and a left-turn lane", two
  // sentences after the divided highway is named, V1 northbound: three.
  EXPECT_EQ(kExtractor
                .Extract("The crash occurred at a T-intersection where a county road met a four-lane divided "
                         "highway from the east. The highway was divided by a 20-meter grass median with a paved "
                         "crossover at the intersection. The northbound side had two through lanes and a left-turn "
                         "lane into the crossover; the southbound side had two through lanes. V1 was traveling "
                         "north on the highway in the left-turn lane. V2 was traveling south. The front of V2 struck "
                         "the right side of V1.")
                .road.lanes_per_direction.value,
            3);
}

TEST(NarrativeExtractorTest, ARoadWideningAtTheJunctionAndAMedianOfTheOtherRoad) {
  // "widened to include a left-turn-only lane ..., for a total of three
  // lanes in each direction at the intersection": coded by its lanes there,
  // and the residential street's two lanes are not the boulevard's.
  const RoadRecord widened =
      kExtractor
          .Extract("V1 was traveling westbound on a divided boulevard. The boulevard had two through lanes in each "
                   "direction separated by a raised grass median; at the signalized intersection with a two-lane "
                   "residential street, each side of the boulevard widened to include a left-turn-only lane cut "
                   "into the median, for a total of three lanes in each direction at the intersection. V1 was "
                   "stopped in the westbound left-turn lane. V2 was traveling eastbound on the boulevard. V1 began "
                   "its turn and the front of V2 contacted the right side of V1.")
          .road;
  EXPECT_TRUE(widened.divided.value);
  EXPECT_EQ(widened.lanes_per_direction.value, 3);
  EXPECT_EQ(widened.lanes_total.value, 6);
  // "The highway had two lanes in each direction separated by a grass
  // median", V1 on the county road: the median is the highway's.
  const RoadRecord county =
      kExtractor
          .Extract("The crash occurred in the westbound lanes of a four-lane divided highway at a T-intersection with "
                   "a county road. The highway had two lanes in each direction separated by a grass median. The "
                   "county road was a two-lane roadway that ended at the highway from the north. V1 was traveling "
                   "south on the county road. V2 was traveling west in the left lane. V1 pulled out and the front "
                   "of V2 struck the left side of V1.")
          .road;
  EXPECT_FALSE(county.divided.value);
  EXPECT_EQ(county.lanes_total.value, 2);
}

TEST(NarrativeExtractorTest, CentreLanesAndBaysToldAfterTheThroughLanes) {
  // "two northbound lanes and two southbound lanes separated by a continuous
  // center two-way left turn lane": five.
  EXPECT_EQ(kExtractor
                .Extract("V2 was traveling northbound on a roadway, intending to turn left into a driveway. The "
                         "roadway consisted of two northbound lanes and two southbound lanes separated by a "
                         "continuous center two-way left turn lane. V1 was traveling southbound in the inside lane. "
                         "V2 began its turn and the front of V1 contacted the right side of V2.")
                .road.lanes_total.value,
            5);
  // "... separated by a raised median": no lane.
  EXPECT_EQ(kExtractor
                .Extract("V1 was traveling northbound on a roadway. The roadway consisted of two northbound lanes and "
                         "two southbound lanes separated by a raised median. V2 was traveling southbound. V1 turned "
                         "left and the front of V2 struck the right side of V1.")
                .road.lanes_total.value,
            4);
  // "..., and a left-turn bay was cut into the median on each approach to
  // the signalized intersection": three lanes on each side there.
  const RoadRecord bays =
      kExtractor
          .Extract("V1 was traveling southbound on a four-lane divided roadway. The north/south roadway had two lanes "
                   "in each direction separated by a landscaped median, and a left-turn bay was cut into the median "
                   "on each approach to the signalized intersection with an east/west roadway. V1 entered the "
                   "southbound left-turn bay and turned left. V2 was traveling northbound. The front of V2 contacted "
                   "the right side of V1.")
          .road;
  EXPECT_EQ(bays.lanes_per_direction.value, 3);
  EXPECT_EQ(bays.lanes_total.value, 6);
  // "..., with a left turn lane in the median for each direction".
  const RoadRecord each =
      kExtractor
          .Extract("The crash occurred at a four-leg intersection on a divided highway. The highway consists of two "
                   "northbound and two southbound through lanes separated by a raised grass median, with a left "
                   "turn lane in the median for each direction. V1 was stopped in the northbound left turn lane "
                   "waiting to turn left. V2 was traveling southbound. V1 began the turn and the front of V2 struck "
                   "the right side of V1.")
          .road;
  EXPECT_EQ(each.lanes_per_direction.value, 3);
  EXPECT_EQ(each.lanes_total.value, 6);
}

TEST(NarrativeExtractorTest, ACoordinatedSubjectsRoadIsV1s) {
  // "V1 and V2 were both traveling northbound on a three-lane one-way
  // roadway": V1's road too.
  const RoadRecord both =
      kExtractor
          .Extract("The crash occurred at a four-leg intersection. V1 and V2 were both traveling northbound on a "
                   "three-lane one-way roadway. The intersecting roadway was a two-lane, two-way street. V1 was in "
                   "lane #1. V2 was in lane #2 and turned right in front of V1. The front of V1 struck the right side "
                   "of V2.")
          .road;
  EXPECT_TRUE(both.one_way.value);
  EXPECT_EQ(both.lanes_total.value, 3);
}

TEST(NarrativeExtractorTest, ACrossroadHasItsOwnLimitAndNoMedian) {
  const std::string scene =
      "This crash occurred at a four-leg intersection where a two-lane crossroad crossed a divided highway. The "
      "crossroad had one lane in each direction and was controlled by stop signs. The highway was posted at 89 km/h "
      "and the crossroad at 56 km/h. V1 was traveling north on the crossroad. V1 stopped at the stop sign and then "
      "began turning left. V2 was traveling west in the right lane. The front of V2 struck the right side of V1. ";
  const AccidentRecord r = kExtractor.Extract(scene);
  // "and the crossroad at 56 km/h": the limit's road in an ellipsis.
  EXPECT_NEAR(r.road.speed_limit_mps.value / 0.44704, 35.0, 0.5);
  // "a two-lane crossroad crossed a divided highway": the highway's median.
  EXPECT_FALSE(r.road.divided.value);
  EXPECT_EQ(r.road.lanes_total.value, 2);
  // "saw the Mercedes pull out of the median": where V1 was, not V1's road.
  const AccidentRecord seen = kExtractor.Extract(
      scene + "The driver of V2 stated that he saw the Mercedes pull out of the median and braked.");
  EXPECT_FALSE(seen.road.divided.value);
}

TEST(NarrativeExtractorTest, AnOncomingVehicleOverTheLineIntoARightTurnerIsNoTurnAcrossPath) {
  const std::string scene =
      "The crash occurred in the westbound lane of a two-lane roadway near a T-intersection. V1 was traveling "
      "eastbound negotiating the curve. V2 was traveling westbound and slowing to turn right onto the side road. V1 "
      "crossed over the double yellow centerline and the left front of V1 struck the left side of V2 in the westbound "
      "lane. The Critical Precrash Event for V1 was this vehicle traveling over the lane line on the left side of the "
      "travel lane. The Critical Precrash Event for V2 was other vehicle encroachment from the opposite direction "
      "over the left lane line.";
  const AccidentRecord r = kExtractor.Extract(scene);
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.crash.type.value, CrashType::kSideswipeOpposite);
  // Turning left, it is.
  std::string left = scene;
  left.replace(left.find("turn right"), 10, "turn left");
  EXPECT_EQ(kExtractor.Extract(left).crash.type.value, CrashType::kTurnAcrossPath);
}

TEST(NarrativeExtractorTest, WhatTheDriverSawOnLookingBackIsTheOthers) {
  // "when he looked back V2 had slowed": V2's slowing, not V1's.
  const AccidentRecord r = kExtractor.Extract(
      "V1 was a 2001 Ford Taurus sedan traveling northbound in the left lane. V2, a 1999 Toyota Sienna minivan, was "
      "traveling northbound in the left lane ahead of V1. V2 slowed with the traffic ahead and the front of V1 struck "
      "the back of V2. V1 was driven by a 33-year-old male who was not injured. He stated that he was traveling about "
      "55 mph and looked over at the disabled vehicle on the shoulder, and when he looked back V2 had slowed. He "
      "braked hard.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, MovingOffARedWhenItTurnedGreenIsStarting) {
  // NASS "starting in traffic lane", coded as going on; a stop at a sign
  // before the turn stays a stop.
  const std::string signal =
      "Vehicle #2 was traveling east on the street and was stopped at the red signal, intending to turn left. When the "
      "signal turned green for Vehicle #2, it started its left turn. Vehicle #1 was traveling west. The front of "
      "Vehicle #1 struck the right side of Vehicle #2.";
  EXPECT_EQ(PreEventOf(signal, 2, 1), Movement::kStraight);
  EXPECT_EQ(kExtractor.Extract(signal).vehicles[1].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(PreEventOf("Vehicle #2 was traveling east and was stopped at the red light. When the light turned green "
                       "it proceeded into the intersection. Vehicle #1 entered the intersection against the red light "
                       "and impacted the left side of Vehicle #2 with its front.",
                       2, 1),
            Movement::kStraight);
  EXPECT_EQ(PreEventOf("Vehicle #2 was traveling east on the street and stopped at the stop sign, intending to turn "
                       "left. Vehicle #2 then started its left turn. Vehicle #1 was traveling west. The front of "
                       "Vehicle #1 struck the right side of Vehicle #2.",
                       2, 1),
            Movement::kStopped);
}

TEST(NarrativeExtractorTest, AWideningToldAfterTheRoadGivesItsLanesAtTheJunction) {
  // "..., so that at the crash site there were three lanes", V1 in lane two
  // of the wider side: three lanes, not two, nor five.
  const RoadRecord total =
      kExtractor
          .Extract("The crash occurred at a signalized intersection. North of the intersection Elm Road was a "
                   "two-lane undivided road with one lane in each direction. About 60 meters south of the "
                   "intersection the northbound side widened to add a right-turn lane at the curb, so that at the "
                   "crash site there were three lanes. V1 was northbound on Elm Road in lane two. V2 was stopped "
                   "ahead of V1. The front of V1 struck the back of V2.")
          .road;
  EXPECT_EQ(total.lanes_total.value, 3);
  // "... a left-turn lane was added, so that there were three eastbound
  // lanes at the intersection", V1 eastbound: three each way on its side.
  EXPECT_EQ(kExtractor
                .Extract("The avenue was divided by a raised median and carried two eastbound through lanes. Some "
                         "50 meters west of the intersection a left-turn lane was added; so that there were three "
                         "eastbound lanes at the intersection. V1 was eastbound on the avenue. V2 was northbound on "
                         "the cross street. The front of V2 struck the right side of V1.")
                .road.lanes_per_direction.value,
            3);
  // Widening on the way to another junction is not the crash site's.
  EXPECT_EQ(kExtractor
                .Extract("The crash occurred at a private driveway on a two-lane, two-way county road. At the "
                         "driveway the road had one lane in each direction; about 150 meters east the road widened "
                         "to four lanes, two in each direction, on the approach to a signalized intersection. V1 "
                         "was eastbound on the county road. V2 pulled out of the driveway to turn left. The front "
                         "of V1 struck the left side of V2.")
                .road.lanes_total.value,
            2);
}

TEST(NarrativeExtractorTest, WhatTheRoadWasElsewhereIsNotItsCount) {
  // "had been a four-lane section" west of the site, "leaving one lane in
  // each direction through the crash site": two lanes.
  EXPECT_EQ(kExtractor
                .Extract("The crash occurred on Route 9, a two-lane rural road. About 200 meters west of the "
                         "crash site the road had been a four-lane section; the eastbound right lane ended at a taper, "
                         "leaving one lane in each direction through the crash site. V1 was eastbound. "
                         "V2 was stopped in the eastbound lane. The front of V1 struck the back of V2.")
                .road.lanes_total.value,
            2);
  // "the highway widened from two lanes to three": three at the junction.
  EXPECT_EQ(kExtractor
                .Extract("A county road met a two-lane state highway at a T-intersection. East of the intersection "
                         "the highway widened from two lanes to three to provide a westbound left-turn lane. V1 was "
                         "westbound on the highway in the left-turn lane. V2 was eastbound on the highway. The "
                         "front of V2 struck the right side of V1.")
                .road.lanes_total.value,
            3);
}

TEST(NarrativeExtractorTest, V1OnARampThatWidensAtItsEnd) {
  // "the ramp was a one-way roadway that widened from one lane to two lanes
  // near its end", V1 "in the left-turn lane of the ramp": two lanes, one way.
  const RoadRecord road =
      kExtractor
          .Extract("The crash occurred where an exit ramp from the interstate formed a T-intersection with a "
                   "four-lane undivided arterial (two lanes in each direction). The ramp was a one-way roadway "
                   "that widened from one lane to two lanes near its end. V1 was in the left-turn lane of the ramp "
                   "and had stopped at the stop sign. V2 was eastbound on the arterial. V1 pulled out to turn left "
                   "and the front of V2 struck the left side of V1.")
          .road;
  EXPECT_EQ(road.lanes_total.value, 2);
  EXPECT_TRUE(road.one_way.value);
}


TEST(NarrativeExtractorTest, LimitsOfTwoRoadsUnpostedRoadsAndSpeedsAfterTheLimit) {
  // "the posted speed limit on the county road was 72KMPH", V1 on the
  // county road: its limit, not the highway's told first.
  const RoadRecord two =
      kExtractor
          .Extract("The crash occurred at the intersection of a two lane state highway and a two lane county road. "
                   "The posted speed limit on the highway was 89KMPH (55MPH) and the posted speed limit on the "
                   "county road was 72KMPH (45MPH). Vehicle #1 was traveling north on the county road. Vehicle #2 "
                   "was traveling east on the highway. Vehicle #2 impacted the left side of Vehicle #1.")
          .road;
  EXPECT_NEAR(two.speed_limit_mps.value * 3.6, 72.0, 0.5);
  // "No speed limit signs were posted along this road": no limit, not the
  // rural road's usual 55 mph.
  const RoadRecord unposted =
      kExtractor
          .Extract("The crash occurred on a bridge on a rural two-lane, two-way road. No speed limit signs were "
                   "posted along this road. Vehicle #1 was westbound and Vehicle #2 was eastbound. The left side "
                   "of Vehicle #1 sideswiped the left side of Vehicle #2.")
          .road;
  EXPECT_FALSE(unposted.speed_limit_mps.known());
  // A vehicle's recorded speed after the limit is no limit.
  EXPECT_NEAR(kExtractor
                      .Extract("V1 was traveling west in the left lane of a freeway. V2 was traveling west in the "
                               "center lane. The speed limit is 70 mph and the event data recorder of V1 recorded a "
                               "pre-crash speed of 68 mph. The left side of V2 struck the right side of V1.")
                      .road.speed_limit_mps.value,
              70 * 0.44704, 1e-6);
  // ... but another road's limit said by its vehicle is still a limit.
  EXPECT_NEAR(kExtractor
                      .Extract("The posted speed limit on V2's road was 45 mph and on V1's road 30 mph. V1 was "
                               "northbound. V2 was eastbound. The front of V1 struck the left side of V2.")
                      .road.speed_limit_mps.value,
              30 * 0.44704, 1e-6);
}

TEST(NarrativeExtractorTest, AMoveTowardTheNextLaneToTurnIsALaneChange) {
  // "moved right toward lane one in order to turn right" and struck the car
  // in that lane: a lane change (a turn only meant), a same-direction
  // sideswipe, not a turn across V2's path.
  const AccidentRecord r = kExtractor.Extract(
      "The roadway has two lanes in each direction. V1, a minivan, was traveling north in lane two. V2, a sedan, "
      "was traveling north in lane one, slightly behind the minivan. The driver of V1 realized that the side "
      "street was her turn and moved right toward lane one in order to turn right. The right side of V1 "
      "contacted the left side of V2. The Critical Pre-crash Event for V1 was coded this vehicle traveling, over "
      "the lane line on the right side of travel lane. The Critical Pre-crash Event for V2 was other vehicle "
      "encroachment from adjacent lane (same direction), over left lane line.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kChangingLanes);
  EXPECT_EQ(r.crash.type.value, CrashType::kSideswipeSame);
}

TEST(NarrativeExtractorTest, WhatADriverThoughtTheOtherWasDoingIsNotHisOwnMovement) {
  // "thought it was only slowing a little": V2's slowing as V1's driver
  // believed it, not V1's.
  const AccidentRecord r = kExtractor.Extract(
      "V1 was traveling westbound in lane one behind V2. The front of V1 contacted the back of V2. The driver of "
      "V1 was a 26-year old male. He stated that he saw V2's brake lights but thought it was only slowing a "
      "little and he had room to stop.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
}

TEST(NarrativeExtractorTest, VehiclesIntroducedByMakeAndNumberedLater) {
  // "A 2005 Chevrolet Malibu was northbound ..., stopped at the stop sign";
  // only later "the driver of the Chevrolet (Vehicle 1)": the Malibu is V1,
  // with its stop and its road.
  const AccidentRecord r = kExtractor.Extract(
      "A northbound two-lane side street, posted at 48 km/h (30 mph), ends at an east/west five-lane roadway "
      "posted at 72 km/h (45 mph). A 2005 Chevrolet Malibu was northbound on the side street, stopped at the "
      "stop sign, and then began a left turn to travel west. A 2002 Ford Crown Victoria was eastbound in the "
      "right curb lane of the five-lane roadway. The front of the Ford struck the left side of the Chevrolet. "
      "The driver of the Chevrolet (Vehicle 1), a belted 29-year-old female, sustained minor injuries. The "
      "driver of the Ford (Vehicle 2), a belted 61-year-old male, was not injured.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.crash.striking.value, "V2");
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStopped);
  EXPECT_EQ(r.road.lanes_total.value, 2);
  EXPECT_NEAR(r.road.speed_limit_mps.value * 3.6, 48.0, 0.5);
}

TEST(NarrativeExtractorTest, RoadsV1MeetsBaysAtItsApproachAndLimitsByKind) {
  // An undivided road with "one through lane in each direction and a
  // left-turn lane for each approach": three lanes across V1's approach.
  EXPECT_EQ(kExtractor
                .Extract("V1 was traveling west on a three-lane, two-way roadway. The roadway had one through lane "
                         "in each direction and a left-turn lane for each approach at the signalized four-way "
                         "intersection. V1 was stopped in the westbound left-turn lane. V2 was traveling east. V1 "
                         "turned left and the front of V2 struck the right side of V1.")
                .road.lanes_total.value,
            3);
  // "... stopped where the street meets a busy four-lane roadway": the
  // four lanes are the other road's; V1's street is "a two-lane road".
  EXPECT_EQ(kExtractor
                .Extract("V1 was eastbound on a narrow residential street and came to a stop at a stop sign where "
                         "the street meets a busy four-lane roadway. V2 was southbound on the four-lane roadway. "
                         "The residential street is a two-lane road posted at 40 kmh (25 mph). V1 pulled out and "
                         "the front of V2 impacted the left side of V1.")
                .road.lanes_total.value,
            2);
  // "stopped beside her in the other two lanes" counts no road; "three
  // lanes in each direction" does.
  EXPECT_EQ(kExtractor
                .Extract("V2 had stopped in the middle lane for a red signal. Several vehicles were stopped beside "
                         "her in the other two lanes. V1 was southbound behind V2 and the front of V1 struck the "
                         "back of V2. The highway at this location is divided by a raised grass median, with three "
                         "lanes in each direction.")
                .road.lanes_per_direction.value,
            3);
  // "the arterial carried a posted limit of 56 km/h", V1 on the "city
  // arterial": its limit, not the collector's.
  EXPECT_NEAR(kExtractor
                      .Extract("V1 was westbound on a city arterial approaching a collector street. The collector "
                               "was posted at 48 km/h (30 mph), while the arterial carried a posted limit of 56 "
                               "km/h (35 mph). V2 was northbound on the collector. The front of V1 struck the "
                               "left side of V2.")
                      .road.speed_limit_mps.value * 3.6,
              56.0, 0.5);
}
TEST(NarrativeExtractorTest, ALaneChangeToldInThePastPerfectIsBackground) {
  // "had entered the highway ... and had moved over into the middle lane,
  // traveling behind" it: long done when it struck the stopped car.
  const AccidentRecord earlier = kExtractor.Extract(
      "V2 was stopped in the middle of three southbound lanes for a red signal. V1 had entered the same "
      "highway from a shopping center about a half mile to the north and had moved over into the middle "
      "lane, traveling behind V2. The front of V1 struck the back of V2.");
  ASSERT_EQ(earlier.vehicles.size(), 2u);
  EXPECT_EQ(earlier.vehicles[0].pre_event.value, Movement::kStraight);
  // "had just moved into the left lane" is the manoeuvre into the crash.
  const AccidentRecord just = kExtractor.Extract(
      "V1 and V2 were traveling south on a four-lane divided highway. V1 had just moved into the left lane "
      "when the right side of V1 contacted the left side of V2.");
  ASSERT_EQ(just.vehicles.size(), 2u);
  EXPECT_EQ(just.vehicles[0].movement.value, Movement::kChangingLanes);
  // "he may have left his signal on from an earlier lane change".
  const AccidentRecord signal = kExtractor.Extract(
      "V1 was northbound in the center turn lane and turned left toward the side street. V2 was southbound "
      "in lane one. The front of V2 struck the right side of V1. The driver of V2 said he may have left his "
      "signal on from an earlier lane change, and that he was going straight.");
  ASSERT_EQ(signal.vehicles.size(), 2u);
  EXPECT_EQ(signal.vehicles[1].movement.value, Movement::kStraight);
}
TEST(NarrativeExtractorTest, OneSideOfADividedRoadWithItsTurnLanesCounted) {
  // "The northbound side of the divided roadway had two through lanes and
  // two left-turn lanes at the intersection": four lanes on V1's side.
  const AccidentRecord r = kExtractor.Extract(
      "The crash occurred in the intersection of a north/south divided roadway and an east/west two-way "
      "roadway. The northbound side of the divided roadway had two through lanes and two left-turn lanes at "
      "the intersection and was separated from the southbound side by a raised grass median. V1 was "
      "northbound turning left from the inside left-turn lane. V2 was northbound turning left from the "
      "outside left-turn lane. The right front of V1 contacted the left side of V2.");
  EXPECT_TRUE(r.road.divided.value);
  EXPECT_EQ(r.road.lanes_per_direction.value, 4);
}
TEST(NarrativeExtractorTest, TheNarrativesWayOfGoingBeatsTheDriversStatement) {
  // The narrative has V2 "negotiating the same curve"; its driver's "he
  // slowed ... because he knew the curve ices up" came before and is not
  // what the narrative tells.
  const AccidentRecord r = kExtractor.Extract(
      "V1 was westbound on a two-lane, two-way rural highway negotiating a curve to the left. V2 was "
      "eastbound negotiating the same curve to the right. V1 lost traction on the ice, slid across the "
      "centerline, and the front of V1 struck the front of V2. The driver of V2 was a 50-year old male who "
      "reported he slowed to about 56 kmph (35 mph) because he knew the curve ices up.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kStraight);
}
TEST(NarrativeExtractorTest, ALimitThatClosesATerseListAboutTheRoad) {
  // "..., straight and level, 25 mph.": the road's limit, said without the
  // word; a speed in a vehicle's own sentence is not.
  const AccidentRecord r = kExtractor.Extract(
      "Uncontrolled intersection of two residential streets, both two-lane two-way, straight and level, 35 "
      "mph. V1 southbound; V2 westbound. Front of V2 struck left side of V1 in the intersection.");
  EXPECT_NEAR(r.road.speed_limit_mps.value / 0.44704, 35.0, 0.01);
  const AccidentRecord speed = kExtractor.Extract(
      "Intersection of two residential streets, straight and level. V1 southbound, straight, 40 mph. V2 "
      "westbound. Front of V2 struck left side of V1.");
  EXPECT_NE(speed.road.speed_limit_mps.value / 0.44704, 40.0);
}
TEST(NarrativeExtractorTest, TwoVehiclesTurningSideBySideSideswipe) {
  // A double left-turn lane: V1 drifts right into V2 in the middle of the
  // turn. Both were turning; the crash is a same-direction sideswipe.
  const AccidentRecord r = kExtractor.Extract(
      "The northbound side of the divided roadway had two through lanes and two left-turn lanes at the "
      "intersection. Vehicle # 1 was turning left from the inside left-turn lane on a green arrow. Vehicle # 2 "
      "was turning left from the outside left-turn lane. During the turn Vehicle # 1 drifted to the right out "
      "of its turning path and its right front contacted the left side of Vehicle # 2. The Critical Pre-crash "
      "Event for Vehicle # 1 was coded as this vehicle traveling over the lane line on the right side of travel "
      "lane. The Critical Pre-crash Event for Vehicle # 2 was coded as other vehicle encroachment from adjacent "
      "lane (same direction) over the left lane line.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.crash.type.value, CrashType::kSideswipeSame);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kTurnLeft);
}
TEST(NarrativeExtractorTest, TheDriversAgeAsSubjectOfTheMovementKeepsTheSentence) {
  // "Its 58-year-old driver stopped at the stop sign and began a right
  // turn": the truck's movement, not a sentence about people.
  const AccidentRecord r = kExtractor.Extract(
      "A 2001 Chevrolet Cavalier (V1, the case vehicle) was westbound on a two-lane state highway approaching "
      "its T-intersection with a township road. V2, a 1993 International dump truck, was southbound on the "
      "township road. Its 58-year-old driver stopped at the stop sign and began a right turn to go west on "
      "the highway. While the truck was still angled across the westbound lane, the front of V1 struck the "
      "left rear corner of V2.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kTurnRight);
  EXPECT_EQ(r.crash.type.value, CrashType::kTurnIntoPath);
}
TEST(NarrativeExtractorTest, AThingParkedNearAVehicleIsNotThatVehicleParked) {
  // "A landscaping trailer parked at the south curb ... limited the V2
  // driver's view": V2 was backing out of a driveway, not parked.
  const AccidentRecord r = kExtractor.Extract(
      "V1 was eastbound on a residential street. V2, a 1995 Ford F-250 pickup truck, was backing out of a "
      "private residential driveway on the south side of the street. A landscaping trailer parked at the "
      "south curb just west of the driveway limited the V2 driver's view to the west. V2 backed into the "
      "eastbound lane, and the rear bumper of V2 struck the left side of V1.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kBacking);
  // "the truck parked at the corner" is no vehicle of the crash.
  const AccidentRecord truck = kExtractor.Extract(
      "V1 was northbound and stopped for a red signal at the intersection, intending to turn right to travel "
      "east. V2 was traveling east in the right lane. A delivery truck was parked along the curb at the "
      "southwest corner. V1 began its right turn on red and the front of V2 struck the left side of V1. The "
      "driver of V1 stated that the truck parked at the corner \"blocked most of the view.\"");
  ASSERT_EQ(truck.vehicles.size(), 2u);
  EXPECT_NE(truck.crash.type.value, CrashType::kSingleVehicle);
}
TEST(NarrativeExtractorTest, WhatADriverQuotesTheOtherDoingToHimIsNotHisMovement) {
  // "she just turned right in front of me": V2's turn, in V1's words.
  const AccidentRecord r = kExtractor.Extract(
      "V1 was northbound in the inside through lane. V2 was southbound and had moved into the center lane to "
      "turn left at the intersection. V2 began her turn and the front of V1 struck the right side of V2. The "
      "driver of V1 stated that \"she just turned right in front of me\" and that he had no time to brake.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kStraight);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kTurnLeft);
}
TEST(NarrativeExtractorTest, AParkedCarWhoseDriverBeganToPullOutLeftItsParkingPosition) {
  // "V2 ... was parallel parked at the west curb ... The 80-year-old female
  // driver of V2 began to pull out of her parking space."
  const AccidentRecord r = kExtractor.Extract(
      "V1 was traveling south on a two-lane downtown street. V2, a 1994 Ford Taurus sedan, was parallel parked "
      "at the west curb, facing south. The 80-year-old female driver of V2 began to pull out of her parking "
      "space. The front of V1 struck the left side of V2 at the left front door.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kMerging);
  EXPECT_FALSE(r.vehicles[1].parked.value);
  EXPECT_NE(r.crash.type.value, CrashType::kSingleVehicle);
}
TEST(NarrativeExtractorTest, AStopToldByTheDriverThatTheNarrativeMovesOffFrom) {
  // The stop is in his statement; the narrative has him accelerate from it.
  const AccidentRecord r = kExtractor.Extract(
      "V1 was northbound on a two-lane county road approaching its intersection with a state highway. The "
      "54-year-old male driver of V1 stated that he came to a complete stop at the stop sign and looked both "
      "ways. He then accelerated from the stop to drive straight across the highway. V2 was eastbound in the "
      "right eastbound lane. The front of V2 struck the left side of V1.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
}
TEST(NarrativeExtractorTest, ALeadSlowingForItsOwnTurnToldByItsDriverIsDecelerating) {
  // The lead's turn is told only in its driver's statement.
  const AccidentRecord r = kExtractor.Extract(
      "V1 and V2 were both traveling east on a two-lane rural highway. The pickup (V2) was ahead of V1. The "
      "driver of V2 was a farmer returning to his property. He stated that he activated his right turn signal "
      "and began to slow from about 80 km/h to turn right into a field driveway. He had slowed to roughly 25 "
      "km/h and had not yet begun his turn when V1 struck the rear of his truck.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.crash.type.value, CrashType::kRearEnd);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kSlowing);
}
TEST(NarrativeExtractorTest, ATowedLoadNamedWithItsModifiersIsItsTowersVehicle) {
  // "the horse trailer" of "V2, a 1999 Ford F-350 pickup towing a loaded
  // gooseneck horse trailer".
  const AccidentRecord r = kExtractor.Extract(
      "V1, a 2005 Chrysler Sebring, and V2, a 1999 Ford F-350 pickup towing a loaded gooseneck horse trailer, "
      "were northbound on a two-lane state highway. V2 was climbing the grade at 20 mph. The driver of V1 "
      "braked and steered left, but the right front of V1 struck the back of the horse trailer.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.crash.type.value, CrashType::kRearEnd);
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kRear);
}
TEST(NarrativeExtractorTest, ALimitReducedThroughAWorkZoneIsTheReducedOne) {
  const AccidentRecord r = kExtractor.Extract(
      "The crash occurred in the westbound lanes of a four-lane divided highway east of a lane closure. "
      "Through the work zone the normal 65 mph limit is reduced to a posted 45 mph (72 km/h). V1 was stopped "
      "in the left westbound lane. The front of V2 struck the back of V1.");
  EXPECT_NEAR(r.road.speed_limit_mps.value / 0.44704, 45.0, 0.01);
}
TEST(NarrativeExtractorTest, ASignsWordsAreNoVehiclesMovement) {
  // '"Lane Ends Merge Left" signs are posted': V1 kept its lane; V2 merged.
  const AccidentRecord r = kExtractor.Extract(
      "V1 was traveling east in the left eastbound lane of a three-lane road. About 150 meters east of the "
      "crash site the right eastbound lane ends, and \"Lane Ends Merge Left\" signs are posted in advance. V2 "
      "was eastbound in the right lane, slightly ahead of V1. The driver of V2 moved left to merge ahead of "
      "the lane drop, and the left side of V2 sideswiped the right side of V1.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kStraight);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kMerging);
}
TEST(NarrativeExtractorTest, TheVanDriverIsTheVansDriver) {
  // "The van driver ... said she ... was braking for the shuttle stop":
  // V2's account, not V1's.
  const AccidentRecord r = kExtractor.Extract(
      "V2, a 2005 Ford E-350 hotel shuttle van, was northbound in lane one. V1, a 2003 Nissan Altima, was "
      "northbound in lane two. V1 moved to the right into lane one and the right side of V1 contacted the left "
      "front corner of V2. The van driver, a 58-year-old female, had seven passengers, none injured. She said "
      "she had her right turn signal on and was braking for the shuttle stop, down to perhaps 15 mph, when the "
      "car came over on her.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kChangingLanes);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kSlowing);
}
TEST(NarrativeExtractorTest, AMoveIntoLaneOneIsALaneChangeOrFromTheRampAMerge) {
  const AccidentRecord change = kExtractor.Extract(
      "V1 and V2 were northbound on a six-lane divided boulevard. V1 was in lane two and V2 in lane one. V1 "
      "moved to the right into lane one and the right side of V1 contacted the left side of V2.");
  ASSERT_EQ(change.vehicles.size(), 2u);
  EXPECT_EQ(change.vehicles[0].movement.value, Movement::kChangingLanes);
  const AccidentRecord merge = kExtractor.Extract(
      "V1 came down the entrance ramp and into the acceleration lane. V2 was eastbound in lane one of the "
      "interstate. V1 moved left into lane one to merge and the left side of V1 struck the right side of V2.");
  ASSERT_EQ(merge.vehicles.size(), 2u);
  EXPECT_EQ(merge.vehicles[0].movement.value, Movement::kMerging);
}
TEST(NarrativeExtractorTest, SlowingForItsOwnTurnAlmostStoppedOrToldByTheDriver) {
  // "westbound ... and slowing to turn left", her "almost stopped" waiting.
  const AccidentRecord slowing = kExtractor.Extract(
      "V1 was northbound on the county road, turning right to go east. V2 was westbound on the state route "
      "and slowing to turn left onto the county road. V1 swung wide in the turn, and the left front of V1 "
      "struck the left front of V2. The driver of V2 had her left signal on and said she had \"almost "
      "stopped\" waiting to make her turn.");
  ASSERT_EQ(slowing.vehicles.size(), 2u);
  EXPECT_EQ(slowing.vehicles[1].pre_event.value, Movement::kSlowing);
  // A lead coded "decelerating" whose driver tells of the turn he slowed for
  // ("had his right signal on and had slowed ... to make the turn").
  const AccidentRecord lead = kExtractor.Extract(
      "Both vehicles were eastbound. V2 was ahead; V1 was following. The front of V1 struck the back of V2. "
      "The driver of V2 told the investigator he had his right signal on and had slowed to around 15 mph to "
      "make the turn onto the township road. The Critical Precrash Event for V1 was other motor vehicle in "
      "lane traveling in same direction while decelerating.");
  ASSERT_EQ(lead.vehicles.size(), 2u);
  EXPECT_EQ(lead.vehicles[1].pre_event.value, Movement::kSlowing);
}
TEST(NarrativeExtractorTest, AStopAtThePreviousLightAndBackingIn) {
  // Her stop was a block back; she was going straight through on the green.
  const AccidentRecord earlier = kExtractor.Extract(
      "Vehicle #1 was eastbound in lane two and turned right at the intersection. Vehicle #2 was eastbound in "
      "lane one. As the truck swung right across lane one, the right side of Vehicle #1 contacted the front of "
      "Vehicle #2. The driver of Vehicle #2 said she had stopped at the previous light a block back and was "
      "speeding back up, going straight through on the green.");
  ASSERT_EQ(earlier.vehicles.size(), 2u);
  EXPECT_EQ(earlier.vehicles[1].pre_event.value, Movement::kStraight);
  // "began backing in" to a parallel space is backing.
  const AccidentRecord backing = kExtractor.Extract(
      "V1 stopped in the westbound lane of a two-lane neighborhood street and began backing in toward an open "
      "space on the north curb. V2 was stopped about a car length behind it. The back of V1 struck the front "
      "of V2.");
  ASSERT_EQ(backing.vehicles.size(), 2u);
  EXPECT_EQ(backing.vehicles[0].movement.value, Movement::kBacking);
}
TEST(NarrativeExtractorTest, ALimitInBracketsAfterTheRoadAndWhatTheOtherDidToTheSpeaker) {
  const AccidentRecord limit = kExtractor.Extract(
      "On a clear weekday afternoon, V2 was northbound on a straight, level two-lane rural road (45 mph, 72 "
      "km/h) with V1 behind it. The front of V1 struck the rear of V2.");
  EXPECT_NEAR(limit.road.speed_limit_mps.value / 0.44704, 45.0, 0.01);
  // "was still stopped ... when it backed into her": V1 backed, not V2.
  const AccidentRecord backed = kExtractor.Extract(
      "Vehicle one was northbound in lane one. Vehicle two was northbound in lane one behind it. The driver of "
      "Vehicle one stopped, put the truck in reverse and began backing down lane one. The rear of Vehicle one "
      "struck the front of Vehicle two. The driver of Vehicle two said she came to a stop behind the truck "
      "and was still stopped and sounding her horn when it backed into her.");
  ASSERT_EQ(backed.vehicles.size(), 2u);
  EXPECT_EQ(backed.vehicles[1].pre_event.value, Movement::kStopped);
}
TEST(NarrativeExtractorTest, APlaceInANamedQueueIsNoVehicleNumber) {
  const AccidentRecord r = kExtractor.Extract(
      "Vehicle two, a 2006 Ford Fusion, was the fourth car in the eastbound queue and had been stopped in the "
      "eastbound lane for about a minute. Vehicle one, a 2001 Chevrolet Express van, came around the curve "
      "and its front struck the back of the Fusion.");
  EXPECT_EQ(r.participant_count.value, 2);
}
TEST(NarrativeExtractorTest, TheCarParkedBesideItIsNotItself) {
  // "V1 ... stopped ... beside the car parked ahead of an open parallel
  // space ... and began backing in": V1 backed from its lane; the parked
  // car is another.
  const AccidentRecord r = kExtractor.Extract(
      "Vehicle one, a 2005 Ford Five Hundred, stopped in the westbound lane of a two-lane neighborhood street "
      "beside the car parked ahead of an open parallel space on the north curb, and began backing in. Vehicle "
      "two, a 2006 Honda Element, had stopped about a car length behind it. The back of the Ford struck the "
      "front of the Element.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_FALSE(r.vehicles[0].parked.value);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kBacking);
  EXPECT_EQ(r.crash.type.value, CrashType::kRearEnd);
}
TEST(NarrativeExtractorTest, AContactThatDidNotHappenAndARakedSide) {
  // "crossed ... without striking any vehicle": one vehicle, into the
  // embankment.
  const AccidentRecord alone = kExtractor.Extract(
      "V1, a 2005 Chevrolet TrailBlazer, was southbound on a two-lane county road that ends at a "
      "T-intersection with a state highway. V1 passed the stop sign at speed, crossed both lanes of the state "
      "highway without striking any vehicle, went through the ditch, and its front struck the embankment.");
  EXPECT_EQ(alone.participant_count.value, 1);
  EXPECT_EQ(alone.crash.type.value, CrashType::kSingleVehicle);
  // "the left front of V2 raked down the left side of V1": a sideswipe
  // across the centre line.
  const AccidentRecord raked = kExtractor.Extract(
      "Vehicle #1 was traveling east on a two-lane, undivided city street. Vehicle #2, a pickup, was westbound "
      "on the same street. The pickup drifted across the double yellow line into the eastbound lane. The "
      "driver of Vehicle #1 steered right toward the curb, but the left front of the pickup raked down the "
      "left side of Vehicle #1, from the front fender to the rear door.");
  EXPECT_EQ(raked.crash.type.value, CrashType::kSideswipeOpposite);
}
TEST(NarrativeExtractorTest, LaneCountsOfOneSideAndTheirBreakdown) {
  // One direction's roadway "at this point" and lanes told with their width.
  const AccidentRecord side = kExtractor.Extract(
      "The eastbound roadway at this point has three 3.6 m lanes and is separated from the westbound lanes by "
      "a concrete median barrier. Vehicle #1 was in the center lane and moved left into the median lane to get "
      "around a slower tractor-trailer. Vehicle #2 was already in the median lane. The left side of Vehicle "
      "#1 contacted the right side of Vehicle #2.");
  EXPECT_TRUE(side.road.divided.value);
  EXPECT_EQ(side.road.lanes_per_direction.value, 3);
  ASSERT_EQ(side.vehicles.size(), 2u);
  EXPECT_EQ(side.vehicles[0].movement.value, Movement::kChangingLanes);
  const AccidentRecord each = kExtractor.Extract(
      "The crash occurred on a four-lane divided highway. The northbound and southbound roadways each have two "
      "3.7 m lanes and are separated by a depressed grass median. V1 was northbound in the right lane when it "
      "slid off the left side of the roadway and its right side struck the guardrail.");
  EXPECT_EQ(each.road.lanes_per_direction.value, 2);
  EXPECT_EQ(each.road.lanes_total.value, 4);
  // "each approach had 3 lanes: 2 through lanes and a left-turn bay", on
  // the divided highway, not the undivided cross street.
  const AccidentRecord bays = kExtractor.Extract(
      "This crash occurred at an intersection of a four-lane divided highway and a two-lane undivided cross "
      "street. The highway ran north and south and was divided by a grass median; left-turn bays were cut "
      "into the median, so that each approach had three lanes at the intersection: two through lanes and a "
      "left-turn bay. Vehicle 1 was northbound in the left-turn bay waiting to turn left. Vehicle 2 was "
      "southbound in the inside through lane. The front of Vehicle 2 struck the right side of Vehicle 1.");
  EXPECT_TRUE(bays.road.divided.value);
  EXPECT_EQ(bays.road.lanes_per_direction.value, 3);
}
TEST(NarrativeExtractorTest, TheRoadTheCrashRoadMeetsIsAnother) {
  // "on the northbound approach of a residential street where it ends at a
  // T-intersection with a four-lane arterial": the street's 2 lanes.
  const AccidentRecord met = kExtractor.Extract(
      "This rear-end crash took place on the northbound approach of a residential street where it ends at a "
      "T-intersection with a four-lane arterial. The residential street is two lanes, one in each direction. "
      "V2 was stopped at the stop sign waiting to turn right onto the arterial. V1 had stopped behind it, "
      "then started forward, and the front of V1 struck the back of V2.");
  EXPECT_EQ(met.road.lanes_total.value, 2);
  // "the intersecting street comes in from the south; it has one lane in
  // each direction", V1 northbound on it.
  const AccidentRecord side = kExtractor.Extract(
      "This crash occurred at a T-intersection. The through roadway runs east-west and is a four-lane, two-way "
      "undivided road, two lanes in each direction. The intersecting street comes in from the south; it has "
      "one lane in each direction and is stop-controlled where it meets the four-lane road. Vehicle #1 was "
      "northbound on the side street, stopped at the stop sign and then began to turn left. Vehicle #2 was "
      "eastbound in the curb lane of the four-lane road. The front of Vehicle #2 struck the left side of "
      "Vehicle #1.");
  EXPECT_EQ(side.road.lanes_per_direction.value, 1);
  EXPECT_EQ(side.road.lanes_total.value, 2);
}
TEST(NarrativeExtractorTest, AFarmLaneIsADrivewayWhenUsedAndALandmarkOtherwise) {
  // Passed on the left as it turned into a farm lane: a turn across path at
  // the driveway, its driver's age the subject of the turn.
  const AccidentRecord used = kExtractor.Extract(
      "V1 was westbound behind a 1993 Ford Ranger pickup (V2) on a two-lane rural highway. V2's 66-year-old "
      "driver had his left signal on and was slowing to turn into the farm lane, where he lives. The driver "
      "of V1 pulled left to pass just as V2 began its turn. The front of V1 struck the left side of V2 in the "
      "eastbound lane.");
  ASSERT_EQ(used.vehicles.size(), 2u);
  EXPECT_EQ(used.vehicles[1].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(used.crash.type.value, CrashType::kTurnAcrossPath);
  EXPECT_EQ(used.crash.location.value, CrashLocation::kDriveway);
  const AccidentRecord landmark = kExtractor.Extract(
      "V1 was southbound on a two-lane road. Just north of a farm lane, V1 drifted gradually across the "
      "centerline into the northbound lane, and the front of V1 struck the front of V2.");
  EXPECT_EQ(landmark.crash.location.value, CrashLocation::kSegment);
  // A driveway 40 m behind the vehicle backing toward it is not the place.
  const AccidentRecord behind = kExtractor.Extract(
      "V1 stopped in the northbound lane of a two-lane rural road and began backing toward the property's "
      "driveway, which was about 40 m behind him. V2 had stopped behind V1. The back of V1 struck the front "
      "of V2.");
  EXPECT_EQ(behind.crash.location.value, CrashLocation::kSegment);
}
TEST(NarrativeExtractorTest, RampsFlashersAndSlowingIntoATurn) {
  // "accelerating up the ramp to merge" where the ramp joins the freeway.
  const AccidentRecord ramp = kExtractor.Extract(
      "This crash occurred at the point where a one-lane entrance ramp joins the eastbound lanes of a freeway. "
      "V1 was accelerating up the ramp to merge. V2 was eastbound in the right through lane. V1 moved left "
      "alongside V2, and the left side of V1 sideswiped the right side of V2.");
  EXPECT_EQ(ramp.crash.location.value, CrashLocation::kRamp);
  EXPECT_EQ(ramp.road.kind.value, RoadKind::kRamp);
  // "four-way flashers" are hazard lights, not a 4-way junction.
  const AccidentRecord flashers = kExtractor.Extract(
      "V2, a stake-bed truck, was eastbound on a two-lane rural road climbing the hill at about 15 mph with "
      "its four-way flashers on. V1 was also eastbound. The front of V1 struck the back of V2.");
  EXPECT_EQ(flashers.crash.location.value, CrashLocation::kSegment);
  EXPECT_NE(flashers.road.kind.value, RoadKind::kIntersection);
  // "slowed and began a left turn": slowing before the turn.
  const AccidentRecord slowed = kExtractor.Extract(
      "Vehicle 1 was eastbound on the main road. Its driver, a 30-year-old man, slowed and began a left turn "
      "onto the residential street. Vehicle 2 was westbound on the main road. The front of Vehicle 2 struck "
      "the right front of Vehicle 1.");
  ASSERT_EQ(slowed.vehicles.size(), 2u);
  EXPECT_EQ(slowed.vehicles[0].pre_event.value, Movement::kSlowing);
}
TEST(NarrativeExtractorTest, WhatTheDriverSawTheOtherDoIsNotHisOwn) {
  const AccidentRecord missed = kExtractor.Extract(
      "Vehicle 2 was eastbound and slowing to turn right into a driveway. Vehicle 1 was eastbound behind it. "
      "The front of Vehicle 1 struck the back of Vehicle 2. The driver of Vehicle 1 said he was looking at a "
      "combine in the field and \"didn't notice she was slowing.\"");
  ASSERT_EQ(missed.vehicles.size(), 2u);
  EXPECT_EQ(missed.vehicles[0].pre_event.value, Movement::kStraight);
  const AccidentRecord reacted = kExtractor.Extract(
      "Vehicle 2 was eastbound in the right lane and braked to stop for a yellow signal. Vehicle 1 was "
      "following in the same lane. The driver of Vehicle 1 said he expected it to go through. When it stopped "
      "he braked hard, but the front of Vehicle 1 struck the back of Vehicle 2.");
  ASSERT_EQ(reacted.vehicles.size(), 2u);
  EXPECT_EQ(reacted.vehicles[0].pre_event.value, Movement::kStraight);
}
TEST(NarrativeExtractorTest, AHeadOnToldWithAPronounSubject) {
  const AccidentRecord r = kExtractor.Extract(
      "The Ford (V1) was northbound in the inside lane of a four-lane undivided street. Its 47-year-old male "
      "driver allowed it to drift across the double yellow line into the southbound inside lane, where it "
      "struck the Nissan (V2) head-on.");
  EXPECT_EQ(r.crash.type.value, CrashType::kHeadOn);
  EXPECT_EQ(r.crash.striking.value, "V1");
  EXPECT_EQ(r.crash.struck.value, "V2");
}
TEST(NarrativeExtractorTest, OneUnnumberedVehicleThatRolledOrPassedABusShelter) {
  const AccidentRecord rolled = kExtractor.Extract(
      "The single-vehicle rollover happened on a two-lane rural road. The vehicle, a 1997 Ford Escort sedan, "
      "was westbound. Entering the curve, the rear of the car began to slide out; it departed the left side "
      "of the road, tripped in the soft shoulder and rolled two quarter turns.");
  EXPECT_EQ(rolled.participant_count.value, 1);
  EXPECT_EQ(rolled.crash.type.value, CrashType::kSingleVehicle);
  const AccidentRecord shelter = kExtractor.Extract(
      "A 1999 Buick Century was northbound in the left lane of a four-lane city street. Witnesses in a bus "
      "shelter said the Buick drifted to the right across the curb lane, mounted the curb, and struck a steel "
      "sign pole with its front.");
  EXPECT_EQ(shelter.participant_count.value, 1);
  EXPECT_EQ(shelter.crash.type.value, CrashType::kSingleVehicle);
}
TEST(NarrativeExtractorTest, ADescriptionBetweenDashesAndWhatTheTruckHauled) {
  const AccidentRecord r = kExtractor.Extract(
      "V1 - a 2005 Freightliner tractor hauling a flatbed semitrailer - was northbound on a two-lane rural "
      "highway. V2, a 2001 Honda Civic, was southbound. The truck drifted left across the center line and the "
      "front of V1 struck the front of V2.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].description.value, "2005 freightliner tractor");
  EXPECT_EQ(r.vehicles[0].vehicle_class.value, VehicleClass::kTruck);
  EXPECT_EQ(r.vehicles[0].vehicle_class.source, Provenance::kInferred);
}
TEST(NarrativeExtractorTest, StartedAcrossAfterWaitingForAPedestrian) {
  const AccidentRecord r = kExtractor.Extract(
      "V1 was northbound on the side street and stopped at the stop sign, waited for a pedestrian to finish "
      "crossing, and then started across the four-lane highway. V2 was eastbound on the highway. The front of "
      "V2 struck the left side of V1 in the intersection.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
}
TEST(NarrativeExtractorTest, ACarThatCreptIntoTheRearOfAnother) {
  const AccidentRecord r = kExtractor.Extract(
      "V2 was stopped in traffic in the eastbound lane of a two-lane road. V1 was stopped behind it. The "
      "driver of V1 took her foot off the brake and V1 crept forward into V2's rear.");
  EXPECT_EQ(r.crash.type.value, CrashType::kRearEnd);
  EXPECT_EQ(r.crash.striking.value, "V1");
  EXPECT_EQ(r.crash.struck.value, "V2");
}
TEST(NarrativeExtractorTest, TheResearchersShorthandForCodedEvents) {
  // "CPE for V1 = other vehicle stopped": the vehicle ahead was stopped.
  const AccidentRecord r = kExtractor.Extract(
      "V1 was eastbound on a two-lane road. V2 was ahead in the same lane. The front of V1 struck the back of "
      "V2. CPE for V1 = other vehicle stopped in lane. CR for V1 = driver inattention.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kStopped);
}
TEST(NarrativeExtractorTest, ARoadThatTeesIntoAnother) {
  const AccidentRecord r = kExtractor.Extract(
      "The crash happened where a two-lane county road tees into a four-lane state highway. V1 was southbound "
      "on the county road and turned left onto the highway. V2 was eastbound on the highway. The front of V2 "
      "struck the left side of V1.");
  EXPECT_EQ(r.road.kind.value, RoadKind::kTJunction);
  EXPECT_EQ(r.crash.location.value, CrashLocation::kJunction);
}
TEST(NarrativeExtractorTest, AnEntranceAheadIsNotWhereTheyCrashed) {
  const AccidentRecord ahead = kExtractor.Extract(
      "V1 was eastbound on a four-lane undivided arterial, slowing to turn right into a mall entrance about "
      "60 m ahead. V2 was eastbound behind it. The front of V2 struck the back of V1.");
  EXPECT_EQ(ahead.crash.location.value, CrashLocation::kSegment);
  // ... and one it turned into is.
  const AccidentRecord into = kExtractor.Extract(
      "V1 was eastbound on a four-lane undivided arterial and turned left into a plaza entrance. V2 was "
      "westbound. The front of V2 struck the right side of V1.");
  EXPECT_EQ(into.crash.location.value, CrashLocation::kDriveway);
}
TEST(NarrativeExtractorTest, ALimitInBracketsAfterTheSideRoadIsItsOwn) {
  const AccidentRecord r = kExtractor.Extract(
      "A 2-lane side road (35 mph, 56 kmh) ends at a state highway posted at 45 mph. V1 was northbound on the "
      "side road approaching the highway. V2 was ahead of it, stopped at the stop sign. The front of V1 struck "
      "the back of V2.");
  EXPECT_NEAR(r.road.speed_limit_mps.value, 35 * 0.44704, 1e-6);
  EXPECT_EQ(r.road.speed_limit_unit.value, "mph");
}
TEST(NarrativeExtractorTest, ASceneSentenceIsNoVehiclesOwn) {
  // The lanes of the highway named after V2's description are not V2's way.
  const AccidentRecord r = kExtractor.Extract(
      "The case vehicle (V1) was a 2001 Ford Windstar minivan. The other vehicle (V2) was a 2003 Volvo tractor. "
      "Location is a rural four-lane divided highway: two eastbound lanes and two westbound lanes separated by a "
      "grass median. V1 was eastbound in the left lane. The van rotated clockwise and crossed the median into "
      "the westbound lanes. V2 was westbound in the left lane. The front of V2 struck the right side of V1.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[1].travel.value, std::optional<Compass>(Compass::kWest));
  EXPECT_EQ(r.crash.type.value, CrashType::kSideswipeOpposite);
}
TEST(NarrativeExtractorTest, ATurnMeantAndThenTaken) {
  // "intended to turn left ... accelerated into the turn".
  const AccidentRecord into = kExtractor.Extract(
      "V2 was northbound on the stem of a T-intersection and stopped at the stop sign. The driver intended to "
      "turn left and go west. V1 was eastbound on the through road. V2 accelerated into the turn, and the front "
      "of V1 struck the left side of V2.");
  ASSERT_EQ(into.vehicles.size(), 2u);
  EXPECT_EQ(into.vehicles[1].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(into.crash.type.value, CrashType::kTurnIntoPath);
  // "waiting to turn left ... his view was blocked, and that he 'inched out
  // and then went for it'".
  const AccidentRecord went = kExtractor.Extract(
      "Vehicle #1 was northbound in the left through lane of a four-lane divided boulevard. Vehicle #2 was "
      "southbound in the left-turn bay, waiting to turn left onto a cross street. The Equinox driver stated "
      "that a northbound box truck in the opposing bay blocked his view, and that he \"inched out and then went "
      "for it.\" The front of Vehicle #1 struck the right side of Vehicle #2 in the intersection.");
  ASSERT_EQ(went.vehicles.size(), 2u);
  EXPECT_EQ(went.vehicles[1].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(went.crash.type.value, CrashType::kTurnAcrossPath);
  // "moved into the turn lane" is no turn.
  const AccidentRecord lane = kExtractor.Extract(
      "V1 was westbound in the inside lane of a five-lane road. Its driver had already moved into the turn lane "
      "when the front of V1 struck the front of V2, which was stopped there facing east.");
  ASSERT_EQ(lane.vehicles.size(), 2u);
  EXPECT_NE(lane.vehicles[0].movement.value, Movement::kTurnLeft);
}
TEST(NarrativeExtractorTest, TheWagonATractorPullsIsItsOwn) {
  const AccidentRecord r = kExtractor.Extract(
      "Vehicle one (V1) was traveling west on a two-lane rural highway. Vehicle two (V2), a 1985 John Deere "
      "farm tractor pulling a loaded hay wagon, was also westbound ahead of V1. He braked and steered left, but "
      "the right front of V1 struck the back of the hay wagon.");
  EXPECT_EQ(r.crash.type.value, CrashType::kRearEnd);
  EXPECT_EQ(r.crash.struck.value, "V2");
}
TEST(NarrativeExtractorTest, TheSideStreetEnteringFromTheEastIsTheTurnersRoad) {
  const AccidentRecord r = kExtractor.Extract(
      "This crash happened at a T-intersection. The north-south trafficway is a four-lane, two-way undivided "
      "state highway (two lanes in each direction) with a posted speed limit of 50 mph. Entering from the east "
      "is a two-lane residential street posted at 25 mph. V1 was westbound on the side street. She stopped at "
      "the stop sign and then began a right turn to go north. V2 was northbound in the right lane of the "
      "highway. The front of V2 struck the left side of V1.");
  EXPECT_EQ(r.road.lanes_total.value, 2);
}
TEST(NarrativeExtractorTest, ARoadSignedAtItsLimitAndWitnessesWhoStopped) {
  const AccidentRecord signed_at = kExtractor.Extract(
      "The crash occurred on a two-lane highway in a rolling rural area. The roadway is signed at 80 km/h "
      "(50 mph). V1 was westbound. V2 was eastbound and drifted across the centerline. The front of V2 struck "
      "the front of V1.");
  EXPECT_NEAR(signed_at.road.speed_limit_mps.value, 80 / 3.6, 1e-6);
  EXPECT_EQ(signed_at.road.speed_limit_unit.value, "km/h");
  const AccidentRecord witnesses = kExtractor.Extract(
      "V1 was southbound in the inside lane of the north-south street. V2 was westbound in the center lane of "
      "the boulevard and had a green signal. Two independent witnesses stopped on the boulevard stated that the "
      "southbound signal had been red. The front of V1 struck the right side of V2.");
  ASSERT_EQ(witnesses.vehicles.size(), 2u);
  EXPECT_EQ(witnesses.vehicles[1].pre_event.value, Movement::kStraight);
}
TEST(NarrativeExtractorTest, MovingOverToReachAnExitIsALaneChange) {
  const AccidentRecord exit = kExtractor.Extract(
      "V1 was in the center eastbound lane of a six-lane divided highway. V2, a tractor-trailer, was in the "
      "right eastbound lane slightly behind V1. The driver of V1 wanted to exit at an off-ramp 0.8 km ahead and "
      "moved right. The right rear side of V1 contacted the front of V2.");
  ASSERT_EQ(exit.vehicles.size(), 2u);
  EXPECT_EQ(exit.vehicles[0].movement.value, Movement::kChangingLanes);
  // ... and moving right to get out of the way is not.
  const AccidentRecord avoid = kExtractor.Extract(
      "V1 was northbound on a two-lane road. V2 was southbound and drifted over the center line. The driver of "
      "V1 stated he saw the car's headlights start to come over and moved right, but the left side of V2 struck "
      "the left side of V1.");
  ASSERT_EQ(avoid.vehicles.size(), 2u);
  EXPECT_EQ(avoid.vehicles[0].movement.value, Movement::kStraight);
}
TEST(NarrativeExtractorTest, TheContactClauseNamesTheSideThatStruck) {
  // The rear that came around is not what struck the guardrail.
  const AccidentRecord r = kExtractor.Extract(
      "V1, a 2003 Ford F-150 pickup, left the interstate on the exit ramp at roughly 55 mph. Partway around the "
      "curve he braked hard. The rear of the pickup came around and the truck slid clockwise, sliding off the "
      "right side of the ramp, where its left side struck the W-beam guardrail.");
  EXPECT_EQ(r.crash.type.value, CrashType::kSingleVehicle);
  EXPECT_EQ(r.crash.striking_area.value, DamageArea::kLeft);
}
TEST(NarrativeExtractorTest, NeitherStreetPostedIsNoLimit) {
  const AccidentRecord r = kExtractor.Extract(
      "This crash occurred at an all-way stop in a residential neighborhood. Both streets are two-lane, two-way, "
      "straight and level. Neither street had a posted speed limit. Vehicle #1 was westbound and stopped at the "
      "stop sign. Vehicle #2 was southbound. The front of Vehicle #2 struck the right side of Vehicle #1.");
  EXPECT_FALSE(r.road.speed_limit_mps.known());
}
TEST(NarrativeExtractorTest, ThePronounObjectOfAContact) {
  // "As V1 crossed ..., the front of V2 struck its left side": V1's side.
  const AccidentRecord r = kExtractor.Extract(
      "Vehicle 1 was westbound on the side road and stopped at the stop sign. Vehicle 2 was northbound on the "
      "highway. After stopping, the driver of Vehicle 1 pulled out. As Vehicle 1 crossed the northbound lanes, "
      "the front of Vehicle 2 struck its left side.");
  EXPECT_EQ(r.crash.striking.value, "V2");
  EXPECT_EQ(r.crash.struck.value, "V1");
  EXPECT_EQ(r.crash.striking_area.value, DamageArea::kFront);
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kLeft);
}
TEST(NarrativeExtractorTest, AtTheRampTerminalOnTheRampsOwnLanesAndLimit) {
  const AccidentRecord r = kExtractor.Extract(
      "The crash occurred at the terminal of the westbound exit ramp from an interstate, where the ramp forms a "
      "T-intersection with Highway 20, a north/south four-lane undivided roadway (two lanes each direction) "
      "posted at 72 km/h (45 mph). At the terminal the ramp widens to two lanes, a left-turn lane and a "
      "right-turn lane, both controlled by a stop sign; the ramp is posted at 56 km/h (35 mph). Vehicle 1 had "
      "exited the interstate and stopped in the ramp's left-turn lane, intending to turn left. Vehicle 2 was "
      "northbound on Highway 20. After stopping, the driver of Vehicle 1 pulled out. As Vehicle 1 crossed the "
      "northbound lanes, the front of Vehicle 2 struck its left side.");
  EXPECT_EQ(r.crash.location.value, CrashLocation::kJunction);
  EXPECT_EQ(r.road.lanes_total.value, 2);
  EXPECT_NEAR(r.road.speed_limit_mps.value, 56 / 3.6, 1e-6);
  // A ramp whose limit comes after what it does: "the ramp curves gently to
  // the left, is posted at 72 km/h".
  const AccidentRecord merge = kExtractor.Extract(
      "The crash occurred where a single-lane entrance ramp joins the northbound roadway of an interstate. The "
      "interstate is posted at 105 km/h (65 mph). The ramp curves gently to the left, is posted at 72 km/h (45 "
      "mph), and has a merge warning sign. V1 was traveling up the ramp to merge into the northbound lanes. V2 "
      "was northbound in lane one. The left side of V1 contacted the right side of V2.");
  EXPECT_NEAR(merge.road.speed_limit_mps.value, 72 / 3.6, 1e-6);
  // ... but a queue's aim at the terminal places no crash there.
  const AccidentRecord queue = kExtractor.Extract(
      "This rear-end crash occurred on a one-lane exit ramp leaving the eastbound lanes of an interstate; it "
      "ends at a signal about 250 meters from the gore. V2 was stopped at the end of the queue, intending to go "
      "straight across at the ramp terminal. V1 exited the interstate behind it. The front of V1 struck the "
      "back of V2.");
  EXPECT_EQ(queue.crash.location.value, CrashLocation::kRamp);
}
TEST(NarrativeExtractorTest, OutOfAGarageAndPastADoubleParkedTruck) {
  const AccidentRecord r = kExtractor.Extract(
      "The crash occurred at the exit of a public parking garage on a one-way northbound downtown street with "
      "three northbound travel lanes. A delivery truck was double-parked in the curb lane just south of the exit. "
      "V1 came out of the garage and stopped at the sidewalk, then turned right to go north. V2 was northbound "
      "in lane two. The front of V2 struck the left side of V1. The driver of V1 said the double-parked truck "
      "blocked his view.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_FALSE(r.vehicles[0].parked.value);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnRight);
  EXPECT_EQ(r.crash.location.value, CrashLocation::kDriveway);
  EXPECT_EQ(r.crash.type.value, CrashType::kTurnIntoPath);
}
TEST(NarrativeExtractorTest, LeavingAFieldByItsSingleLaneAccess) {
  const AccidentRecord r = kExtractor.Extract(
      "This crash occurred at a farm field access on the west side of a two-lane county highway. The field "
      "access is a single-lane dirt drive with no control. V1 was leaving the field. The driver stopped at the "
      "edge of the highway and then began a left turn to go north. V2 was southbound. The front of V2 struck "
      "the left front of V1.");
  EXPECT_EQ(r.crash.location.value, CrashLocation::kDriveway);
  EXPECT_EQ(r.road.lanes_total.value, 1);
}
TEST(NarrativeExtractorTest, TheNamedRoadIsNotTheOneAcrossItsCourse) {
  // "plaza road" is named in the first sentence with the arterial's count.
  const AccidentRecord r = kExtractor.Extract(
      "The crash occurred at a T-intersection formed by the exit road of a shopping plaza (the south leg) and "
      "a five-lane east/west arterial. The arterial has two through lanes in each direction and a center "
      "two-way left-turn lane. The plaza road is a two-lane public street posted at 40 km/h (25 mph), "
      "controlled by a stop sign. Vehicle one was northbound on the plaza road and stopped at the stop sign, "
      "waiting to turn left. Vehicle two was eastbound. The front of Vehicle two struck the left side of "
      "Vehicle one.");
  EXPECT_EQ(r.road.lanes_total.value, 2);
}
TEST(NarrativeExtractorTest, TheTurnersOwnSentenceNamesTheMinivanAndTheRoadItTurnedOnto) {
  const AccidentRecord r = kExtractor.Extract(
      "The Kia was making a right turn from a stop-controlled side street onto a four-lane arterial when it was "
      "struck from behind by an eastbound minivan. Roadway: the arterial runs east/west, has two travel lanes in "
      "each direction and a posted limit of 45 mph. The side street is a two-lane, two-way residential street "
      "posted at 25 mph that forms a T with the arterial from the south. Vehicle #1, a 2004 Kia Spectra, "
      "stopped at the stop sign facing north and then began a right turn to head east. Vehicle #2, a 1999 Ford "
      "Windstar, was eastbound in the curb lane. The front of the Windstar struck the left rear of the Spectra.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].travel.value, std::optional<Compass>(Compass::kNorth));
  EXPECT_EQ(r.road.lanes_total.value, 2);
  EXPECT_NEAR(r.road.speed_limit_mps.value, 25 * 0.44704, 1e-6);
}
TEST(NarrativeExtractorTest, ACarOccupiedByTeenagersStillTellsItsRoad) {
  const AccidentRecord r = kExtractor.Extract(
      "V1, a 2001 Pontiac Grand Am coupe occupied by three 19-year-olds, was westbound on a two-lane county "
      "road posted at 45 MPH. The road bends to the left at the crash site. The front of the car struck an oak "
      "tree about 6 m off the road.");
  EXPECT_NEAR(r.road.speed_limit_mps.value, 45 * 0.44704, 1e-6);
}
TEST(NarrativeExtractorTest, AModelNumberedOnceNamesItsVehicleLater) {
  const AccidentRecord r = kExtractor.Extract(
      "At 9 pm a 2004 Nissan Xterra turning right on red was struck by a taxi. The Xterra (V1) was southbound. "
      "V2, a 2000 Ford Crown Victoria operating as a taxi, was westbound. The front of the Crown Victoria struck "
      "the left side of the Xterra as it entered the westbound curb lane.");
  EXPECT_EQ(r.crash.striking.value, "V2");
  EXPECT_EQ(r.crash.struck.value, "V1");
  EXPECT_NE(r.crash.type.value, CrashType::kSingleVehicle);
}
TEST(NarrativeExtractorTest, ARoadEndingAtATAndACarWaitedFor) {
  const AccidentRecord r = kExtractor.Extract(
      "Vehicle No. 1 was northbound on a county road that ends at a T with an east/west state route. The "
      "county road is two lanes with a stop sign at the T. The driver of Vehicle No. 1 stopped, waited for an eastbound car "
      "approaching from his left to pass, looked left again, and pulled out to turn left (west). Vehicle No. 2 "
      "was westbound from his right. The front of Vehicle No. 2 struck the right side of Vehicle No. 1 in the "
      "westbound lane.");
  EXPECT_EQ(r.road.kind.value, RoadKind::kTJunction);
  EXPECT_EQ(r.crash.location.value, CrashLocation::kJunction);
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(r.crash.type.value, CrashType::kTurnIntoPath);
}
TEST(NarrativeExtractorTest, AParkedCarNumberedAfterItsDescription) {
  const AccidentRecord r = kExtractor.Extract(
      "V1 was northbound on a two-lane city street with parking along both curbs. V1 drifted to the right into "
      "the parking lane and its front struck the left rear of a legally parked, unoccupied 1994 Oldsmobile "
      "Cutlass Ciera (V2).");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_FALSE(r.vehicles[0].parked.value);
  EXPECT_TRUE(r.vehicles[1].parked.value);
  EXPECT_EQ(r.vehicles[1].description.value, "1994 oldsmobile cutlass ciera");  // not "legally"
  EXPECT_EQ(r.crash.type.value, CrashType::kSingleVehicle);
}
TEST(NarrativeExtractorTest, ATurnToldByTheCompassIsLeftOrRightOfTheCourse) {
  // Northbound and meaning to turn west: a left turn, begun.
  const AccidentRecord a = kExtractor.Extract(
      "V1, a 2008 Honda Civic, was northbound in the left-turn bay intending to turn west. V2, a 2006 Ford "
      "Explorer, was southbound in the inside through lane. The V1 driver told the investigator that a bus in the "
      "outside lane blocked her view. She began her turn and the front of V2 struck the right side of V1.");
  ASSERT_EQ(a.vehicles.size(), 2u);
  EXPECT_EQ(a.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(a.vehicles[1].movement.value, Movement::kStraight);
  EXPECT_EQ(a.crash.type.value, CrashType::kTurnAcrossPath);
  // Westbound and turning north: a right turn.
  const AccidentRecord b = kExtractor.Extract(
      "V1 was traveling west on Oak Street and turned north onto Elm Avenue. V2 was northbound on Elm Avenue in "
      "the right lane. The front of V2 struck the rear of V1.");
  ASSERT_EQ(b.vehicles.size(), 2u);
  EXPECT_EQ(b.vehicles[0].movement.value, Movement::kTurnRight);
  // A direction that is the course itself is no turn.
  const AccidentRecord c = kExtractor.Extract(
      "V1 was traveling west on Oak Street and continued west through the intersection. V2 was northbound on Elm "
      "Avenue and the front of V2 struck the left side of V1.");
  ASSERT_EQ(c.vehicles.size(), 2u);
  EXPECT_EQ(c.vehicles[0].movement.value, Movement::kStraight);
}
TEST(NarrativeExtractorTest, TheNumberedDriverIsThatVehiclesDriver) {
  // "the v1 driver said ... she began her turn" is v1's account, not v2's.
  const AccidentRecord r = kExtractor.Extract(
      "V1 was eastbound and stopped at the stop sign. V2 was northbound on the main road. The V1 driver said "
      "she looked both ways and then she turned left. The front of V2 struck the left side of V1.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(r.vehicles[1].movement.value, Movement::kStraight);
}
TEST(NarrativeExtractorTest, ASideStreetThatComesInFromTheSouthIsNotV1sRoad) {
  // V1 is eastbound on the four-lane street; the two-lane street that
  // "enters from the south" runs north-south; a speed range after "the
  // speed limit" is V1's speed.
  const AccidentRecord r = kExtractor.Extract(
      "The crash occurred at a T-intersection. The east/west street has two lanes in each direction, no median, and "
      "is posted at 30 mph (48 km/h). A two-lane street posted at 25 mph (40 km/h) enters from the south and has a "
      "stop sign. V2 stopped at the stop sign on the south leg, then pulled out to turn left. V1 was eastbound in "
      "the curb lane. The front of V1 struck the left side of V2. The V1 driver told police he was doing the speed "
      "limit, but the reconstruction put V1 at 60-65 km/h (37-40 mph).");
  EXPECT_EQ(r.road.lanes_total.value, 4);
  EXPECT_NEAR(r.road.speed_limit_mps.value, 30 * 0.44704, 1e-6);
  // V1 on the side street that "comes in from the south", meaning to turn
  // and then accelerating into the intersection: its road, and its turn.
  const AccidentRecord s = kExtractor.Extract(
      "The through road runs east/west and is a four-lane roadway with two lanes in each direction, posted at 72 "
      "km/h (45 mph). A two-lane street posted at 48 km/h (30 mph) comes in from the south and ends at the "
      "intersection. V1 was northbound on the side street and was stopped at the red light intending to turn left "
      "(west). When the light turned green the driver accelerated into the intersection. V2 was eastbound in the "
      "curb lane. The front of V2 struck the left side of V1.");
  EXPECT_EQ(s.road.lanes_total.value, 2);
  EXPECT_NEAR(s.road.speed_limit_mps.value * 3.6, 48.0, 1e-6);
  ASSERT_EQ(s.vehicles.size(), 2u);
  EXPECT_EQ(s.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(s.crash.type.value, CrashType::kTurnIntoPath);
}
TEST(NarrativeExtractorTest, AStopSkippedAtTheControlIsTheTurnUnlessTheTextSlowsIt) {
  const char* kRest = " V2 was northbound. The front of V2 struck the left side of V1.";
  // Skipped where it should have stopped, no slowing told: the turn.
  const AccidentRecord a = kExtractor.Extract(
      std::string("V1 was westbound in a driveway. The driver of V1 did not stop at the end of the driveway and began "
                  "a left turn to travel south.") + kRest);
  ASSERT_EQ(a.vehicles.size(), 2u);
  EXPECT_EQ(a.vehicles[0].pre_event.value, Movement::kTurnLeft);
  // ... and slowed there: slowing.
  const AccidentRecord b = kExtractor.Extract(
      std::string("V1 was westbound. V1 slowed at the stop sign without coming to a complete stop and turned left "
                  "to travel south.") + kRest);
  ASSERT_EQ(b.vehicles.size(), 2u);
  EXPECT_EQ(b.vehicles[0].pre_event.value, Movement::kSlowing);
  // No stop before the turn at an uncontrolled corner: slowing for it.
  const AccidentRecord c = kExtractor.Extract(
      std::string("V1 was westbound and made a left turn at the intersection. The driver said he did not stop before "
                  "making the turn.") + kRest);
  ASSERT_EQ(c.vehicles.size(), 2u);
  EXPECT_EQ(c.vehicles[0].pre_event.value, Movement::kSlowing);
}
TEST(NarrativeExtractorTest, TheLimitOfARoadNamedWithItsAxisIsThatRoads) {
  // V1 on the northbound side road; the highway is the east/west one.
  const AccidentRecord r = kExtractor.Extract(
      "V1 had stopped at the stop sign at the end of a northbound two-lane road where it meets an east/west two-lane "
      "highway. V2 was eastbound on the highway. The highway is posted at 45 mph (72 km/h) and the side road at 35 "
      "mph (56 km/h). V1 pulled out and began its left turn; the front of V2 struck the left side of V1.");
  EXPECT_NEAR(r.road.speed_limit_mps.value, 35 * 0.44704, 1e-6);
}
TEST(NarrativeExtractorTest, AVehicleMetAfterTheImpactKeepsItsStateWithoutAComma) {
  const AccidentRecord r = kExtractor.Extract(
      "V1 was northbound and turned left on a green ball. V2 was southbound in the curb lane. The front of V2 "
      "struck the right side of V1. V2 rotated and its right side struck the front of V3, a 2004 Ford Escape that "
      "was stopped eastbound at the red signal on the west leg.");
  ASSERT_EQ(r.vehicles.size(), 3u);
  EXPECT_EQ(r.vehicles[2].pre_event.value, Movement::kStopped);
}
TEST(NarrativeExtractorTest, WhatBothDidTogetherIsEachOnes) {
  // A bare "both" that started off: V1 went straight from its stop.
  const AccidentRecord a = kExtractor.Extract(
      "All-way stop. V1 (2001 Ford Focus) northbound, V2 (2004 Dodge Caravan) southbound; both stopped at their signs "
      "at nearly the same moment and both started off. V1 went straight; V2 began a left turn toward the west leg "
      "and the front of V1 hit V2's right side.");
  ASSERT_EQ(a.vehicles.size(), 2u);
  EXPECT_EQ(a.vehicles[0].pre_event.value, Movement::kStraight);
  // "both vehicles started to move" after an unpunctuated clause.
  const AccidentRecord b = kExtractor.Extract(
      "Vehicle 2 had been stopped first in the left-turn lane and Vehicle 1 was stopped behind it. When the green "
      "arrow came on both vehicles started to move. The driver of Vehicle 2 braked hard for a pedestrian and the "
      "front of Vehicle 1 struck the back of Vehicle 2.");
  ASSERT_EQ(b.vehicles.size(), 2u);
  EXPECT_EQ(b.vehicles[0].pre_event.value, Movement::kStraight);
  // Traffic ahead of both is neither.
  const AccidentRecord c = kExtractor.Extract(
      "V1 and V2 were westbound in lane two. Traffic ahead of both vehicles began to slow. The front of V1 struck "
      "the back of V2.");
  ASSERT_EQ(c.vehicles.size(), 2u);
  EXPECT_EQ(c.vehicles[0].pre_event.value, Movement::kStraight);
}
TEST(NarrativeExtractorTest, WhatADriverLookedAtOrTookTheOtherForIsNotItsOwn) {
  // The traffic looked at over a shoulder does not end V1's sentence; the
  // merge it meant to judge is still to come.
  const AccidentRecord a = kExtractor.Extract(
      "Vehicle 2 entered the slip lane and came to a complete stop at the yield line. Vehicle 1 followed it into "
      "the slip lane. The driver of Vehicle 1 was looking over his left shoulder at eastbound traffic to judge his "
      "own merge, and was still slowing when the front of his car struck the back of the stopped minivan.");
  ASSERT_EQ(a.vehicles.size(), 2u);
  EXPECT_EQ(a.vehicles[0].pre_event.value, Movement::kSlowing);
  EXPECT_EQ(a.vehicles[1].pre_event.value, Movement::kStopped);
  // "thought it was parked" is the other vehicle as the driver took it.
  const AccidentRecord b = kExtractor.Extract(
      "Vehicle #2, a refuse truck, was westbound moving at about 10 km/h. Vehicle #1 was westbound behind it. The "
      "front of Vehicle #1 struck the back of the refuse truck. The Prius driver said he saw lights ahead but "
      "\"thought it was parked, or going normal speed, I couldn't tell.\"");
  ASSERT_EQ(b.vehicles.size(), 2u);
  EXPECT_EQ(b.vehicles[0].pre_event.value, Movement::kStraight);
  EXPECT_FALSE(b.vehicles[0].parked.value);
}
TEST(NarrativeExtractorTest, AVehicleOutOfTheAccelerationLaneIsMerging) {
  const AccidentRecord r = kExtractor.Extract(
      "A one-lane entrance ramp joins the eastbound side of a four-lane freeway. Vehicle 1 came down the ramp and "
      "reached the end of the acceleration lane while Vehicle 2 was traveling east in the right lane beside it. "
      "Vehicle 1 moved left into lane one and the left side of Vehicle 1 struck the right side of Vehicle 2.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kMerging);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kStraight);
  // Near the end of the acceleration lane is a place, not the focus vehicle's merge.
  const AccidentRecord s = kExtractor.Extract(
      "V1 came down the ramp and was merging into the right lane of the interstate. V2 was eastbound in the right "
      "lane. Near the end of the acceleration lane, V1 moved left and its left front contacted the right side of V2.");
  ASSERT_EQ(s.vehicles.size(), 2u);
  EXPECT_EQ(s.vehicles[1].pre_event.value, Movement::kStraight);
}
TEST(NarrativeExtractorTest, VehiclesNamedByMakeAndNumberedAtTheEnd) {
  const AccidentRecord a = kExtractor.Extract(
      "The Chevrolet Express was a parcel delivery van. Its driver had passed the house he was looking for and "
      "stopped in the southbound lane. The Saturn SL behind him also stopped. The van driver then put the van in "
      "reverse and backed up in the lane. Its back struck the front of the Saturn. The van was numbered Vehicle 2 "
      "and the Saturn Vehicle 1.");
  ASSERT_EQ(a.vehicles.size(), 2u);
  EXPECT_EQ(a.vehicles[0].pre_event.value, Movement::kStopped);
  EXPECT_EQ(a.vehicles[1].pre_event.value, Movement::kBacking);
  EXPECT_EQ(a.crash.striking.value, "V2");
  const AccidentRecord b = kExtractor.Extract(
      "The Lincoln, a 1998 Town Car, was parallel-parked on the east curb facing north. Its driver pulled out of the "
      "space to continue north. The Volkswagen, a 2002 Jetta, was northbound in the travel lane. The left front "
      "corner of the Lincoln struck the right side of the Volkswagen. The Lincoln was coded as Vehicle 1. Vehicle "
      "2, the Jetta, had other vehicle encroachment from the parking lane as its critical event.");
  ASSERT_EQ(b.vehicles.size(), 2u);
  EXPECT_EQ(b.vehicles[0].pre_event.value, Movement::kMerging);  // leaving the parking position
  EXPECT_EQ(b.crash.striking.value, "V1");
  EXPECT_EQ(b.crash.struck_area.value, DamageArea::kRight);
}
TEST(NarrativeExtractorTest, APassingVehicleTakesTheDirectionOfTheVehicleItFollowed) {
  // "Behind v3" is relative to V3; the lane it pulled into and the lane of
  // the contact are not its own direction.
  const AccidentRecord r = kExtractor.Extract(
      "The two-lane highway runs north-south and is posted at 45 mph. V3, a grain truck, was northbound at about 25 "
      "mph. V2, a 2006 Honda Civic, had been following V3 for a mile and pulled out into the southbound lane to pass "
      "it. V1, a 2001 Dodge Dakota, was southbound. The fronts of V1 and V2 collided in the southbound lane, and V2 "
      "then struck the left side of V3.");
  ASSERT_EQ(r.vehicles.size(), 3u);
  EXPECT_EQ(r.crash.type.value, CrashType::kHeadOn);
  EXPECT_EQ(r.vehicles[1].travel.value, Compass::kNorth);
  EXPECT_EQ(r.crash.striking_area.value, DamageArea::kFront);
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kFront);
}
TEST(NarrativeExtractorTest, VehiclesNamedTogetherAndTheCodedPartnerOfAChain) {
  // "Vehicles 3 and 4 were stopped" after the impact is their state before
  // it; V1's coded "other vehicle stopped" is the vehicle it struck.
  const AccidentRecord r = kExtractor.Extract(
      "Traffic on the two-lane road was held at a work zone. Vehicle #4, a Ford Ranger, was first in the queue, "
      "with Vehicle #3, a Honda Accord, and Vehicle #2, a Jeep Liberty, behind it. Vehicle #1, a Chevrolet "
      "Silverado, came over the hill and struck the back of Vehicle #2. Vehicle #2 was pushed into Vehicle #3, which "
      "was pushed into Vehicle #4. Vehicles #3 and #4 were stopped and took no part in the first impact. V1: "
      "critical event, other vehicle stopped.");
  ASSERT_EQ(r.vehicles.size(), 4u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kStopped);
  EXPECT_EQ(r.vehicles[2].pre_event.value, Movement::kStopped);
  EXPECT_EQ(r.vehicles[3].pre_event.value, Movement::kStopped);
}
TEST(NarrativeExtractorTest, CarsParkedAlongTheCurbsAreNotTheVehicleOfTheLastSentence) {
  const AccidentRecord r = kExtractor.Extract(
      "V1 was backing out of a driveway on the north side of the street. V2 was traveling east on the street at "
      "about 25 mph. Cars were parked along both curbs. V1 backed into the eastbound lane and the front of V2 struck "
      "the left side of V1.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kBacking);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kStraight);
}
TEST(NarrativeExtractorTest, ARoadWideningToACountAtTheEndOfASentenceIsRead) {
  // The count ends the sentence: what follows it is empty, not past the end.
  AccidentRecord r;
  ASSERT_NO_THROW(r = kExtractor.Extract(
                      "V1 was eastbound on the avenue. East of the last cross street the eastbound side widens from "
                      "two lanes to three; the added lane becomes the ramp. V1 struck the back of V2."));
  EXPECT_EQ(r.vehicles.size(), 2u);
  ASSERT_NO_THROW(kExtractor.Extract("The road widened from 2 lanes to 3"));
}
TEST(NarrativeExtractorTest, ATurnBayOfEachDirectionIsOneMoreLaneOfIt) {
  const AccidentRecord r = kExtractor.Extract(
      "V1 was westbound on a divided suburban arterial with three through lanes in each direction separated by a "
      "raised median; each approach also has a left-turn bay. V1 turned left and V2, eastbound, struck its right "
      "side.");
  EXPECT_TRUE(r.road.divided.value);
  EXPECT_EQ(r.road.lanes_per_direction.value, 4);
  // Without the bay, the through lanes.
  const AccidentRecord s = kExtractor.Extract(
      "V1 was westbound on a divided suburban arterial with three through lanes in each direction separated by a "
      "raised median. V1 turned left and V2, eastbound, struck its right side.");
  EXPECT_EQ(s.road.lanes_per_direction.value, 3);
}
TEST(NarrativeExtractorTest, TheLimitAtTheCrashIsTheReducedOneAndTheSideRoadsForAVehicleOnIt) {
  auto limit_mph = [](const char* text) { return kExtractor.Extract(text).road.speed_limit_mps.value / 0.44704; };
  // "drops from 55 mph to 35 mph": the value it drops to.
  EXPECT_NEAR(limit_mph("V1 was eastbound. The posted speed limit drops from 55 mph to 35 mph (56 km/h) about 300 "
                        "meters west of the signal. V1 struck the back of V2."),
              35.0, 1e-6);
  // The normal limit, then the work zone's told after a semicolon.
  EXPECT_NEAR(limit_mph("The normal speed limit is 65 mph; within the posted work zone the limit is reduced to 45 mph "
                        "(72 km/h). V1 was eastbound and struck the back of V2."),
              45.0, 1e-6);
  // A "normal" told of something else earlier, or between, does not hide
  // the normal limit the reduction replaces.
  EXPECT_NEAR(limit_mph("Traffic was normal for a weekday. It was dark and the road was dry. The normal speed limit "
                        "is 65 mph. Within the work zone the limit is reduced to 45 mph. V1 was eastbound and struck "
                        "the back of V2."),
              45.0, 1e-6);
  EXPECT_NEAR(limit_mph("The normal speed limit is 65 mph. Traffic was normal at the time. Within the work zone the "
                        "limit is reduced to 45 mph. V1 was eastbound and struck the back of V2."),
              45.0, 1e-6);
  // V1's street ends at the arterial: it is "the side street".
  EXPECT_NEAR(limit_mph("V1 was southbound on a two-lane residential street that ends in a T-intersection with a "
                        "divided arterial. The arterial is posted 55 mph; the side street, 25 mph. V1 stopped at the "
                        "stop sign and turned left, and V2, eastbound, struck the right side of V1."),
              25.0, 1e-6);
  // Who rode along does not make V1's travel sentence one about people.
  EXPECT_NEAR(limit_mph("The east-west road has a 55 mph speed limit and the north-south road a 45 mph limit. V1, a "
                        "2002 Mitsubishi Galant, was southbound on the north-south road with the driver's 10-year-old "
                        "grandson in the back seat. V2 was westbound and struck the left side of V1."),
              45.0, 1e-6);
}
TEST(NarrativeExtractorTest, AQueueListedBeforeItsStateIsAllInThatState) {
  const AccidentRecord r = kExtractor.Extract(
      "Traffic was stopped in the right lane for a work zone. From front to back: V4, a 2006 Honda Odyssey; V3, a "
      "2004 Chevrolet Malibu; and V2, a 2005 Toyota Camry, were all stopped in the right lane. V1, a pickup, "
      "approached in the right lane and its front struck the rear of the Camry.");
  ASSERT_EQ(r.vehicles.size(), 4u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
  for (size_t i = 1; i < 4; ++i) EXPECT_EQ(r.vehicles[i].pre_event.value, Movement::kStopped) << "V" << i + 1;
}
TEST(NarrativeExtractorTest, ARearEndOfAVehicleHeldByTheSignalIsAtTheJunction) {
  const AccidentRecord r = kExtractor.Extract(
      "V1, a 2004 Ford Focus, rear-ended V2, a 2006 Toyota Camry, which was stopped at a red arrow in the southbound "
      "left-turn lane of a seven-lane arterial. Posted 45 mph; straight, level, dry.");
  EXPECT_EQ(r.crash.location.value, CrashLocation::kJunction);
  const AccidentRecord s = kExtractor.Extract(
      "V1, a 2004 Ford Focus, rear-ended V2, a 2006 Toyota Camry, which was stopped in traffic in the right lane of a "
      "four-lane highway. Posted 45 mph; straight, level, dry.");
  EXPECT_EQ(s.crash.location.value, CrashLocation::kSegment);
}
TEST(NarrativeExtractorTest, PreImpactSkidMarksAreNoContact) {
  const AccidentRecord r = kExtractor.Extract(
      "V1 was eastbound, following V2. V2 was slowing to turn right into a driveway. She braked hard and steered "
      "left, and 18 meters of pre-impact skid marks were documented, but the front of V1 struck the back of V2.");
  EXPECT_EQ(r.crash.striking.value, "V1");
  EXPECT_EQ(r.crash.type.value, CrashType::kRearEnd);
}
TEST(NarrativeExtractorTest, AVehicleDescribedWithTheArticleKeepsItsName) {
  // "V1, the 2002 Lincoln Town Car," names V1 as "the Lincoln" later on.
  const AccidentRecord r = kExtractor.Extract(
      "V1, the 2002 Lincoln Town Car, was in lane one and turned sharply left to make a U-turn. V2, the 2007 Honda "
      "Accord, was in lane two coming up on its left at about 30 mph. The Accord driver locked up the brakes and hit "
      "the Lincoln's left front door with its front.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.crash.striking.value, "V2");
  EXPECT_EQ(r.crash.type.value, CrashType::kTurnAcrossPath);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kStraight);
}
TEST(NarrativeExtractorTest, ACarCrossingFromADriveThroughStoppedLanesStrikesAtAnAngle) {
  // The lanes it eased across are not its direction; the bank's drive is a drive.
  const AccidentRecord r = kExtractor.Extract(
      "Vehicle #2 pulled out of a bank's two-lane, two-way exit driveway on the south side of a four-lane road "
      "intending to drive straight across. Eastbound traffic in both near lanes was stopped. The driver of Vehicle "
      "#2 eased across the stopped eastbound lanes and into the westbound lanes, where the front of her vehicle "
      "struck the left side of Vehicle #1, a pickup traveling west in lane two.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_NE(r.vehicles[1].travel.value, Compass::kEast);
  EXPECT_EQ(r.crash.type.value, CrashType::kAngle);
  EXPECT_EQ(r.crash.location.value, CrashLocation::kDriveway);
}
TEST(NarrativeExtractorTest, TheSideOfTheOtherVehicleIsTheStruckVehiclesSide) {
  const AccidentRecord r = kExtractor.Extract(
      "V1 was traveling south in the right southbound lane of a divided interstate. V2 was traveling north. The "
      "driver of V2 lost control, crossed the median and entered the southbound lanes traveling sideways. The driver "
      "of V1 braked but the front of V1 struck the right side of the other vehicle.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.crash.struck.value, "V2");
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kRight);
  EXPECT_EQ(r.crash.type.value, CrashType::kSideswipeOpposite);
}
TEST(NarrativeExtractorTest, TiresThatLeftMarksAreNotTheStrikersContactArea) {
  const AccidentRecord r = kExtractor.Extract(
      "Vehicle #2, a 2005 Honda CR-V, was stopped in lane one for a red signal. Vehicle #1, a 2003 International box "
      "truck, was westbound in lane one. Its driver looked up, braked hard (about 14 meters of skid marks were "
      "measured from the truck's rear tires), and struck the rear of the CR-V.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.crash.type.value, CrashType::kRearEnd);
  EXPECT_EQ(r.crash.striking.value, "V1");
  EXPECT_EQ(r.crash.striking_area.value, DamageArea::kFront);
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kRear);
  // A tire named as the part struck is still a contact area.
  const AccidentRecord t = kExtractor.Extract(
      "V1 was eastbound and V2 was northbound. V1 ran the red light and struck V2's left front tire.");
  EXPECT_EQ(t.crash.struck_area.value, DamageArea::kLeft);
}
TEST(NarrativeExtractorTest, TheLanesOfTheArterialAndTheLanesCrossedAreNotTheCrossersDirection) {
  const AccidentRecord r = kExtractor.Extract(
      "V1, a 2005 Chrysler PT Cruiser, left a shopping center on the east side of a five-lane arterial through the "
      "center's main driveway. The arterial has two northbound lanes, two southbound lanes and a two-way left-turn "
      "lane. V1 started forward when the light turned green, intending to go straight across. V2, a pickup, was "
      "southbound in lane two and entered on red. The front of V2 struck the right side of V1 after V1 had crossed "
      "the northbound lanes and the center lane.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_NE(r.vehicles[0].travel.value, Compass::kNorth);
  EXPECT_EQ(r.vehicles[1].travel.value, Compass::kSouth);
  EXPECT_EQ(r.crash.type.value, CrashType::kAngle);
}
TEST(NarrativeExtractorTest, AVehiclePlacedFromAnotherIsIntroducedInAShortDescription) {
  // "the guy on my right", "the car behind it", "the car in the right lane".
  const AccidentRecord a = kExtractor.Extract(
      "We both stopped at the four-way stop. I got there first so I went straight through, but the guy on my right "
      "pulled out at the same time and smashed into my passenger door.");
  ASSERT_EQ(a.vehicles.size(), 2u);
  EXPECT_EQ(a.crash.type.value, CrashType::kAngle);
  EXPECT_EQ(a.crash.struck.value, "V1");
  const AccidentRecord b = kExtractor.Extract(
      "A school bus was slowing down to turn right into the school driveway when the car behind it ran into its back "
      "end. Two-lane road, 35 mph limit.");
  ASSERT_EQ(b.vehicles.size(), 2u);
  EXPECT_EQ(b.crash.type.value, CrashType::kRearEnd);
  EXPECT_EQ(b.crash.struck_area.value, DamageArea::kRear);
  const AccidentRecord c = kExtractor.Extract(
      "Merging onto the freeway from the on-ramp, I got squeezed: the car in the right lane didn't move over, and the "
      "left side of my car scraped along its right side.");
  ASSERT_EQ(c.vehicles.size(), 2u);
  EXPECT_EQ(c.vehicles[0].pre_event.value, Movement::kMerging);
}
TEST(NarrativeExtractorTest, ATextThatOpensOnTheBlueCarHasIntroducedIt) {
  const AccidentRecord r = kExtractor.Extract(
      "The blue car stopped at the stop sign on Elm Street, then pulled out to turn left onto Highway 50 and got hit "
      "in the driver's door by an eastbound semi in the right lane.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStopped);
  EXPECT_EQ(r.vehicles[1].vehicle_class.value, VehicleClass::kTruck);
  EXPECT_EQ(r.crash.struck.value, "V1");
}
TEST(NarrativeExtractorTest, ATurnOnAGreenWithoutStoppingIsATurnUnlessItSlowed) {
  const AccidentRecord r = kExtractor.Extract(
      "V1 was southbound intending to turn left. V2 was northbound. V1 had a green ball and, without stopping, "
      "continued into its left turn. The front of V2 struck the right side of V1 in the intersection.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kTurnLeft);
  const AccidentRecord s = kExtractor.Extract(
      "V1 was southbound. V2 was northbound. V1 slowed in the turn lane and began its left turn on a circular green "
      "without stopping. The front of V2 struck the right side of V1 in the intersection.");
  ASSERT_EQ(s.vehicles.size(), 2u);
  EXPECT_EQ(s.vehicles[0].pre_event.value, Movement::kSlowing);
}
TEST(NarrativeExtractorTest, V1sRoadCountedInTheOtherVehiclesSentenceIsV1s) {
  const AccidentRecord r = kExtractor.Extract(
      "V2, a 2002 Saturn SL1, was northbound on a two-lane residential street (speed limit 25 mph) and stopped for a "
      "red signal at a four-way intersection with a four-lane undivided avenue, two lanes each way, posted 30 mph. "
      "The driver then began a right turn on red. V1, a 2007 Hyundai Sonata, was eastbound in the curb lane of the "
      "avenue on a green light. The front of V1 struck the left side of V2.");
  EXPECT_EQ(r.road.lanes_total.value, 4);
  EXPECT_NEAR(r.road.speed_limit_mps.value, 30 * 0.44704, 0.01);
}
TEST(NarrativeExtractorTest, TheMakeBeforeAnUnnumberedModelYearNamesTheVehicle) {
  // "the buick, a 1997 century": v1, called "the buick" after; its coded
  // critical event without "this vehicle" is still its own.
  const AccidentRecord r = kExtractor.Extract(
      "The Buick, a 1997 Century, was eastbound in the curb lane and slowed to make a left. The Chevrolet, a 2005 "
      "Malibu, was eastbound in the inside lane behind and to the left of the Buick. As the Buick angled left across "
      "the inside lane, the front of the Malibu struck the left side of the Buick in the intersection. The Buick's "
      "critical precrash event was turning left at the intersection.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_EQ(r.crash.struck.value, "V1");
  EXPECT_EQ(r.crash.type.value, CrashType::kTurnAcrossPath);
}
TEST(NarrativeExtractorTest, WordsThatOnlyLookLikeAStopOrAPersonLeaveTheMovement) {
  // Vans neighbours say park at a corner are not the vehicle parked.
  const AccidentRecord r = kExtractor.Extract(
      "Vehicle #2 was southbound, stopped at the stop sign, and turned left to go east. Vehicle #1 was westbound on "
      "the through street. The front of vehicle #1 struck the left side of vehicle #2. The driver of vehicle #1 said "
      "he braked. Neighbors said vans parked at that corner are a recurring complaint.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
  // A hospital's road is a road, not a sentence about people.
  const AccidentRecord h = kExtractor.Extract(
      "Vehicle one was southbound and stopped in the left-turn lane waiting for a gap to turn east into the hospital "
      "road. Vehicle two was northbound in the through lane. Vehicle one began its turn and the front of vehicle one "
      "struck the left side of vehicle two.");
  ASSERT_EQ(h.vehicles.size(), 2u);
  EXPECT_EQ(h.vehicles[0].pre_event.value, Movement::kStopped);
  // Nor is a vehicle's driver told by age and trade.
  const AccidentRecord d = kExtractor.Extract(
      "Vehicle 1, a 1995 Ford Crown Victoria driven by a 67-year-old retired farmer, was westbound and stopped to "
      "turn left. Vehicle 2 was westbound behind it and struck the rear of Vehicle 1.");
  ASSERT_EQ(d.vehicles.size(), 2u);
  EXPECT_EQ(d.vehicles[0].travel.value, Compass::kWest);
  EXPECT_EQ(d.vehicles[0].pre_event.value, Movement::kStopped);
}
TEST(NarrativeExtractorTest, AnOffRampTerminalIsAJunction) {
  const AccidentRecord r = kExtractor.Extract(
      "The crash occurred at the terminal of a freeway off-ramp, where the one-way ramp ends in a T with a two-lane "
      "state route. V1 exited the freeway and stopped at the end of the ramp to turn left. V2 was southbound on the "
      "state route with its right turn signal on; its driver meant to turn into a gas station beyond the ramp. V1 "
      "pulled out and the front of V2 struck the left side of V1.");
  EXPECT_EQ(r.crash.location.value, CrashLocation::kJunction);
}
TEST(NarrativeExtractorTest, AReportThatCallsTheCrashHeadOnIsHeadOn) {
  const AccidentRecord r = kExtractor.Extract(
      "This head-on crash occurred on a rural two-lane highway. V2 was southbound and its rear slid out in the curve; "
      "it rotated across the center line into the northbound lane. V1 was northbound. The front of V1 struck the "
      "right side of V2.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.crash.type.value, CrashType::kHeadOn);
}
TEST(NarrativeExtractorTest, AListOfVehiclesAllBrakingAreEachSlowing) {
  const AccidentRecord r = kExtractor.Extract(
      "Vehicle 4, Vehicle 3, and Vehicle 2 were eastbound in lane three in that order, all braking. Vehicle 1 was "
      "following in lane three and the front of V1 struck the rear of V2. V2 was driven into the rear of V3, and V3 "
      "into the rear of V4.");
  ASSERT_EQ(r.vehicles.size(), 4u);
  EXPECT_EQ(r.vehicles[2].pre_event.value, Movement::kSlowing);
  EXPECT_EQ(r.vehicles[3].pre_event.value, Movement::kSlowing);
}
TEST(NarrativeExtractorTest, ManoeuvresTheRulesNowRead) {
  // Along a short acceleration lane: a merge.
  const AccidentRecord m = kExtractor.Extract(
      "Vehicle 1 came down the entrance ramp and accelerated along the short acceleration lane. Vehicle 2 was "
      "eastbound in lane one. As Vehicle 1 moved left into lane one, its left side contacted the right side of "
      "Vehicle 2.");
  ASSERT_EQ(m.vehicles.size(), 2u);
  EXPECT_EQ(m.vehicles[0].pre_event.value, Movement::kMerging);
  EXPECT_EQ(m.crash.type.value, CrashType::kTurnIntoPath);
  // A contractor's trailer parked by the drive is not the backing vehicle parked.
  const AccidentRecord b = kExtractor.Extract(
      "V1 was backing out of a residential driveway. A contractor's trailer parked at the curb blocked the view. V2 "
      "was eastbound and struck the left side of V1 with its front.");
  ASSERT_EQ(b.vehicles.size(), 2u);
  EXPECT_EQ(b.vehicles[0].pre_event.value, Movement::kBacking);
  // A vehicle in the left-turn lane that swung into its turn turned left.
  const AccidentRecord t = kExtractor.Extract(
      "V1 was northbound in the left-turn lane. Its driver said the green arrow was lit, so she kept moving and swung "
      "into her turn toward the west leg. V2 was southbound and ran the red light. The front of V2 struck the right "
      "side of V1.");
  ASSERT_EQ(t.vehicles.size(), 2u);
  EXPECT_EQ(t.vehicles[0].movement.value, Movement::kTurnLeft);
  // Backing into a parking space is entering a parking position.
  const AccidentRecord p = kExtractor.Extract(
      "V2 pulled up beside an open space, stopped, shifted into reverse and began backing in. V1 had stopped behind "
      "her. The rear bumper of V2 struck the front of V1.");
  ASSERT_EQ(p.vehicles.size(), 2u);
  EXPECT_EQ(p.vehicles[1].movement.value, Movement::kBacking);
  EXPECT_EQ(p.vehicles[1].pre_event.value, Movement::kMerging);
  // A turn out of a drive is the turner's own, though it ends up going the other's way.
  const AccidentRecord d = kExtractor.Extract(
      "V2 left a gas station and exited in one continuous sweeping right turn, heading east. V1 was eastbound in "
      "lane one. The front of V1 struck the left side of V2. V2's critical precrash event was coded as this vehicle "
      "traveling, turning right.");
  ASSERT_EQ(d.vehicles.size(), 2u);
  EXPECT_EQ(d.vehicles[1].pre_event.value, Movement::kTurnRight);
}
TEST(NarrativeExtractorTest, AQueueThatMovedOffTookItsStoppedVehiclesWithIt) {
  const AccidentRecord r = kExtractor.Extract(
      "V2 and V1 were stopped in a queue about 20 m back from a red signal, in the right eastbound lane. The light "
      "turned green and the queue began to move. V2 pulled away slowly. The front of V1 ran into the rear of V2.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
  EXPECT_EQ(r.crash.location.value, CrashLocation::kJunction);
}
TEST(NarrativeExtractorTest, ANoncontactVehicleInAnUnnumberedReportIsNotAParticipant) {
  const AccidentRecord r = kExtractor.Extract(
      "The case vehicle was northbound on a two-lane rural road. A dark pickup pulled out of a farm driveway ahead "
      "of it. The driver braked and steered right, the car slid, and its front struck a wooden fence. The pickup "
      "did not stop. No critical reason was coded to the case vehicle, since the non-contact pickup's entry was the "
      "cause.");
  EXPECT_EQ(r.participant_count.value, 1);
  EXPECT_EQ(r.crash.type.value, CrashType::kSingleVehicle);
}
TEST(NarrativeExtractorTest, OneSidesCountAfterAColonIsPerDirection) {
  const AccidentRecord r = kExtractor.Extract(
      "Interstate, eastbound side: two lanes, separated from the westbound lanes by a wide grass median, posted 70 "
      "mph. V1 was eastbound in lane one. V2 was in the left lane and moved right; the right side of V2 struck the "
      "left side of V1.");
  EXPECT_EQ(r.road.lanes_per_direction.value, 2);
}
TEST(NarrativeExtractorTest, APickupIsTheTruckInTheOtherDriversWordsUnlessATruckTookPart) {
  const AccidentRecord r = kExtractor.Extract(
      "V1, a 2004 Honda Civic, was traveling north. V2, a 1993 Ford F-250 pickup, was traveling south and had "
      "stopped waiting to turn left into a farm lane. V2 began its left turn and the front of V1 struck the right "
      "side of V2. The driver of V1 stated that the truck 'just turned right in front of me'.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
  EXPECT_EQ(r.crash.type.value, CrashType::kTurnAcrossPath);
  // With a dump truck in the crash, "the truck" stays the dump truck's.
  const AccidentRecord s = kExtractor.Extract(
      "Traffic had stopped. V2, a 2005 Chevrolet Colorado pickup, was stopped first in line. V1, a 2001 "
      "International 4900 dump truck, approached. The front of the truck struck the rear of V2.");
  ASSERT_EQ(s.vehicles.size(), 2u);
  EXPECT_EQ(s.crash.striking.value, "V1");
  EXPECT_EQ(s.crash.type.value, CrashType::kRearEnd);
}
TEST(NarrativeExtractorTest, AHabitGivenUpIsNoStop) {
  const AccidentRecord r = kExtractor.Extract(
      "V1 was traveling east. V2 was traveling west. V1 drifted across the centerline and its front struck the "
      "front of V2. His family stated he had recently stopped taking his medication.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[0].pre_event.value, Movement::kStraight);
}
TEST(NarrativeExtractorTest, ALegOfTheJunctionRunsToItsSide) {
  const AccidentRecord r = kExtractor.Extract(
      "The crash occurred at a T-intersection. The north/south roadway was a four-lane, two-way undivided roadway "
      "with a posted speed limit of 40 MPH. The west leg was a two-lane, two-way roadway with a posted speed limit "
      "of 30 MPH. V1 was traveling eastbound on the west leg and turned right. V2 was southbound. The front of V2 "
      "struck the left side of V1.");
  EXPECT_EQ(r.road.lanes_total.value, 2);
  EXPECT_NEAR(r.road.speed_limit_mps.value, 30 * 0.44704, 1e-6);
}
TEST(NarrativeExtractorTest, ASignalTurningGreenAndTheVehicleGoingIsAStart) {
  const AccidentRecord r = kExtractor.Extract(
      "V2 was stopped northbound at the red signal intending to turn left. V1 was traveling eastbound. V2's signal "
      "turned green and V2 proceeded into the intersection and began to turn left. V1 entered against the red and "
      "the front of V1 struck the left side of V2.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.vehicles[1].pre_event.value, Movement::kStraight);  // NASS "starting in traffic lane"
  const AccidentRecord s = kExtractor.Extract(
      "V1 was traveling east and stopped at the stop sign intending to turn left. V2 was traveling west and stopped "
      "at the stop sign intending to go straight. Both vehicles started from their stop signs at about the same "
      "time. V1 turned left and the front of V2 struck the right front of V1.");
  ASSERT_EQ(s.vehicles.size(), 2u);
  EXPECT_EQ(s.vehicles[1].pre_event.value, Movement::kStraight);
}
TEST(NarrativeExtractorTest, AnOddLaneCountOnADividedRoadIsOneSides) {
  const AccidentRecord r = kExtractor.Extract(
      "V1 was traveling northbound in lane two of a three-lane, divided, dry concrete interstate highway. A concrete "
      "median barrier separated the northbound and southbound lanes. V2 was northbound in lane one. V1 changed "
      "lanes to the right and its right side contacted the left side of V2.");
  EXPECT_TRUE(r.road.divided.value);
  EXPECT_EQ(r.road.lanes_per_direction.value, 3);
}
TEST(NarrativeExtractorTest, PoliceShorthandForSidesRoutesAndDriversIsRead) {
  const AccidentRecord r = kExtractor.Extract(
      "Veh 1 (2001 Ford Taurus) was stopped at the stop sign on Millbrook Rd (2 lanes, 25 mph) at the T-int with "
      "SR 14, waiting to turn L to go WB. Veh 2 (2004 Chevrolet Trailblazer) was EB on SR 14 (2 lanes, 45 mph, no "
      "control) when Veh 1 pulled out, and the front of Veh 2 struck the L side of Veh 1. D-1 stated he looked "
      "but never saw Veh 2.");
  ASSERT_EQ(r.vehicles.size(), 2u);
  EXPECT_EQ(r.road.kind.value, RoadKind::kTJunction);
  EXPECT_EQ(r.crash.location.value, CrashLocation::kJunction);
  EXPECT_EQ(r.crash.struck_area.value, DamageArea::kLeft);
  EXPECT_EQ(r.vehicles[0].movement.value, Movement::kTurnLeft);
  EXPECT_FALSE(r.vehicles[0].travel.value.has_value());  // westbound is where the turn would take it
  EXPECT_EQ(r.crash.type.value, CrashType::kTurnIntoPath);  // from the side road, held by its stop sign
  EXPECT_NEAR(r.road.speed_limit_mps.value, 25 * 0.44704, 1e-6);
  const AccidentRecord s = kExtractor.Extract(
      "V1 (2004 Toyota Camry) NB on Rte 9 slowed and turned L onto Hollis Ln across the path of V2 (1997 Jeep "
      "Cherokee), SB on Rte 9. V2 braked hard and its front struck the R side of V1. Rte 9 2 lanes, 45 mph.");
  ASSERT_EQ(s.vehicles.size(), 2u);
  EXPECT_EQ(s.vehicles[1].travel.value, Compass::kSouth);
  EXPECT_EQ(s.crash.type.value, CrashType::kTurnAcrossPath);
  EXPECT_EQ(s.crash.struck_area.value, DamageArea::kRight);
  const AccidentRecord t = kExtractor.Extract(
      "Unit 1 (2000 Honda Accord) was SB in lane 1 of Walnut St, a 2-lane one-way, when unit 2, WB on Church St "
      "(2-way, 2 lanes), failed to stop for the stop sign and entered the intersection. The front of unit 1 struck "
      "the R side of unit 2. Both streets 30 mph; night, clear, dry.");
  EXPECT_NEAR(t.road.speed_limit_mps.value, 30 * 0.44704, 1e-6);
}
TEST(NarrativeExtractorTest, ALimitInBracketsAfterTheRoadV1MeetsIsThatRoads) {
  const AccidentRecord r = kExtractor.Extract(
      "V1 was southbound on a two-lane side street and stopped at a stop sign at its intersection with an "
      "east-west, four-lane undivided arterial (two lanes each way, 35 mph/56 km/h). The side street is posted 25 "
      "mph. V1 pulled out to turn left. V2 was westbound and struck the left side of V1 with its front.");
  EXPECT_NEAR(r.road.speed_limit_mps.value, 25 * 0.44704, 1e-6);
  EXPECT_EQ(r.road.speed_limit_unit.value, "mph");
}
TEST(NarrativeExtractorTest, AVehiclesSpeedInItsLaneIsNoLimit) {
  const AccidentRecord r = kExtractor.Extract(
      "V1 was northbound on a 4-lane undivided road posted at 35 mph. V2 was ahead of V1. The driver of V2 stated "
      "she was going straight in the right lane at about 20 mph and braked when the light changed. The front of V1 "
      "struck the back of V2.");
  EXPECT_NEAR(r.road.speed_limit_mps.value, 35 * 0.44704, 1e-6);
}
}  // namespace
}  // namespace accsim
