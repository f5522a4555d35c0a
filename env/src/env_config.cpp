// CrashEnvConfig: JSON/YAML reading with full validation, and the
// observation/action layout derived from it.
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>

#include "accsim/env/crash_env.h"
#include "accsim/env/json_fields.h"

namespace accsim {
namespace {

// YAML scalars carry no type; numbers and booleans are recognised the way
// YAML 1.2 core schema does, everything else stays a string.
nlohmann::json YamlToJson(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null:
    case YAML::NodeType::Undefined:
      return nullptr;
    case YAML::NodeType::Scalar: {
      const std::string& s = node.Scalar();
      if (node.Tag() == "!") return s;  // quoted
      if (s == "true" || s == "True" || s == "TRUE") return true;
      if (s == "false" || s == "False" || s == "FALSE") return false;
      if (s == "null" || s == "~") return nullptr;
      try {
        size_t used = 0;
        const long long i = std::stoll(s, &used);
        if (used == s.size()) return i;
      } catch (...) {
      }
      try {
        size_t used = 0;
        const double d = std::stod(s, &used);
        if (used == s.size()) return d;
      } catch (...) {
      }
      if (s == ".nan" || s == ".NaN") return std::nan("");
      return s;
    }
    case YAML::NodeType::Sequence: {
      nlohmann::json a = nlohmann::json::array();
      for (const auto& n : node) a.push_back(YamlToJson(n));
      return a;
    }
    case YAML::NodeType::Map: {
      nlohmann::json o = nlohmann::json::object();
      for (const auto& kv : node) o[kv.first.as<std::string>()] = YamlToJson(kv.second);
      return o;
    }
  }
  return nullptr;
}

}  // namespace

const char* RewardTermName(int term) {
  static constexpr const char* kNames[kNumRewardTerms] = {
      "progress", "collision", "off_road", "lane_deviation", "comfort", "goal"};
  return term >= 0 && term < kNumRewardTerms ? kNames[term] : "unknown";
}

CrashEnvConfig CrashEnvConfigFromJson(const nlohmann::json& j) {
  CrashEnvConfig c;
  JsonFields f(j, "");
  c.policy_hz = f.Number("policy_hz", 1.0, 100.0, c.policy_hz);
  c.physics_hz = f.Number("physics_hz", 100.0, 2000.0, c.physics_hz);
  const double ratio = c.physics_hz / c.policy_hz;
  if (std::abs(ratio - std::round(ratio)) > 1e-9) {
    throw FieldError("physics_hz", "must be an integer multiple of policy_hz (" +
                                       std::to_string(c.physics_hz) + " / " +
                                       std::to_string(c.policy_hz) + " is not whole)");
  }
  c.solver_iterations = static_cast<int>(f.Integer("solver_iterations", 1, 100, c.solver_iterations));
  c.time_limit = f.Number("time_limit", 0.0, 3600.0, c.time_limit);
  c.observed_vehicles = static_cast<int>(f.Integer("observed_vehicles", 0, 64, c.observed_vehicles));
  c.observation_range = f.Number("observation_range", 1.0, 1000.0, c.observation_range);
  c.num_rays = static_cast<int>(f.Integer("num_rays", 0, 360, c.num_rays));
  c.ray_range = f.Number("ray_range", 1.0, 1000.0, c.ray_range);
  c.goal_tolerance = f.Number("goal_tolerance", 0.0, 100.0, c.goal_tolerance);
  c.post_contact_brake = f.Number("post_contact_brake", 0.0, 1.0, c.post_contact_brake);
  c.start_speed_jitter = f.Number("start_speed_jitter", 0.0, 20.0, c.start_speed_jitter);
  c.npc_time_jitter = f.Number("npc_time_jitter", 0.0, 5.0, c.npc_time_jitter);
  c.terminate_on_collision = f.Bool("terminate_on_collision", c.terminate_on_collision);
  if (f.Has("reward")) {
    JsonFields r = f.Object("reward");
    auto& w = c.reward;
    w.progress = r.Number("progress", -1e3, 1e3, w.progress);
    w.collision = r.Number("collision", -1e3, 1e3, w.collision);
    w.off_road = r.Number("off_road", -1e3, 1e3, w.off_road);
    w.lane_deviation = r.Number("lane_deviation", -1e3, 1e3, w.lane_deviation);
    w.comfort = r.Number("comfort", -1e3, 1e3, w.comfort);
    w.goal = r.Number("goal", -1e3, 1e3, w.goal);
    r.RejectUnknown();
  }
  f.RejectUnknown();
  return c;
}

