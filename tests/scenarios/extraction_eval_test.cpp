#include "accsim/scenarios/extraction_eval.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <fstream>

namespace accsim {
namespace {

// Each attribute at least its floor (a little under the measured figure: a drop is a regression).
void ExpectAtLeast(const ExtractionScore& s, const std::map<std::string, double>& floors) {
  for (const auto& [attribute, floor] : floors) EXPECT_GE(s.attributes.at(attribute), floor) << attribute;
}

TEST(ExtractionEvalTest, ScoresTheDevelopmentSetOnSixAttributes) {
  const ExtractionScore s =
      EvaluateExtraction(std::string(ACCSIM_SHARED_DIR) + "/data/narratives/nmvccs", NarrativeExtractor{});
  EXPECT_EQ(s.n, 75);
  ASSERT_EQ(s.attributes.size(), 6u);
  ExpectAtLeast(s, {{"participant_count", 0.98}, {"speed_limit", 0.95}, {"lane_count", 0.95},
                   {"collision_location", 0.93}, {"driving_actions", 0.86}, {"crash_type", 0.96}});
  for (const auto& a : ExtractionAttributes()) EXPECT_EQ(s.scored.at(a), 75) << a;
  EXPECT_EQ(s.group_sizes.size(), 3u);
  EXPECT_EQ(ToJson(s)["n"], 75);
}

TEST(ExtractionEvalTest, ReadsTheCirenLayoutToo) {
  const ExtractionScore s =
      EvaluateExtraction(std::string(ACCSIM_SHARED_DIR) + "/data/narratives/ciren", NarrativeExtractor{});
  EXPECT_EQ(s.n, 20);
  EXPECT_EQ(s.scored.at("participant_count"), 20);
  EXPECT_GT(s.scored.at("crash_type"), 10);  // codes 98 (other) are not scored
  EXPECT_GE(s.attributes.at("participant_count"), 0.95);
  EXPECT_GE(s.attributes.at("speed_limit"), 0.70);  // never stated there: the road-class prior
}

// Reports in six other styles (police ALL CAPS, "Unit 1", first-person
// claims, news, British/metric wording, terse CIREN-like), written and
// labelled apart from the rules; docs/extraction.md gives the figures.
TEST(ExtractionEvalTest, ReadsReportsInOtherStyles) {
  const ExtractionScore s =
      EvaluateExtraction(std::string(ACCSIM_SOURCE_DIR) + "/tests/data/report_styles", NarrativeExtractor{});
  EXPECT_EQ(s.n, 36);
  EXPECT_EQ(s.extra.count("impact_areas"), 0U);  // no row codes its events: nothing to score, no 0 %
  ExpectAtLeast(s, {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.94},
                   {"collision_location", 0.97}, {"driving_actions", 0.91}, {"crash_type", 0.97}});
}

// Invented reports in the NMVCCS researchers' own style, each set by its own
// hands, labelled in NASS terms without reading the rules; each was first
// scored after the fixes for the sets before it (docs/extraction.md gives
// every first look). Set A's labeller codes a turner or a lane changer by its
// own manoeuvre, and A's, B's, D's and F's a lead vehicle struck while braking
// as decelerating; the real NMVCCS coding, which the rules follow, does not
// (crossing/23, straight/17), hence their lower driving-action floors; AT's
// and AW's code turns and lane changes by what the vehicle did, hence theirs.
TEST(ExtractionEvalTest, ReadsNewReportsInTheNmvccsStyle) {
  struct Set {
    const char* dir;
    int n;
    std::map<std::string, double> floors;
  };
  const Set sets[] = {
      {"nmvccs_style", 45,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.95},
        {"collision_location", 0.97}, {"driving_actions", 0.82}, {"crash_type", 0.95}}},
      {"nmvccs_style_b", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.97},
        {"collision_location", 0.97}, {"driving_actions", 0.92}, {"crash_type", 0.97}}},
      {"nmvccs_style_c", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.92}, {"lane_count", 0.97},
        {"collision_location", 0.92}, {"driving_actions", 0.90}, {"crash_type", 0.95}}},
      {"nmvccs_style_d", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.90}, {"lane_count", 0.90},
        {"collision_location", 0.92}, {"driving_actions", 0.78}, {"crash_type", 0.97}}},
      {"nmvccs_style_e", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.95}, {"lane_count", 0.95},
        {"collision_location", 0.97}, {"driving_actions", 0.94}, {"crash_type", 0.97}}},
      {"nmvccs_style_f", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.95},
        {"collision_location", 0.95}, {"driving_actions", 0.84}, {"crash_type", 0.92}}},
      {"nmvccs_style_g", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.97},
        {"collision_location", 0.97}, {"driving_actions", 0.92}, {"crash_type", 0.92}}},
      {"nmvccs_style_i", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.97},
        {"collision_location", 0.97}, {"driving_actions", 0.92}, {"crash_type", 0.95}}},
      {"nmvccs_style_j", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.97},
        {"collision_location", 0.97}, {"driving_actions", 0.92}, {"crash_type", 0.92}}},
      {"nmvccs_style_l", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.95}, {"lane_count", 0.95},
        {"collision_location", 0.95}, {"driving_actions", 0.85}, {"crash_type", 0.97}}},
      {"nmvccs_style_m", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.92},
        {"collision_location", 0.95}, {"driving_actions", 0.80}, {"crash_type", 0.87}}},
      {"nmvccs_style_q", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.95}, {"lane_count", 0.97},
        {"collision_location", 0.95}, {"driving_actions", 0.85}, {"crash_type", 0.97}}},
      {"nmvccs_style_s", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.95}, {"lane_count", 0.97},
        {"collision_location", 0.97}, {"driving_actions", 0.87}, {"crash_type", 0.92}}},
      {"nmvccs_style_t", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.95}, {"lane_count", 0.95},
        {"collision_location", 0.95}, {"driving_actions", 0.85}, {"crash_type", 0.97}}},
      {"nmvccs_style_u", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.95}, {"lane_count", 0.95},
        {"collision_location", 0.95}, {"driving_actions", 0.89}, {"crash_type", 0.95}}},
      {"nmvccs_style_n", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.95}, {"lane_count", 0.97},
        {"collision_location", 0.95}, {"driving_actions", 0.83}, {"crash_type", 0.97}}},
      {"nmvccs_style_w", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.97},
        {"collision_location", 0.97}, {"driving_actions", 0.91}, {"crash_type", 0.95}}},
      {"nmvccs_style_x", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.97},
        {"collision_location", 0.97}, {"driving_actions", 0.86}, {"crash_type", 0.97}}},
      {"nmvccs_style_y", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.95},
        {"collision_location", 0.97}, {"driving_actions", 0.92}, {"crash_type", 0.92}}},
      {"nmvccs_style_o", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.95},
        {"collision_location", 0.92}, {"driving_actions", 0.85}, {"crash_type", 0.92}}},
      {"nmvccs_style_aa", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.95}, {"lane_count", 0.95},
        {"collision_location", 0.97}, {"driving_actions", 0.90}, {"crash_type", 0.92}}},
      {"nmvccs_style_ac", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.95}, {"lane_count", 0.95},
        {"collision_location", 0.95}, {"driving_actions", 0.92}, {"crash_type", 0.95}}},
      {"nmvccs_style_ae", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.95},
        {"collision_location", 0.97}, {"driving_actions", 0.85}, {"crash_type", 0.95}}},
      {"nmvccs_style_ag", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.95}, {"lane_count", 0.97},
        {"collision_location", 0.97}, {"driving_actions", 0.85}, {"crash_type", 0.97}}},
      {"nmvccs_style_ah", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.97},
        {"collision_location", 0.97}, {"driving_actions", 0.90}, {"crash_type", 0.95}}},
      {"nmvccs_style_aj", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.95},
        {"collision_location", 0.97}, {"driving_actions", 0.87}, {"crash_type", 0.95}}},
      {"nmvccs_style_al", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.97},
        {"collision_location", 0.97}, {"driving_actions", 0.92}, {"crash_type", 0.95}}},
      {"nmvccs_style_am", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.95}, {"lane_count", 0.97},
        {"collision_location", 0.97}, {"driving_actions", 0.80}, {"crash_type", 0.92}}},
      {"nmvccs_style_an", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.92},
        {"collision_location", 0.97}, {"driving_actions", 0.90}, {"crash_type", 0.97}}},
      {"nmvccs_style_ap", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.97},
        {"collision_location", 0.95}, {"driving_actions", 0.87}, {"crash_type", 0.97}}},
      {"nmvccs_style_aq", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.95},
        {"collision_location", 0.95}, {"driving_actions", 0.90}, {"crash_type", 0.92}}},
      {"nmvccs_style_as", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.97},
        {"collision_location", 0.95}, {"driving_actions", 0.87}, {"crash_type", 0.95}}},
      // (Crash type 0.94: a merge out of the acceleration lane is coded turn
      // into path, as the real coding has the ramp merge; this set's
      // labeller coded one as a sideswipe.)
      {"nmvccs_style_at", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.95}, {"lane_count", 0.97},
        {"collision_location", 0.92}, {"driving_actions", 0.80}, {"crash_type", 0.94}}},
      {"nmvccs_style_au", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.95},
        {"collision_location", 0.97}, {"driving_actions", 0.87}, {"crash_type", 0.95}}},
      {"nmvccs_style_aw", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.95}, {"lane_count", 0.97},
        {"collision_location", 0.97}, {"driving_actions", 0.75}, {"crash_type", 0.92}}},
      {"nmvccs_style_ax", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.95},
        {"collision_location", 0.97}, {"driving_actions", 0.87}, {"crash_type", 0.95}}},
      {"nmvccs_style_az", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.95},
        {"collision_location", 0.95}, {"driving_actions", 0.82}, {"crash_type", 0.92}}},
      {"nmvccs_style_ba", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.97},
        {"collision_location", 0.97}, {"driving_actions", 0.87}, {"crash_type", 0.92}}},
      {"nmvccs_style_bc", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.95}, {"lane_count", 0.87},
        {"collision_location", 0.97}, {"driving_actions", 0.78}, {"crash_type", 0.92}}},
      {"nmvccs_style_bd", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.92},
        {"collision_location", 0.97}, {"driving_actions", 0.80}, {"crash_type", 0.89}}},
      {"nmvccs_style_bf", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.97},
        {"collision_location", 0.97}, {"driving_actions", 0.83}, {"crash_type", 0.95}}},
      // (Lane count 0.75: the ramp's lanes for a vehicle at the ramp's
      // terminal, and turn lanes on divided arterials, are read as the
      // arterial's through lanes.)
      {"nmvccs_style_bg", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.75},
        {"collision_location", 0.92}, {"driving_actions", 0.82}, {"crash_type", 0.87}}},
      {"nmvccs_style_bi", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.97},
        {"collision_location", 0.97}, {"driving_actions", 0.87}, {"crash_type", 0.90}}},
      // (Written to the pre-event movements: its labeller codes lane
      // changes, passes and merges that are the critical event as the
      // movement, where the development set codes what came before, and a
      // pull out of a parallel space as a lane change, where the other sets
      // code a turn across the path.)
      {"nmvccs_style_bj", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.92},
        {"collision_location", 0.87}, {"driving_actions", 0.68}, {"crash_type", 0.70}}},
      {"nmvccs_style_bl", 40,
       {{"participant_count", 0.97}, {"speed_limit", 0.97}, {"lane_count", 0.95},
        {"collision_location", 0.95}, {"driving_actions", 0.86}, {"crash_type", 0.87}}},
      // (Short texts: terse summaries and descriptions a member of the
      // public types, many with no vehicle numbers, some with no lane count
      // or limit, persons for vehicles: "the guy on my right", "someone
      // turning left".)
      {"nmvccs_style_bm", 40,
       {{"participant_count", 0.82}, {"speed_limit", 0.85}, {"lane_count", 0.87},
        {"collision_location", 0.80}, {"driving_actions", 0.75}, {"crash_type", 0.67}}},
  };
  for (const Set& set : sets) {
    SCOPED_TRACE(set.dir);
    const ExtractionScore s =
        EvaluateExtraction(std::string(ACCSIM_SOURCE_DIR) + "/tests/data/" + set.dir, NarrativeExtractor{});
    EXPECT_EQ(s.n, set.n);
    ExpectAtLeast(s, set.floors);
  }
}

