#include "accsim/scenarios/extraction_eval.h"

#include <gtest/gtest.h>

#include <fstream>

namespace accsim {
namespace {

TEST(ExtractionEvalTest, ScoresTheDevelopmentSetOnSixAttributes) {
  const ExtractionScore s =
      EvaluateExtraction(std::string(ACCSIM_SHARED_DIR) + "/data/narratives/nmvccs", NarrativeExtractor{});
  EXPECT_EQ(s.n, 75);
  ASSERT_EQ(s.attributes.size(), 6u);
  // Floors at the measured figures (see docs/extraction.md): a drop is a regression.
  EXPECT_GE(s.attributes.at("participant_count"), 0.95);
  EXPECT_GE(s.attributes.at("speed_limit"), 0.80);
  EXPECT_GE(s.attributes.at("lane_count"), 0.70);
  EXPECT_GE(s.attributes.at("collision_location"), 0.60);
  EXPECT_GE(s.attributes.at("driving_actions"), 0.65);
  EXPECT_GE(s.attributes.at("crash_type"), 0.55);
  EXPECT_EQ(s.group_sizes.size(), 3u);
  EXPECT_EQ(ToJson(s)["n"], 75);
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
