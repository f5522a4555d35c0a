#include "accsim/eval/safebench.h"

#include <gtest/gtest.h>

#include "accsim/env/scripted_drivers.h"

namespace accsim {
namespace {

std::vector<std::shared_ptr<const Scenario>> Examples() {
  std::vector<std::shared_ptr<const Scenario>> out;
  for (const char* f : {"straight_obstacle", "unprotected_left_turn", "right_turn", "lane_changing"}) {
    out.push_back(std::make_shared<const Scenario>(
        LoadScenarioFile(std::string(ACCSIM_SOURCE_DIR) + "/scenarios/examples/" + f + ".json")));
  }
  return out;
}

TEST(SafeBenchTest, HoldingDriverCollidesEverywhereAndBrakingNowhere) {
  const auto scenarios = Examples();
  const EvaluationReport hold = Evaluate(scenarios, [](const CrashEnv& e) { return HoldPolicy(e); }, "hold");
  const EvaluationReport brake = Evaluate(scenarios, [](const CrashEnv& e) { return BrakePolicy(e); }, "brake");
  EXPECT_EQ(hold.overall.episodes, 4);
  EXPECT_DOUBLE_EQ(hold.overall.collision_rate, 1.0);
  EXPECT_DOUBLE_EQ(brake.overall.collision_rate, 0.0);
  EXPECT_GT(hold.overall.mean_collision_speed, 5.0);
  EXPECT_LT(brake.overall.route_completion, hold.overall.route_completion);
  ASSERT_EQ(hold.cells.size(), 4u);
  EXPECT_EQ(hold.cells.count("lane_changing/many"), 1u);  // four vehicles
  EXPECT_EQ(hold.cells.count("right_turn/two"), 1u);
  const std::string md = ToMarkdown({hold, brake});
  EXPECT_NE(md.find("| **all** | 100.0 %"), std::string::npos) << md;
}

TEST(SafeBenchTest, EmptySuiteIsAnError) {
  EXPECT_THROW(Evaluate({}, [](const CrashEnv& e) { return HoldPolicy(e); }, "hold"), std::invalid_argument);
}

}  // namespace
}  // namespace accsim
