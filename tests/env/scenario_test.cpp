#include "accsim/env/scenario.h"

#include <gtest/gtest.h>

#include <fstream>

#include "accsim/env/json_fields.h"

namespace accsim {
namespace {

std::string ExamplePath(const std::string& family) {
  return std::string(ACCSIM_SOURCE_DIR) + "/scenarios/examples/" + family + ".json";
}

nlohmann::json ExampleJson() {
  std::ifstream in(ExamplePath("lane_changing"));
  return nlohmann::json::parse(in);
}

// The message of the error ScenarioFromJson raises for `j`.
std::string ErrorOf(const nlohmann::json& j) {
  try {
    ScenarioFromJson(j);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

TEST(ScenarioTest, ExamplesLoadAndRoundTrip) {
  for (const char* f : {"straight_obstacle", "unprotected_left_turn", "right_turn", "lane_changing"}) {
    const Scenario s = LoadScenarioFile(ExamplePath(f));
    EXPECT_EQ(ToString(s.family), f);
    EXPECT_EQ(ToJson(ScenarioFromJson(ToJson(s))).dump(), ToJson(s).dump());
  }
  const Scenario lc = LoadScenarioFile(ExamplePath("lane_changing"));
  EXPECT_EQ(lc.vehicle_count(), 4);
  EXPECT_EQ(lc.npcs[2].vehicle_class, VehicleClass::kTruck);
}

TEST(ScenarioTest, MissingFieldsAreNamed) {
  auto j = ExampleJson();
  j.erase("map");
  EXPECT_EQ(ErrorOf(j), "map: missing required field");
  j = ExampleJson();
  j["ego"].erase("speed");
  EXPECT_EQ(ErrorOf(j), "ego.speed: missing required field");
  j = ExampleJson();
  j["npcs"][1].erase("reference");
  EXPECT_EQ(ErrorOf(j), "npcs[1].reference: missing required field");
}

TEST(ScenarioTest, WrongTypesAndValuesAreNamed) {
  auto j = ExampleJson();
  j["ego"]["speed"] = "fast";
  EXPECT_EQ(ErrorOf(j), "ego.speed: expected a number, got string");
  j = ExampleJson();
  j["map"]["lanes_per_direction"] = 9;
  EXPECT_EQ(ErrorOf(j), "map.lanes_per_direction: must be in [1, 4], got 9");
  j = ExampleJson();
  j["map"]["surface"] = "lava";
  EXPECT_NE(ErrorOf(j).find("map.surface: unknown 'lava'"), std::string::npos);
  j = ExampleJson();
  j["npcs"][0]["vehicle_class"] = "tank";
  EXPECT_NE(ErrorOf(j).find("npcs[0].vehicle_class: unknown 'tank'"), std::string::npos);
  j = ExampleJson();
  j["npcs"][0]["reference"][3]["t"] = 0.0;
  EXPECT_NE(ErrorOf(j).find("npcs[0].reference[3].t: times must be strictly increasing"), std::string::npos);
  j = ExampleJson();
  j["npcs"][0]["reference"][2]["x"] = nullptr;
  EXPECT_EQ(ErrorOf(j), "npcs[0].reference[2].x: expected a number, got null");
  j = ExampleJson();
  j["npcs"][0]["reference"][2]["v"] = -45.0;  // reversing is negative, but not that fast
  EXPECT_EQ(ErrorOf(j), "npcs[0].reference[2].v: must be in [-30, 100], got -45");
  j = ExampleJson();
  j["ego"]["route"] = {{0, 0}};
  EXPECT_EQ(ErrorOf(j), "ego.route: needs at least 2 entries, got 1");
  j = ExampleJson();
  j["ego"]["route"][1] = {1, "x"};
  EXPECT_EQ(ErrorOf(j), "ego.route[1]: expected [x, y] with two numbers");
}

TEST(ScenarioTest, ConsistencyIsChecked) {
  auto j = ExampleJson();
  j["vehicle_count"] = 3;
  EXPECT_NE(ErrorOf(j).find("vehicle_count: says 3 but the scenario has 4"), std::string::npos);
  j = ExampleJson();
  j["npcs"][1]["id"] = j["npcs"][0]["id"];
  EXPECT_NE(ErrorOf(j).find("npcs[1].id: duplicate vehicle id"), std::string::npos);
  j = ExampleJson();
  j["schema_version"] = 2;
  EXPECT_NE(ErrorOf(j).find("schema_version: unsupported version 2"), std::string::npos);
  j = ExampleJson();
  j["ego"]["colour"] = "red";
  EXPECT_NE(ErrorOf(j).find("ego.colour: unknown field"), std::string::npos);
  j = ExampleJson();
  j["npcs"][0]["post_collision"] = {{"source", "predicted"}};
  EXPECT_EQ(ErrorOf(j), "npcs[0].post_collision.trajectory: missing required field");
  EXPECT_EQ(ErrorOf(nlohmann::json::array()), "(document): expected an object, got array");
}

TEST(ScenarioTest, MalformedFilesNameTheFile) {
  const std::string path = ::testing::TempDir() + "/broken.json";
  std::ofstream(path) << "{\"schema_version\": 1, \"map\": ";
  try {
    LoadScenarioFile(path);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": malformed JSON"), std::string::npos);
  }
  EXPECT_THROW(LoadScenarioFile(path + ".missing"), std::invalid_argument);
}

TEST(ScenarioTest, SaveIsAtomicAndLeavesNoTemporaryFile) {
  const std::string path = ::testing::TempDir() + "/saved.json";
  SaveJsonFile(ExampleJson(), path);
  EXPECT_EQ(LoadScenarioFile(path).name, "example_lane_changing");
  EXPECT_FALSE(std::ifstream(path + ".tmp").good());
  // Writing into a missing directory fails loudly instead of half-writing.
  EXPECT_THROW(SaveJsonFile(ExampleJson(), ::testing::TempDir() + "/no/such/dir/x.json"), std::runtime_error);
}

TEST(TrajectoryTest, SamplesInterpolateAndExtrapolate) {
  const Trajectory t({{0.0, 0, 0, 0, 10}, {1.0, 10, 0, kPi / 2, 10}});
  EXPECT_NEAR(t.Sample(0.5).x, 5.0, 1e-12);
  EXPECT_NEAR(t.Sample(0.5).yaw, kPi / 4, 1e-12);
  EXPECT_NEAR(t.Sample(2.0).y, 10.0, 1e-9);  // continues north at 10 m/s
  EXPECT_NEAR(t.Sample(-1.0).x, 0.0, 1e-12);
  size_t cursor = 0;
  EXPECT_NEAR(t.Sample(0.25, &cursor).x, 2.5, 1e-12);
}

}  // namespace
}  // namespace accsim
