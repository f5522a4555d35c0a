#include "accsim/env/scenario.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include "accsim/env/json_fields.h"

namespace accsim {
namespace {

struct FamilyName {
  ScenarioFamily family;
  std::string_view name;
};
constexpr std::array<FamilyName, 5> kFamilies{{
    {ScenarioFamily::kStraightObstacle, "straight_obstacle"},
    {ScenarioFamily::kUnprotectedLeftTurn, "unprotected_left_turn"},
    {ScenarioFamily::kRightTurn, "right_turn"},
    {ScenarioFamily::kLaneChanging, "lane_changing"},
    {ScenarioFamily::kReconstructed, "reconstructed"},
}};

// Wraps enum parsers that throw std::invalid_argument into FieldErrors with
// the full path.
template <typename F>
auto ParseEnum(const std::string& path, F&& parse) {
  try {
    return parse();
  } catch (const FieldError&) {
    throw;
  } catch (const std::invalid_argument& e) {
    std::string msg = e.what();
    const auto colon = msg.find(": ");
    throw FieldError(path, colon == std::string::npos ? msg : msg.substr(colon + 2));
  }
}

Pose2 PoseFromJson(JsonFields f) {
  Pose2 p;
  p.x = f.Number("x", -1e5, 1e5);
  p.y = f.Number("y", -1e5, 1e5);
  p.yaw = f.Number("yaw", -2 * kPi, 2 * kPi);
  f.RejectUnknown();
  return p;
}

nlohmann::json ToJson(const Pose2& p) { return {{"x", p.x}, {"y", p.y}, {"yaw", p.yaw}}; }

VehicleClass ReadVehicleClass(JsonFields& f) {
  const std::string name = f.String("vehicle_class", "car");
  return ParseEnum(f.PathOf("vehicle_class"), [&] { return VehicleClassFromString(name); });
}

}  // namespace

std::string_view ToString(ScenarioFamily f) {
  for (const auto& r : kFamilies) {
    if (r.family == f) return r.name;
  }
  return "unknown";
}

ScenarioFamily ScenarioFamilyFromString(std::string_view name) {
  std::string names;
  for (const auto& r : kFamilies) {
    if (r.name == name) return r.family;
    names += (names.empty() ? "" : ", ") + std::string(r.name);
  }
  throw FieldError("family", "unknown '" + std::string(name) + "' (expected " + names + ")");
}

RoadMapSpec RoadMapSpecFromJson(const nlohmann::json& j, const std::string& path) {
  JsonFields f(j, path);
  RoadMapSpec m;
  const std::string type = f.String("type");
  m.type = ParseEnum(f.PathOf("type"), [&] { return RoadTypeFromString(type); });
  m.lanes_per_direction = static_cast<int>(f.Integer("lanes_per_direction", 1, 4, 1));
  m.divided = f.Bool("divided", false);
  m.lane_width = f.Number("lane_width", 2.5, 5.0, m.lane_width);
  m.median_width = f.Number("median_width", 0.5, 20.0, m.median_width);
  m.length = f.Number("length", 20.0, 2000.0, m.length);
  m.speed_limit = f.Number("speed_limit", 1.0, 50.0, m.speed_limit);
  const std::string surface = f.String("surface", "dry");
  m.surface = ParseEnum(f.PathOf("surface"), [&] { return SurfaceFromString(surface); });
  f.RejectUnknown();
  // The map must be buildable (e.g. junction arms longer than the junction);
  // RoadMap's messages start with the field name.
  try {
    RoadMap check(m);
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    const auto colon = msg.find(": ");
    throw FieldError(f.PathOf(msg.substr(0, colon)), colon == std::string::npos ? msg : msg.substr(colon + 2));
  }
  return m;
}

nlohmann::json ToJson(const RoadMapSpec& m) {
  return {{"type", std::string(ToString(m.type))},
          {"lanes_per_direction", m.lanes_per_direction},
          {"divided", m.divided},
          {"lane_width", m.lane_width},
          {"median_width", m.median_width},
          {"length", m.length},
          {"speed_limit", m.speed_limit},
          {"surface", std::string(ToString(m.surface))}};
}

Trajectory TrajectoryFromJson(const nlohmann::json& j, const std::string& path) {
  if (!j.is_array()) throw FieldError(path, std::string("expected an array, got ") + j.type_name());
  if (j.empty()) throw FieldError(path, "needs at least 1 point");
  std::vector<TrajectoryPoint> pts;
  pts.reserve(j.size());
  for (size_t i = 0; i < j.size(); ++i) {
    JsonFields f(j[i], path + "[" + std::to_string(i) + "]");
    TrajectoryPoint p;
    p.t = f.Number("t", 0.0, 3600.0);
    p.x = f.Number("x", -1e5, 1e5);
    p.y = f.Number("y", -1e5, 1e5);
    p.yaw = f.Number("yaw", -2 * kPi, 2 * kPi);
    p.v = f.Number("v", -30.0, 100.0);  // negative: reversing (a vehicle backing out of a drive)
    f.RejectUnknown();
    pts.push_back(p);
  }
  try {
    return Trajectory(std::move(pts));
  } catch (const std::invalid_argument& e) {
    // Trajectory reports "[i].field: reason"; prefix it with our path.
    const std::string msg = e.what();
    const auto colon = msg.find(": ");
    throw FieldError(path + msg.substr(0, colon), msg.substr(colon + 2));
  }
}

nlohmann::json ToJson(const Trajectory& t) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& p : t.points()) {
    a.push_back({{"t", p.t}, {"x", p.x}, {"y", p.y}, {"yaw", p.yaw}, {"v", p.v}});
  }
  return a;
}

