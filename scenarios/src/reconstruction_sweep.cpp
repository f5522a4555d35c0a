// A sweep of reconstructions over described crash configurations: every
// road type and crash type with the movements and damaged areas a report
// of that type gives, vehicle classes rotated by seed. Even seeds leave
// directions, speeds, lanes and surface to the planner (reports that state
// none of them); odd seeds state them all, drawn from the seed: speeds
// 3-30 m/s (turns 3.6-9, a same-direction striker faster than the other),
// 1-3 lanes per direction, dry/wet/snow, the first vehicle's direction at
// random and the second's as the crash type has it. It measures what the
// labelled report sets cannot: whether the planner meets configurations no
// report in them happens to describe.
#include <array>
#include <optional>
#include <random>
#include <string>

#include "accsim/scenarios/reconstruction.h"

namespace accsim {
namespace {

struct Config {
  RoadType road;
  CrashType type;
  Manoeuvre m1, m2;
  ImpactArea a1, a2;
  bool v2_strikes = false;
  std::optional<ObstaclePlace> obstacle;  // single vehicle: where the object stands
};

Config Pair(RoadType road, CrashType type, Manoeuvre m1, Manoeuvre m2, ImpactArea a1, ImpactArea a2,
            bool v2_strikes = false) {
  return Config{road, type, m1, m2, a1, a2, v2_strikes, std::nullopt};
}

// What a report of each crash type can describe: the movements and damaged
// areas of striker (V1 unless `v2_strikes`) and struck. Turning types and
// angle crashes need crossing roads and are enumerated at junctions only;
// the others on every road type.
std::vector<Config> Configs() {
  using M = Manoeuvre;
  using A = ImpactArea;
  using T = CrashType;
  std::vector<Config> c;
  for (RoadType r : {RoadType::kStraight, RoadType::kIntersection, RoadType::kTJunction}) {
    for (M lead : {M::kStopped, M::kSlowing, M::kStraight}) c.push_back(Pair(r, T::kRearEnd, M::kStraight, lead, A::kFront, A::kRear));
    c.push_back(Pair(r, T::kHeadOn, M::kStraight, M::kStraight, A::kFront, A::kFront));
    c.push_back(Pair(r, T::kHeadOn, M::kPassing, M::kStraight, A::kFront, A::kFront));
    // Sideswipes: the struck vehicle is on the side the changer moves to;
    // opposing vehicles meet left side to left side (right-hand traffic).
    c.push_back(Pair(r, T::kSideswipeSame, M::kLaneChangeLeft, M::kStraight, A::kLeft, A::kRight));
    c.push_back(Pair(r, T::kSideswipeSame, M::kLaneChangeLeft, M::kStraight, A::kFrontLeft, A::kRight));
    c.push_back(Pair(r, T::kSideswipeSame, M::kLaneChangeRight, M::kStraight, A::kRight, A::kLeft));
    c.push_back(Pair(r, T::kSideswipeSame, M::kLaneChangeRight, M::kStraight, A::kFrontRight, A::kLeft));
    c.push_back(Pair(r, T::kSideswipeOpposite, M::kStraight, M::kStraight, A::kLeft, A::kLeft));
    c.push_back(Pair(r, T::kSideswipeOpposite, M::kStraight, M::kStraight, A::kFrontLeft, A::kLeft));
    c.push_back(Pair(r, T::kSideswipeOpposite, M::kStraight, M::kStraight, A::kFrontLeft, A::kFrontLeft));
    const std::array<std::pair<ObstaclePlace, A>, 3> kObjects = {{{ObstaclePlace::kInLane, A::kFront},
                                                                  {ObstaclePlace::kLeftRoadside, A::kFrontLeft},
                                                                  {ObstaclePlace::kRightRoadside, A::kFrontRight}}};
    for (const auto& [place, area] : kObjects) {
      c.push_back(Config{r, T::kSingleVehicle, M::kStraight, M::kStraight, area, A::kUnknown, false, place});
    }
    if (r == RoadType::kStraight) continue;
    c.push_back(Pair(r, T::kAngle, M::kStraight, M::kStraight, A::kFront, A::kLeft));
    c.push_back(Pair(r, T::kAngle, M::kStraight, M::kStraight, A::kFront, A::kRight));
    for (T type : {T::kTurnAcrossPath, T::kTurnIntoPath}) {
      for (M turn : {M::kTurnLeft, M::kTurnRight}) {
        // The turner strikes the through vehicle's side, or is struck on a
        // side, on its back (turning into the path) or head on (across it).
        c.push_back(Pair(r, type, turn, M::kStraight, A::kFront, A::kLeft));
        c.push_back(Pair(r, type, turn, M::kStraight, A::kFront, A::kRight));
        c.push_back(Pair(r, type, turn, M::kStraight, A::kLeft, A::kFront, true));
        c.push_back(Pair(r, type, turn, M::kStraight, A::kRight, A::kFront, true));
        c.push_back(Pair(r, type, turn, M::kStraight, type == T::kTurnIntoPath ? A::kRear : A::kFront, A::kFront, true));
      }
    }
  }
  return c;
}

VehicleDescription Vehicle(const std::string& id, VehicleClass cls, Manoeuvre m, ImpactArea a) {
  VehicleDescription v;
  v.id = id;
  v.vehicle_class.Set(cls, Provenance::kStated);
  v.movement.Set(m, Provenance::kStated);
  if (a != ImpactArea::kUnknown) v.impact_area.Set(a, Provenance::kStated);
  return v;
}

// The second vehicle's direction relative to the first as the crash type
// has it: same, opposite, or crossing (either side).
Compass Other(Compass first, CrashType type, std::mt19937_64& rng) {
  const int f = static_cast<int>(first);
  switch (type) {
    case CrashType::kRearEnd:
    case CrashType::kSideswipeSame:
      return first;
    case CrashType::kHeadOn:
    case CrashType::kSideswipeOpposite:
    case CrashType::kTurnAcrossPath:
      return static_cast<Compass>((f + 2) % 4);
    default:
      return static_cast<Compass>((f + (rng() % 2 ? 1 : 3)) % 4);
  }
}

void StateEverything(CrashDescription& d, const Config& c, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> speed(3.0, 30.0);
  const int min_lanes = c.type == CrashType::kSideswipeSame ? 2 : 1;
  d.road.lanes_per_direction.Set(min_lanes + static_cast<int>(rng() % static_cast<uint64_t>(4 - min_lanes)),
                                 Provenance::kStated);
  static constexpr std::array<Surface, 3> kSurfaces = {Surface::kDry, Surface::kWet, Surface::kSnow};
  d.road.surface.Set(kSurfaces[rng() % kSurfaces.size()], Provenance::kStated);
  const Compass first = static_cast<Compass>(rng() % 4);
  for (size_t k = 0; k < d.vehicles.size(); ++k) {
    VehicleDescription& v = d.vehicles[k];
    v.travel.Set(k == 0 ? first : Other(first, c.type, rng), Provenance::kStated);
    if (v.movement.value == Manoeuvre::kStopped) continue;
    const bool turning = v.movement.value == Manoeuvre::kTurnLeft || v.movement.value == Manoeuvre::kTurnRight;
    v.speed.Set(turning ? 3.0 + 0.2 * speed(rng) : speed(rng), Provenance::kStated);  // turns: 3.6-9 m/s
  }
  // Same direction: the striker is the faster one, as such reports say.
  if (d.vehicles.size() == 2 && (c.type == CrashType::kRearEnd || c.type == CrashType::kSideswipeSame)) {
    VehicleDescription& striker = d.vehicles[c.v2_strikes ? 1 : 0];
    const VehicleDescription& other = d.vehicles[c.v2_strikes ? 0 : 1];
    const double ahead = other.speed.value.value_or(0.0);
    striker.speed.Set(ahead + 3.0 + 0.3 * speed(rng), Provenance::kStated);
  }
}

}  // namespace

std::vector<CrashDescription> SweepDescriptions(uint64_t seed) {
  static constexpr std::array<VehicleClass, 4> kClasses = {VehicleClass::kCar, VehicleClass::kSuv,
                                                           VehicleClass::kTruck, VehicleClass::kMotorcycle};
  std::vector<CrashDescription> out;
  size_t i = 0;
  for (const Config& c : Configs()) {
    CrashDescription d;
    d.source_id = std::string(ToString(c.road)) + "/" + std::string(ToString(c.type)) + "#" + std::to_string(i);
    d.road.type.Set(c.road, Provenance::kStated);
    d.road.lanes_per_direction.Set(c.type == CrashType::kSideswipeSame ? 2 : 1, Provenance::kStated);
    d.type.Set(c.type, Provenance::kStated);
    d.location.Set(c.road == RoadType::kStraight ? CrashLocation::kSegment : CrashLocation::kJunction,
                   Provenance::kStated);
    const VehicleClass c1 = kClasses[(seed + i) % kClasses.size()];
    const VehicleClass c2 = kClasses[(seed + i + 1) % kClasses.size()];
    d.vehicles.push_back(Vehicle("V1", c1, c.m1, c.a1));
    if (c.obstacle) {
      d.obstacle.Set(*c.obstacle, Provenance::kStated);
      d.striker.Set("V1", Provenance::kStated);
      d.struck.Set(std::string(kObjectId), Provenance::kStated);
    } else {
      d.vehicles.push_back(Vehicle("V2", c2, c.m2, c.a2));
      d.striker.Set(c.v2_strikes ? "V2" : "V1", Provenance::kStated);
      d.struck.Set(c.v2_strikes ? "V1" : "V2", Provenance::kStated);
    }
    if (seed % 2 == 1) StateEverything(d, c, seed * 1000 + i);
    out.push_back(std::move(d));
    ++i;
  }
  return out;
}

SrrReport SweepReconstruction(uint64_t first_seed, int seeds) {
  SrrReport rep;
  for (int k = 0; k < seeds; ++k) {
    const uint64_t seed = first_seed + static_cast<uint64_t>(k);
    for (const CrashDescription& d : SweepDescriptions(seed)) {
      const std::string group = std::string(ToString(d.road.type.value)) + "/" + std::string(ToString(d.type.value));
      rep.Tally(group, d.source_id + " seed " + std::to_string(seed), seed, [&] { return d; });
    }
  }
  return rep;
}

}  // namespace accsim
