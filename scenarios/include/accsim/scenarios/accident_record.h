// AccidentRecord: what a crash report says, in fields the planner can use.
// Every field records whether the text stated it, it was inferred from
// other statements, or it is a default.
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
enum class Movement {
  kStraight, kTurnLeft, kTurnRight, kChangingLanes, kStopped, kSlowing, kBacking, kPassing, kMerging, kUnknown
};
enum class CrashType {
  kRearEnd, kHeadOn, kAngle, kSideswipeSame, kSideswipeOpposite, kTurnAcrossPath, kTurnIntoPath, kSingleVehicle,
  kUnknown
};
enum class DamageArea { kFront, kRear, kLeft, kRight, kUnknown };
enum class CrashLocation { kJunction, kSegment };

std::string_view ToString(RoadKind k);
std::string_view ToString(Movement m);
std::string_view ToString(CrashType t);
std::string_view ToString(DamageArea a);
std::string_view ToString(CrashLocation l);

struct RoadRecord {
  Field<RoadKind> kind{RoadKind::kStraight};
  Field<int> lanes_total{2};          // both directions (one-way: all lanes)
  Field<int> lanes_per_direction{1};
  Field<bool> divided{false};
  Field<bool> one_way{false};
  Field<double> speed_limit_mps{13.41};  // 30 mph
  Field<std::string> speed_limit_unit{"mph"};  // as stated: "mph" or "km/h"
  Field<Surface> surface{Surface::kDry};
  Field<std::string> lighting{"daylight"};
  Field<std::string> grade{"level"};
};

struct VehicleRecord {
  std::string id;                              // "V1", "V2", ...
  Field<VehicleClass> vehicle_class{VehicleClass::kCar};
  Field<std::string> description;              // make/model/body text as written
  Field<std::optional<Compass>> travel;        // direction of travel
  Field<int> lane{0};                          // lane number as stated (1 = first)
  Field<Movement> movement{Movement::kStraight};
  Field<double> speed_mps{0.0};
};

struct CrashRecord {
  Field<CrashType> type{CrashType::kUnknown};
  Field<std::string> striking;   // vehicle id
  Field<std::string> struck;     // vehicle id, or "object"
  Field<DamageArea> striking_area{DamageArea::kFront};
  Field<DamageArea> struck_area{DamageArea::kUnknown};
  Field<CrashLocation> location{CrashLocation::kSegment};
};

struct AccidentRecord {
  RoadRecord road;
  Field<int> participant_count{2};
  std::vector<VehicleRecord> vehicles;
  CrashRecord crash;
  Field<std::string> camera_hint;  // e.g. "overhead", "behind V1", when the text asks
  std::vector<std::string> warnings;  // what could not be read, and why
};

nlohmann::json ToJson(const AccidentRecord& r);

}  // namespace accsim