// Invented CIREN case summaries in the CIREN layout (limits often unstated,
// as in the real ones: the floor on speed limit is the prior's). K's labeller
// codes a case vehicle that stopped and then turned as stopped, the NMVCCS
// habit; the real CIREN coding, which the rules follow, codes its turn
// (119489), hence K's lower driving-action floor.
TEST(ExtractionEvalTest, ReadsNewReportsInTheCirenStyle) {
  const std::map<std::string, double> floors = {{"participant_count", 0.97}, {"speed_limit", 0.78},
                                                {"lane_count", 0.95},        {"collision_location", 0.95},
                                                {"driving_actions", 0.90},   {"crash_type", 0.92}};
  for (const char* dir : {"ciren_style", "ciren_style_k", "ciren_style_p", "ciren_style_r", "ciren_style_v", "ciren_style_z",
                          "ciren_style_ab", "ciren_style_ad", "ciren_style_af",
                          "ciren_style_ai", "ciren_style_ak", "ciren_style_ao", "ciren_style_ar",
                          "ciren_style_av", "ciren_style_ay", "ciren_style_bb", "ciren_style_be", "ciren_style_bh",
                          "ciren_style_bk", "ciren_style_bn"}) {
    SCOPED_TRACE(dir);
    const ExtractionScore s =
        EvaluateExtraction(std::string(ACCSIM_SOURCE_DIR) + "/tests/data/" + dir, NarrativeExtractor{});
    EXPECT_EQ(s.n, 30);
    auto own = floors;
    if (std::string(dir) == "ciren_style_k") own["driving_actions"] = 0.60;
    if (std::string(dir) == "ciren_style_ab") own["lane_count"] = 0.92;
    if (std::string(dir) == "ciren_style_bh") own["driving_actions"] = 0.83;  // a pass and a lane change coded as the manoeuvre
    if (std::string(dir) == "ciren_style_bn") {
      own["driving_actions"] = 0.86;  // passes, lane changes and slowing leads coded as the manoeuvre
      own["collision_location"] = 0.92;
    }
    ExpectAtLeast(s, own);
  }
}

