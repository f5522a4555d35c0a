// The accsim CLI end to end, run as a user runs it.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace {

struct Result {
  int status = -1;
  std::string out;  // stdout and stderr
};

Result RunCli(const std::string& args) {
  Result r;
  const std::string cmd = std::string(ACCSIM_CLI_PATH) + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int status = pclose(p);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::string Example(const std::string& family) {
  return std::string(ACCSIM_SOURCE_DIR) + "/scenarios/examples/" + family + ".json";
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class CliExampleTest : public ::testing::TestWithParam<std::string> {};

TEST_P(CliExampleTest, HoldCollidesAndBrakeDoesNot) {
  const Result hold = RunCli("simulate " + Example(GetParam()) + " --ego hold --json");
  ASSERT_EQ(hold.status, 0) << hold.out;
  const auto h = nlohmann::json::parse(hold.out);
  EXPECT_TRUE(h["collision"].get<bool>());
  EXPECT_GT(h["time"].get<double>(), 0.0);
  EXPECT_EQ(h["bodies"].size(), 2u);
  EXPECT_GT(h["impulse"].get<double>(), 0.0);
  EXPECT_GT(h["relative_speed"].get<double>(), 0.0);

  const Result brake = RunCli("simulate " + Example(GetParam()) + " --ego brake --json");
  ASSERT_EQ(brake.status, 0) << brake.out;
  EXPECT_FALSE(nlohmann::json::parse(brake.out)["collision"].get<bool>());
}

INSTANTIATE_TEST_SUITE_P(Families, CliExampleTest,
                         ::testing::Values("straight_obstacle", "unprotected_left_turn", "right_turn",
                                           "lane_changing"));

TEST(CliTest, SavedTrajectoriesAreByteIdentical) {
  const std::string a = ::testing::TempDir() + "/traj_a.json", b = ::testing::TempDir() + "/traj_b.json";
  ASSERT_EQ(RunCli("simulate " + Example("lane_changing") + " --ego rule --out " + a).status, 0);
  ASSERT_EQ(RunCli("simulate " + Example("lane_changing") + " --ego rule --out " + b).status, 0);
  const std::string ta = ReadFile(a);
  EXPECT_GT(ta.size(), 1000u);
  EXPECT_EQ(ta, ReadFile(b));
  const auto j = nlohmann::json::parse(ta);
  EXPECT_EQ(j["vehicles"].size(), 4u);
}

TEST(CliTest, BadInputGetsAClearErrorAndExitCode) {
  const std::string bad = ::testing::TempDir() + "/bad.json";
  std::ofstream(bad) << "{\"schema_version\": 1, \"family\": \"lane_changing\"}";
  Result r = RunCli("simulate " + bad);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("error: " + bad + ": map: missing required field"), std::string::npos) << r.out;

  std::ofstream(bad) << "not json";
  r = RunCli("simulate " + bad);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("malformed JSON"), std::string::npos) << r.out;

  r = RunCli("simulate " + Example("lane_changing") + " --ego sideways");
  EXPECT_EQ(r.status, 2);  // a bad flag is a usage error like any other
  EXPECT_NE(r.out.find("--ego"), std::string::npos) << r.out;

  r = RunCli("simulate /no/such/file.json");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("/no/such/file.json"), std::string::npos) << r.out;
}

TEST(CliTest, EvalExtractionThroughARewriteScoresTheSame) {
  const std::string dir = std::string(ACCSIM_SOURCE_DIR) + "/tests/data/report_styles";
  const Result plain = RunCli("eval-extraction " + dir + " --json");
  const Result upper = RunCli("eval-extraction " + dir + " --json --rewrite upper");
  ASSERT_EQ(plain.status, 0) << plain.out;
  ASSERT_EQ(upper.status, 0) << upper.out;
  EXPECT_EQ(nlohmann::json::parse(upper.out)["attributes"], nlohmann::json::parse(plain.out)["attributes"]);
  const Result bad = RunCli("eval-extraction " + dir + " --rewrite pig-latin");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("--rewrite"), std::string::npos) << bad.out;
}

TEST(CliTest, SweepReconstructionPrintsRatesAndRefusesZeroSeeds) {
  Result r = RunCli("sweep-reconstruction --seeds 1");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("straight/rear_end"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(89 descriptions)"), std::string::npos) << r.out;
  r = RunCli("sweep-reconstruction --seeds 0");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("--seeds"), std::string::npos) << r.out;
}

TEST(CliTest, WritesCollisionVideoAndImage) {
  const std::string video = ::testing::TempDir() + "/crash.mp4", png = ::testing::TempDir() + "/crash.png";
  const Result r = RunCli("simulate " + Example("right_turn") + " --ego hold --video " + video + " --png " + png +
                          " --size 320");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_GT(ReadFile(video).size(), 10000u);
  const std::string img = ReadFile(png);
  ASSERT_GT(img.size(), 1000u);
  EXPECT_EQ(img.substr(1, 3), "PNG");
  // The summary is the same as without rendering.
  EXPECT_NE(r.out.find("COLLISION at t = "), std::string::npos);
}

TEST(CliTest, ReconstructsANarrativeIntoASimulatableScenario) {
  const std::string text = ::testing::TempDir() + "/report.txt", out = ::testing::TempDir() + "/rec.json";
  std::ofstream(text) << "Vehicle one was traveling east at 35 mph. Vehicle two was stopped in the lane ahead. "
                         "The front of V1 struck the back of V2.";
  Result r = RunCli("reconstruct " + text + " -o " + out + " --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["success"].get<bool>()) << r.out;
  EXPECT_EQ(j["crash_type"], "rear_end");
  // The reconstruction is an environment scenario: holding V2 (the ego,
  // stopped) is hit by V1.
  r = RunCli("simulate " + out + " --ego hold --json");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(nlohmann::json::parse(r.out)["collision"].get<bool>());
  EXPECT_NE(RunCli("reconstruct /no/such.txt -o " + out).status, 0);
}

TEST(CliTest, HelpListsSubcommands) {
  const Result r = RunCli("--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("simulate"), std::string::npos);
  EXPECT_NE(r.out.find("bench"), std::string::npos);
  EXPECT_EQ(RunCli("simulate --help").status, 0);
}

TEST(CliTest, BenchPrintsJsonWithTheThroughput) {
  const Result r = RunCli("bench --json --seconds 0.2");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["single_env_steps_per_second"].get<double>(), 0.0);
  EXPECT_EQ(j["vehicles"].get<int>(), 4);
}

}  // namespace
