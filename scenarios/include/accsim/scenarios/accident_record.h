// AccidentRecord: what a crash report says, in fields the planner can use.
// Every field records whether the text stated it, it was inferred from
// other statements, or it is a default, so a consumer can tell a reported
// fact from a guess. JSON: schema_version 1, each field
// {"value": ..., "source": "stated" | "inferred" | "defaulted"}.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "accsim/env/physical_tables.h"
#include "accsim/env/road_map.h"

namespace accsim {

constexpr int kAccidentRecordSchemaVersion = 1;

enum class Provenance { kStated, kInferred, kDefaulted };
std::string_view ToString(Provenance p);

template <typename T>
struct Field {
  T value{};
  Provenance source = Provenance::kDefaulted;
  void Set(T v, Provenance p) {
    value = std::move(v);
    source = p;
  }
  bool known() const { return source != Provenance::kDefaulted; }
};

enum class RoadKind { kStraight, kCurve, kIntersection, kTJunction, kRamp, kDriveway };
// Pre-crash movement (NASS "pre-event movement", coarsened).
enum class Movement {
  kStraight, kTurnLeft, kTurnRight, kChangingLanes, kStopped, kSlowing, kBacking, kPassing, kMerging, kUnknown
};
// Crash configuration (NHTSA crash-type categories; see docs/extraction.md).
enum class CrashType {
  kRearEnd, kHeadOn, kAngle, kSideswipeSame, kSideswipeOpposite, kTurnAcrossPath, kTurnIntoPath, kSingleVehicle,
  kUnknown
};
// Damaged plane of a vehicle, as NASS codes the general area of damage.
// Corners are kept apart in the *_detail fields ("front-left", "left-rear").
enum class DamageArea { kFront, kRear, kLeft, kRight, kUnknown };
// Where the crash happened relative to a junction (NASS relation to junction, coarsened):
// in or at an intersection (including its approach), at a driveway/alley access,
// on or at a ramp, or on a plain segment.
enum class CrashLocation { kJunction, kSegment, kDriveway, kRamp };

std::string_view ToString(RoadKind k);
std::string_view ToString(Movement m);
std::string_view ToString(CrashType t);
std::string_view ToString(DamageArea a);
std::string_view ToString(CrashLocation l);

// Inverse of ToString; throw std::invalid_argument naming the accepted values.
RoadKind RoadKindFromString(std::string_view s);
Movement MovementFromString(std::string_view s);
CrashType CrashTypeFromString(std::string_view s);
DamageArea DamageAreaFromString(std::string_view s);
CrashLocation CrashLocationFromString(std::string_view s);

// The road V1 travelled on (where the crash happened).
struct RoadRecord {
  Field<RoadKind> kind{RoadKind::kStraight};
  Field<int> lanes_total{2};                    // both directions (one-way: all lanes)
  Field<int> lanes_per_direction{1};            // V1's direction
  Field<bool> divided{false};
  Field<bool> one_way{false};
  Field<double> speed_limit_mps{13.41};         // [m/s]; default 30 mph
  Field<std::string> speed_limit_unit{"mph"};   // as stated: "mph" or "km/h"
  Field<Surface> surface{Surface::kDry};        // friction follows from it (physical_tables.h)
  Field<std::string> weather{"clear"};          // clear, rain, snow, fog, cloudy
  Field<std::string> lighting{"daylight"};      // daylight, dark, dark_lighted, dusk, dawn
  Field<std::string> grade{"level"};            // level, uphill, downhill
};

struct VehicleRecord {
  std::string id;                               // "V1", "V2", ...
  Field<VehicleClass> vehicle_class{VehicleClass::kCar};
  Field<std::string> description;               // make/model/body text as written
  Field<std::optional<Compass>> travel;         // initial direction of travel
  Field<int> lane{0};                           // lane number as stated (1 = first); 0 = not stated
  Field<Movement> movement{Movement::kStraight};   // the manoeuvre into the crash
  // NASS "pre-event movement": what the vehicle did before the critical
  // event. Differs from `movement` when a vehicle stopped (or slowed) and
  // then turned: stopped (slowing), while `movement` is the turn.
  Field<Movement> pre_event{Movement::kStraight};
  Field<double> speed_mps{0.0};                 // [m/s] stated or reported travel speed
  Field<std::string> speed_unit{"mph"};         // unit the speed was stated in
  Field<bool> parked{false};                    // parked/unoccupied: an object, not a traffic unit
};

struct CrashRecord {
  Field<CrashType> type{CrashType::kUnknown};
  Field<std::string> striking;                  // vehicle id
  Field<std::string> struck;                    // vehicle id, or "object"
  Field<DamageArea> striking_area{DamageArea::kFront};
  Field<DamageArea> struck_area{DamageArea::kUnknown};
  Field<std::string> striking_detail;           // e.g. "front-left", "front"
  Field<std::string> struck_detail;             // e.g. "left-rear", "right"
  Field<CrashLocation> location{CrashLocation::kSegment};
};

struct AccidentRecord {
  RoadRecord road;
  Field<int> participant_count{2};
  std::vector<VehicleRecord> vehicles;
  CrashRecord crash;
  Field<std::string> camera_hint;     // "overhead", "behind V1", "driver V2", "side": when the text asks
  std::vector<std::string> warnings;  // what could not be read, and why

  // The damaged plane of one vehicle in the first vehicle-to-vehicle impact
  // (kUnknown when the vehicle is neither striker nor struck).
  DamageArea AreaOf(const std::string& vehicle_id) const;
};

nlohmann::json ToJson(const AccidentRecord& r);
// Reads ToJson's output back; throws std::invalid_argument naming the
// offending field (e.g. "vehicles[1].movement.value: unknown value 'flying'").
AccidentRecord AccidentRecordFromJson(const nlohmann::json& j);

}  // namespace accsim