Scenario ScenarioFromJson(const nlohmann::json& j) {
  JsonFields root(j, "");
  const auto version = root.Integer("schema_version", 1, 1000);
  if (version != kScenarioSchemaVersion) {
    throw FieldError("schema_version", "unsupported version " + std::to_string(version) +
                                           " (this accsim reads version " +
                                           std::to_string(kScenarioSchemaVersion) + ")");
  }
  Scenario s;
  s.name = root.String("name", "");
  const std::string family = root.String("family");
  s.family = ScenarioFamilyFromString(family);
  const auto seed = root.Raw("seed");
  if (seed) {
    if (!seed->is_number_unsigned() && !(seed->is_number_integer() && seed->get<long long>() >= 0)) {
      throw FieldError("seed", "expected a non-negative integer");
    }
    s.seed = seed->get<uint64_t>();
  }
  s.time_limit = root.Number("time_limit", 0.1, 600.0, s.time_limit);
  s.map = RoadMapSpecFromJson(*[&] {
    const auto* m = root.Raw("map");
    if (!m) throw FieldError("map", "missing required field");
    return m;
  }(), "map");

  {
    JsonFields e = root.Object("ego");
    s.ego.id = e.String("id", "ego");
    s.ego.vehicle_class = ReadVehicleClass(e);
    s.ego.start = PoseFromJson(e.Object("start"));
    s.ego.speed = e.Number("speed", 0.0, 70.0);
    s.ego.target_speed = e.Number("target_speed", 0.0, 70.0, s.ego.speed);
    const auto& route = e.Array("route", 2);
    std::vector<Vec2> pts;
    for (size_t i = 0; i < route.size(); ++i) {
      auto [x, y] = ReadPoint(route[i], e.PathOf("route") + "[" + std::to_string(i) + "]");
      pts.emplace_back(x, y);
    }
    try {
      s.ego.route = Polyline(std::move(pts));
    } catch (const std::invalid_argument& ex) {
      throw FieldError(e.PathOf("route"), ex.what());
    }
    e.RejectUnknown();
  }

  const auto& npcs = root.Array("npcs");
  std::set<std::string> ids{s.ego.id};
  for (size_t i = 0; i < npcs.size(); ++i) {
    const std::string path = "npcs[" + std::to_string(i) + "]";
    JsonFields n(npcs[i], path);
    NpcSpec npc;
    npc.id = n.String("id");
    if (npc.id.empty()) throw FieldError(n.PathOf("id"), "must not be empty");
    if (!ids.insert(npc.id).second) {
      throw FieldError(n.PathOf("id"), "duplicate vehicle id '" + npc.id + "'");
    }
    npc.vehicle_class = ReadVehicleClass(n);
    npc.reference = TrajectoryFromJson(n.Array("reference", 1), n.PathOf("reference"));
    if (n.Has("post_collision")) {
      JsonFields pc = n.Object("post_collision");
      const std::string source = pc.String("source");
      if (source == "physics") {
        npc.post_collision = PostCollisionSource::kPhysics;
      } else if (source == "predicted") {
        npc.post_collision = PostCollisionSource::kPredicted;
        npc.predicted = TrajectoryFromJson(pc.Array("trajectory", 1), pc.PathOf("trajectory"));
      } else {
        throw FieldError(pc.PathOf("source"),
                         "unknown '" + source + "' (expected physics, predicted)");
      }
      pc.RejectUnknown();
    }
    n.RejectUnknown();
    s.npcs.push_back(std::move(npc));
  }
  const auto count = root.Integer("vehicle_count", 1, 64);
  if (count != s.vehicle_count()) {
    throw FieldError("vehicle_count", "says " + std::to_string(count) + " but the scenario has " +
                                          std::to_string(s.vehicle_count()) +
                                          " vehicles (ego + npcs)");
  }
  if (const auto* p = root.Raw("provenance")) {
    if (!p->is_object()) throw FieldError("provenance", "expected an object");
    s.provenance = *p;
  }
  root.RejectUnknown();
  return s;
}

