#include "accsim/scenarios/labelled_case.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <limits>
#include <optional>
#include <stdexcept>

namespace accsim {
namespace {

std::string Get(const nlohmann::json& j, const char* key) {
  return j.is_object() && j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : "";
}
bool Starts(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }
bool Has(const std::string& s, const char* p) { return s.find(p) != std::string::npos; }
int Number(const std::string& s) {
  static const char* kWords[] = {"Zero", "One", "Two", "Three", "Four", "Five", "Six", "Seven", "Eight"};
  for (int i = 0; i < 9; ++i) {
    if (s == kWords[i]) return i;
  }
  return std::atoi(s.c_str());
}

ImpactArea AreaCode(const std::string& s) {
  if (s == "Front") return ImpactArea::kFront;
  if (s == "Back") return ImpactArea::kRear;
  if (s == "Left Side") return ImpactArea::kLeft;
  if (s == "Right Side") return ImpactArea::kRight;
  return ImpactArea::kUnknown;
}

// NHTSA crash-type codes (both folders code them; CIREN prefixes the text).
CrashType TypeCode(int code) {
  return code >= 1 && code <= 19    ? CrashType::kSingleVehicle
         : code >= 20 && code <= 43 ? CrashType::kRearEnd
         : code >= 44 && code <= 49 ? CrashType::kSideswipeSame
         : code >= 50 && code <= 63 ? CrashType::kHeadOn
         : code >= 64 && code <= 67 ? CrashType::kSideswipeOpposite
         : code >= 68 && code <= 75 ? CrashType::kTurnAcrossPath
         : code >= 76 && code <= 85 ? CrashType::kTurnIntoPath
         : code >= 86 && code <= 91 ? CrashType::kAngle
                                    : CrashType::kUnknown;
}

// Single-driver crash types: 1-5 right roadside departure, 6-10 left,
// 11-19 forward impact (an object or parked vehicle in the lane).
std::optional<ObstaclePlace> PlaceCode(int code) {
  if (code >= 1 && code <= 5) return ObstaclePlace::kRightRoadside;
  if (code >= 6 && code <= 10) return ObstaclePlace::kLeftRoadside;
  if (code >= 11 && code <= 19) return ObstaclePlace::kInLane;
  return std::nullopt;
}

Manoeuvre MovementCode(const std::string& m) {
  if (Starts(m, "Turning left")) return Manoeuvre::kTurnLeft;
  if (Starts(m, "Turning right")) return Manoeuvre::kTurnRight;
  if (Starts(m, "Stopped")) return Manoeuvre::kStopped;
  if (Starts(m, "Decelerating")) return Manoeuvre::kSlowing;
  if (Starts(m, "Changing lanes") || Starts(m, "Merging")) return Manoeuvre::kLaneChangeLeft;
  if (Starts(m, "Passing")) return Manoeuvre::kPassing;
  if (Starts(m, "Backing")) return Manoeuvre::kBacking;
  if (Starts(m, "Going") || Starts(m, "Negotiating") || Starts(m, "Accelerating") || Starts(m, "Starting")) {
    return Manoeuvre::kStraight;
  }
  return Manoeuvre::kUnknown;
}

VehicleClass BodyCode(const std::string& body) {
  std::string b = body;
  std::transform(b.begin(), b.end(), b.begin(), [](unsigned char c) { return std::tolower(c); });
  if (Has(b, "pickup")) return VehicleClass::kPickup;
  if (Has(b, "van")) return VehicleClass::kVan;
  if (Has(b, "utility")) return VehicleClass::kSuv;
  if (Has(b, "bus")) return VehicleClass::kBus;
  if (Has(b, "truck") || Has(b, "tractor")) return VehicleClass::kTruck;
  if (Has(b, "motorcycle")) return VehicleClass::kMotorcycle;
  return VehicleClass::kCar;
}

bool Ciren(const nlohmann::json& row) { return Has(Get(row, "file"), "CIREN") || row.contains("vehicle_summaries"); }

}  // namespace

RoadType LabelledRoadType(const nlohmann::json& row) {
  const std::string file = Get(row, "file");
  if (!Ciren(row)) {
    const std::string folder = file.substr(0, file.find('/'));
    if (folder == "crossing") return RoadType::kIntersection;
    if (folder == "t") return RoadType::kTJunction;
    if (folder == "straight") return RoadType::kStraight;
  }
  const std::string rel = row.contains("vehicles") && !row["vehicles"].empty()
                              ? Get(row["vehicles"][0], "relation_to_junction")
                              : "";
  if (Starts(rel, "Intersection")) return RoadType::kIntersection;
  if (Starts(rel, "Driveway")) return RoadType::kTJunction;
  return RoadType::kStraight;
}

CrashDescription DescriptionFromLabels(const nlohmann::json& row) {
  if (!row.is_object() || !row.contains("vehicles") || !row["vehicles"].is_array() || row["vehicles"].empty()) {
    throw std::invalid_argument("vehicles: the labelled case lists no vehicle");
  }
  const bool ciren = Ciren(row);
  CrashDescription d;
  d.source_id = Get(row, "file");
  d.road.type.Set(LabelledRoadType(row), Provenance::kStated);
  const auto& v1 = row["vehicles"][0];
  const std::string flow = Get(v1, ciren ? "relation_to_flow" : "trafficway_flow");
  const int lanes = ciren ? Number(Get(v1, "travel_lanes")) : std::atoi(Get(v1, "num_travel_lanes_code").c_str());
  if (!flow.empty()) d.road.divided.Set(Starts(flow, "Divided"), Provenance::kStated);
  if (lanes > 0) {
    // NASS counts both directions on undivided roads, one on divided ones.
    d.road.lanes_per_direction.Set(std::clamp(d.road.divided.value ? lanes : std::max(1, lanes / 2), 1, 4),
                                   Provenance::kStated);
  }
  const std::string limit = Get(v1, ciren ? "posted_speed_limit_kmph" : "speed_limit_kmph");
  if (!limit.empty() && std::isdigit(static_cast<unsigned char>(limit[0])) && std::stod(limit) > 0) {
    d.road.speed_limit.Set(std::clamp(std::stod(limit) / 3.6, 4.0, 40.0), Provenance::kStated);
  }
  const std::string surface = Get(v1, "surface_condition");
  if (!surface.empty()) {
    d.road.surface.Set(Starts(surface, "Wet")       ? Surface::kWet
                       : Has(surface, "Snow")       ? Surface::kSnow
                       : Has(surface, "Ice")        ? Surface::kIce
                                                    : Surface::kDry,
                       Provenance::kStated);
  }
  const std::string align = Get(v1, ciren ? "alignment" : "roadway_alignment");
  if (Starts(align, "Curve") && d.road.type.value == RoadType::kStraight) d.road.layout_note = "curve planned as straight";
  for (size_t i = 0; i < row["vehicles"].size(); ++i) {
    const auto& v = row["vehicles"][i];
    VehicleDescription o;
    const std::string num = Get(v, ciren ? "veh" : "veh_number");
    o.id = "V" + (num.empty() ? std::to_string(i + 1) : num);
    const Manoeuvre m = MovementCode(Get(v, "pre_event_movement"));
    if (m != Manoeuvre::kUnknown) o.movement.Set(m, Provenance::kStated);
    else o.movement.Set(Manoeuvre::kUnknown, Provenance::kDefaulted);
    const std::string body = Get(v, "body_type");
    if (!body.empty()) o.vehicle_class.Set(BodyCode(body), Provenance::kStated);
    const double kmh = std::atof(Get(v, ciren ? "police_travel_speed_kmph" : "police_travel_speed").c_str());
    if (kmh > 0) o.speed.Set(kmh / 3.6, Provenance::kStated);
    // "Stopped" with a police travel speed: stopped, then moved off at that
    // speed (the code records the wait, the speed the impact).
    if (o.movement.value == Manoeuvre::kStopped && kmh > 3.6) o.movement.Set(Manoeuvre::kStraight, Provenance::kInferred);
    d.vehicles.push_back(std::move(o));
  }
  // The crash type is coded per vehicle; the first vehicle with a code wins.
  for (const auto& v : row["vehicles"]) {
    const int code = std::atoi((ciren ? Get(v, "crash_type") : Get(v, "crash_type_code")).c_str());
    const CrashType t = TypeCode(code);
    if (t != CrashType::kUnknown) {
      d.type.Set(t, Provenance::kStated);
      if (const auto place = PlaceCode(code)) d.obstacle.Set(*place, Provenance::kStated);
      break;
    }
  }
  // The reconstructed impact: the first vehicle-to-vehicle event by number;
  // with none, the first impact on an object.
  if (row.contains("events") && row["events"].is_array()) {
    const auto first_event = [&](bool vehicle) -> const nlohmann::json* {
      const nlohmann::json* first = nullptr;
      int best = std::numeric_limits<int>::max();
      for (const auto& ev : row["events"]) {
        const bool hit_vehicle = Starts(Get(ev, ciren ? "contacted" : "object_hit"), "Vehicle#");
        const bool impact = AreaCode(Get(ev, ciren ? "area_of_damage" : "striker_area_damage")) != ImpactArea::kUnknown;
        if (vehicle ? !hit_vehicle : hit_vehicle || !impact) continue;
        const int n = std::atoi(Get(ev, ciren ? "event" : "event_number").c_str());
        if (n < best) best = n, first = &ev;
      }
      return first;
    };
    const nlohmann::json* first = first_event(true);
    const nlohmann::json* object = first ? nullptr : first_event(false);
    if (object) {
      const auto& e = *object;
      const int ia = d.IndexOf("V" + Get(e, ciren ? "veh" : "striker_vehicle"));
      if (ia >= 0) {
        d.striker.Set(d.vehicles[static_cast<size_t>(ia)].id, Provenance::kStated);
        d.struck.Set(std::string(kObjectId), Provenance::kStated);
        d.vehicles[static_cast<size_t>(ia)].impact_area.Set(
            AreaCode(Get(e, ciren ? "area_of_damage" : "striker_area_damage")), Provenance::kStated);
      }
    }
    if (first) {
      const auto& e = *first;
      const std::string a = "V" + Get(e, ciren ? "veh" : "striker_vehicle");
      const std::string b = "V" + Get(e, ciren ? "contacted" : "object_hit").substr(8);
      const ImpactArea area_a = AreaCode(Get(e, ciren ? "area_of_damage" : "striker_area_damage"));
      const ImpactArea area_b = AreaCode(Get(e, ciren ? "contacted_area_of_damage" : "hit_area_damage"));
      const int ia = d.IndexOf(a), ib = d.IndexOf(b);
      if (ia >= 0 && ib >= 0 && ia != ib) {
        // CIREN lists events from the case vehicle, which need not strike;
        // the planner decides the physical roles from the areas.
        d.striker.Set(a, Provenance::kStated);
        d.struck.Set(b, Provenance::kStated);
        if (area_a != ImpactArea::kUnknown) d.vehicles[static_cast<size_t>(ia)].impact_area.Set(area_a, Provenance::kStated);
        if (area_b != ImpactArea::kUnknown) d.vehicles[static_cast<size_t>(ib)].impact_area.Set(area_b, Provenance::kStated);
      }
    }
  }
  return d;
}

}  // namespace accsim
