// accsim bench: single-environment policy steps per second, and where a
// step's time goes.
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <thread>

#include "accsim/env/crash_env.h"
#include "accsim/env/scenario.h"
#include "commands.h"

namespace accsim::cli {
namespace {

struct BenchOptions {
  double seconds = 3.0;
  std::string scenario;
  bool json = false;
};

// Four vehicles on a two-lane-per-direction road: the ego, a lead car, a
// car in the next lane and an oncoming one, all at urban speeds.
Scenario FourVehicleScenario() {
  Scenario s;
  s.name = "bench_four_vehicles";
  s.family = ScenarioFamily::kLaneChanging;
  s.time_limit = 20.0;
  s.map.type = RoadType::kStraight;
  s.map.lanes_per_direction = 2;
  s.map.length = 800.0;
  s.map.speed_limit = 15.0;
  s.ego.start = Pose2{-350.0, -5.25, 0.0};
  s.ego.speed = 14.0;
  s.ego.target_speed = 14.0;
  s.ego.route = Polyline({Vec2(-350.0, -5.25), Vec2(390.0, -5.25)});
  auto line = [](double x0, double y, double yaw, double v, double t_end) {
    std::vector<TrajectoryPoint> pts;
    for (double t = 0.0; t <= t_end + 1e-9; t += 1.0) {
      pts.push_back({t, x0 + std::cos(yaw) * v * t, y, yaw, v});
    }
    return Trajectory(pts);
  };
  s.npcs.push_back({"lead", VehicleClass::kCar, line(-320.0, -5.25, 0.0, 14.0, 25.0),
                    PostCollisionSource::kPhysics, {}});
  s.npcs.push_back({"adjacent", VehicleClass::kSuv, line(-345.0, -1.75, 0.0, 15.0, 25.0),
                    PostCollisionSource::kPhysics, {}});
  s.npcs.push_back({"oncoming", VehicleClass::kTruck, line(350.0, 1.75, kPi, 13.0, 25.0),
                    PostCollisionSource::kPhysics, {}});
  return s;
}

std::string CpuModel() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(colon + 2);
    }
  }
  return "unknown";
}

// Steps the environment for about `seconds`, resetting when an episode ends.
// Actions are a fixed smooth pattern so the ego really drives.
double MeasureStepsPerSecond(CrashEnv& env, double seconds, long* steps_out) {
  env.Reset(1);
  long steps = 0;
  const auto start = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  while (elapsed < seconds) {
    for (int k = 0; k < 1000; ++k) {
      const float a[2] = {0.2f * static_cast<float>(std::sin(steps * 0.05)),
                          0.05f * static_cast<float>(std::sin(steps * 0.13))};
      env.Step(a, 2);
      ++steps;
      if (env.needs_reset()) env.Reset();
    }
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  if (steps_out) *steps_out = steps;
  return static_cast<double>(steps) / elapsed;
}

void RunBench(const BenchOptions& o) {
  auto scenario = std::make_shared<const Scenario>(o.scenario.empty() ? FourVehicleScenario()
                                                                      : LoadScenarioFile(o.scenario));
  CrashEnvConfig config;
  CrashEnv env(config, {scenario});
  long steps = 0;
  const double sps = MeasureStepsPerSecond(env, o.seconds, &steps);

  CrashEnv profiled(config, {scenario});
  profiled.set_profiling(true);
  MeasureStepsPerSecond(profiled, std::min(1.0, o.seconds), nullptr);
  const StepProfile& p = profiled.profile();
  const double total = p.npc_control + p.physics + p.reward + p.observation;
  auto us = [&](double t) { return 1e6 * t / static_cast<double>(std::max(1L, p.steps)); };
  auto share = [&](double t) { return total > 0 ? t / total : 0.0; };

  const std::string cpu = CpuModel();
  const unsigned cores = std::thread::hardware_concurrency();
  if (o.json) {
    nlohmann::json j;
    j["single_env_steps_per_second"] = sps;
    j["steps"] = steps;
    j["scenario"] = scenario->name;
    j["vehicles"] = scenario->vehicle_count();
    j["policy_dt"] = env.spec().policy_dt;
    j["substeps"] = env.spec().substeps;
    j["obs_dim"] = env.spec().obs_dim;
    j["profile_us_per_step"] = {{"physics", us(p.physics)},
                                {"npc_control", us(p.npc_control)},
                                {"reward_and_termination", us(p.reward)},
                                {"observation", us(p.observation)}};
    j["machine"] = {{"cpu", cpu}, {"cores", cores}};
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::printf("accsim bench: one CrashEnv on one core, %s (%d vehicles)\n", scenario->name.c_str(),
              scenario->vehicle_count());
  std::printf("  machine      %s, %u cores\n", cpu.c_str(), cores);
  std::printf("  policy step  %.3f s = %d physics substeps, obs_dim %d\n", env.spec().policy_dt,
              env.spec().substeps, env.spec().obs_dim);
  std::printf("  throughput   %.0f steps/s (%.2f us/step, %ld steps)\n", sps, 1e6 / sps, steps);
  std::printf("  where a step's time goes (profiled run):\n");
  std::printf("    physics (Bullet, tyres, contacts)  %6.2f us  %5.1f %%\n", us(p.physics), 100 * share(p.physics));
  std::printf("    NPC reference control              %6.2f us  %5.1f %%\n", us(p.npc_control), 100 * share(p.npc_control));
  std::printf("    reward and termination             %6.2f us  %5.1f %%\n", us(p.reward), 100 * share(p.reward));
  std::printf("    observation                        %6.2f us  %5.1f %%\n", us(p.observation), 100 * share(p.observation));
}

}  // namespace

void AddBenchCommand(CLI::App& app) {
  auto opts = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand("bench", "Measure single-environment steps per second");
  cmd->add_option("--seconds", opts->seconds, "How long to measure")
      ->check(CLI::Range(0.1, 600.0))
      ->capture_default_str();
  cmd->add_option("--scenario", opts->scenario, "Scenario JSON (default: a built-in 4-vehicle road)")
      ->check(CLI::ExistingFile);
  cmd->add_flag("--json", opts->json, "Print the figures as JSON");
  cmd->callback([opts] { RunBench(*opts); });
}

}  // namespace accsim::cli