nlohmann::json ToJson(const CrashEnvConfig& c) {
  return {{"policy_hz", c.policy_hz},
          {"physics_hz", c.physics_hz},
          {"solver_iterations", c.solver_iterations},
          {"time_limit", c.time_limit},
          {"observed_vehicles", c.observed_vehicles},
          {"observation_range", c.observation_range},
          {"num_rays", c.num_rays},
          {"ray_range", c.ray_range},
          {"goal_tolerance", c.goal_tolerance},
          {"post_contact_brake", c.post_contact_brake},
          {"start_speed_jitter", c.start_speed_jitter},
          {"npc_time_jitter", c.npc_time_jitter},
          {"terminate_on_collision", c.terminate_on_collision},
          {"reward",
           {{"progress", c.reward.progress},
            {"collision", c.reward.collision},
            {"off_road", c.reward.off_road},
            {"lane_deviation", c.reward.lane_deviation},
            {"comfort", c.reward.comfort},
            {"goal", c.reward.goal}}}};
}

CrashEnvConfig LoadCrashEnvConfig(const std::string& yaml_path) {
  YAML::Node node;
  try {
    node = YAML::LoadFile(yaml_path);
  } catch (const YAML::BadFile&) {
    throw std::invalid_argument(yaml_path + ": cannot open file");
  } catch (const YAML::Exception& e) {
    throw std::invalid_argument(yaml_path + ": malformed YAML (" + e.what() + ")");
  }
  try {
    nlohmann::json j = YamlToJson(node);
    if (j.is_null()) j = nlohmann::json::object();  // an empty file means all defaults
    return CrashEnvConfigFromJson(j);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(yaml_path + ": " + e.what());
  }
}

EnvSpec MakeEnvSpec(const CrashEnvConfig& c) {
  EnvSpec s;
  s.policy_dt = 1.0 / c.policy_hz;
  s.substeps = static_cast<int>(std::lround(c.physics_hz / c.policy_hz));
  auto add = [&](std::string name, std::string unit) {
    s.obs_names.push_back(std::move(name));
    s.obs_units.push_back(std::move(unit));
  };
  s.ego_offset = 0;
  add("ego.speed", "40 m/s");
  add("ego.accel", "10 m/s^2");
  add("ego.yaw_rate", "1 rad/s");
  add("ego.steer", "max_steer");
  add("ego.lateral_velocity", "10 m/s");
  add("ego.lane_offset", "half lane width (+ left)");
  add("ego.lane_heading_error", "pi rad");
  add("ego.on_road", "flag");
  add("ego.speed_limit", "40 m/s");
  add("ego.time_remaining", "time limit");
  s.route_offset = static_cast<int>(s.obs_names.size());
  add("route.progress", "route length");
  add("route.remaining", "200 m");
  add("route.offset", "5 m (+ left of the route)");
  add("route.heading_error_sin", "1");
  add("route.heading_error_cos", "1");
  s.vehicles_offset = static_cast<int>(s.obs_names.size());
  static const char* kFeatures[] = {"present", "dx", "dy", "dvx", "dvy", "cos_yaw", "sin_yaw", "length", "width"};
  static const char* kUnits[] = {"flag", "observation_range", "observation_range", "40 m/s", "40 m/s", "1", "1", "20 m", "5 m"};
  s.vehicle_features = 9;
  for (int k = 0; k < c.observed_vehicles; ++k) {
    for (int f = 0; f < s.vehicle_features; ++f) {
      add("vehicle[" + std::to_string(k) + "]." + kFeatures[f], kUnits[f]);
    }
  }
  s.rays_offset = static_cast<int>(s.obs_names.size());
  for (int r = 0; r < c.num_rays; ++r) add("ray[" + std::to_string(r) + "]", "ray_range");
  s.obs_dim = static_cast<int>(s.obs_names.size());
  s.action_names = {"accel", "steer"};
  for (int t = 0; t < kNumRewardTerms; ++t) s.reward_terms.emplace_back(RewardTermName(t));
  return s;
}

}  // namespace accsim
