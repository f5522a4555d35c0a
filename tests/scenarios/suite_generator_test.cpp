#include "accsim/scenarios/suite_generator.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "accsim/env/rollout.h"

namespace accsim {
namespace {

std::vector<ReportSeed> ExampleSeeds() {
  std::vector<ReportSeed> seeds;
  for (const char* f : {"straight_obstacle", "unprotected_left_turn", "right_turn", "lane_changing"}) {
    seeds.push_back(ReportSeedFromScenario(
        LoadScenarioFile(std::string(ACCSIM_SOURCE_DIR) + "/scenarios/examples/" + f + ".json")));
    seeds.back().source_id = f;
  }
  return seeds;
}

class FamilyCellTest : public ::testing::TestWithParam<std::tuple<ScenarioFamily, VehicleCount>> {};

TEST_P(FamilyCellTest, MostSampledScenariosAreDangerousAndAvoidable) {
  const auto [family, count] = GetParam();
  std::mt19937_64 rng(11);
  const auto seeds = ExampleSeeds();
  int built = 0, kept = 0;
  for (int i = 0; i < 20; ++i) {
    const FamilyParams p = SampleFamilyParams(family, count, seeds[static_cast<size_t>(i) % seeds.size()], rng);
    Scenario s;
    try {
      s = BuildFamilyScenario(p);
    } catch (const std::invalid_argument&) {
      continue;
    }
    ++built;
    const int expected = count == VehicleCount::kTwo ? 2 : count == VehicleCount::kThree ? 3 : 4;
    EXPECT_GE(s.vehicle_count(), expected);
    if (count != VehicleCount::kMany) {
      EXPECT_EQ(s.vehicle_count(), expected);
    }
    EXPECT_EQ(s.family, family);
    // Round trip through JSON: what a suite file holds is loadable.
    EXPECT_NO_THROW(ScenarioFromJson(ToJson(s)));
    const ScenarioCheck c = CheckScenario(s);
    kept += c.dangerous && c.avoidable;
  }
  EXPECT_GE(built, 15);
  // Generation keeps only checked scenarios; the sampler should rarely waste work.
  EXPECT_GE(kept, built / 2) << ToString(family) << "/" << ToString(count) << ": kept " << kept << " of " << built;
}

INSTANTIATE_TEST_SUITE_P(
    Cells, FamilyCellTest,
    ::testing::Combine(::testing::Values(ScenarioFamily::kStraightObstacle, ScenarioFamily::kUnprotectedLeftTurn,
                                         ScenarioFamily::kRightTurn, ScenarioFamily::kLaneChanging),
                       ::testing::Values(VehicleCount::kTwo, VehicleCount::kThree, VehicleCount::kMany)));

TEST(FamilyTest, ManyVehicleCellCrashesOtherVehiclesAhead) {
  std::mt19937_64 rng(3);
  FamilyParams p = SampleFamilyParams(ScenarioFamily::kStraightObstacle, VehicleCount::kMany, ExampleSeeds()[0], rng);
  const Scenario s = BuildFamilyScenario(p);
  CrashEnv env(CrashEnvConfig{}, {std::make_shared<const Scenario>(s)});
  const EpisodeResult r = RunEpisode(env, [](const CrashEnv& e) { return BrakePolicy(e, 0.0); }, 0, 0);
  EXPECT_GE(r.npc_contacts, 1);  // the wreck happened
  EXPECT_FALSE(r.collision.has_value());
}

TEST(FamilyTest, BadParametersAreNamed) {
  FamilyParams p;
  p.family = ScenarioFamily::kLaneChanging;
  p.lanes_per_direction = 1;
  try {
    BuildFamilyScenario(p);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("lanes_per_direction"), std::string::npos);
  }
  p.family = ScenarioFamily::kStraightObstacle;
  p.ego_speed = -3;
  EXPECT_THROW(BuildFamilyScenario(p), std::invalid_argument);
}

TEST(SuiteGeneratorTest, SuitesAreBalancedDisjointAndDeterministic) {
  SuiteOptions o;
  o.train = 24;
  o.test = 12;
  o.seed = 5;
  o.threads = 2;
  const auto seeds = ExampleSeeds();
  const Suite a = GenerateSuite(seeds, o);
  ASSERT_EQ(a.train.scenarios.size(), 24u);
  ASSERT_EQ(a.test.scenarios.size(), 12u);
  for (const auto& c : a.train.cells) EXPECT_EQ(c.kept, 2);
  for (const auto& c : a.test.cells) EXPECT_EQ(c.kept, 1);
  // Disjoint source reports.
  std::set<std::string> train_reports(a.train.reports.begin(), a.train.reports.end());
  for (const auto& r : a.test.reports) EXPECT_EQ(train_reports.count(r), 0u) << r;
  for (const auto& s : a.test.scenarios) {
    EXPECT_EQ(train_reports.count(s.provenance["source_report"].get<std::string>()), 0u);
  }
  // Same seed, other thread count: identical suites.
  o.threads = 1;
  const Suite b = GenerateSuite(seeds, o);
  ASSERT_EQ(b.train.scenarios.size(), a.train.scenarios.size());
  for (size_t i = 0; i < a.train.scenarios.size(); ++i) {
    EXPECT_EQ(ToJson(a.train.scenarios[i]).dump(), ToJson(b.train.scenarios[i]).dump());
  }
  // Another seed: another suite.
  o.seed = 6;
  EXPECT_NE(ToJson(GenerateSuite(seeds, o).train.scenarios[0]).dump(), ToJson(a.train.scenarios[0]).dump());
}

TEST(SuiteGeneratorTest, WrittenSuitesLoadBack) {
  SuiteOptions o;
  o.train = 12;
  o.test = 12;
  const Suite s = GenerateSuite(ExampleSeeds(), o);
  const std::string dir = ::testing::TempDir() + "/suite";
  WriteSuite(s, dir, o);
  EXPECT_EQ(LoadSuite(dir + "/train.jsonl").size(), 12u);
  EXPECT_EQ(LoadSuite(dir + "/test.jsonl").size(), 12u);
  std::ifstream stats(dir + "/stats.json");
  const auto j = nlohmann::json::parse(stats);
  EXPECT_EQ(j["train"]["cells"].size(), 12u);
}

TEST(SuiteGeneratorTest, BadInputsAreRejected) {
  EXPECT_THROW(GenerateSuite({ExampleSeeds()[0]}, SuiteOptions{}), std::invalid_argument);
  const std::string path = ::testing::TempDir() + "/bad.jsonl";
  std::ofstream(path) << "{\"schema_version\": 1}\n";
  try {
    LoadSuite(path);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(path + ":1: family: missing required field"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace accsim
