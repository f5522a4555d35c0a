// accsim simulate SCENARIO.json --ego hold|brake|rule
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "accsim/env/crash_env.h"
#include "accsim/env/renderer.h"
#include "accsim/env/scenario.h"
#include "accsim/env/rollout.h"
#include "accsim/env/scripted_drivers.h"
#include "commands.h"

namespace accsim::cli {
namespace {

struct SimulateOptions {
  std::string scenario;
  std::string ego = "hold";
  double brake_onset = 0.0;
  std::string config;
  uint64_t seed = 0;
  bool json = false;
  std::string out;
  std::string video;
  std::string png;
  std::string camera = "collision";
  double after = 2.0;
  int width = 640, height = 480;
};

PolicyFn MakeEgoPolicy(const SimulateOptions& o) {
  if (o.ego == "hold") return [](const CrashEnv& env) { return HoldPolicy(env); };
  if (o.ego == "brake") {
    const double onset = o.brake_onset;
    return [onset](const CrashEnv& env) { return BrakePolicy(env, onset); };
  }
  return [](const CrashEnv& env) { return RuleBasedPolicy(env); };
}

void RunSimulate(const SimulateOptions& o) {
  auto scenario = std::make_shared<const Scenario>(LoadScenarioFile(o.scenario));
  CrashEnvConfig config = o.config.empty() ? CrashEnvConfig{} : LoadCrashEnvConfig(o.config);
  const bool rendering = !o.video.empty() || !o.png.empty();
  EpisodeOptions episode;
  episode.record = !o.out.empty();

  // The collision camera looks at where the ego is first hit; find that
  // point with a first, unrendered run (the simulation is deterministic).
  Vec2 focus = scenario->ego.start.position();
  if (rendering && o.camera == "collision") {
    CrashEnv probe(config, {scenario});
    const EpisodeResult first = RunEpisode(probe, MakeEgoPolicy(o), o.seed, 0);
    if (first.collision) focus = first.collision->point;
  }
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<VideoWriter> video;
  std::vector<uint8_t> frame, collision_frame;
  if (rendering) {
    RenderOptions ro;
    ro.width = o.width;
    ro.height = o.height;
    ro.camera = o.camera == "collision" ? CameraMode::kPoint : CameraModeFromString(o.camera);
    ro.point = focus;
    renderer = std::make_unique<Renderer>(ro);
    frame.resize(static_cast<size_t>(o.width) * o.height * 3);
    if (!o.video.empty()) {
      video = std::make_unique<VideoWriter>(o.video, 1.0 / MakeEnvSpec(config).policy_dt, o.width, o.height);
    }
    // Keep simulating after the ego is hit so the video shows the aftermath.
    config.terminate_on_collision = false;
    episode.after_collision = o.after;
    episode.on_step = [&](const CrashEnv& e) {
      renderer->Render(e, frame.data());
      if (video) video->Write(frame.data());
      if (collision_frame.empty() && e.info().ego_collision) collision_frame = frame;
    };
  }
  CrashEnv env(config, {scenario});
  const EpisodeResult r = RunEpisode(env, MakeEgoPolicy(o), o.seed, 0, episode);
  if (video) video->Close();
  if (!o.png.empty()) WritePng(o.png, collision_frame.empty() ? frame.data() : collision_frame.data(), o.width, o.height);
  if (!o.out.empty()) {
    nlohmann::json traj = TrajectoriesJson(r);
    traj["scenario"] = scenario->name;
    traj["ego_policy"] = o.ego;
    traj["seed"] = o.seed;
    SaveJsonFile(traj, o.out);
  }
  if (o.json) {
    nlohmann::json j = SummaryJson(r);
    j["scenario"] = scenario->name;
    j["family"] = std::string(ToString(scenario->family));
    j["vehicle_count"] = scenario->vehicle_count();
    j["ego_policy"] = o.ego;
    j["seed"] = o.seed;
    std::cout << j.dump() << "\n";
    return;
  }
  std::printf("scenario  %s (%s, %d vehicles)\n", scenario->name.c_str(),
              std::string(ToString(scenario->family)).c_str(), scenario->vehicle_count());
  std::printf("ego       %s\n", o.ego.c_str());
  if (r.collision) {
    const CollisionInfo& c = *r.collision;
    std::printf("outcome   COLLISION at t = %.2f s: %s <-> %s\n", c.time, r.ids.front().c_str(),
                c.other_id.c_str());
    std::printf("          impulse %.0f N s, relative speed %.2f m/s (closing %.2f m/s) at (%.2f, %.2f)\n",
                c.impulse, c.relative_speed, c.closing_speed, c.point.x(), c.point.y());
  } else {
    std::printf("outcome   no collision (%s after %.1f s, %.1f m of route)\n", r.outcome.c_str(), r.time,
                r.route_progress);
  }
  if (std::isfinite(r.min_ttc)) std::printf("min TTC   %.2f s\n", r.min_ttc);
  if (r.npc_contacts > 0) std::printf("other     %d contact(s) between other vehicles\n", r.npc_contacts);
  if (!o.out.empty()) std::printf("saved     %s\n", o.out.c_str());
  if (!o.video.empty()) std::printf("video     %s\n", o.video.c_str());
  if (!o.png.empty()) std::printf("image     %s\n", o.png.c_str());
}

}  // namespace

void AddSimulateCommand(CLI::App& app) {
  auto opts = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "simulate", "Simulate a scenario with a scripted ego driver and print the outcome");
  cmd->add_option("scenario", opts->scenario, "Scenario JSON file (schema version 1)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--ego", opts->ego,
                  "Ego driver: hold (keep speed along the route), brake (full brake from "
                  "--brake-onset), rule (brakes for predicted conflicts)")
      ->check(CLI::IsMember({"hold", "brake", "rule"}))
      ->capture_default_str();
  cmd->add_option("--brake-onset", opts->brake_onset, "Seconds before the brake driver brakes")
      ->check(CLI::Range(0.0, 600.0))
      ->capture_default_str();
  cmd->add_option("--config", opts->config, "Environment config YAML (default: built-in defaults)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--seed", opts->seed, "Reset seed")->capture_default_str();
  cmd->add_flag("--json", opts->json, "Print the outcome as one JSON object");
  cmd->add_option("--out", opts->out, "Save every vehicle's trajectory to this JSON file");
  cmd->add_option("--video", opts->video, "Write a top-down video (.mp4), continuing --after seconds past a collision");
  cmd->add_option("--png", opts->png, "Write a top-down image of the collision (or of the last step)");
  cmd->add_option("--camera", opts->camera, "Viewpoint: collision (fixed on the impact point), ego (follows it), map (whole map)")
      ->check(CLI::IsMember({"collision", "ego", "map"}))
      ->capture_default_str();
  cmd->add_option("--after", opts->after, "Seconds of video after the ego's collision")
      ->check(CLI::Range(0.0, 60.0))
      ->capture_default_str();
  cmd->add_option("--size", opts->width, "Frame width in pixels (height is 3/4 of it)")
      ->check(CLI::Range(64, 4096))
      ->each([opts](const std::string&) { opts->height = opts->width * 3 / 4; });
  cmd->callback([opts] { RunSimulate(*opts); });
}

}  // namespace accsim::cli