nlohmann::json ToJson(const Scenario& s) {
  nlohmann::json route = nlohmann::json::array();
  for (const auto& p : s.ego.route.points()) route.push_back({p.x(), p.y()});
  nlohmann::json npcs = nlohmann::json::array();
  for (const auto& n : s.npcs) {
    nlohmann::json pc = {{"source", n.post_collision == PostCollisionSource::kPhysics ? "physics"
                                                                                      : "predicted"}};
    if (n.post_collision == PostCollisionSource::kPredicted) pc["trajectory"] = ToJson(n.predicted);
    npcs.push_back({{"id", n.id},
                    {"vehicle_class", std::string(ToString(n.vehicle_class))},
                    {"reference", ToJson(n.reference)},
                    {"post_collision", pc}});
  }
  return {{"schema_version", kScenarioSchemaVersion},
          {"name", s.name},
          {"family", std::string(ToString(s.family))},
          {"vehicle_count", s.vehicle_count()},
          {"seed", s.seed},
          {"time_limit", s.time_limit},
          {"map", ToJson(s.map)},
          {"ego",
           {{"id", s.ego.id},
            {"vehicle_class", std::string(ToString(s.ego.vehicle_class))},
            {"start", ToJson(s.ego.start)},
            {"speed", s.ego.speed},
            {"target_speed", s.ego.target_speed},
            {"route", route}}},
          {"npcs", npcs},
          {"provenance", s.provenance}};
}

Scenario LoadScenarioFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot open file");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::invalid_argument(path + ": malformed JSON (" + e.what() + ")");
  }
  try {
    return ScenarioFromJson(j);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(path + ": " + e.what());
  }
}

void SaveJsonFile(const nlohmann::json& j, const std::string& path, int indent) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path + ": cannot write (" + tmp + ")");
    out << j.dump(indent) << "\n";
    out.flush();
    if (!out) throw std::runtime_error(path + ": write failed");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot replace the file");
  }
}

}  // namespace accsim