TEST(ExtractionEvalTest, ScoresEachLabelAsDocumented) {
  const std::string dir = ::testing::TempDir() + "/eval_mapping";
  std::filesystem::create_directories(dir);
  const nlohmann::json row = {
      {"file", "t/0.xml"},
      {"vehcount", "2"},
      {"narrative",
       "The crash occurred at a T-intersection of two two-lane undivided roads with a posted speed limit of 35 mph. "
       "V1 was traveling east and turned left. V2 was traveling west. The front of V2 struck the right side of V1."},
      {"vehicles",
       {{{"speed_limit_kmph", "56"}, {"num_travel_lanes_code", "2"}, {"relation_to_junction", "Intersection"},
         {"pre_event_movement", "Turning left"}, {"crash_type_code", "68"}},
        {{"speed_limit_kmph", "56"}, {"num_travel_lanes_code", "2"}, {"relation_to_junction", "Intersection"},
         {"pre_event_movement", "Going straight"}, {"crash_type_code", "69"}}}},
      {"events", {{{"striker_vehicle", "1"}, {"striker_area_damage", "Right Side"}, {"object_hit", "Vehicle#2"},
                   {"hit_area_damage", "Front"}}}}};
  std::ofstream(dir + "/labels.jsonl") << row.dump() << "\n";
  const ExtractionScore s = EvaluateExtraction(dir, NarrativeExtractor{});
  for (const auto& a : ExtractionAttributes()) EXPECT_EQ(s.attributes.at(a), 1.0) << a;
  EXPECT_EQ(s.extra.at("impact_areas"), 1.0);
  EXPECT_EQ(s.group_sizes.at("t"), 1);
}

