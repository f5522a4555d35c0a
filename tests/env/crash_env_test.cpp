#include "accsim/env/crash_env.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

namespace accsim {
namespace {

std::shared_ptr<const Scenario> Example(const std::string& family) {
  return std::make_shared<const Scenario>(
      LoadScenarioFile(std::string(ACCSIM_SOURCE_DIR) + "/scenarios/examples/" + family + ".json"));
}

std::vector<std::shared_ptr<const Scenario>> AllExamples() {
  return {Example("straight_obstacle"), Example("unprotected_left_turn"), Example("right_turn"),
          Example("lane_changing")};
}

// A rollout's observations and rewards, as raw bytes, under a fixed action pattern.
std::string Rollout(CrashEnv& env, uint64_t seed, int steps) {
  std::string bytes;
  const float* obs = env.Reset(seed);
  bytes.append(reinterpret_cast<const char*>(obs), sizeof(float) * env.spec().obs_dim);
  for (int t = 0; t < steps; ++t) {
    const float a[2] = {0.3f * std::sin(0.1f * t), 0.2f * std::cos(0.07f * t)};
    env.Step(a, 2);
    bytes.append(reinterpret_cast<const char*>(env.observation()), sizeof(float) * env.spec().obs_dim);
    const double r = env.reward();
    bytes.append(reinterpret_cast<const char*>(&r), sizeof r);
    if (env.needs_reset()) env.Reset();
  }
  return bytes;
}

CrashEnvConfig JitterConfig() {
  CrashEnvConfig c;
  c.npc_time_jitter = 0.5;
  c.start_speed_jitter = 2.0;
  c.num_rays = 8;
  return c;
}

TEST(CrashEnvTest, SameSeedGivesBitIdenticalRollouts) {
  CrashEnv a(JitterConfig(), AllExamples()), b(JitterConfig(), AllExamples());
  const std::string ra = Rollout(a, 42, 300), rb = Rollout(b, 42, 300);
  ASSERT_EQ(ra.size(), rb.size());
  EXPECT_EQ(0, std::memcmp(ra.data(), rb.data(), ra.size()));
  // And the same env re-seeded repeats itself.
  EXPECT_EQ(Rollout(a, 42, 300), ra);
}

TEST(CrashEnvTest, OtherSeedGivesOtherRollout) {
  CrashEnv a(JitterConfig(), AllExamples());
  EXPECT_NE(Rollout(a, 1, 100), Rollout(a, 2, 100));
}

TEST(CrashEnvTest, ObservationMatchesSpecAndStaysInBounds) {
  CrashEnv env(JitterConfig(), AllExamples());
  const EnvSpec& spec = env.spec();
  EXPECT_EQ(spec.obs_dim, static_cast<int>(spec.obs_names.size()));
  EXPECT_EQ(spec.obs_dim, 10 + 5 + 6 * 9 + 8);
  EXPECT_EQ(spec.substeps, 10);
  for (uint64_t seed = 0; seed < 8; ++seed) {
    env.Reset(seed);
    for (int t = 0; t < 150 && !env.needs_reset(); ++t) {
      const float a[2] = {1.0f, 0.5f * std::sin(0.3f * t)};
      env.Step(a, 2);
      for (int k = 0; k < spec.obs_dim; ++k) {
        const float v = env.observation()[k];
        ASSERT_TRUE(std::isfinite(v)) << spec.obs_names[k];
        ASSERT_GE(v, spec.obs_low) << spec.obs_names[k];
        ASSERT_LE(v, spec.obs_high) << spec.obs_names[k];
      }
    }
  }
}

TEST(CrashEnvTest, ObservationSeesTheObstacleAhead) {
  CrashEnv env(CrashEnvConfig{}, {Example("straight_obstacle")});
  const float* obs = env.Reset(0);
  const EnvSpec& s = env.spec();
  const float* v0 = obs + s.vehicles_offset;
  EXPECT_EQ(v0[0], 1.0f);                                  // present
  EXPECT_NEAR(v0[1] * 60.0f, 60.0f, 1e-3);                  // 60 m ahead
  EXPECT_NEAR(v0[2], 0.0f, 1e-6);                           // same lane
  EXPECT_NEAR(v0[3] * 40.0f, -13.0f, 1e-3);                 // closing at 13 m/s
  EXPECT_EQ(obs[s.vehicles_offset + s.vehicle_features], 0.0f);  // no second vehicle
  EXPECT_NEAR(obs[0] * 40.0f, 13.0f, 1e-4);                 // ego speed
  EXPECT_EQ(obs[7], 1.0f);                                  // on road
}

TEST(CrashEnvTest, RewardIsTheSumOfItsNamedTerms) {
  CrashEnv env(CrashEnvConfig{}, AllExamples());
  env.Reset(3);
  for (int t = 0; t < 50 && !env.needs_reset(); ++t) {
    const float a[2] = {0.5f, 0.1f * (t % 3)};
    env.Step(a, 2);
    double sum = 0.0;
    for (double term : env.info().reward_terms) sum += term;
    EXPECT_DOUBLE_EQ(sum, env.reward());
  }
}

TEST(CrashEnvTest, CollisionTerminatesWithDetailsAndPenalty) {
  CrashEnv env(CrashEnvConfig{}, {Example("straight_obstacle")});
  env.Reset(0);
  const float hold[2] = {0.0f, 0.0f};
  while (!env.needs_reset()) env.Step(hold, 2);
  EXPECT_TRUE(env.terminated());
  EXPECT_FALSE(env.truncated());
  ASSERT_TRUE(env.info().ego_collision.has_value());
  EXPECT_EQ(env.info().ego_collision->other_id, "stopped_car");
  EXPECT_DOUBLE_EQ(env.info().reward_terms[kRewardCollision], CrashEnvConfig{}.reward.collision);
  EXPECT_LT(env.info().min_ttc, 0.5);  // the TTC just before impact was tiny
}

TEST(CrashEnvTest, EpisodeCanContinuePastTheCollision) {
  CrashEnvConfig c;
  c.terminate_on_collision = false;
  CrashEnv env(c, {Example("straight_obstacle")});
  env.Reset(0);
  const float hold[2] = {0.0f, 0.0f};
  int steps_after = 0;
  while (!env.needs_reset()) {
    env.Step(hold, 2);
    if (env.info().ego_collision) ++steps_after;
  }
  EXPECT_TRUE(env.truncated());  // ran to the time limit
  EXPECT_GT(steps_after, 10);
  EXPECT_EQ(env.info().ego_collision->other_id, "stopped_car");
}

TEST(CrashEnvTest, PredictedPostCollisionTrajectoryIsReplayedFromTheContactPose) {
  auto scenario = std::make_shared<Scenario>(*Example("straight_obstacle"));
  NpcSpec& npc = scenario->npcs[0];
  npc.post_collision = PostCollisionSource::kPredicted;
  // Predicted: pushed 6 m forward and turned by 0.3 rad over 1.5 s, then at rest.
  npc.predicted = Trajectory({{0.0, 0.0, 0.0, 0.0, 6.0}, {1.5, 6.0, 0.0, 0.3, 0.0}});
  CrashEnvConfig c;
  c.terminate_on_collision = false;
  CrashEnv env(c, {scenario});
  env.Reset(0);
  const float brake_after[2] = {-1.0f, 0.0f}, hold[2] = {0.0f, 0.0f};
  std::optional<Pose2> at_contact;
  double t_contact = 0.0;
  while (!env.needs_reset()) {
    env.Step(env.info().ego_collision ? brake_after : hold, 2);
    if (env.info().ego_collision && !at_contact) {
      t_contact = env.info().ego_collision->time;
      at_contact = env.world().state(1).pose;
    }
    if (at_contact && env.time() >= t_contact + 2.0) break;
  }
  ASSERT_TRUE(at_contact.has_value());
  EXPECT_EQ(env.world().control(1), BodyControl::kTracking);  // replaying, not under physics
  const Pose2 end = env.world().state(1).pose;
  // The contact pose is recorded at the first touching substep; the step's
  // end is up to 0.1 s later, so compare with the whole predicted motion.
  EXPECT_NEAR(end.yaw - at_contact->yaw, 0.3, 0.05);
  EXPECT_NEAR(end.x - at_contact->x, 6.0, 1.0);
}

TEST(CrashEnvTest, TimeLimitTruncates) {
  CrashEnvConfig c;
  c.time_limit = 2.0;
  CrashEnv env(c, {Example("straight_obstacle")});
  env.Reset(0);
  const float brake[2] = {-1.0f, 0.0f};
  int steps = 0;
  while (!env.needs_reset()) {
    env.Step(brake, 2);
    ++steps;
  }
  EXPECT_EQ(steps, 20);
  EXPECT_TRUE(env.truncated());
  EXPECT_FALSE(env.terminated());
  EXPECT_THROW(env.Step(brake, 2), std::logic_error);
}

TEST(CrashEnvTest, BadActionsThrowAndLeaveTheEnvUnchanged) {
  CrashEnv env(CrashEnvConfig{}, {Example("lane_changing")});
  env.Reset(0);
  const std::vector<float> before(env.observation(), env.observation() + env.spec().obs_dim);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const float bad_nan[2] = {nan, 0.0f}, bad_inf[2] = {0.0f, -inf}, three[3] = {0, 0, 0};
  try {
    env.Step(bad_nan, 2);
    FAIL() << "NaN accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("action[0]"), std::string::npos) << e.what();
  }
  try {
    env.Step(bad_inf, 2);
    FAIL() << "inf accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("action[1] (steer)"), std::string::npos) << e.what();
  }
  EXPECT_THROW(env.Step(three, 3), std::invalid_argument);
  EXPECT_THROW(env.Step(three, 1), std::invalid_argument);
  EXPECT_DOUBLE_EQ(env.time(), 0.0);
  EXPECT_EQ(before, std::vector<float>(env.observation(), env.observation() + env.spec().obs_dim));
}

TEST(CrashEnvTest, OutOfRangeActionsAreClippedAndCounted) {
  CrashEnv a(CrashEnvConfig{}, {Example("lane_changing")}), b(CrashEnvConfig{}, {Example("lane_changing")});
  a.Reset(0);
  b.Reset(0);
  const float big[2] = {7.0f, -3.0f}, unit[2] = {1.0f, -1.0f};
  a.Step(big, 2);
  b.Step(unit, 2);
  EXPECT_EQ(0, std::memcmp(a.observation(), b.observation(), sizeof(float) * a.spec().obs_dim));
  EXPECT_EQ(a.info().clipped_actions, 2);
  EXPECT_EQ(b.info().clipped_actions, 0);
}

TEST(CrashEnvTest, StepBeforeResetIsAnError) {
  CrashEnv env(CrashEnvConfig{}, {Example("lane_changing")});
  const float a[2] = {0, 0};
  EXPECT_THROW(env.Step(a, 2), std::logic_error);
}

TEST(CrashEnvTest, ScenarioIndexOutOfRangeIsAnError) {
  CrashEnv env(CrashEnvConfig{}, AllExamples());
  EXPECT_THROW(env.Reset(0, 4), std::invalid_argument);
  env.Reset(0, 3);
  EXPECT_EQ(env.scenario().name, "example_lane_changing");
}

TEST(CrashEnvTest, NpcsBecomePhysicalAfterContact) {
  CrashEnv env(CrashEnvConfig{}, {Example("straight_obstacle")});
  env.Reset(0);
  const float hold[2] = {0.0f, 0.0f};
  while (!env.needs_reset()) env.Step(hold, 2);
  EXPECT_EQ(env.world().control(1), BodyControl::kDriven);
  // The stopped car was pushed forward by the impact.
  EXPECT_GT(env.world().state(1).speed(), 1.0);
}

TEST(CrashEnvConfigTest, ReadsYamlAndNamesBadFields) {
  const std::string path = ::testing::TempDir() + "/env.yaml";
  {
    std::ofstream(path) << "policy_hz: 10\nphysics_hz: 200\nnum_rays: 4\nreward:\n  collision: -50\n";
  }
  const CrashEnvConfig c = LoadCrashEnvConfig(path);
  EXPECT_EQ(c.physics_hz, 200.0);
  EXPECT_EQ(c.num_rays, 4);
  EXPECT_EQ(c.reward.collision, -50.0);
  EXPECT_EQ(MakeEnvSpec(c).substeps, 20);

  auto error_of = [&](const std::string& text) {
    std::ofstream(path) << text;
    try {
      LoadCrashEnvConfig(path);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of("physics_hz: 50\n").find("physics_hz: must be in [100"), std::string::npos);
  EXPECT_NE(error_of("physics_hz: 105\n").find("physics_hz: must be an integer multiple"), std::string::npos);
  EXPECT_NE(error_of("num_rays: lots\n").find("num_rays: expected an integer"), std::string::npos);
  EXPECT_NE(error_of("reward:\n  colision: -5\n").find("reward.colision: unknown field"), std::string::npos);
  EXPECT_NE(error_of("policy_hz: .nan\n").find("policy_hz"), std::string::npos);
  EXPECT_NE(error_of("policy_hz: [1\n").find("malformed YAML"), std::string::npos);
  EXPECT_NE(error_of("observed_vehicles: 2.5\n").find("observed_vehicles: expected an integer"),
            std::string::npos);
}

}  // namespace
}  // namespace accsim
