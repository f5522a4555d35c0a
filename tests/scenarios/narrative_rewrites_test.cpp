#include "accsim/scenarios/narrative_rewrites.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accsim/scenarios/narrative_extractor.h"

namespace accsim {
namespace {

TEST(NarrativeRewritesTest, EachRewriteSaysTheSameInOtherWords) {
  const std::string text =
      "V1, a 2000 Ford Taurus, was traveling north on a two-lane roadway posted at 48 km/h (30 mph). Vehicle #2, a "
      "2003 Honda Civic, was stopped in the center of the road. The front of V1 struck the back of Vehicle 2.";
  EXPECT_EQ(RewriteNarrative("V1 struck V2.", "vehicle-words"), "Vehicle one struck Vehicle two.");
  EXPECT_EQ(RewriteNarrative("Vehicle #1 struck vehicle 2 and Vehicle three.", "vehicle-numbers"), "V1 struck V2 and V3.");
  EXPECT_EQ(RewriteNarrative("posted at 48 km/h (30 mph) and 45 MPH (72 KPH)", "mph-only"), "posted at 30 mph and 45 mph");
  EXPECT_EQ(RewriteNarrative("posted at 30 mph (48 km/h); about 45 mph", "kmh-only"), "posted at 48 km/h; about 72 km/h");
  EXPECT_EQ(RewriteNarrative("a two-lane road with four lanes", "lane-digits"), "a 2-lane road with 4 lanes");
  EXPECT_EQ(RewriteNarrative("a 2-lane road with 4 lanes", "lane-words"), "a two-lane road with four lanes");
  EXPECT_EQ(RewriteNarrative("The roadway was dry; the roadways met.", "road"), "The road was dry; the roadways met.");
  EXPECT_EQ(RewriteNarrative("V1 was northbound and struck V2, which had stopped.", "present-tense"),
            "V1 is northbound and strikes V2, which has stopped.");
  EXPECT_EQ(RewriteNarrative("traveling in the center lane", "british"), "travelling in the centre lane");
  EXPECT_EQ(RewriteNarrative("V1 was Northbound, V2 southbound", "compass-abbreviations"), "V1 was NB, V2 SB");
  EXPECT_EQ(RewriteNarrative("V1 was eastbound.", "upper"), "V1 WAS EASTBOUND.");
  EXPECT_EQ(RewriteNarrative(text, "makes"),
            "V1, a 2000 Ford Taurus, was traveling north on a two-lane roadway posted at 48 km/h (30 mph). Vehicle #2, "
            "a 2003 Honda Civic, was stopped in the center of the road. The front of the Ford struck the back of "
            "Vehicle 2.");
  // Two vehicles of one make cannot be told apart by it: unchanged.
  const std::string same = "V1, a 2000 Ford Taurus, and V2, a 2001 Ford Focus, met. V1 struck V2.";
  EXPECT_EQ(RewriteNarrative(same, "makes"), same);
  EXPECT_EQ(NarrativeRewrites().size(), 12u);
}

TEST(NarrativeRewritesTest, AnUnknownRewriteNamesTheKnownOnes) {
  try {
    RewriteNarrative("V1 struck V2.", "pig-latin");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("pig-latin"), std::string::npos);
    EXPECT_NE(what.find("present-tense"), std::string::npos);
  }
}

// What the six scored attributes are read from, with the limit to the km/h.
std::string Projection(const AccidentRecord& r) {
  std::string p = std::to_string(r.road.lanes_total.value) + "/" + std::to_string(r.road.lanes_per_direction.value) +
                  (r.road.divided.value ? " divided" : "") + (r.road.one_way.value ? " one-way" : "") + " limit " +
                  (r.road.speed_limit_mps.known() ? std::to_string(std::lround(r.road.speed_limit_mps.value * 3.6)) : "-") +
                  " location " + std::to_string(static_cast<int>(r.crash.location.value)) + " type " +
                  std::to_string(static_cast<int>(r.crash.type.value)) + " n " + std::to_string(r.participant_count.value);
  for (const auto& v : r.vehicles) p += " " + v.id + ":" + std::to_string(static_cast<int>(v.pre_event.value));
  return p;
}

// The development set's reports read the same through every rewrite:
// the rules read facts, not one writer's wording.
TEST(NarrativeRewritesTest, TheRecordDoesNotHangOnTheWording) {
  std::ifstream in(std::string(ACCSIM_SHARED_DIR) + "/data/narratives/nmvccs/labels.jsonl");
  ASSERT_TRUE(in);
  std::vector<std::string> narratives;  // every third report: 25 of the 75, all three kinds of place
  int row = 0;
  for (std::string line; std::getline(in, line); ++row) {
    if (row % 3 == 2) narratives.push_back(nlohmann::json::parse(line).at("narrative").get<std::string>());
  }
  ASSERT_EQ(narratives.size(), 25u);
  const NarrativeExtractor extractor;
  std::vector<std::string> plain;
  for (const auto& n : narratives) plain.push_back(Projection(extractor.Extract(n)));
  for (const auto& rewrite : NarrativeRewrites()) {
    int changed_texts = 0;
    for (size_t i = 0; i < narratives.size(); ++i) {
      const std::string text = RewriteNarrative(narratives[i], rewrite.name);
      changed_texts += text != narratives[i];
      EXPECT_EQ(Projection(extractor.Extract(text)), plain[i]) << rewrite.name << ", report " << i;
    }
    EXPECT_GT(changed_texts, 0) << rewrite.name << " changed none of the reports";
  }
}

}  // namespace
}  // namespace accsim