// One labelled case in a temporary folder.
ExtractionScore ScoreOne(const std::string& name, const nlohmann::json& row) {
  const std::string dir = ::testing::TempDir() + "/" + name;
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/labels.jsonl") << row.dump() << "\n";
  return EvaluateExtraction(dir, NarrativeExtractor{});
}

TEST(ExtractionEvalTest, CodedVehiclesArePairedByTheirNumberNotTheirOrder) {
  // The labels list V2 first; V1 stopped, V2 struck it from behind.
  const nlohmann::json row = {
      {"vehcount", "2"},
      {"narrative",
       "V1 was stopped in the eastbound lane of a two-lane road with a posted speed limit of 30 mph. V2 was "
       "traveling east behind V1. The front of V2 struck the rear of V1."},
      {"vehicles",
       {{{"veh_number", "2"}, {"speed_limit_kmph", "80"}, {"pre_event_movement", "Going straight"}},
        {{"veh_number", "1"}, {"speed_limit_kmph", "48"}, {"pre_event_movement", "Stopped in traffic lane"}}}}};
  const ExtractionScore s = ScoreOne("eval_numbers", row);
  EXPECT_EQ(s.attributes.at("driving_actions"), 1.0);
  EXPECT_EQ(s.attributes.at("speed_limit"), 1.0);  // V1's limit, though V2 is listed first
  EXPECT_TRUE(s.pairings.empty());
}

