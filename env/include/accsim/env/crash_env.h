// CrashEnv: one ego vehicle, driven by the policy, through a reconstructed
// crash. Gymnasium semantics: Reset(seed) -> observation; Step(action) ->
// observation, reward, terminated, truncated, info.
//
// Observation: a fixed-size float32 vector in [-1, 1], laid out by
// ObservationLayout (one place; Python builds its spaces from it):
//   ego (10)      speed, longitudinal accel, yaw rate, steering angle,
//                 lateral (slip) velocity, lane lateral offset, lane heading
//                 error, on-road flag, speed limit, time remaining
//   route (5)     progress fraction, remaining distance, lateral offset
//                 from the route, sin/cos of the route heading error at a
//                 speed-dependent look-ahead
//   vehicles (K x 9)  the K nearest other vehicles within range, nearest
//                 first, in the ego frame: present, dx, dy, dvx, dvy,
//                 cos/sin of relative yaw, length, width (absent: zeros)
//   rays (R)      free distance along R rays evenly spaced around the ego
//                 (Bullet ray tests), 1 = nothing within ray_range
// Each element's name and scale are in EnvSpec::obs_names / obs_scales.
//
// Action: Box[-1, 1]^2 = (acceleration/brake, steering). a[0] >= 0 asks
// for a[0] * max_accel, a[0] < 0 for -a[0] * max_brake (the tyres may give
// less); a[1] * max_steer is the target road-wheel angle (+ left),
// approached at max_steer_rate. Values outside [-1, 1] are clipped (and
// counted in info); NaN, infinity or a wrong size throw
// std::invalid_argument and leave the environment unchanged.
//
// Reward: a weighted sum of named terms (RewardTerm), each reported in
// StepInfo::reward_terms; weights from the config.
// Terminated on ego collision, off-road, or goal; truncated at the time limit.
//
// Thread-safety: one CrashEnv per thread; scenarios are shared const.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accsim/env/road_map.h"
#include "accsim/env/scenario.h"
#include "accsim/env/world.h"

namespace accsim {

enum RewardTerm : int {
  kRewardProgress = 0,
  kRewardCollision,
  kRewardOffRoad,
  kRewardLaneDeviation,
  kRewardComfort,
  kRewardGoal,
  kNumRewardTerms
};
const char* RewardTermName(int term);

struct RewardWeights {
  double progress = 0.1;         // per metre of route progress
  double collision = -20.0;      // once, when the ego first touches another vehicle
  double off_road = -10.0;       // once, when the ego's centre leaves the drivable area
  double lane_deviation = -0.05; // per step, x (lane offset / half lane width)^2, capped at 1
  double comfort = -0.02;        // per step, x squared change of the action / 8, in [0, 1]
  double goal = 10.0;            // once, on reaching the end of the route
};

struct CrashEnvConfig {
  double policy_hz = 10.0;           // [Hz] decisions per second
  double physics_hz = 100.0;         // [Hz] integer multiple of policy_hz, >= 100 (no tunnelling)
  int solver_iterations = 10;        // Bullet sequential-impulse iterations
  double time_limit = 0.0;           // [s] episode limit; 0 = the scenario's own
  int observed_vehicles = 6;         // K nearest vehicles in the observation
  double observation_range = 60.0;   // [m] vehicles farther away are absent
  int num_rays = 0;                  // range rays; 0 disables them
  double ray_range = 50.0;           // [m]
  double goal_tolerance = 2.0;       // [m] of route left that counts as reaching the goal
  double post_contact_brake = 0.5;   // [-] fraction of max brake an NPC applies after its contact
  double start_speed_jitter = 0.0;   // [m/s] uniform +- on the ego's start speed, drawn at reset
  double npc_time_jitter = 0.0;      // [s] uniform +- shift of each NPC's timing, drawn at reset
  bool terminate_on_collision = true;  // false: the episode goes on after the ego's first contact
  RewardWeights reward;
};

// Validates every field; errors name the field ("physics_hz: ...").
CrashEnvConfig CrashEnvConfigFromJson(const nlohmann::json& j);
nlohmann::json ToJson(const CrashEnvConfig& c);
// YAML file -> config; errors name the file and the field.
CrashEnvConfig LoadCrashEnvConfig(const std::string& yaml_path);

// Everything about the observation/action interface, derived from a config.
struct EnvSpec {
  int obs_dim = 0;
  int action_dim = 2;
  float obs_low = -1.0f, obs_high = 1.0f;        // every element
  float action_low = -1.0f, action_high = 1.0f;  // every element
  std::vector<std::string> obs_names;            // obs_dim entries
  std::vector<std::string> obs_units;            // the physical quantity 1.0 stands for
  std::vector<std::string> action_names;
  std::vector<std::string> reward_terms;
  double policy_dt = 0.1;  // [s]
  int substeps = 10;
  // Offsets of the observation blocks.
  int ego_offset = 0, route_offset = 0, vehicles_offset = 0, rays_offset = 0;
  int vehicle_features = 9;
};
EnvSpec MakeEnvSpec(const CrashEnvConfig& config);

struct CollisionInfo {
  double time = 0.0;            // [s]
  int other = -1;               // vehicle index (0 = ego)
  std::string other_id;
  Vec2 point = Vec2::Zero();    // [m]
  double impulse = 0.0;         // [N s] normal impulse exchanged since first touch (to the step's end)
  double relative_speed = 0.0;  // [m/s]
  double closing_speed = 0.0;   // [m/s]
};

struct StepInfo {
  std::array<double, kNumRewardTerms> reward_terms{};  // weighted contributions; sum = reward
  bool collision = false;     // the ego touched a vehicle in this step
  bool off_road = false;
  bool goal = false;
  bool time_limit = false;
  std::optional<CollisionInfo> ego_collision;  // set from the step it happened on
  int npc_contacts = 0;       // pairs of NPCs that have touched (wreckage ahead)
  int clipped_actions = 0;    // action elements clipped into [-1, 1] this episode
  double time = 0.0;          // [s] since reset
  double route_progress = 0.0;  // [m]
  double route_length = 0.0;    // [m]
  double min_ttc = 0.0;         // [s] smallest time-to-collision seen this episode (inf if none)
  int episode_steps = 0;
  double episode_return = 0.0;
  int scenario_index = -1;
};

// Where step time goes, accumulated while profiling is on [s].
struct StepProfile {
  double npc_control = 0.0;  // reference sampling and post-contact switching
  double physics = 0.0;      // Bullet substeps, tyre model, contact scan
  double reward = 0.0;       // route projection, lane queries, termination
  double observation = 0.0;
  long steps = 0;
};

class CrashEnv {
 public:
  // `scenarios` must not be empty; they are shared, never modified.
  CrashEnv(CrashEnvConfig config, std::vector<std::shared_ptr<const Scenario>> scenarios);
  ~CrashEnv();

