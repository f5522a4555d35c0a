#include "accsim/scenarios/crash_description.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <utility>

namespace accsim {
namespace {

constexpr std::array<std::pair<Manoeuvre, std::string_view>, 11> kManoeuvres{{
    {Manoeuvre::kStraight, "straight"},
    {Manoeuvre::kTurnLeft, "turn_left"},
    {Manoeuvre::kTurnRight, "turn_right"},
    {Manoeuvre::kLaneChangeLeft, "lane_change_left"},
    {Manoeuvre::kLaneChangeRight, "lane_change_right"},
    {Manoeuvre::kStopped, "stopped"},
    {Manoeuvre::kSlowing, "slowing"},
    {Manoeuvre::kBacking, "backing"},
    {Manoeuvre::kPassing, "passing"},
    {Manoeuvre::kMerging, "merging"},
    {Manoeuvre::kUnknown, "unknown"},
}};
constexpr std::array<std::pair<ImpactArea, std::string_view>, 9> kAreas{{
    {ImpactArea::kFront, "front"},
    {ImpactArea::kRear, "rear"},
    {ImpactArea::kLeft, "left"},
    {ImpactArea::kRight, "right"},
    {ImpactArea::kFrontLeft, "front_left"},
    {ImpactArea::kFrontRight, "front_right"},
    {ImpactArea::kRearLeft, "rear_left"},
    {ImpactArea::kRearRight, "rear_right"},
    {ImpactArea::kUnknown, "unknown"},
}};

constexpr std::array<std::pair<ObstaclePlace, std::string_view>, 3> kPlaces{{
    {ObstaclePlace::kInLane, "in_lane"},
    {ObstaclePlace::kLeftRoadside, "left_roadside"},
    {ObstaclePlace::kRightRoadside, "right_roadside"},
}};

template <typename E, size_t N>
std::string_view Name(const std::array<std::pair<E, std::string_view>, N>& table, E value) {
  for (const auto& [e, name] : table) {
    if (e == value) return name;
  }
  return "unknown";
}

template <typename E, size_t N>
E Parse(const std::array<std::pair<E, std::string_view>, N>& table, std::string_view s, const char* what) {
  std::string names;
  for (const auto& [e, name] : table) {
    if (name == s) return e;
    names += (names.empty() ? "" : ", ") + std::string(name);
  }
  throw std::invalid_argument(std::string(what) + ": unknown value '" + std::string(s) + "' (expected one of " +
                              names + ")");
}

Provenance ProvenanceFromString(std::string_view s, const std::string& path) {
  for (const Provenance p : {Provenance::kStated, Provenance::kInferred, Provenance::kDefaulted}) {
    if (ToString(p) == s) return p;
  }
  throw std::invalid_argument(path + ".source: unknown value '" + std::string(s) +
                              "' (expected stated, inferred or defaulted)");
}

bool Stated(Provenance p) { return p == Provenance::kStated; }
// Kept on a contradiction: stated over inferred over defaulted.
int Rank(Provenance p) { return p == Provenance::kStated ? 2 : p == Provenance::kInferred ? 1 : 0; }

std::string VehicleField(size_t i) { return "vehicles[" + std::to_string(i) + "]"; }

std::string_view Expected(CrashType t) {
  switch (t) {
    case CrashType::kRearEnd:
    case CrashType::kSideswipeSame: return "the same direction";
    case CrashType::kHeadOn:
    case CrashType::kSideswipeOpposite: return "the opposite direction";
    case CrashType::kAngle: return "a crossing direction";
    default: return "any direction";
  }
}

// The striker and struck vehicles' indices, -1 when not named.
std::pair<int, int> Pair(const CrashDescription& d) {
  return {d.striker.known() ? d.IndexOf(d.striker.value) : -1, d.struck.known() ? d.IndexOf(d.struck.value) : -1};
}

// Directions against the crash type: the weaker of the type and the
// weaker direction gives way (a direction on a tie).
void ReconcileCourse(CrashDescription& d) {
  const auto [a, b] = Pair(d);
  if (a < 0 || b < 0 || a == b || !d.type.known()) return;
  auto& va = d.vehicles[static_cast<size_t>(a)];
  auto& vb = d.vehicles[static_cast<size_t>(b)];
  const auto course = CourseOf(va, vb);
  if (!course || TypeFits(d.type.value, *course)) return;
  const bool a_weaker = Rank(va.travel.source) < Rank(vb.travel.source);
  auto& weak = a_weaker ? va : vb;
  const size_t weak_index = static_cast<size_t>(a_weaker ? a : b);
  if (Stated(d.type.source) && Stated(weak.travel.source)) return;  // Validate refuses
  const std::string directions = va.id + " " + std::string(ToString(*va.travel.value)) + ", " + vb.id + " " +
                                 std::string(ToString(*vb.travel.value));
  if (Rank(d.type.source) < Rank(weak.travel.source)) {
    d.warnings.push_back("type: " + std::string(ToString(d.type.source)) + " " + std::string(ToString(d.type.value)) +
                         " contradicts the " + std::string(ToString(weak.travel.source)) + " directions (" +
                         directions + "); set aside, the type is inferred again");
    d.type = {CrashType::kUnknown, Provenance::kDefaulted};
  } else {
    d.warnings.push_back(VehicleField(weak_index) + ".travel: " + std::string(ToString(weak.travel.source)) + " " +
                         std::string(ToString(*weak.travel.value)) + " contradicts the " +
                         std::string(ToString(d.type.source)) + " crash type " + std::string(ToString(d.type.value)) +
                         " (expected " + std::string(Expected(d.type.value)) + "); set aside");
    weak.travel = {};
  }
}

// A stopped vehicle with a speed: the weaker gives way (the speed on a tie).
void ReconcileStopped(CrashDescription& d) {
  for (size_t i = 0; i < d.vehicles.size(); ++i) {
    auto& v = d.vehicles[i];
    if (v.movement.value != Manoeuvre::kStopped || !v.speed.value || *v.speed.value <= 1.0) continue;
    if (!v.movement.known() || !v.speed.known()) continue;
    if (Stated(v.movement.source) && Stated(v.speed.source)) continue;  // Validate refuses
    char speed[32];
    std::snprintf(speed, sizeof speed, "%.1f m/s", *v.speed.value);
    if (Rank(v.movement.source) < Rank(v.speed.source)) {
      d.warnings.push_back(VehicleField(i) + ".movement: inferred stopped contradicts the stated speed " + speed +
                           "; set aside, planned straight");
      v.movement = {Manoeuvre::kStraight, Provenance::kDefaulted};
    } else {
      d.warnings.push_back(VehicleField(i) + ".speed: " + std::string(ToString(v.speed.source)) + " " + speed +
                           " contradicts movement stopped; set aside");
      v.speed = {};
    }
  }
}

// A lane outside the lane count: a stated lane widens an unstated count,
// else the lane gives way.
void ReconcileLanes(CrashDescription& d) {
  auto& lanes = d.road.lanes_per_direction;
  for (size_t i = 0; i < d.vehicles.size(); ++i) {
    auto& lane = d.vehicles[i].lane;
    if (!lane.value || (*lane.value >= 0 && *lane.value < lanes.value)) continue;
    if (Stated(lane.source) && Stated(lanes.source)) continue;  // Validate refuses
    if (Rank(lanes.source) < Rank(lane.source) && *lane.value >= 0 && *lane.value < 4) {
      d.warnings.push_back("road.lanes_per_direction: " + std::string(ToString(lanes.source)) + " " +
                           std::to_string(lanes.value) + " has no lane " + std::to_string(*lane.value) + " (" +
                           VehicleField(i) + ".lane); raised to " + std::to_string(*lane.value + 1));
      lanes.Set(*lane.value + 1, Provenance::kInferred);
    } else {
      d.warnings.push_back(VehicleField(i) + ".lane: " + std::string(ToString(lane.source)) + " " +
                           std::to_string(*lane.value) + " is not a lane of a road with " +
                           std::to_string(lanes.value) + " lane(s) per direction; set aside");
      lane = {};
    }
  }
}

template <typename T, typename F>
nlohmann::json J(const Field<T>& f, F&& conv) {
  return {{"value", conv(f.value)}, {"source", std::string(ToString(f.source))}};
}
template <typename T>
nlohmann::json J(const Field<T>& f) {
  return J(f, [](const T& v) { return v; });
}

// Reads {"value": ..., "source": ...}; a missing field keeps its default.
template <typename T, typename F>
void Read(const nlohmann::json& j, const char* key, const std::string& path, Field<T>& f, F&& conv) {
  if (!j.contains(key)) return;
  const std::string p = path + key;
  const auto& o = j.at(key);
  if (!o.is_object() || !o.contains("value")) throw std::invalid_argument(p + ": expected {\"value\", \"source\"}");
  try {
    f.value = conv(o.at("value"));
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(p + ".value: " + e.what());
  }
  f.source = o.contains("source") ? ProvenanceFromString(o.at("source").get<std::string>(), p) : Provenance::kStated;
}
template <typename T>
void Read(const nlohmann::json& j, const char* key, const std::string& path, Field<T>& f) {
  Read(j, key, path, f, [](const nlohmann::json& v) { return v.get<T>(); });
}

}  // namespace

std::string_view ToString(Manoeuvre m) { return Name(kManoeuvres, m); }
std::string_view ToString(ImpactArea a) { return Name(kAreas, a); }
std::string_view ToString(ObstaclePlace p) { return Name(kPlaces, p); }
Manoeuvre ManoeuvreFromString(std::string_view s) { return Parse(kManoeuvres, s, "movement"); }
ImpactArea ImpactAreaFromString(std::string_view s) { return Parse(kAreas, s, "impact_area"); }
ObstaclePlace ObstaclePlaceFromString(std::string_view s) { return Parse(kPlaces, s, "obstacle"); }

bool AreaIncludes(ImpactArea area, ImpactArea face) {
  if (area == ImpactArea::kUnknown || area == face) return true;
  switch (area) {
    case ImpactArea::kFrontLeft: return face == ImpactArea::kFront || face == ImpactArea::kLeft;
    case ImpactArea::kFrontRight: return face == ImpactArea::kFront || face == ImpactArea::kRight;
    case ImpactArea::kRearLeft: return face == ImpactArea::kRear || face == ImpactArea::kLeft;
    case ImpactArea::kRearRight: return face == ImpactArea::kRear || face == ImpactArea::kRight;
    default: return false;
  }
}

ImpactArea ImpactAreaFrom(DamageArea plane, std::string_view detail) {
  const bool front = detail.find("front") != std::string_view::npos;
  const bool rear = detail.find("rear") != std::string_view::npos || detail.find("back") != std::string_view::npos;
  const bool left = detail.find("left") != std::string_view::npos;
  const bool right = detail.find("right") != std::string_view::npos;
  if (front && left) return ImpactArea::kFrontLeft;
  if (front && right) return ImpactArea::kFrontRight;
  if (rear && left) return ImpactArea::kRearLeft;
  if (rear && right) return ImpactArea::kRearRight;
  switch (plane) {
    case DamageArea::kFront: return ImpactArea::kFront;
    case DamageArea::kRear: return ImpactArea::kRear;
    case DamageArea::kLeft: return ImpactArea::kLeft;
    case DamageArea::kRight: return ImpactArea::kRight;
    case DamageArea::kUnknown: break;
  }
  return ImpactArea::kUnknown;
}

int CrashDescription::IndexOf(const std::string& id) const {
  for (size_t i = 0; i < vehicles.size(); ++i) {
    if (vehicles[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

std::optional<Course> CourseOf(const VehicleDescription& a, const VehicleDescription& b) {
  if (!a.travel.known() || !b.travel.known() || !a.travel.value || !b.travel.value) return std::nullopt;
  const int x = static_cast<int>(*a.travel.value), y = static_cast<int>(*b.travel.value);
  return x == y ? Course::kSame : (x + 2) % 4 == y ? Course::kOpposite : Course::kCrossing;
}

bool TypeFits(CrashType type, Course course) {
  switch (type) {
    case CrashType::kRearEnd:
    case CrashType::kSideswipeSame: return course == Course::kSame;
    case CrashType::kHeadOn:
    case CrashType::kSideswipeOpposite: return course == Course::kOpposite;
    case CrashType::kAngle: return course == Course::kCrossing;
    default: return true;
  }
}

void Reconcile(CrashDescription& d) {
  ReconcileCourse(d);
  ReconcileStopped(d);
  ReconcileLanes(d);
}

bool CrashDescription::SingleVehicle() const {
  if (vehicles.size() == 1 || (struck.known() && struck.value == kObjectId)) return true;
  const bool pair_named = striker.known() && struck.known() && IndexOf(struck.value) >= 0;
  return type.value == CrashType::kSingleVehicle && type.known() && !pair_named;
}

void Validate(const CrashDescription& d) {
  if (d.vehicles.empty()) throw std::invalid_argument("vehicles: the description names no vehicle");
  const RoadDescription& r = d.road;
  if (r.lanes_per_direction.value < 1 || r.lanes_per_direction.value > 4) {
    throw std::invalid_argument("road.lanes_per_direction: must be in [1, 4], got " +
                                std::to_string(r.lanes_per_direction.value));
  }
  if (!std::isfinite(r.speed_limit.value) || r.speed_limit.value <= 0.0 || r.speed_limit.value > 50.0) {
    throw std::invalid_argument("road.speed_limit: must be in (0, 50] m/s, got " + std::to_string(r.speed_limit.value));
  }
  std::set<std::string> ids;
  for (size_t i = 0; i < d.vehicles.size(); ++i) {
    const VehicleDescription& v = d.vehicles[i];
    const std::string path = "vehicles[" + std::to_string(i) + "]";
    if (v.id.empty()) throw std::invalid_argument(path + ".id: empty");
    if (!ids.insert(v.id).second) throw std::invalid_argument(path + ".id: '" + v.id + "' appears twice");
    if (v.speed.value) {
      const double s = *v.speed.value;
      if (!std::isfinite(s) || s < 0.0) throw std::invalid_argument(path + ".speed: must be a finite value >= 0");
      if (s > 70.0) {
        throw std::invalid_argument(path + ".speed: " + std::to_string(s) +
                                    " m/s is impossible for a road vehicle (at most 70 m/s)");
      }
      if (v.movement.value == Manoeuvre::kStopped && Stated(v.movement.source) && Stated(v.speed.source) && s > 1.0) {
        throw std::invalid_argument(path + ".speed: " + std::to_string(s) + " m/s contradicts movement stopped");
      }
    }
    if (v.lane.value && Stated(v.lane.source) && Stated(r.lanes_per_direction.source) &&
        (*v.lane.value < 0 || *v.lane.value >= r.lanes_per_direction.value)) {
      throw std::invalid_argument(path + ".lane: " + std::to_string(*v.lane.value) + " is not a lane of a road with " +
                                  std::to_string(r.lanes_per_direction.value) + " lane(s) per direction");
    }
  }
  const auto [a, b] = Pair(d);
  if (d.striker.known() && a < 0) throw std::invalid_argument("striker: no vehicle '" + d.striker.value + "'");
  if (d.struck.known() && b < 0 && d.struck.value != kObjectId) {
    throw std::invalid_argument("struck: no vehicle '" + d.struck.value + "'");
  }
  if (a >= 0 && a == b) throw std::invalid_argument("struck: the same vehicle as the striker (" + d.striker.value + ")");
  // Stated directions must fit the stated crash type.
  if (a >= 0 && b >= 0 && Stated(d.type.source)) {
    const auto& va = d.vehicles[static_cast<size_t>(a)];
    const auto& vb = d.vehicles[static_cast<size_t>(b)];
    const auto course = CourseOf(va, vb);
    if (course && Stated(va.travel.source) && Stated(vb.travel.source) && !TypeFits(d.type.value, *course)) {
      throw std::invalid_argument(VehicleField(static_cast<size_t>(b)) + ".travel: " +
                                  std::string(ToString(*vb.travel.value)) + " contradicts crash type " +
                                  std::string(ToString(d.type.value)) + " (expected " +
                                  std::string(Expected(d.type.value)) + " to " + va.id + "'s " +
                                  std::string(ToString(*va.travel.value)) + ")");
    }
  }
}

nlohmann::json ToJson(const CrashDescription& d) {
  nlohmann::json vs = nlohmann::json::array();
  for (const auto& v : d.vehicles) {
    vs.push_back({
        {"id", v.id},
        {"class", J(v.vehicle_class, [](VehicleClass c) { return std::string(ToString(c)); })},
        {"travel", J(v.travel,
                     [](const std::optional<Compass>& c) {
                       return c ? nlohmann::json(std::string(ToString(*c))) : nlohmann::json("unknown");
                     })},
        {"movement", J(v.movement, [](Manoeuvre m) { return std::string(ToString(m)); })},
        {"speed", J(v.speed, [](const std::optional<double>& s) { return s ? nlohmann::json(*s) : nlohmann::json(); })},
        {"lane", J(v.lane, [](const std::optional<int>& l) { return l ? nlohmann::json(*l) : nlohmann::json(); })},
        {"impact_area", J(v.impact_area, [](ImpactArea a) { return std::string(ToString(a)); })},
        {"parked", v.parked},
    });
  }
  return {
      {"source_id", d.source_id},
      {"road",
       {{"type", J(d.road.type, [](RoadType t) { return std::string(ToString(t)); })},
        {"lanes_per_direction", J(d.road.lanes_per_direction)},
        {"divided", J(d.road.divided)},
        {"speed_limit", J(d.road.speed_limit)},
        {"surface", J(d.road.surface, [](Surface s) { return std::string(ToString(s)); })},
        {"layout_note", d.road.layout_note}}},
      {"vehicles", vs},
      {"type", J(d.type, [](CrashType t) { return std::string(ToString(t)); })},
      {"location", J(d.location, [](CrashLocation l) { return std::string(ToString(l)); })},
      {"striker", J(d.striker)},
      {"struck", J(d.struck)},
      {"obstacle", J(d.obstacle, [](ObstaclePlace p) { return std::string(ToString(p)); })},
      {"notes", d.notes},
      {"warnings", d.warnings},
  };
}

CrashDescription CrashDescriptionFromJson(const nlohmann::json& j) {
  if (!j.is_object()) throw std::invalid_argument("crash description: expected a JSON object");
  CrashDescription d;
  const auto str = [](const nlohmann::json& v) { return v.get<std::string>(); };
  if (j.contains("source_id")) d.source_id = j.at("source_id").get<std::string>();
  if (j.contains("road")) {
    const auto& r = j.at("road");
    Read(r, "type", "road.", d.road.type, [&](const nlohmann::json& v) { return RoadTypeFromString(str(v)); });
    Read(r, "lanes_per_direction", "road.", d.road.lanes_per_direction);
    Read(r, "divided", "road.", d.road.divided);
    Read(r, "speed_limit", "road.", d.road.speed_limit);
    Read(r, "surface", "road.", d.road.surface, [&](const nlohmann::json& v) { return SurfaceFromString(str(v)); });
    if (r.contains("layout_note")) d.road.layout_note = r.at("layout_note").get<std::string>();
  }
  if (j.contains("vehicles")) {
    if (!j.at("vehicles").is_array()) throw std::invalid_argument("vehicles: expected an array");
    for (size_t i = 0; i < j.at("vehicles").size(); ++i) {
      const auto& o = j.at("vehicles")[i];
      const std::string path = "vehicles[" + std::to_string(i) + "].";
      VehicleDescription v;
      v.id = o.contains("id") ? o.at("id").get<std::string>() : "V" + std::to_string(i + 1);
      Read(o, "class", path, v.vehicle_class, [&](const nlohmann::json& x) { return VehicleClassFromString(str(x)); });
      Read(o, "travel", path, v.travel, [&](const nlohmann::json& x) -> std::optional<Compass> {
        if (x.is_null() || str(x) == "unknown") return std::nullopt;
        return CompassFromString(str(x));
      });
      Read(o, "movement", path, v.movement, [&](const nlohmann::json& x) { return ManoeuvreFromString(str(x)); });
      Read(o, "speed", path, v.speed, [](const nlohmann::json& x) -> std::optional<double> {
        if (x.is_null()) return std::nullopt;
        return x.get<double>();
      });
      Read(o, "lane", path, v.lane, [](const nlohmann::json& x) -> std::optional<int> {
        if (x.is_null()) return std::nullopt;
        return x.get<int>();
      });
      Read(o, "impact_area", path, v.impact_area, [&](const nlohmann::json& x) { return ImpactAreaFromString(str(x)); });
      if (o.contains("parked")) v.parked = o.at("parked").get<bool>();
      d.vehicles.push_back(std::move(v));
    }
  }
  Read(j, "type", "", d.type, [&](const nlohmann::json& v) { return CrashTypeFromString(str(v)); });
  Read(j, "location", "", d.location, [&](const nlohmann::json& v) { return CrashLocationFromString(str(v)); });
  Read(j, "striker", "", d.striker);
  Read(j, "struck", "", d.struck);
  Read(j, "obstacle", "", d.obstacle, [&](const nlohmann::json& v) { return ObstaclePlaceFromString(str(v)); });
  if (j.contains("notes")) d.notes = j.at("notes").get<std::vector<std::string>>();
  if (j.contains("warnings")) d.warnings = j.at("warnings").get<std::vector<std::string>>();
  return d;
}

CrashDescription FromAccidentRecord(const AccidentRecord& r, std::optional<RoadType> road) {
  if (r.vehicles.empty()) throw std::invalid_argument("vehicles: the record names no vehicle");
  CrashDescription d;
  const auto& k = r.road.kind;
  switch (k.value) {
    case RoadKind::kIntersection: d.road.type.Set(RoadType::kIntersection, k.source); break;
    case RoadKind::kTJunction: d.road.type.Set(RoadType::kTJunction, k.source); break;
    case RoadKind::kDriveway:
      d.road.type.Set(RoadType::kTJunction, Provenance::kInferred);
      d.road.layout_note = "driveway planned as a T-junction";
      break;
    case RoadKind::kCurve:
    case RoadKind::kRamp:
      d.road.type.Set(RoadType::kStraight, Provenance::kInferred);
      d.road.layout_note = std::string(ToString(k.value)) + " planned as a straight road";
      break;
    case RoadKind::kStraight: d.road.type.Set(RoadType::kStraight, k.source); break;
  }
  if (road) d.road.type.Set(*road, Provenance::kStated);
  d.road.lanes_per_direction.Set(std::clamp(r.road.lanes_per_direction.value, 1, 4), r.road.lanes_per_direction.source);
  d.road.divided = r.road.divided;
  d.road.speed_limit.Set(std::clamp(r.road.speed_limit_mps.value, 4.0, 40.0), r.road.speed_limit_mps.source);
  d.road.surface = r.road.surface;
  d.type = r.crash.type;
  d.location = r.crash.location;
  for (const auto& v : r.vehicles) {
    VehicleDescription o;
    o.id = v.id;
    o.vehicle_class = v.vehicle_class;
    o.travel = v.travel;
    o.parked = v.parked.value;
    Manoeuvre m = Manoeuvre::kStraight;
    switch (v.movement.value) {
      case Movement::kStraight: m = Manoeuvre::kStraight; break;
      case Movement::kTurnLeft: m = Manoeuvre::kTurnLeft; break;
      case Movement::kTurnRight: m = Manoeuvre::kTurnRight; break;
      // The record does not keep the side; the planner takes it from the damage.
      case Movement::kChangingLanes: m = Manoeuvre::kLaneChangeLeft; break;
      case Movement::kStopped: m = Manoeuvre::kStopped; break;
      case Movement::kSlowing: m = Manoeuvre::kSlowing; break;
      case Movement::kBacking: m = Manoeuvre::kBacking; break;
      case Movement::kPassing: m = Manoeuvre::kPassing; break;
      case Movement::kMerging: m = Manoeuvre::kMerging; break;
      case Movement::kUnknown: m = Manoeuvre::kUnknown; break;
    }
    o.movement.Set(m, v.movement.source);
    if (v.speed_mps.known() && v.speed_mps.value > 0.0) o.speed.Set(v.speed_mps.value, v.speed_mps.source);
    if (v.movement.value == Movement::kStopped && v.movement.known()) o.speed.Set(0.0, Provenance::kInferred);
    const int lanes = d.road.lanes_per_direction.value;
    // NASS numbers lanes from the kerb ("lane one" is the outside lane).
    if (v.lane.known() && v.lane.value >= 1 && v.lane.value <= lanes) o.lane.Set(lanes - v.lane.value, Provenance::kInferred);
    d.vehicles.push_back(std::move(o));
  }
  if (r.crash.striking.known() && d.IndexOf(r.crash.striking.value) >= 0) d.striker = r.crash.striking;
  if (r.crash.struck.known() && (d.IndexOf(r.crash.struck.value) >= 0 || r.crash.struck.value == kObjectId)) {
    d.struck = r.crash.struck;
  }
  if (d.striker.known() && d.striker.value == d.struck.value) d.struck = {};
  const auto area = [&](const Field<std::string>& who, const Field<DamageArea>& plane, const Field<std::string>& detail) {
    if (!who.known()) return;
    const int i = d.IndexOf(who.value);
    if (i < 0 || !plane.known()) return;
    d.vehicles[static_cast<size_t>(i)].impact_area.Set(ImpactAreaFrom(plane.value, detail.value), plane.source);
  };
  area(d.striker, r.crash.striking_area, r.crash.striking_detail);
  area(d.struck, r.crash.struck_area, r.crash.struck_detail);
  for (const auto& w : r.warnings) d.notes.push_back("extraction: " + w);
  return d;
}

}  // namespace accsim
