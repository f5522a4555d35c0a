#include "accsim/env/rollout.h"

#include <gtest/gtest.h>

#include <string>

#include "accsim/env/scenario.h"

namespace accsim {
namespace {

std::shared_ptr<const Scenario> Example(const std::string& family) {
  return std::make_shared<const Scenario>(
      LoadScenarioFile(std::string(ACCSIM_SOURCE_DIR) + "/scenarios/examples/" + family + ".json"));
}

class ExampleScenarioTest : public ::testing::TestWithParam<std::string> {};

TEST_P(ExampleScenarioTest, EgoHoldingItsSpeedIsHit) {
  CrashEnv env(CrashEnvConfig{}, {Example(GetParam())});
  const EpisodeResult r = RunEpisode(env, [](const CrashEnv& e) { return HoldPolicy(e); }, 0);
  ASSERT_TRUE(r.collision.has_value()) << GetParam() << " ended with " << r.outcome;
  EXPECT_EQ(r.outcome, "collision");
  EXPECT_GT(r.collision->impulse, 0.0);
  EXPECT_GT(r.collision->relative_speed, 1.0);
}

TEST_P(ExampleScenarioTest, EgoBrakingEarlyIsNotHit) {
  CrashEnv env(CrashEnvConfig{}, {Example(GetParam())});
  const EpisodeResult r = RunEpisode(env, [](const CrashEnv& e) { return BrakePolicy(e, 0.0); }, 0);
  EXPECT_FALSE(r.collision.has_value()) << GetParam() << ": hit by " << r.collision->other_id
                                        << " at t = " << r.collision->time;
  EXPECT_EQ(r.outcome, "time_limit");
}

TEST_P(ExampleScenarioTest, RuleBasedDriverAvoidsTheCrash) {
  CrashEnv env(CrashEnvConfig{}, {Example(GetParam())});
  const EpisodeResult r = RunEpisode(env, [](const CrashEnv& e) { return RuleBasedPolicy(e); }, 0);
  EXPECT_FALSE(r.collision.has_value()) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Families, ExampleScenarioTest,
                         ::testing::Values("straight_obstacle", "unprotected_left_turn", "right_turn",
                                           "lane_changing"));

TEST(RolloutTest, RecordedTrajectoriesAreIdenticalForTheSameSeed) {
  CrashEnvConfig config;
  config.npc_time_jitter = 0.3;
  config.start_speed_jitter = 1.0;
  auto run = [&](uint64_t seed) {
    CrashEnv env(config, {Example("lane_changing")});
    return TrajectoriesJson(RunEpisode(env, [](const CrashEnv& e) { return HoldPolicy(e); }, seed, 0, true))
        .dump();
  };
  EXPECT_EQ(run(7), run(7));
  EXPECT_NE(run(7), run(8));
}

TEST(RolloutTest, SummaryHasTheDocumentedKeys) {
  CrashEnv env(CrashEnvConfig{}, {Example("straight_obstacle")});
  const auto j = SummaryJson(RunEpisode(env, [](const CrashEnv& e) { return HoldPolicy(e); }, 0));
  for (const char* key : {"collision", "time", "bodies", "impulse", "relative_speed", "outcome"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_TRUE(j["collision"].get<bool>());
  EXPECT_EQ(j["bodies"][0], "ego");
  EXPECT_EQ(j["bodies"][1], "stopped_car");
}

}  // namespace
}  // namespace accsim
