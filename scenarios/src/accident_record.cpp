#include "accsim/scenarios/accident_record.h"

#include <array>
#include <stdexcept>
#include <utility>

namespace accsim {

std::string_view ToString(Provenance p) {
  switch (p) {
    case Provenance::kStated: return "stated";
    case Provenance::kInferred: return "inferred";
    case Provenance::kDefaulted: return "defaulted";
  }
  return "defaulted";
}

std::string_view ToString(RoadKind k) {
  switch (k) {
    case RoadKind::kStraight: return "straight";
    case RoadKind::kCurve: return "curve";
    case RoadKind::kIntersection: return "intersection";
    case RoadKind::kTJunction: return "t_junction";
    case RoadKind::kRamp: return "ramp";
    case RoadKind::kDriveway: return "driveway";
  }
  return "straight";
}

std::string_view ToString(Movement m) {
  switch (m) {
    case Movement::kStraight: return "going_straight";
    case Movement::kTurnLeft: return "turning_left";
    case Movement::kTurnRight: return "turning_right";
    case Movement::kChangingLanes: return "changing_lanes";
    case Movement::kStopped: return "stopped";
    case Movement::kSlowing: return "slowing";
    case Movement::kBacking: return "backing";
    case Movement::kPassing: return "passing";
    case Movement::kMerging: return "merging";
    case Movement::kUnknown: return "unknown";
  }
  return "unknown";
}

std::string_view ToString(CrashType t) {
  switch (t) {
    case CrashType::kRearEnd: return "rear_end";
    case CrashType::kHeadOn: return "head_on";
    case CrashType::kAngle: return "angle";
    case CrashType::kSideswipeSame: return "sideswipe_same_direction";
    case CrashType::kSideswipeOpposite: return "sideswipe_opposite_direction";
    case CrashType::kTurnAcrossPath: return "turn_across_path";
    case CrashType::kTurnIntoPath: return "turn_into_path";
    case CrashType::kSingleVehicle: return "single_vehicle";
    case CrashType::kUnknown: return "unknown";
  }
  return "unknown";
}

std::string_view ToString(DamageArea a) {
  switch (a) {
    case DamageArea::kFront: return "front";
    case DamageArea::kRear: return "rear";
    case DamageArea::kLeft: return "left";
    case DamageArea::kRight: return "right";
    case DamageArea::kUnknown: return "unknown";
  }
  return "unknown";
}

std::string_view ToString(CrashLocation l) {
  switch (l) {
    case CrashLocation::kJunction: return "junction";
    case CrashLocation::kSegment: return "segment";
    case CrashLocation::kDriveway: return "driveway";
    case CrashLocation::kRamp: return "ramp";
  }
  return "segment";
}

namespace {

// One generic inverse for the small enums above: tries every value.
template <typename E, size_t N>
E FromName(std::string_view s, const std::array<E, N>& all, const char* what) {
  for (E e : all) {
    if (ToString(e) == s) return e;
  }
  std::string names;
  for (E e : all) names += (names.empty() ? "" : ", ") + std::string(ToString(e));
  throw std::invalid_argument(std::string(what) + ": unknown value '" + std::string(s) + "' (expected one of " +
                              names + ")");
}

}  // namespace

RoadKind RoadKindFromString(std::string_view s) {
  return FromName(s,
                  std::array{RoadKind::kStraight, RoadKind::kCurve, RoadKind::kIntersection, RoadKind::kTJunction,
                             RoadKind::kRamp, RoadKind::kDriveway},
                  "road kind");
}
Movement MovementFromString(std::string_view s) {
  return FromName(s,
                  std::array{Movement::kStraight, Movement::kTurnLeft, Movement::kTurnRight, Movement::kChangingLanes,
                             Movement::kStopped, Movement::kSlowing, Movement::kBacking, Movement::kPassing,
                             Movement::kMerging, Movement::kUnknown},
                  "movement");
}
CrashType CrashTypeFromString(std::string_view s) {
  return FromName(s,
                  std::array{CrashType::kRearEnd, CrashType::kHeadOn, CrashType::kAngle, CrashType::kSideswipeSame,
                             CrashType::kSideswipeOpposite, CrashType::kTurnAcrossPath, CrashType::kTurnIntoPath,
                             CrashType::kSingleVehicle, CrashType::kUnknown},
                  "crash type");
}
DamageArea DamageAreaFromString(std::string_view s) {
  return FromName(
      s, std::array{DamageArea::kFront, DamageArea::kRear, DamageArea::kLeft, DamageArea::kRight, DamageArea::kUnknown},
      "damage area");
}
CrashLocation CrashLocationFromString(std::string_view s) {
  return FromName(
      s, std::array{CrashLocation::kJunction, CrashLocation::kSegment, CrashLocation::kDriveway, CrashLocation::kRamp},
      "crash location");
}

DamageArea AccidentRecord::AreaOf(const std::string& vehicle_id) const {
  if (crash.striking.known() && crash.striking.value == vehicle_id) return crash.striking_area.value;
  if (crash.struck.known() && crash.struck.value == vehicle_id) return crash.struck_area.value;
  return DamageArea::kUnknown;
}

namespace {

template <typename T, typename F>
nlohmann::json J(const Field<T>& f, F&& conv) {
  return {{"value", conv(f.value)}, {"source", std::string(ToString(f.source))}};
}
template <typename T>
nlohmann::json J(const Field<T>& f) {
  return J(f, [](const T& v) { return v; });
}
const auto kStr = [](auto v) { return std::string(ToString(v)); };
const auto kCompass = [](const std::optional<Compass>& c) {
  return c ? nlohmann::json(std::string(ToString(*c))) : nlohmann::json(nullptr);
};

}  // namespace

nlohmann::json ToJson(const AccidentRecord& r) {
  nlohmann::json vehicles = nlohmann::json::array();
  for (const auto& v : r.vehicles) {
    vehicles.push_back({{"id", v.id},
                        {"vehicle_class", J(v.vehicle_class, kStr)},
                        {"description", J(v.description)},
                        {"travel", J(v.travel, kCompass)},
                        {"lane", J(v.lane)},
                        {"movement", J(v.movement, kStr)},
                        {"pre_event_movement", J(v.pre_event, kStr)},
                        {"speed_mps", J(v.speed_mps)},
                        {"speed_unit", J(v.speed_unit)},
                        {"parked", J(v.parked)}});
  }
  return {{"schema_version", kAccidentRecordSchemaVersion},
          {"road",
           {{"kind", J(r.road.kind, kStr)},
            {"lanes_total", J(r.road.lanes_total)},
            {"lanes_per_direction", J(r.road.lanes_per_direction)},
            {"divided", J(r.road.divided)},
            {"one_way", J(r.road.one_way)},
            {"speed_limit_mps", J(r.road.speed_limit_mps)},
            {"speed_limit_unit", J(r.road.speed_limit_unit)},
            {"surface", J(r.road.surface, kStr)},
            {"friction", FrictionCoefficient(r.road.surface.value)},
            {"weather", J(r.road.weather)},
            {"lighting", J(r.road.lighting)},
            {"grade", J(r.road.grade)}}},
          {"participant_count", J(r.participant_count)},
          {"vehicles", vehicles},
          {"crash",
           {{"type", J(r.crash.type, kStr)},
            {"striking", J(r.crash.striking)},
            {"struck", J(r.crash.struck)},
            {"striking_area", J(r.crash.striking_area, kStr)},
            {"struck_area", J(r.crash.struck_area, kStr)},
            {"striking_detail", J(r.crash.striking_detail)},
            {"struck_detail", J(r.crash.struck_detail)},
            {"location", J(r.crash.location, kStr)}}},
          {"camera_hint", J(r.camera_hint)},
          {"warnings", r.warnings}};
}

namespace {

Provenance ProvenanceFrom(const nlohmann::json& j, const std::string& path) {
  if (!j.is_string()) throw std::invalid_argument(path + ".source: expected a string");
  const std::string s = j.get<std::string>();
  if (s == "stated") return Provenance::kStated;
  if (s == "inferred") return Provenance::kInferred;
  if (s == "defaulted") return Provenance::kDefaulted;
  throw std::invalid_argument(path + ".source: unknown value '" + s + "' (expected stated, inferred or defaulted)");
}

// Reads {"value": ..., "source": ...} at j[key] into f with conv; a missing
// key keeps the default.
template <typename T, typename F>
void ReadField(const nlohmann::json& j, const char* key, const std::string& parent, Field<T>& f, F&& conv) {
  if (!j.contains(key)) return;
  const std::string path = parent.empty() ? key : parent + "." + key;
  const nlohmann::json& fj = j.at(key);
  if (!fj.is_object() || !fj.contains("value")) throw std::invalid_argument(path + ": expected {\"value\", \"source\"}");
  try {
    f.value = conv(fj.at("value"));
  } catch (const std::exception& e) {
    throw std::invalid_argument(path + ".value: " + e.what());
  }
  f.source = fj.contains("source") ? ProvenanceFrom(fj.at("source"), path) : Provenance::kStated;
}

template <typename T>
T Plain(const nlohmann::json& v) {
  return v.get<T>();
}

int CountIn(const nlohmann::json& v, int lo, int hi) {
  const int n = v.get<int>();
  if (n < lo || n > hi) throw std::invalid_argument("out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return n;
}

}  // namespace

AccidentRecord AccidentRecordFromJson(const nlohmann::json& j) {
  if (!j.is_object()) throw std::invalid_argument("record: expected a JSON object");
  if (j.contains("schema_version") && j["schema_version"] != kAccidentRecordSchemaVersion) {
    throw std::invalid_argument("schema_version: expected " + std::to_string(kAccidentRecordSchemaVersion));
  }
  AccidentRecord r;
  const auto str = [](const nlohmann::json& v) { return v.get<std::string>(); };
  if (j.contains("road")) {
    const nlohmann::json& road = j["road"];
    if (!road.is_object()) throw std::invalid_argument("road: expected an object");
    ReadField(road, "kind", "road", r.road.kind, [&](const nlohmann::json& v) { return RoadKindFromString(str(v)); });
    ReadField(road, "lanes_total", "road", r.road.lanes_total, [](const nlohmann::json& v) { return CountIn(v, 1, 16); });
    ReadField(road, "lanes_per_direction", "road", r.road.lanes_per_direction,
              [](const nlohmann::json& v) { return CountIn(v, 1, 8); });
    ReadField(road, "divided", "road", r.road.divided, Plain<bool>);
    ReadField(road, "one_way", "road", r.road.one_way, Plain<bool>);
    ReadField(road, "speed_limit_mps", "road", r.road.speed_limit_mps, [](const nlohmann::json& v) {
      const double x = v.get<double>();
      if (!(x > 0.0 && x < 70.0)) throw std::invalid_argument("out of range (0, 70) m/s");
      return x;
    });
    ReadField(road, "speed_limit_unit", "road", r.road.speed_limit_unit, str);
    ReadField(road, "surface", "road", r.road.surface, [&](const nlohmann::json& v) { return SurfaceFromString(str(v)); });
    ReadField(road, "weather", "road", r.road.weather, str);
    ReadField(road, "lighting", "road", r.road.lighting, str);
    ReadField(road, "grade", "road", r.road.grade, str);
  }
  ReadField(j, "participant_count", "", r.participant_count, [](const nlohmann::json& v) { return CountIn(v, 1, 9); });
  if (j.contains("vehicles")) {
    if (!j["vehicles"].is_array()) throw std::invalid_argument("vehicles: expected an array");
    for (size_t i = 0; i < j["vehicles"].size(); ++i) {
      const nlohmann::json& vj = j["vehicles"][i];
      const std::string p = "vehicles[" + std::to_string(i) + "]";
      if (!vj.is_object()) throw std::invalid_argument(p + ": expected an object");
      VehicleRecord v;
      v.id = vj.contains("id") && vj["id"].is_string() ? vj["id"].get<std::string>() : "V" + std::to_string(i + 1);
      ReadField(vj, "vehicle_class", p, v.vehicle_class,
                [&](const nlohmann::json& x) { return VehicleClassFromString(str(x)); });
      ReadField(vj, "description", p, v.description, str);
      ReadField(vj, "travel", p, v.travel, [&](const nlohmann::json& x) -> std::optional<Compass> {
        if (x.is_null()) return std::nullopt;
        return CompassFromString(str(x));
      });
      ReadField(vj, "lane", p, v.lane, [](const nlohmann::json& x) { return CountIn(x, 0, 16); });
      ReadField(vj, "movement", p, v.movement, [&](const nlohmann::json& x) { return MovementFromString(str(x)); });
      v.pre_event = v.movement;
      ReadField(vj, "pre_event_movement", p, v.pre_event,
                [&](const nlohmann::json& x) { return MovementFromString(str(x)); });
      ReadField(vj, "speed_mps", p, v.speed_mps, [](const nlohmann::json& x) {
        const double s = x.get<double>();
        if (!(s >= 0.0 && s < 90.0)) throw std::invalid_argument("out of range [0, 90) m/s");
        return s;
      });
      ReadField(vj, "speed_unit", p, v.speed_unit, str);
      ReadField(vj, "parked", p, v.parked, Plain<bool>);
      r.vehicles.push_back(std::move(v));
    }
  }
  if (j.contains("crash")) {
    const nlohmann::json& c = j["crash"];
    if (!c.is_object()) throw std::invalid_argument("crash: expected an object");
    ReadField(c, "type", "crash", r.crash.type, [&](const nlohmann::json& v) { return CrashTypeFromString(str(v)); });
    ReadField(c, "striking", "crash", r.crash.striking, str);
    ReadField(c, "struck", "crash", r.crash.struck, str);
    const auto area = [&](const nlohmann::json& v) { return DamageAreaFromString(str(v)); };
    ReadField(c, "striking_area", "crash", r.crash.striking_area, area);
    ReadField(c, "struck_area", "crash", r.crash.struck_area, area);
    ReadField(c, "striking_detail", "crash", r.crash.striking_detail, str);
    ReadField(c, "struck_detail", "crash", r.crash.struck_detail, str);
    ReadField(c, "location", "crash", r.crash.location,
              [&](const nlohmann::json& v) { return CrashLocationFromString(str(v)); });
  }
  ReadField(j, "camera_hint", "", r.camera_hint, str);
  if (j.contains("warnings") && j["warnings"].is_array()) {
    for (const auto& w : j["warnings"]) {
      if (w.is_string()) r.warnings.push_back(w.get<std::string>());
    }
  }
  return r;
}

}  // namespace accsim
