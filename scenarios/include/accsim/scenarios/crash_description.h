// CrashDescription: the pre-collision planner's input. It says what a
// report (or an investigator's coding) tells about one crash, in the terms
// the planner needs, and for every attribute whether it was stated,
// inferred from other attributes, or defaulted. The planner fills what is
// missing (with seeded draws) and records each fill in `notes`, so a
// reconstruction always says which parts of it are guesses.
//
// It shares its vocabulary (Field, Provenance, CrashType, CrashLocation)
// with AccidentRecord but not its structure: the planner is written against
// this struct, and FromAccidentRecord / the labelled-case readers adapt to it.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "accsim/env/physical_tables.h"
#include "accsim/env/road_map.h"
#include "accsim/scenarios/accident_record.h"

namespace accsim {

// What a vehicle was doing just before the crash (NASS pre-event movement,
// with the direction of a lane change kept).
enum class Manoeuvre {
  kStraight, kTurnLeft, kTurnRight, kLaneChangeLeft, kLaneChangeRight, kStopped, kSlowing, kBacking, kPassing,
  kMerging, kUnknown
};
// The part of a vehicle involved in the impact: a plane or a corner.
enum class ImpactArea { kFront, kRear, kLeft, kRight, kFrontLeft, kFrontRight, kRearLeft, kRearRight, kUnknown };

// Where the fixed object a single vehicle struck stood: in its lane, or
// beside the road on the left or right of its direction of travel.
enum class ObstaclePlace { kInLane, kLeftRoadside, kRightRoadside };

// The struck party's id when it is an object, not a vehicle.
inline constexpr std::string_view kObjectId = "object";

std::string_view ToString(Manoeuvre m);
std::string_view ToString(ImpactArea a);
std::string_view ToString(ObstaclePlace p);
// Throw std::invalid_argument naming the accepted values.
Manoeuvre ManoeuvreFromString(std::string_view s);
ImpactArea ImpactAreaFromString(std::string_view s);
ObstaclePlace ObstaclePlaceFromString(std::string_view s);
// True when `area` includes the plane `face` (kFrontLeft includes kFront
// and kLeft; kUnknown includes every face).
bool AreaIncludes(ImpactArea area, ImpactArea face);
// The area a corner detail such as "front-left" / "left-rear" names, else
// the plane; kUnknown for anything else.
ImpactArea ImpactAreaFrom(DamageArea plane, std::string_view detail = {});

struct RoadDescription {
  // Curves and ramps are planned as straight roads, driveways and alleys as
  // T-junctions (the nearest layout RoadMap builds); `layout_note` keeps what
  // the report said.
  Field<RoadType> type{RoadType::kStraight};
  Field<int> lanes_per_direction{1};  // [1, 4]
  Field<bool> divided{false};
  Field<double> speed_limit{13.41};   // [m/s]; default 30 mph
  Field<Surface> surface{Surface::kDry};
  std::string layout_note;            // e.g. "curve planned as straight"
};

struct VehicleDescription {
  std::string id;                            // "V1", "V2", ...
  Field<VehicleClass> vehicle_class{VehicleClass::kCar};
  Field<std::optional<Compass>> travel;      // initial direction of travel
  Field<Manoeuvre> movement{Manoeuvre::kStraight};
  Field<std::optional<double>> speed;        // [m/s] at the impact (police or stated travel speed)
  Field<std::optional<int>> lane;            // 0 next to the centre line, growing to the kerb
  Field<ImpactArea> impact_area{ImpactArea::kUnknown};  // damaged area in the reconstructed impact
  bool parked = false;                       // a parked, unoccupied vehicle: an object, not a traffic unit
};

struct CrashDescription {
  std::string source_id;  // report or case the description came from
  RoadDescription road;
  std::vector<VehicleDescription> vehicles;
  Field<CrashType> type{CrashType::kUnknown};
  Field<CrashLocation> location{CrashLocation::kSegment};
  Field<std::string> striker;  // vehicle id of the striking vehicle
  Field<std::string> struck;   // vehicle id of the struck vehicle, or kObjectId
  // Single-vehicle crashes: where the struck object stood.
  Field<ObstaclePlace> obstacle{ObstaclePlace::kRightRoadside};
  std::vector<std::string> notes;     // what was inferred or drawn, and why
  std::vector<std::string> warnings;  // contradictions Reconcile resolved, each naming the field it set aside

  // Index of the vehicle with that id; -1 when there is none.
  int IndexOf(const std::string& id) const;
  // One traffic unit: a single vehicle, a struck object, or a crash coded
  // single-vehicle that names no struck vehicle.
  bool SingleVehicle() const;
};

// How two directions of travel relate.
enum class Course { kSame, kOpposite, kCrossing };
// The relation of two vehicles' directions when both are known.
std::optional<Course> CourseOf(const VehicleDescription& a, const VehicleDescription& b);
// Whether a crash type allows that relation: rear-end and sideswipe-same
// need the same direction, head-on and sideswipe-opposite the opposite one,
// angle crossing ones; the other types allow any.
bool TypeFits(CrashType type, Course course);

// Resolves contradictions that involve a field not stated (inferred or
// defaulted): the weaker field is set aside (an inferred direction, crash
// type, movement, speed or lane; on a tie the one the planner needs least)
// and a warning naming it is recorded in `warnings`. Contradictions between
// stated fields are left for Validate to refuse.
void Reconcile(CrashDescription& d);

// Throws std::invalid_argument naming the field and the reason when the
// description cannot describe a crash: no vehicles, duplicate ids,
// striker/struck not among the vehicles or the same one, impossible speeds
// (negative, not finite, above 70 m/s), and stated facts that contradict
// each other: a stated speed on a vehicle stated as stopped, stated
// directions contradicting the stated crash type ("vehicles[1].travel:
// north contradicts crash type rear_end ..."), a stated lane outside the
// stated lane count; road attributes outside what a map can be built with.
void Validate(const CrashDescription& d);

nlohmann::json ToJson(const CrashDescription& d);
// Reads ToJson's output back; throws std::invalid_argument naming the field.
CrashDescription CrashDescriptionFromJson(const nlohmann::json& j);

// Adapter from the extractor's record. `road` overrides the road type (a
// labelled folder knows it). Throws std::invalid_argument when the record
// names no vehicle.
CrashDescription FromAccidentRecord(const AccidentRecord& r, std::optional<RoadType> road = std::nullopt);

}  // namespace accsim