TEST(ExtractionEvalTest, VehiclesNumberedTheOtherWayArePairedByYearMakeAndModel) {
  // The narrative calls the Civic V1; the coded data numbers it 2.
  const nlohmann::json row = {
      {"file", "x/0.xml"},
      {"vehcount", "2"},
      {"narrative",
       "V1, a 2003 Honda Civic, was stopped in the eastbound lane. V2, a 1998 Ford Ranger pickup, was traveling east "
       "behind V1. The front of V2 struck the rear of V1."},
      {"vehicles",
       {{{"veh_number", "1"}, {"model_year", "1998"}, {"make", "FORD"}, {"model", "RANGER"},
         {"pre_event_movement", "Going straight"}},
        {{"veh_number", "2"}, {"model_year", "2003"}, {"make", "HONDA"}, {"model", "CIVIC"},
         {"pre_event_movement", "Stopped in traffic lane"}}}}};
  const ExtractionScore s = ScoreOne("eval_identity", row);
  EXPECT_EQ(s.attributes.at("driving_actions"), 1.0);
  ASSERT_EQ(s.pairings.size(), 2u);
  EXPECT_EQ(s.pairings[0], "x/0.xml: coded V1 is the narrative's V2 (year, make, model)");
  // Without identities the numbers pair them, and both movements are wrong.
  nlohmann::json anonymous = row;
  for (auto& v : anonymous["vehicles"]) v.erase("make"), v.erase("model"), v.erase("model_year");
  EXPECT_EQ(ScoreOne("eval_anonymous", anonymous).attributes.at("driving_actions"), 0.0);
}

TEST(ExtractionEvalTest, LaneCountIsV1sOwnCodeOnly) {
  // V1's road is a side street nobody counted; V2's four lanes are another road's.
  auto row = [](const char* v1_lanes) {
    return nlohmann::json{
        {"vehcount", "2"},
        {"narrative", "V1 was eastbound on a side street. V2 was southbound on a four-lane road. V2 struck V1."},
        {"vehicles",
         {{{"veh_number", "1"}, {"num_travel_lanes_code", v1_lanes}},
          {{"veh_number", "2"}, {"num_travel_lanes_code", "4"}}}}};
  };
  EXPECT_EQ(ScoreOne("eval_v1_lanes_unknown", row("Unknown")).scored.at("lane_count"), 0);
  EXPECT_EQ(ScoreOne("eval_v1_lanes_two", row("2")).scored.at("lane_count"), 1);
}

TEST(ExtractionEvalTest, ABlankLimitIsNotScoredButNoStatutoryLimitIs) {
  auto row = [](const char* limit) {
    return nlohmann::json{{"vehcount", "2"},
                          {"narrative", "V1 was traveling east. V2 was traveling west. V1 struck V2."},
                          {"vehicles", {{{"veh_number", "1"}, {"speed_limit_kmph", limit}}}}};
  };
  EXPECT_EQ(ScoreOne("eval_blank_limit", row("")).scored.at("speed_limit"), 0);
  EXPECT_EQ(ScoreOne("eval_unknown_limit", row("Unknown")).scored.at("speed_limit"), 0);
  const ExtractionScore none = ScoreOne("eval_no_limit", row("No Statutory Limit"));
  EXPECT_EQ(none.scored.at("speed_limit"), 1);
  EXPECT_EQ(none.attributes.at("speed_limit"), 1.0);  // the text states none and names no road class
}

TEST(ExtractionEvalTest, BadFoldersAreNamed) {
  EXPECT_THROW(EvaluateExtraction("/no/such/folder", NarrativeExtractor{}), std::invalid_argument);
  const std::string dir = ::testing::TempDir();
  std::ofstream(dir + "/labels.jsonl") << "{\"narrative\": 3}\n";
  try {
    EvaluateExtraction(dir, NarrativeExtractor{});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("labels.jsonl:1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace accsim
