#include "accsim/env/vector_env.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

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

std::vector<float> Actions(int n, int t) {
  std::vector<float> a(static_cast<size_t>(n) * 2);
  for (int i = 0; i < n; ++i) {
    a[2 * i] = 0.4f * std::sin(0.1f * t + i);
    a[2 * i + 1] = 0.2f * std::cos(0.05f * t + 2 * i);
  }
  return a;
}

// Every output buffer over `steps` steps, as bytes.
std::string RunVector(VectorEnv& v, int steps) {
  std::string bytes;
  const int n = v.num_envs(), dim = v.spec().obs_dim;
  v.Reset(100);
  for (int t = 0; t < steps; ++t) {
    const auto a = Actions(n, t);
    v.Step(a.data(), a.size());
    bytes.append(reinterpret_cast<const char*>(v.observations()), sizeof(float) * n * dim);
    bytes.append(reinterpret_cast<const char*>(v.rewards()), sizeof(double) * n);
    bytes.append(reinterpret_cast<const char*>(v.terminated()), n);
    bytes.append(reinterpret_cast<const char*>(v.truncated()), n);
  }
  return bytes;
}

TEST(VectorEnvTest, ThreadCountDoesNotChangeResults) {
  VectorEnv one(9, CrashEnvConfig{}, Examples(), 1), two(9, CrashEnvConfig{}, Examples(), 2),
      three(9, CrashEnvConfig{}, Examples(), 3);
  const std::string a = RunVector(one, 200);
  EXPECT_EQ(a, RunVector(two, 200));
  EXPECT_EQ(a, RunVector(three, 200));
}

// More threads than cores, and episodes (1 s) ending all the time: workers
// wake late, find nothing left, or take over each other's share.
TEST(VectorEnvTest, OversubscribedPoolWithFrequentResetsStaysDeterministic) {
  CrashEnvConfig c;
  c.time_limit = 1.0;
  c.npc_time_jitter = 0.3;
  VectorEnv one(6, c, Examples(), 1), six(6, c, Examples(), 6);
  EXPECT_EQ(six.num_threads(), 6);
  EXPECT_EQ(RunVector(one, 300), RunVector(six, 300));
}

TEST(VectorEnvTest, MatchesSingleEnvironmentsWithTheSameSeeds) {
  VectorEnv v(3, CrashEnvConfig{}, Examples(), 2);
  std::vector<std::unique_ptr<CrashEnv>> singles;
  for (int i = 0; i < 3; ++i) {
    singles.push_back(std::make_unique<CrashEnv>(CrashEnvConfig{}, Examples()));
    singles.back()->Reset(100 + i);
  }
  v.Reset(100);
  const int dim = v.spec().obs_dim;
  for (int t = 0; t < 150; ++t) {
    const auto a = Actions(3, t);
    v.Step(a.data(), a.size());
    for (int i = 0; i < 3; ++i) {
      CrashEnv& e = *singles[static_cast<size_t>(i)];
      if (e.needs_reset()) {  // NEXT_STEP: this step is the reset
        e.Reset();
        EXPECT_EQ(v.rewards()[i], 0.0);
      } else {
        e.Step(a.data() + 2 * i, 2);
        EXPECT_EQ(v.rewards()[i], e.reward());
        EXPECT_EQ(v.terminated()[i] != 0, e.terminated());
      }
      ASSERT_EQ(0, std::memcmp(v.observations() + i * dim, e.observation(), sizeof(float) * dim)) << "t " << t;
    }
  }
}

TEST(VectorEnvTest, SameStepAutoresetKeepsTheFinalObservation) {
  CrashEnvConfig c;
  c.time_limit = 1.0;  // 10 steps
  VectorEnv v(2, c, Examples(), 1, AutoresetMode::kSameStep);
  CrashEnv single(c, Examples());
  v.Reset(7);
  single.Reset(7);
  for (int t = 0; t < 10; ++t) {
    const auto a = Actions(2, t);
    v.Step(a.data(), a.size());
    single.Step(a.data(), 2);
  }
  EXPECT_TRUE(single.truncated());
  EXPECT_EQ(v.truncated()[0], 1);
  const int dim = v.spec().obs_dim;
  EXPECT_EQ(0, std::memcmp(v.final_observations(), single.observation(), sizeof(float) * dim));
  // The new episode has begun, but the ended one's statistics are kept.
  EXPECT_EQ(v.env(0).info().episode_steps, 0);
  EXPECT_EQ(v.final_info(0).episode_steps, 10);
  EXPECT_TRUE(v.final_info(0).time_limit);
  EXPECT_EQ(v.final_info(0).episode_return, single.info().episode_return);
  single.Reset();
  EXPECT_EQ(0, std::memcmp(v.observations(), single.observation(), sizeof(float) * dim));
}

TEST(VectorEnvTest, PerEnvironmentSeedsAndRewardTerms) {
  VectorEnv a(3, CrashEnvConfig{}, Examples(), 2), b(3, CrashEnvConfig{}, Examples(), 1);
  a.Reset(40);
  b.Reset(std::vector<uint64_t>{40, 41, 42});
  const int dim = a.spec().obs_dim;
  EXPECT_EQ(0, std::memcmp(a.observations(), b.observations(), sizeof(float) * 3 * dim));
  EXPECT_THROW(b.Reset(std::vector<uint64_t>{1, 2}), std::invalid_argument);
  b.Reset(std::vector<uint64_t>{40, 41, 42});
  for (int t = 0; t < 40; ++t) {
    const auto act = Actions(3, t);
    a.Step(act.data(), act.size());
    for (int i = 0; i < 3; ++i) {
      double sum = 0.0;
      for (int k = 0; k < kNumRewardTerms; ++k) sum += a.reward_terms()[i * kNumRewardTerms + k];
      EXPECT_NEAR(sum, a.rewards()[i], 1e-9);
    }
  }
}

TEST(VectorEnvTest, BadActionsAreRejectedBeforeAnythingSteps) {
  VectorEnv v(4, CrashEnvConfig{}, Examples(), 2);
  const float a[2] = {0, 0};
  EXPECT_THROW(v.Step(a, 2), std::logic_error);  // before Reset
  v.Reset(1);
  const std::vector<float> before(v.observations(), v.observations() + 4 * v.spec().obs_dim);
  auto good = Actions(4, 0);
  EXPECT_THROW(v.Step(good.data(), 6), std::invalid_argument);
  good[5] = std::numeric_limits<float>::quiet_NaN();
  try {
    v.Step(good.data(), good.size());
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("actions[2][1]"), std::string::npos) << e.what();
  }
  EXPECT_EQ(before, std::vector<float>(v.observations(), v.observations() + 4 * v.spec().obs_dim));
  EXPECT_EQ(v.env(0).time(), 0.0);
}

}  // namespace
}  // namespace accsim
