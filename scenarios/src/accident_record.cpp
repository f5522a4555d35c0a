#include "accsim/scenarios/accident_record.h"

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

std::string_view ToString(CrashLocation l) { return l == CrashLocation::kJunction ? "junction" : "segment"; }

namespace {

template <typename T, typename F>
nlohmann::json J(const Field<T>& f, F&& conv) {
  return {{"value", conv(f.value)}, {"source", std::string(ToString(f.source))}};
}
template <typename T>
nlohmann::json J(const Field<T>& f) {
  return J(f, [](const T& v) { return v; });
}
auto Str = [](auto v) { return std::string(ToString(v)); };

}  // namespace

nlohmann::json ToJson(const AccidentRecord& r) {
  nlohmann::json vehicles = nlohmann::json::array();
  for (const auto& v : r.vehicles) {
    vehicles.push_back(
        {{"id", v.id},
         {"vehicle_class", J(v.vehicle_class, Str)},
         {"description", J(v.description)},
         {"travel", J(v.travel, [](const std::optional<Compass>& c) {
            return c ? nlohmann::json(std::string(ToString(*c))) : nlohmann::json(nullptr);
          })},
         {"lane", J(v.lane)},
         {"movement", J(v.movement, Str)},
         {"speed_mps", J(v.speed_mps)}});
  }
  return {{"schema_version", kAccidentRecordSchemaVersion},
          {"road",
           {{"kind", J(r.road.kind, Str)},
            {"lanes_total", J(r.road.lanes_total)},
            {"lanes_per_direction", J(r.road.lanes_per_direction)},
            {"divided", J(r.road.divided)},
            {"one_way", J(r.road.one_way)},
            {"speed_limit_mps", J(r.road.speed_limit_mps)},
            {"speed_limit_unit", J(r.road.speed_limit_unit)},
            {"surface", J(r.road.surface, Str)},
            {"friction", FrictionCoefficient(r.road.surface.value)},
            {"lighting", J(r.road.lighting)},
            {"grade", J(r.road.grade)}}},
          {"participant_count", J(r.participant_count)},
          {"vehicles", vehicles},
          {"crash",
           {{"type", J(r.crash.type, Str)},
            {"striking", J(r.crash.striking)},
            {"struck", J(r.crash.struck)},
            {"striking_area", J(r.crash.striking_area, Str)},
            {"struck_area", J(r.crash.struck_area, Str)},
            {"location", J(r.crash.location, Str)}}},
          {"camera_hint", J(r.camera_hint)},
          {"warnings", r.warnings}};
}

}  // namespace accsim
