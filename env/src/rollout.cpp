#include "accsim/env/rollout.h"

#include <cmath>
#include <limits>

namespace accsim {
namespace {

void Record(const CrashEnv& env, EpisodeResult& r) {
  const World& w = env.world();
  for (int i = 0; i < w.num_vehicles(); ++i) {
    const VehicleState& s = w.state(i);
    r.trajectories[static_cast<size_t>(i)].push_back(
        TrajectoryPoint{w.time(), s.pose.x, s.pose.y, s.pose.yaw, s.speed()});
  }
}

}  // namespace

EpisodeResult RunEpisode(CrashEnv& env, const PolicyFn& policy, std::optional<uint64_t> seed,
                         int scenario_index, bool record) {
  EpisodeOptions o;
  o.record = record;
  return RunEpisode(env, policy, seed, scenario_index, o);
}

EpisodeResult RunEpisode(CrashEnv& env, const PolicyFn& policy, std::optional<uint64_t> seed,
                         int scenario_index, const EpisodeOptions& options) {
  EpisodeResult r;
  env.Reset(seed, scenario_index);
  r.ids = env.vehicle_ids();
  if (options.record) {
    r.trajectories.resize(r.ids.size());
    Record(env, r);
  }
  if (options.on_step) options.on_step(env);
  while (!env.needs_reset()) {
    const Action a = policy(env);
    env.Step(a.data(), a.size());
    if (options.record) Record(env, r);
    if (options.on_step) options.on_step(env);
    const auto& hit = env.info().ego_collision;
    if (hit && options.after_collision > 0.0 && env.time() >= hit->time + options.after_collision - 1e-9) break;
  }
  const StepInfo& info = env.info();
  r.collision = info.ego_collision;
  r.outcome = info.ego_collision ? "collision" : info.off_road ? "off_road" : info.goal ? "goal" : "time_limit";
  r.time = info.time;
  r.steps = info.episode_steps;
  r.episode_return = info.episode_return;
  r.min_ttc = info.min_ttc;
  r.route_progress = info.route_progress;
  r.npc_contacts = info.npc_contacts;
  return r;
}

nlohmann::json SummaryJson(const EpisodeResult& r) {
  nlohmann::json j;
  j["outcome"] = r.outcome;
  j["collision"] = r.collision.has_value();
  if (r.collision) {
    j["time"] = r.collision->time;
    j["bodies"] = {r.ids.front(), r.collision->other_id};
    j["impulse"] = r.collision->impulse;
    j["relative_speed"] = r.collision->relative_speed;
    j["closing_speed"] = r.collision->closing_speed;
    j["point"] = {r.collision->point.x(), r.collision->point.y()};
  } else {
    j["time"] = nullptr;
    j["bodies"] = nlohmann::json::array();
    j["impulse"] = nullptr;
    j["relative_speed"] = nullptr;
    j["closing_speed"] = nullptr;
    j["point"] = nullptr;
  }
  j["episode_time"] = r.time;
  j["steps"] = r.steps;
  j["return"] = r.episode_return;
  j["min_ttc"] = std::isfinite(r.min_ttc) ? nlohmann::json(r.min_ttc) : nlohmann::json(nullptr);
  j["route_progress"] = r.route_progress;
  j["npc_contacts"] = r.npc_contacts;
  return j;
}

nlohmann::json TrajectoriesJson(const EpisodeResult& r) {
  nlohmann::json vehicles = nlohmann::json::object();
  for (size_t i = 0; i < r.ids.size() && i < r.trajectories.size(); ++i) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& p : r.trajectories[i]) {
      a.push_back({{"t", p.t}, {"x", p.x}, {"y", p.y}, {"yaw", p.yaw}, {"v", p.v}});
    }
    vehicles[r.ids[i]] = std::move(a);
  }
  return {{"ids", r.ids}, {"vehicles", vehicles}, {"summary", SummaryJson(r)}};
}

}  // namespace accsim
