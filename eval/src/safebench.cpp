#include "accsim/eval/safebench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace accsim {
namespace {

constexpr double kTtcCap = 10.0;  // [s] episodes without a finite TTC count as this

struct Accumulator {
  int n = 0, collisions = 0, off_road = 0, goals = 0;
  double completion = 0, ttc = 0, collision_speed = 0, ret = 0;

  void Add(const EpisodeResult& r, double route_length) {
    ++n;
    collisions += r.collision.has_value();
    off_road += r.outcome == "off_road";
    goals += r.outcome == "goal";
    completion += route_length > 0 ? std::clamp(r.route_progress / route_length, 0.0, 1.0) : 0.0;
    ttc += std::isfinite(r.min_ttc) ? std::min(r.min_ttc, kTtcCap) : kTtcCap;
    if (r.collision) collision_speed += r.collision->relative_speed;
    ret += r.episode_return;
  }
  SafetyMetrics Metrics() const {
    SafetyMetrics m;
    m.episodes = n;
    if (n == 0) return m;
    m.collision_rate = static_cast<double>(collisions) / n;
    m.off_road_rate = static_cast<double>(off_road) / n;
    m.goal_rate = static_cast<double>(goals) / n;
    m.route_completion = completion / n;
    m.mean_min_ttc = ttc / n;
    m.mean_collision_speed = collisions ? collision_speed / collisions : 0.0;
    m.mean_return = ret / n;
    return m;
  }
};

nlohmann::json ToJson(const SafetyMetrics& m) {
  return {{"episodes", m.episodes},
          {"collision_rate", m.collision_rate},
          {"off_road_rate", m.off_road_rate},
          {"route_completion", m.route_completion},
          {"goal_rate", m.goal_rate},
          {"mean_min_ttc", m.mean_min_ttc},
          {"mean_collision_speed", m.mean_collision_speed},
          {"mean_return", m.mean_return}};
}

}  // namespace

std::string VehicleCountCell(const Scenario& s) {
  if (s.provenance.contains("vehicle_count_cell") && s.provenance["vehicle_count_cell"].is_string()) {
    return s.provenance["vehicle_count_cell"].get<std::string>();
  }
  return s.vehicle_count() <= 2 ? "two" : s.vehicle_count() == 3 ? "three" : "many";
}

EvaluationReport Evaluate(const std::vector<std::shared_ptr<const Scenario>>& scenarios, const PolicyFn& policy,
                          const std::string& driver_name, const CrashEnvConfig& config) {
  if (scenarios.empty()) throw std::invalid_argument("scenarios: nothing to evaluate");
  EvaluationReport report;
  report.driver = driver_name;
  CrashEnv env(config, scenarios);
  Accumulator all;
  std::map<std::string, Accumulator> cells;
  for (size_t i = 0; i < scenarios.size(); ++i) {
    const EpisodeResult r = RunEpisode(env, policy, i, static_cast<int>(i));
    const double length = env.info().route_length;
    all.Add(r, length);
    const Scenario& s = *scenarios[i];
    cells[std::string(ToString(s.family)) + "/" + VehicleCountCell(s)].Add(r, length);
  }
  report.overall = all.Metrics();
  for (const auto& [key, acc] : cells) report.cells[key] = acc.Metrics();
  return report;
}

nlohmann::json ToJson(const EvaluationReport& r) {
  nlohmann::json cells = nlohmann::json::object();
  for (const auto& [key, m] : r.cells) cells[key] = ToJson(m);
  return {{"driver", r.driver}, {"overall", ToJson(r.overall)}, {"cells", cells}};
}

std::string ToMarkdown(const std::vector<EvaluationReport>& reports) {
  std::ostringstream os;
  os << "| cell |";
  for (const auto& r : reports) os << " CR " << r.driver << " | RC " << r.driver << " |";
  os << " episodes |\n|---|";
  for (size_t i = 0; i < reports.size(); ++i) os << "---|---|";
  os << "---|\n";
  if (reports.empty()) return os.str();
  auto row = [&](const std::string& name, auto get) {
    os << "| " << name << " |";
    int episodes = 0;
    for (const auto& r : reports) {
      const SafetyMetrics m = get(r);
      char buf[64];
      std::snprintf(buf, sizeof buf, " %.1f %% | %.1f %% |", 100 * m.collision_rate, 100 * m.route_completion);
      os << buf;
      episodes = m.episodes;
    }
    os << " " << episodes << " |\n";
  };
  for (const auto& cell : reports.front().cells) {
    const auto& key = cell.first;
    row(key, [&](const EvaluationReport& r) {
      const auto it = r.cells.find(key);
      return it == r.cells.end() ? SafetyMetrics{} : it->second;
    });
  }
  row("**all**", [](const EvaluationReport& r) { return r.overall; });
  return os.str();
}

}  // namespace accsim