  const EnvSpec& spec() const { return spec_; }
  const CrashEnvConfig& config() const { return config_; }

  // Starts an episode. A seed re-seeds the environment's own generator;
  // without one it continues its stream. scenario_index < 0 draws the
  // scenario from the generator. Returns the observation (spec().obs_dim).
  const float* Reset(std::optional<uint64_t> seed = std::nullopt, int scenario_index = -1);
  // Advances one policy period. `action` has `size` elements.
  void Step(const float* action, size_t size);

  const float* observation() const { return obs_.data(); }
  // Writes the observation into `out` (spec().obs_dim floats) as well as the
  // internal buffer; for batched environments.
  void CopyObservation(float* out) const;
  double reward() const { return reward_; }
  bool terminated() const { return terminated_; }
  bool truncated() const { return truncated_; }
  const StepInfo& info() const { return info_; }
  bool needs_reset() const { return needs_reset_; }

  // Timing of the parts of Step(); off by default (it costs clock reads).
  void set_profiling(bool on) { profiling_ = on; }
  const StepProfile& profile() const { return profile_; }

  // Read-only state for controllers, renderers and bridges.
  const World& world() const { return *world_; }
  const Scenario& scenario() const { return *scenario_; }
  int scenario_index() const { return info_.scenario_index; }
  size_t num_scenarios() const { return scenarios_.size(); }
  const RoadMap& map() const { return *map_; }
  const std::vector<std::string>& vehicle_ids() const { return ids_; }
  double time() const { return world_ ? world_->time() : 0.0; }
  double time_limit() const { return time_limit_; }
  // Route progress of the ego [m] and the route.
  double route_s() const { return route_s_; }
  const Polyline& route() const { return scenario_->ego.route; }

 private:
  void UpdateNpcTargets(double t_next);
  void OnContacts();
  void ComputeObservation();
  double MinTimeToCollision() const;
  double Uniform();  // [0, 1), from the env's generator

  CrashEnvConfig config_;
  EnvSpec spec_;
  std::vector<std::shared_ptr<const Scenario>> scenarios_;
  std::shared_ptr<const Scenario> scenario_;
  std::shared_ptr<const RoadMap> map_;
  std::unique_ptr<World> world_;
  std::mt19937_64 rng_;
  std::vector<std::string> ids_;
  std::vector<size_t> npc_cursor_;
  std::vector<double> npc_time_offset_;
  std::vector<double> contact_time_;   // per vehicle; < 0 before contact
  std::vector<Pose2> contact_pose_;
  std::vector<std::pair<double, int>> neighbours_;  // scratch: distance, index
  std::vector<float> obs_;
  std::array<float, 2> prev_action_{};
  double prev_forward_speed_ = 0.0;
  double route_s_ = 0.0;
  double route_start_s_ = 0.0;
  double time_limit_ = 0.0;
  double reward_ = 0.0;
  bool terminated_ = false, truncated_ = false, needs_reset_ = true;
  bool off_road_reported_ = false;
  StepInfo info_;
  bool profiling_ = false;
  StepProfile profile_;
};

}  // namespace accsim
