// Runs one episode of a CrashEnv under a policy and summarises it.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accsim/env/crash_env.h"
#include "accsim/env/scripted_drivers.h"

namespace accsim {

using PolicyFn = std::function<Action(const CrashEnv&)>;

struct EpisodeResult {
  std::string outcome;  // "collision", "off_road", "goal" or "time_limit"
  std::optional<CollisionInfo> collision;
  double time = 0.0;    // [s] episode length
  int steps = 0;
  double episode_return = 0.0;
  double min_ttc = 0.0;
  double route_progress = 0.0;
  int npc_contacts = 0;
  std::vector<std::string> ids;
  // Per vehicle, the state at reset and after every policy step (when recorded).
  std::vector<std::vector<TrajectoryPoint>> trajectories;
};

struct EpisodeOptions {
  bool record = false;           // keep every vehicle's trajectory
  // With CrashEnvConfig::terminate_on_collision = false: stop this long
  // after the ego's first contact [s] (0 = run to the episode's end).
  double after_collision = 0.0;
  std::function<void(const CrashEnv&)> on_step;  // after reset and after every step
};

EpisodeResult RunEpisode(CrashEnv& env, const PolicyFn& policy, std::optional<uint64_t> seed,
                         int scenario_index = -1, bool record = false);
EpisodeResult RunEpisode(CrashEnv& env, const PolicyFn& policy, std::optional<uint64_t> seed,
                         int scenario_index, const EpisodeOptions& options);

// Summary keys: outcome, collision, time, bodies, impulse, relative_speed,
// closing_speed, point, steps, return, min_ttc, route_progress, npc_contacts.
nlohmann::json SummaryJson(const EpisodeResult& r);
// The recorded trajectories: {"ids": [...], "dt": .., "vehicles": {id: [{t,x,y,yaw,v}...]}}.
nlohmann::json TrajectoriesJson(const EpisodeResult& r);

}  // namespace accsim
