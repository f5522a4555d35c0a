#include "accsim/scenarios/pre_collision_planner.h"

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/DubinsStateSpace.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <stdexcept>
#include <tuple>

namespace accsim {
namespace {

constexpr double kStraightLength = 600.0;  // [m] straight map, x in [-300, 300]
constexpr double kArmLength = 220.0;       // [m] junction arms
constexpr double kFaceTolerance = 0.35;    // [m] a contact this close to a face touches it
constexpr double kFollowGap = 30.0;        // [m] vehicles outside the impact follow the striker this far back
constexpr double kObjectX = 60.0;          // [m] where a stationary object or vehicle across the lane stands
constexpr double kQueueGap = 1.5;          // [m] between stopped vehicles queued ahead of a rear-end's struck vehicle

std::string Fmt(const char* f, double a) {
  char b[64];
  std::snprintf(b, sizeof b, f, a);
  return b;
}

double HalfLength(VehicleClass c) { return Params(c).length / 2; }
double HalfWidth(VehicleClass c) { return Params(c).width / 2; }
bool IsFront(ImpactArea a) {
  return a == ImpactArea::kFront || a == ImpactArea::kFrontLeft || a == ImpactArea::kFrontRight;
}
bool IsSideOrBack(ImpactArea a) { return a != ImpactArea::kUnknown && !IsFront(a); }
bool HasLeft(ImpactArea a) { return a == ImpactArea::kLeft || a == ImpactArea::kFrontLeft || a == ImpactArea::kRearLeft; }
bool HasRight(ImpactArea a) {
  return a == ImpactArea::kRight || a == ImpactArea::kFrontRight || a == ImpactArea::kRearRight;
}
// The heading of a path near s (smoothed over a metre, as the references use).
double HeadingNear(const Polyline& p, double s) {
  const Vec2 d = p.PointAt(s + 0.5) - p.PointAt(s - 0.5);
  return d.norm() < 1e-6 ? p.HeadingAt(s) : std::atan2(d.y(), d.x());
}
bool Turning(Manoeuvre m) { return m == Manoeuvre::kTurnLeft || m == Manoeuvre::kTurnRight; }
// A vehicle outside a rear-end's impact that was stopped waits in the queue
// ahead of the struck vehicle (the chain it is pushed into).
bool QueuedAhead(const ImpactConfiguration& c, int i) {
  return c.type == CrashType::kRearEnd && i != c.striker && i != c.struck &&
         c.description.vehicles[static_cast<size_t>(i)].movement.value == Manoeuvre::kStopped;
}
bool JunctionType(CrashType t) {
  return t == CrashType::kAngle || t == CrashType::kTurnAcrossPath || t == CrashType::kTurnIntoPath;
}

// Friction-capped limits on the described surface.
struct Limits {
  double accel, decel, lateral, jerk;
};
Limits LimitsFor(const PlannerConfig& c, Surface s) {
  const double mu_g = FrictionCoefficient(s) * kGravity;
  return {std::min(c.max_accel, 0.5 * mu_g), std::min(c.max_decel, 0.8 * mu_g),
          std::min(c.max_lateral_accel, 0.8 * mu_g), c.max_jerk};
}

// ---------------------------------------------------------------- Phase 1

// The crash type when the description leaves it open, from the damaged
// areas, the movements and the road.
CrashType TypeFromAreas(ImpactArea a, ImpactArea b, Manoeuvre ma, Manoeuvre mb, RoadType road) {
  const bool left_turn = ma == Manoeuvre::kTurnLeft || mb == Manoeuvre::kTurnLeft;
  const bool right_turn = ma == Manoeuvre::kTurnRight || mb == Manoeuvre::kTurnRight;
  const bool lane_change = ma == Manoeuvre::kLaneChangeLeft || ma == Manoeuvre::kLaneChangeRight ||
                           ma == Manoeuvre::kMerging || ma == Manoeuvre::kPassing;
  if (IsFront(a) && (b == ImpactArea::kRear || b == ImpactArea::kRearLeft || b == ImpactArea::kRearRight)) {
    return CrashType::kRearEnd;
  }
  if (IsFront(a) && IsFront(b)) {
    if (road != RoadType::kStraight && left_turn) return CrashType::kTurnAcrossPath;
    return CrashType::kHeadOn;
  }
  if (IsSideOrBack(a) && IsSideOrBack(b)) return CrashType::kSideswipeSame;
  if (lane_change) return CrashType::kSideswipeSame;
  if (left_turn) return CrashType::kTurnAcrossPath;
  if (right_turn) return CrashType::kTurnIntoPath;
  if (a == ImpactArea::kUnknown && b == ImpactArea::kUnknown && road == RoadType::kStraight) return CrashType::kRearEnd;
  return CrashType::kAngle;
}

// As TypeFromAreas, kept to the known directions of travel: the nearest
// type that fits them.
CrashType InferType(ImpactArea a, ImpactArea b, Manoeuvre ma, Manoeuvre mb, RoadType road,
                    std::optional<Course> course) {
  const CrashType t = TypeFromAreas(a, b, ma, mb, road);
  if (!course || TypeFits(t, *course)) return t;
  const bool rear = b == ImpactArea::kRear || b == ImpactArea::kRearLeft || b == ImpactArea::kRearRight;
  switch (*course) {
    case Course::kSame: return IsFront(a) && rear ? CrashType::kRearEnd : CrashType::kSideswipeSame;
    case Course::kOpposite:
      if (ma == Manoeuvre::kTurnLeft || mb == Manoeuvre::kTurnLeft) return CrashType::kTurnAcrossPath;
      return IsFront(a) && IsFront(b) ? CrashType::kHeadOn : CrashType::kSideswipeOpposite;
    case Course::kCrossing: return Turning(ma) || Turning(mb) ? CrashType::kTurnIntoPath : CrashType::kAngle;
  }
  return t;
}

// A single-vehicle crash: the struck object becomes a stationary body (a
// parked car's box: the scenario holds vehicles only), placed where the
// description puts it, else on the side the damage faces.
void AddObstacle(CrashDescription& d) {
  auto note = [&](std::string s) { d.notes.push_back(std::move(s)); };
  if (!d.striker.known() || d.IndexOf(d.striker.value) < 0) {
    d.striker.Set(d.vehicles.front().id, Provenance::kInferred);
    note("striker: not stated; " + d.striker.value + " (the only traffic unit)");
  }
  if (!d.struck.known() || d.struck.value != kObjectId) d.struck.Set(std::string(kObjectId), Provenance::kInferred);
  if (!d.type.known() || d.type.value != CrashType::kSingleVehicle) {
    d.type.Set(CrashType::kSingleVehicle, Provenance::kInferred);
  }
  const ImpactArea area = d.vehicles[static_cast<size_t>(d.IndexOf(d.striker.value))].impact_area.value;
  if (!d.obstacle.known()) {
    d.obstacle.Set(HasLeft(area) ? ObstaclePlace::kLeftRoadside : ObstaclePlace::kRightRoadside, Provenance::kInferred);
    note("obstacle: not stated; " + std::string(ToString(d.obstacle.value)) +
         " (the side the damage faces, else the right)");
  }
  VehicleDescription o;
  o.id = std::string(kObjectId);
  o.movement.Set(Manoeuvre::kStopped, Provenance::kInferred);
  o.speed.Set(0.0, Provenance::kInferred);
  o.parked = true;
  d.vehicles.push_back(std::move(o));
  note("object: a stationary car-sized box, " + std::string(ToString(d.obstacle.value)));
}

}  // namespace

ImpactConfiguration ResolveImpact(const CrashDescription& in, uint64_t seed, const PlannerConfig& config) {
  ImpactConfiguration c;
  c.description = in;
  CrashDescription& d = c.description;
  Reconcile(d);
  Validate(d);
  auto note = [&](std::string s) { d.notes.push_back(std::move(s)); };
  std::mt19937_64 rng(seed);
  if (d.vehicles.empty()) throw std::invalid_argument("vehicles: a reconstruction needs a vehicle, there is none");
  if (d.SingleVehicle()) {
    AddObstacle(d);
    c.obstacle = true;
  }
  const int n = static_cast<int>(d.vehicles.size());
  // Roles as described, filled where open.
  int a = d.striker.known() ? d.IndexOf(d.striker.value) : -1;
  int b = d.struck.known() ? d.IndexOf(d.struck.value) : -1;
  if (a < 0) {
    for (int i = 0; i < n && a < 0; ++i) {
      if (i != b && IsFront(d.vehicles[static_cast<size_t>(i)].impact_area.value)) a = i;
    }
    if (a < 0) a = b == 0 ? 1 : 0;
    d.striker.Set(d.vehicles[static_cast<size_t>(a)].id, Provenance::kInferred);
    note("striker: not stated; " + d.striker.value + " (front damage, else the first vehicle)");
  }
  if (b < 0) {
    b = a == 0 ? 1 : 0;
    d.struck.Set(d.vehicles[static_cast<size_t>(b)].id, Provenance::kInferred);
    note("struck: not stated; " + d.struck.value);
  }
  if (!c.obstacle && d.type.value == CrashType::kSingleVehicle) {
    note("type: coded single-vehicle, but " + d.striker.value + " struck " + d.struck.value +
         "; the type is inferred from the damaged areas");
    d.type.Set(CrashType::kUnknown, Provenance::kDefaulted);
  }
  ImpactArea area_a = d.vehicles[static_cast<size_t>(a)].impact_area.value;
  ImpactArea area_b = d.vehicles[static_cast<size_t>(b)].impact_area.value;
  // Investigators list the vehicle that caused the crash first even when its
  // side or back was hit (it ran the light, pulled out); physically the
  // other's front strikes. Plan the physics, check the description.
  if (!c.obstacle && IsSideOrBack(area_a) && (IsFront(area_b) || area_b == ImpactArea::kUnknown)) {
    std::swap(a, b);
    std::swap(area_a, area_b);
    c.roles_swapped = true;
    note("roles: " + d.vehicles[static_cast<size_t>(a)].id + "'s front strikes " +
         d.vehicles[static_cast<size_t>(b)].id + "'s " + std::string(ToString(area_b)) +
         " (the described striker was hit on its side or back)");
  }
  if (area_a == ImpactArea::kUnknown) {
    area_a = ImpactArea::kFront;
    note("striker area: not stated; front");
  }
  c.striker = a;
  c.struck = b;
  c.striker_area = area_a;
  c.struck_area = area_b;
  auto& va = d.vehicles[static_cast<size_t>(a)];
  auto& vb = d.vehicles[static_cast<size_t>(b)];
  for (auto& v : d.vehicles) {
    if (v.movement.value == Manoeuvre::kUnknown) {
      v.movement.Set(Manoeuvre::kStraight, Provenance::kDefaulted);
      note(v.id + ".movement: not stated; straight");
    }
    if (v.parked && v.movement.value != Manoeuvre::kStopped) v.movement.Set(Manoeuvre::kStopped, Provenance::kInferred);
  }
  c.type = d.type.value;
  if (c.type == CrashType::kUnknown || !d.type.known()) {
    const auto course = CourseOf(va, vb);
    c.type = InferType(area_a, area_b, va.movement.value, vb.movement.value, d.road.type.value, course);
    d.type.Set(c.type, Provenance::kInferred);
    note("type: not stated; " + std::string(ToString(c.type)) + " from the areas and movements" +
         (course ? " within the directions of travel" : ""));
  }
  if (c.type == CrashType::kRearEnd && c.struck_area == ImpactArea::kUnknown) c.struck_area = ImpactArea::kRear;
  if ((c.type == CrashType::kHeadOn) && c.struck_area == ImpactArea::kUnknown) c.struck_area = ImpactArea::kFront;
  // A vehicle stopped crosswise on the road away from any junction (spun
  // out, stalled) and struck in the side: it stands across the striker's
  // lane on a straight road, instead of pulling out of a side road.
  c.across_lane = !c.obstacle && c.type == CrashType::kAngle && vb.movement.value == Manoeuvre::kStopped &&
                  va.movement.value != Manoeuvre::kStopped && d.location.known() &&
                  d.location.value == CrashLocation::kSegment && d.road.type.value == RoadType::kStraight;
  if (c.across_lane) note(vb.id + ": stopped off any junction; stands across " + va.id + "'s lane");
  c.approach_angle = c.type == CrashType::kRearEnd || c.type == CrashType::kSideswipeSame ? 0.0
                     : c.type == CrashType::kHeadOn || c.type == CrashType::kSideswipeOpposite ||
                             c.type == CrashType::kTurnAcrossPath
                         ? kPi
                         : (HasRight(c.struck_area) ? -kPi / 2 : kPi / 2);

  // Speeds at the impact: stated, else drawn (seeded) from documented
  // distributions: U(0.8, 1.0) x the limit on the approach, half that when
  // slowing, U(4, 7) m/s through a turn, U(1.5, 3) m/s backing; zero when
  // stopped.
  const double limit = d.road.speed_limit.value;
  const bool junction = JunctionType(c.type);
  c.start_speed.assign(static_cast<size_t>(n), 0.0);
  c.impact_speed.assign(static_cast<size_t>(n), 0.0);
  for (int i = 0; i < n; ++i) {
    auto& v = d.vehicles[static_cast<size_t>(i)];
    const Manoeuvre m = v.movement.value;
    double s = 0.0;
    if (m == Manoeuvre::kStopped) {
      s = 0.0;
    } else if (v.speed.value) {
      s = std::clamp(*v.speed.value, 0.0, 40.0);
    } else {
      if (Turning(m)) {
        s = std::uniform_real_distribution<double>(4.0, 7.0)(rng);
      } else if (m == Manoeuvre::kBacking) {
        s = std::uniform_real_distribution<double>(1.5, 3.0)(rng);  // reversing out of a drive
      } else {
        s = limit * std::uniform_real_distribution<double>(0.8, 1.0)(rng);
        if (m == Manoeuvre::kSlowing) s *= 0.5;
      }
      v.speed.Set(s, Provenance::kDefaulted);
      note(v.id + ".speed: not stated; drawn " + Fmt("%.1f m/s", s));
    }
    double s0 = s;
    if (m == Manoeuvre::kSlowing) s0 = std::max(s, std::min(s + 5.0, std::max(limit, s)));
    // "Stopped" in a junction crash is coded for the wait at the stop line;
    // the vehicle then pulls into the junction from rest.
    if ((i == a || (i == b && !c.across_lane)) && junction && s < 0.5) {
      s = config.pull_away_speed;
      s0 = 0.0;
      note(v.id + ": stopped before a junction crash; pulls away from rest to " + Fmt("%.1f m/s", s));
    }
    c.start_speed[static_cast<size_t>(i)] = s0;
    c.impact_speed[static_cast<size_t>(i)] = s;
  }
  auto& sa = c.impact_speed[static_cast<size_t>(a)];
  auto& sb = c.impact_speed[static_cast<size_t>(b)];
  // Same-direction crashes need the striker to close on the struck vehicle.
  // (Not a striker backing out across the road: it meets the other's side.)
  const double closing = va.movement.value == Manoeuvre::kBacking       ? -1.0
                         : c.type == CrashType::kRearEnd        ? 3.0
                         : c.type == CrashType::kSideswipeSame  ? 2.0
                                                                : -1.0;
  if (closing > 0.0 && sa < sb + closing) {
    if (!vb.speed.known() && sa > closing) {
      sb = sa - closing;
      note(vb.id + ".speed: lowered to " + Fmt("%.1f m/s", sb) + " so " + va.id + " closes on it");
    } else {
      sa = sb + closing;
      note(va.id + ".speed: raised to " + Fmt("%.1f m/s", sa) + " so it closes on " + vb.id);
    }
    c.start_speed[static_cast<size_t>(a)] = std::max(c.start_speed[static_cast<size_t>(a)], sa);
    c.start_speed[static_cast<size_t>(b)] = std::min(c.start_speed[static_cast<size_t>(b)], std::max(sb, 0.0));
    if (vb.movement.value != Manoeuvre::kSlowing) c.start_speed[static_cast<size_t>(b)] = sb;
  }
  // Vehicles outside the reconstructed impact: queued ones stand (QueuedAhead);
  // the others follow the striker, each a gap further back.
  int following = 0;
  for (int i = 0; i < n; ++i) {
    if (i == a || i == b) continue;
    const auto& vi = d.vehicles[static_cast<size_t>(i)];
    if (QueuedAhead(c, i)) {
      c.start_speed[static_cast<size_t>(i)] = 0.0;
      c.impact_speed[static_cast<size_t>(i)] = 0.0;
      note(vi.id + ": not in the reconstructed impact; stopped in the queue ahead of " + vb.id);
      continue;
    }
    ++following;
    c.start_speed[static_cast<size_t>(i)] = c.start_speed[static_cast<size_t>(a)];
    c.impact_speed[static_cast<size_t>(i)] = sa;
    note(vi.id + ": not in the reconstructed impact; follows " + va.id + " " + Fmt("%.0f m", following * kFollowGap) +
         " back");
  }
  return c;
}

namespace {

// ---------------------------------------------------------------- Phase 2

// Straight on at `y`, an OMPL Dubins curve (radius r) to `y_to` starting at
// x_from, then straight on; eastbound, x from -300 to 300.
Polyline DubinsLaneChange(double y_from, double y_to, double x_from, double r) {
  auto space = std::make_shared<ompl::base::DubinsStateSpace>(r);
  ompl::base::ScopedState<ompl::base::DubinsStateSpace> p(space), q(space), s(space);
  const double dy = std::abs(y_to - y_from);
  // Two opposite arcs, each taking half the offset, plus some straight.
  const double theta = std::acos(std::max(-1.0, 1.0 - dy / (2.0 * r)));
  const double length = 1.2 * 2.0 * r * std::sin(theta) + 5.0;
  p->setXY(x_from, y_from);
  p->setYaw(0.0);
  q->setXY(x_from + length, y_to);
  q->setYaw(0.0);
  std::vector<Vec2> pts{Vec2(-kStraightLength / 2, y_from)};
  const int steps = std::max(20, static_cast<int>(length));
  for (int i = 0; i <= steps; ++i) {
    space->interpolate(p.get(), q.get(), static_cast<double>(i) / steps, s.get());
    pts.emplace_back(s->getX(), s->getY());
  }
  pts.emplace_back(kStraightLength / 2, y_to);
  return Polyline(pts);
}

// A vehicle in a front-corner contact or a single-vehicle crash.
struct Party {
  VehicleClass cls;
  ImpactArea area;  // as described
  Manoeuvre movement;
  double radius;    // [m] Dubins radius at its speed
};

// Lane `index` (0 next to the centre line) for `travel`, kept.
VehiclePath KeepLane(const RoadMap& map, Compass travel, int index) {
  const int id = map.FindLane(travel, false, index);
  if (id < 0) throw std::invalid_argument("road: no such lane");
  return {map.lane(id).centreline, 0.0, std::string(ToString(travel)) + " lane " + std::to_string(index) +
                                            " keeps its lane", false};
}
double LaneY(const RoadMap& map, Compass travel, int index) {
  return KeepLane(map, travel, index).path.PointAt(0.0).y();
}
// Eastbound from lane `from` to lateral position `y_to` on a Dubins curve.
VehiclePath LeaveLane(const RoadMap& map, int from, double y_to, double x_from, double radius, const std::string& how) {
  return {DubinsLaneChange(LaneY(map, Compass::kEast, from), y_to, x_from, radius), 0.0,
          "east lane " + std::to_string(from) + " " + how, true};
}

// Puts the changer where its front corner (side +1 left, -1 right) reaches
// the lateral position of `target` (a point in the keeper's frame, keeper
// heading `keeper_yaw`), and the keeper so that the target is there.
void MeetAtFrontCorner(VehiclePath& changer, VehiclePath& keeper, VehicleClass cls, int side, double keeper_yaw,
                       const Vec2& target) {
  const Vec2 offset(std::cos(keeper_yaw) * target.x() - std::sin(keeper_yaw) * target.y(),
                    std::sin(keeper_yaw) * target.x() + std::cos(keeper_yaw) * target.y());
  const double y = keeper.path.PointAt(0.0).y() + offset.y();
  const Polyline& p = changer.path;
  double previous = 0.0;
  for (double s = 0.0; s <= p.length(); s += 0.02) {
    const double h = HeadingNear(p, s);
    const Vec2 u(std::cos(h), std::sin(h)), left(-u.y(), u.x());
    const Vec2 corner = p.PointAt(s) + HalfLength(cls) * u + side * HalfWidth(cls) * left;
    const double gap = corner.y() - y;
    if (s > 0.0 && (gap > 0.0) != (previous > 0.0)) {
      changer.impact_s = s;
      keeper.impact_s = keeper.path.Project(corner - offset).s;
      return;
    }
    previous = gap;
  }
  throw std::invalid_argument("road: the lane change never brings its front corner to the other vehicle");
}

// Whether a described area allows the changer to strike with its front
// corner on `side`.
bool CornerFits(ImpactArea area, int side) {
  if (area == ImpactArea::kRear) return false;
  return side > 0 ? !HasRight(area) : !HasLeft(area);
}

// Where along the keeper's side the corner lands: towards the named corner,
// else the middle (the rear half with `rearward`).
double AlongSide(ImpactArea keeper_area, double half_length, bool rearward) {
  if (IsFront(keeper_area)) return 0.5 * half_length;
  if (keeper_area == ImpactArea::kRearLeft || keeper_area == ImpactArea::kRearRight || rearward) {
    return -0.5 * half_length;
  }
  return 0.0;
}

// A sideswipe as investigators code it: a vehicle leaving its lane (the
// changer) touches the other (the keeper) with the front corner on the side
// it moves to, on the keeper's side; or, when it pulls out from behind the
// keeper and the keeper was hit on its back, with the other front corner on
// the keeper's back beside the corner. Same direction, eastbound on a road
// with two lanes at least.
std::pair<VehiclePath, VehiclePath> SameDirectionCorner(const RoadMap& map, const Party& changer, const Party& keeper,
                                                        bool rearward) {
  const double hl = HalfLength(keeper.cls), hw = HalfWidth(keeper.cls);
  const bool from_behind = keeper.area == ImpactArea::kRear;
  // Pulling out from behind: towards the side the changer's damaged side
  // trails. Else into the keeper's lane from the side its damage names,
  // then the side the changer's damage names, then its lane change.
  const bool says_left = changer.movement != Manoeuvre::kLaneChangeRight;
  const bool moves_left =
      from_behind ? HasRight(changer.area) || (!HasLeft(changer.area) && says_left)
                  : HasRight(keeper.area) ||
                        (!HasLeft(keeper.area) && !HasRight(changer.area) && (HasLeft(changer.area) || says_left));
  const int dir = moves_left ? 1 : -1;
  const int side = from_behind ? -dir : dir;  // the changer's front corner that touches
  if (!from_behind && !CornerFits(changer.area, side)) {
    throw std::invalid_argument("road: the damaged areas rule out a corner contact");
  }
  const int from = moves_left ? 1 : 0, to = 1 - from;
  VehiclePath k = KeepLane(map, Compass::kEast, from_behind ? from : to);
  const std::string how = (from_behind ? "pulling out " : "changing lanes ") +
                          std::string(moves_left ? "left" : "right") + (from_behind ? " from behind" : "");
  VehiclePath c = LeaveLane(map, from, LaneY(map, Compass::kEast, to),
                            -20.0 - 2.4 * std::sqrt(changer.radius * map.spec().lane_width), changer.radius,
                            how + ", front corner first");
  const Vec2 target = from_behind ? Vec2(-hl, dir * (hw - 0.3)) : Vec2(AlongSide(keeper.area, hl, rearward), -dir * hw);
  MeetAtFrontCorner(c, k, changer.cls, side, 0.0, target);
  return {c, k};
}

// Opposite directions: the changer drifts over the centre line and its
// front-left corner meets the oncoming keeper's left side.
std::pair<VehiclePath, VehiclePath> OppositeDirectionCorner(const RoadMap& map, const Party& changer,
                                                            const Party& keeper, bool rearward) {
  if (!CornerFits(changer.area, 1) || HasRight(keeper.area) || keeper.area == ImpactArea::kRear) {
    throw std::invalid_argument("road: the damaged areas rule out a corner contact");
  }
  VehiclePath k = KeepLane(map, Compass::kWest, 0);
  VehiclePath c = LeaveLane(map, 0, LaneY(map, Compass::kWest, 0),
                            -30.0 - 2.4 * std::sqrt(changer.radius * map.spec().lane_width), changer.radius,
                            "drifting over the centre line, front corner first");
  const double hl = HalfLength(keeper.cls), hw = HalfWidth(keeper.cls);
  MeetAtFrontCorner(c, k, changer.cls, 1, kPi, Vec2(AlongSide(keeper.area, hl, rearward), hw));
  return {c, k};
}

// A single vehicle and the stationary object it strikes: in its lane ahead,
// or beside the road, reached on a Dubins drift off the road. The front
// meets the object's back; a described side meets the object's near side
// with the front corner.
std::pair<VehiclePath, VehiclePath> ObstaclePaths(const RoadMap& map, ObstaclePlace place, const Party& v,
                                                  VehicleClass object) {
  if (v.area == ImpactArea::kRear || v.area == ImpactArea::kRearLeft || v.area == ImpactArea::kRearRight) {
    throw std::invalid_argument("plan: an object struck with the back needs backing, which is not planned");
  }
  const double w = map.spec().lane_width, hl = HalfLength(object), hw = HalfWidth(object);
  const int lanes = map.spec().lanes_per_direction;
  const int lane = place == ObstaclePlace::kLeftRoadside ? 0 : lanes - 1;
  const double y0 = LaneY(map, Compass::kEast, lane);
  const double y = place == ObstaclePlace::kInLane         ? y0
                   : place == ObstaclePlace::kRightRoadside ? y0 - w / 2 - 1.0 - hw
                                                            : LaneY(map, Compass::kWest, lanes - 1) + w / 2 + 1.0 + hw;
  const double half = kStraightLength / 2;
  const std::string where(ToString(place));
  VehiclePath k{Polyline({Vec2(-half, y), Vec2(half, y)}), half + kObjectX, "object " + where, false, true};
  VehiclePath a = KeepLane(map, Compass::kEast, lane);
  if (place != ObstaclePlace::kInLane) {
    const double x_from = kObjectX - 25.0 - 2.4 * std::sqrt(v.radius * std::abs(y - y0));
    a = LeaveLane(map, lane, y, x_from, v.radius,
                  std::string("leaving the road to the ") + (place == ObstaclePlace::kLeftRoadside ? "left" : "right"));
    a.off_road = true;
  }
  if (IsFront(v.area) || v.area == ImpactArea::kUnknown) {
    a.impact_s = a.path.Project(Vec2(kObjectX - hl - HalfLength(v.cls), y)).s;
    return {a, k};
  }
  const int side = HasLeft(v.area) ? 1 : -1;
  if (place == ObstaclePlace::kInLane || (side > 0) != (place == ObstaclePlace::kLeftRoadside)) {
    throw std::invalid_argument("plan: a " + std::string(ToString(v.area)) + " impact cannot reach an object " +
                                where);
  }
  MeetAtFrontCorner(a, k, v.cls, side, 0.0, Vec2(0.0, -side * hw));
  return {a, k};
}

double Meet(const Polyline& p, const Polyline& q) {
  for (double s = 0; s <= p.length(); s += 0.05) {
    if (q.Project(p.PointAt(s)).distance < 0.05) return s;
  }
  throw std::invalid_argument("road: the planned paths do not cross");
}

std::vector<LaneCombination> Combinations(const ImpactConfiguration& c, CrashType type, const PlannerConfig& config,
                                          int variant) {
  const CrashDescription& d = c.description;
  const bool flip = variant & 1, swap_turner = variant & 2, corner = variant & 4;
  const auto& A = d.vehicles[static_cast<size_t>(c.striker)];
  const auto& B = d.vehicles[static_cast<size_t>(c.struck)];
  const VehicleClass ca = A.vehicle_class.value, cb = B.vehicle_class.value;
  const double va = c.impact_speed[static_cast<size_t>(c.striker)];
  RoadMapSpec spec;
  spec.lanes_per_direction = d.road.lanes_per_direction.value;
  spec.speed_limit = d.road.speed_limit.value;
  spec.surface = d.road.surface.value;
  // A median only matters for same-direction crashes on a straight road; a
  // head-on across it, or a junction, is planned undivided.
  // A striker backing with its back into the other is planned on a straight
  // road whatever the type (the drive it leaves is not a mapped leg).
  const bool backs_in = A.movement.value == Manoeuvre::kBacking && c.striker_area != ImpactArea::kUnknown &&
                        AreaIncludes(c.striker_area, ImpactArea::kRear) && !c.obstacle;
  const bool across = c.across_lane && type == CrashType::kAngle;
  const bool junction = JunctionType(type) && !backs_in && !across;
  spec.divided = d.road.divided.value && (type == CrashType::kRearEnd || type == CrashType::kSideswipeSame);
  if (junction) {
    spec.type = d.road.type.value == RoadType::kIntersection ? RoadType::kIntersection : RoadType::kTJunction;
    spec.length = kArmLength;
  } else {
    spec.type = RoadType::kStraight;
    spec.length = kStraightLength;
    if (type == CrashType::kSideswipeSame && !backs_in) {
      spec.lanes_per_direction = std::max(2, spec.lanes_per_direction);
    }
  }
  const RoadMap map(spec);
  const double w = spec.lane_width;
  const int kerb = spec.lanes_per_direction - 1;
  const Limits lim = LimitsFor(config, spec.surface);
  const double radius = std::max(config.min_turn_radius, va * va / lim.lateral);
  auto label = [](Compass t, int i, const char* how) {
    return std::string(ToString(t)) + " lane " + std::to_string(i) + " " + how;
  };
  auto through = [&](Compass travel, int index) -> VehiclePath {
    const int in = map.FindLane(travel, true, index);
    const int conn = in < 0 ? -1 : map.FindConnector(in, Turn::kStraight);
    if (conn < 0) throw std::invalid_argument("road: no straight path for that direction on this map");
    return {map.RouteThrough({in, conn, map.lane(conn).to_lane}), 0.0, label(travel, index, "straight on"), false};
  };
  auto turning = [&](Compass travel, int index, Turn turn) -> VehiclePath {
    const int in = map.FindLane(travel, true, index);
    const int conn = in < 0 ? -1 : map.FindConnector(in, turn);
    if (conn < 0) throw std::invalid_argument("road: no such turn on this map");
    return {map.RouteThrough({in, conn, map.lane(conn).to_lane}), 0.0,
            label(travel, index, turn == Turn::kLeft ? "turning left" : "turning right"), false};
  };
  auto road_lane = [&](Compass travel, int index) { return KeepLane(map, travel, index); };
  VehiclePath pa, pb;
  // A sideswipe's front-corner contact: the struck vehicle is the changer
  // with bit 1, the corner lands towards the keeper's rear with bit 0.
  const auto corner_contact = [&] {
    const double vb = c.impact_speed[static_cast<size_t>(c.struck)];
    const Party striker{ca, c.striker_area, A.movement.value, radius};
    const Party struck{cb, c.struck_area, B.movement.value, std::max(config.min_turn_radius, vb * vb / lim.lateral)};
    const Party& changer = swap_turner ? struck : striker;
    const Party& keeper = swap_turner ? striker : struck;
    auto [pc, pk] = type == CrashType::kSideswipeSame ? SameDirectionCorner(map, changer, keeper, flip)
                                                      : OppositeDirectionCorner(map, changer, keeper, flip);
    pa = swap_turner ? pk : pc;
    pb = swap_turner ? pc : pk;
  };
  // A striker backing into the other with its back: out of a drive beside
  // the road, across it, into the side of a vehicle eastbound in its lane
  // (the kerb lane for a right side, the lane by the centre line for a left
  // side, reached across the westbound lanes). The backer is planned in
  // reverse: its path runs rear first.
  if (across) {
    // Eastbound in its lane into the side of a vehicle standing crosswise
    // ahead: facing north when its left side is struck (it faces west),
    // south for its right.
    if (variant != 0) throw std::invalid_argument("plan: one geometry for a vehicle across the lane");
    const int lane = A.lane.value ? std::min(*A.lane.value, kerb) : 0;
    const double y = LaneY(map, Compass::kEast, lane), x = kObjectX, reach = 20.0;
    const double dir = HasRight(c.struck_area) ? -1.0 : 1.0;
    pa = road_lane(Compass::kEast, lane);
    pb = VehiclePath{Polyline({Vec2(x, y - dir * reach), Vec2(x, y + dir * reach)}), reach,
                     std::string("standing across the lane, facing ") + (dir > 0 ? "north" : "south"), false, true};
    pa.impact_s = pa.path.Project(Vec2(x - HalfWidth(cb) - HalfLength(ca), y)).s;
  } else if (backs_in) {
    if (variant != 0) throw std::invalid_argument("plan: one backing geometry only");
    const bool left = HasLeft(c.struck_area);
    const int lane = left ? 0 : kerb;
    const double y_lane = LaneY(map, Compass::kEast, lane);
    const double side = left ? 1.0 : -1.0;  // where the drive is: the struck face points there
    const double edge = spec.lanes_per_direction * w + 30.0;
    pb = road_lane(Compass::kEast, lane);
    pb.impact_s = pb.path.Project(Vec2(0.0, y_lane)).s;
    pa = VehiclePath{Polyline({Vec2(0.0, side * edge), Vec2(0.0, -side * edge)}), 0.0,
                     std::string("backing out of a drive on the ") + (left ? "north" : "south") + " side", false, true};
    pa.reverse = true;
    pa.impact_s = pa.path.Project(Vec2(0.0, y_lane + side * (HalfWidth(cb) + HalfLength(ca)))).s;
  } else {
    switch (type) {
      case CrashType::kRearEnd: {
        const int lane =
            B.lane.value ? std::min(*B.lane.value, kerb) : A.lane.value ? std::min(*A.lane.value, kerb) : 0;
        pa = pb = road_lane(Compass::kEast, lane);
        pb.impact_s = kStraightLength / 2;
        pa.impact_s = pb.impact_s - HalfLength(ca) - HalfLength(cb);
        break;
      }
      case CrashType::kHeadOn:
      case CrashType::kSideswipeOpposite: {
        if (corner) {
          corner_contact();
          break;
        }
        // The striker drifts over the centre line into the oncoming lane.
        pb = road_lane(Compass::kWest, 0);
        const double overlap = type == CrashType::kHeadOn ? 0.0 : HalfWidth(ca) + HalfWidth(cb) - 0.4;
        const double y_to = w / 2 - overlap;
        pa = {DubinsLaneChange(-w / 2, y_to, -30.0 - 2.4 * std::sqrt(radius * w), radius), 0.0,
              "east lane 0 drifting over the centre line", true};
        pb.impact_s = pb.path.Project(Vec2(HalfLength(cb), w / 2)).s;
        pa.impact_s = pa.path.Project(Vec2(-HalfLength(ca), y_to)).s;
        break;
      }
      case CrashType::kSideswipeSame: {
        if (corner) {
          corner_contact();
          break;
        }
        // One vehicle moves into the other's lane from the side the damage
        // names (a struck left side or a striking right side: the striker is
        // on the struck vehicle's left); without damage, from the side its
        // lane change says. Variants: the struck vehicle is the one changing
        // lanes (bit 1), the striker's front further forward (bit 0).
        bool from_left = HasLeft(c.struck_area) || (c.struck_area == ImpactArea::kUnknown && HasRight(c.striker_area));
        if (!HasLeft(c.struck_area) && !HasRight(c.struck_area) && !HasLeft(c.striker_area) &&
            !HasRight(c.striker_area)) {
          from_left = A.movement.value == Manoeuvre::kLaneChangeRight;
        }
        const int lb = from_left ? 1 : 0, la = from_left ? 0 : 1;
        const double ya = -(0.5 + la) * w, yb = -(0.5 + lb) * w;
        const double forward = flip ? HalfLength(cb) : 0.0;
        if (!swap_turner) {
          pb = road_lane(Compass::kEast, lb);
          pa = {DubinsLaneChange(ya, yb, -20.0 - 2.4 * std::sqrt(radius * w), radius), 0.0,
                label(Compass::kEast, la, from_left ? "changing lanes right" : "changing lanes left"), true};
          pb.impact_s = pb.path.Project(Vec2(0.0, yb)).s;
          pa.impact_s = pa.path.Project(Vec2(-HalfLength(ca) + forward, yb)).s;
        } else {
          const double vb = c.impact_speed[static_cast<size_t>(c.struck)];
          const double rb = std::max(config.min_turn_radius, vb * vb / lim.lateral);
          pa = road_lane(Compass::kEast, la);
          pb = {DubinsLaneChange(yb, ya, -2.4 * std::sqrt(rb * w), rb), 0.0,
                label(Compass::kEast, lb, from_left ? "changing lanes left" : "changing lanes right"), true};
          pb.impact_s = pb.path.Project(Vec2(0.0, ya)).s;
          pa.impact_s = pa.path.Project(Vec2(-HalfLength(ca) + forward, ya)).s;
        }
        break;
      }
      case CrashType::kAngle: {
        // The striker's front meets the struck vehicle's side; which side
        // decides where the striker comes from.
        const bool from_left = !HasRight(c.struck_area);
        if (spec.type == RoadType::kIntersection) {
          pb = through(flip ? Compass::kWest : Compass::kEast, kerb);
          pa = through(from_left != flip ? Compass::kSouth : Compass::kNorth, kerb);
        } else if (!swap_turner) {  // the striker comes out of the stem, northbound
          const bool west = from_left != flip;
          pb = through(west ? Compass::kWest : Compass::kEast, kerb);
          pa = turning(Compass::kNorth, kerb, west ? Turn::kLeft : Turn::kRight);
        } else {  // the struck vehicle pulls out of the stem across the striker's path
          const bool left = !from_left;
          pb = turning(Compass::kNorth, left ? 0 : kerb, left ? Turn::kLeft : Turn::kRight);
          pa = through(flip != left ? Compass::kWest : Compass::kEast, left ? 0 : kerb);
        }
        pa.impact_s = Meet(pa.path, pb.path);
        pb.impact_s = pb.path.Project(pa.path.PointAt(pa.impact_s)).s;
        pa.impact_s -= HalfLength(ca) + HalfWidth(cb);
        break;
      }
      case CrashType::kTurnAcrossPath:
      case CrashType::kTurnIntoPath: {
        // One vehicle turns; the other goes straight.
        const bool a_turns = (Turning(A.movement.value) || !Turning(B.movement.value)) != swap_turner;
        const auto& turner = a_turns ? A : B;
        const Turn turn = turner.movement.value == Manoeuvre::kTurnRight ? Turn::kRight : Turn::kLeft;
        VehiclePath turn_path, straight_path;
        if (type == CrashType::kTurnAcrossPath) {
          if (spec.type == RoadType::kIntersection) {
            turn_path = turning(Compass::kNorth, turn == Turn::kLeft ? 0 : kerb, turn);
            straight_path =
                through(turn == Turn::kLeft ? Compass::kSouth : Compass::kNorth, turn == Turn::kLeft ? 0 : kerb);
          } else {  // westbound on the through road, turning left into the stem
            turn_path = turning(Compass::kWest, 0, Turn::kLeft);
            straight_path = through(Compass::kEast, 0);
          }
        } else {  // from the side road (south) into the main road; the other from the west (or east)
          turn_path = turning(Compass::kNorth, turn == Turn::kLeft ? 0 : kerb, turn);
          straight_path = flip ? through(Compass::kWest, 0) : through(Compass::kEast, turn == Turn::kLeft ? 0 : kerb);
        }
        pa = a_turns ? turn_path : straight_path;
        pb = a_turns ? straight_path : turn_path;
        pa.impact_s = Meet(pa.path, pb.path);
        pb.impact_s = pb.path.Project(pa.path.PointAt(pa.impact_s)).s;
        pa.impact_s -= HalfLength(ca) + HalfWidth(cb);
        break;
      }
      case CrashType::kSingleVehicle:
        std::tie(pa, pb) =
            ObstaclePaths(map, d.obstacle.value, Party{ca, c.striker_area, A.movement.value, radius}, cb);
        break;
      default: throw std::invalid_argument("type: cannot reconstruct crash type " + std::string(ToString(type)));
    }
  }
  std::vector<LaneCombination> out;
  for (const double shift : {0.0, -0.35, 0.35}) {
    LaneCombination k;
    k.map = spec;
    k.paths.resize(d.vehicles.size());
    // Others as ResolveImpact placed them: stopped ones queued ahead of the
    // struck vehicle, bumper to bumper 1.5 m apart; moving ones behind the
    // striker, a follow gap each.
    int following = 0;
    double queue_front = pb.impact_s + HalfLength(cb);
    for (size_t i = 0; i < d.vehicles.size(); ++i) {
      if (static_cast<int>(i) == c.striker) {
        k.paths[i] = pa;
      } else if (static_cast<int>(i) == c.struck) {
        k.paths[i] = pb;
      } else if (QueuedAhead(c, static_cast<int>(i))) {
        const double hl = HalfLength(d.vehicles[i].vehicle_class.value);
        k.paths[i] = pb;
        k.paths[i].impact_s = queue_front + kQueueGap + hl;
        k.paths[i].lanes = "queued ahead of " + B.id;
        queue_front = k.paths[i].impact_s + hl;
      } else {
        k.paths[i] = pa;
        k.paths[i].impact_s -= ++following * kFollowGap;
        k.paths[i].lanes = "following " + A.id;
      }
    }
    k.striker_shift = shift;
    k.label = std::string(ToString(type)) + ": " + A.id + ": " + pa.lanes + "; " + B.id + ": " + pb.lanes +
              (flip ? "; variant" : "") +
              (swap_turner ? "; other turner" : "") + (shift != 0.0 ? Fmt("; striker %+.2f s", shift) : "");
    out.push_back(std::move(k));
  }
  return out;
}

bool ChangesLanes(Manoeuvre m) {
  return m == Manoeuvre::kLaneChangeLeft || m == Manoeuvre::kLaneChangeRight || m == Manoeuvre::kMerging;
}

// Variants of a type's combinations, in the order they are tried: the other
// vehicle's direction or the striker further forward (bit 0), which vehicle
// turns, pulls out or changes lanes (bit 1), a sideswipe's front-corner
// contact (bit 2). The described lane changer first.
std::vector<int> Variants(CrashType type, Manoeuvre striker, Manoeuvre struck) {
  if (JunctionType(type)) return {0, 1, 2, 3};
  if (type == CrashType::kSideswipeOpposite) return {0, 4, 5, 6, 7};
  if (type != CrashType::kSideswipeSame) return {0};
  if (ChangesLanes(struck) && !ChangesLanes(striker)) return {2, 3, 0, 1, 6, 7, 4, 5};
  return {0, 1, 2, 3, 4, 5, 6, 7};
}

}  // namespace

std::vector<LaneCombination> GatherLaneCombinations(const ImpactConfiguration& c, const PlannerConfig& config) {
  std::vector<LaneCombination> all;
  std::string first_error;
  const CrashDescription& d = c.description;
  // The stated type first; then the type the damaged areas imply, when it
  // differs (codes sometimes name the pre-crash situation, e.g. a turn
  // across the path that ended side to side).
  std::vector<CrashType> types{c.type};
  const CrashType by_areas =
      TypeFromAreas(c.striker_area, c.struck_area, d.vehicles[static_cast<size_t>(c.striker)].movement.value,
                    d.vehicles[static_cast<size_t>(c.struck)].movement.value, d.road.type.value);
  if (!c.obstacle && by_areas != c.type && c.striker_area != ImpactArea::kUnknown &&
      c.struck_area != ImpactArea::kUnknown) {
    types.push_back(by_areas);
  }
  for (const CrashType type : types) {
    const Manoeuvre mb = d.vehicles[static_cast<size_t>(c.struck)].movement.value;
    const Manoeuvre ma = d.vehicles[static_cast<size_t>(c.striker)].movement.value;
    for (const int v : Variants(type, ma, mb)) {
      try {
        for (auto& k : Combinations(c, type, config, v)) all.push_back(std::move(k));
      } catch (const std::invalid_argument& e) {
        if (first_error.empty()) first_error = e.what();
      }
    }
  }
  if (all.empty()) throw std::invalid_argument(first_error);
  // Nominal timings first, then the shifted ones.
  std::stable_sort(all.begin(), all.end(), [](const LaneCombination& x, const LaneCombination& y) {
    return std::abs(x.striker_shift) < std::abs(y.striker_shift);
  });
  return all;
}

namespace {

// ---------------------------------------------------------------- Phase 3

// Speed from v0 to v1 over a smoothstep ramp ending at `end`:
// v = v0 + dv (3x^2 - 2x^3), x = (t - (end - tau)) / tau; peak acceleration
// 1.5 dv / tau, peak jerk 6 dv / tau^2.
struct SpeedProfile {
  double v0 = 0, v1 = 0, end = 0, tau = 1;
  double X(double t) const { return std::clamp((t - (end - tau)) / tau, 0.0, 1.0); }
  double V(double t) const {
    const double x = X(t);
    return v0 + (v1 - v0) * x * x * (3 - 2 * x);
  }
  // Distance travelled since t = 0.
  double S(double t) const {
    const double t0 = end - tau;
    if (t <= t0) return v0 * t;
    const double x = X(t);
    const double ramp = v0 * tau * x + (v1 - v0) * tau * (x * x * x - x * x * x * x / 2);
    return v0 * t0 + ramp + (t > end ? v1 * (t - end) : 0.0);
  }
  double PeakAccel() const { return 1.5 * std::abs(v1 - v0) / tau; }
  double PeakJerk() const { return 6.0 * std::abs(v1 - v0) / (tau * tau); }
};

double CurvatureAt(const Polyline& p, double s) {
  return std::abs(WrapAngle(HeadingNear(p, s + 1.0) - HeadingNear(p, s - 1.0))) / 2.0;
}

struct Box {
  Vec2 c, u, v;  // centre, heading unit, left unit
  double hl, hw;
};
Box BoxOf(const TrajectoryPoint& p, VehicleClass cls) {
  const Vec2 u(std::cos(p.yaw), std::sin(p.yaw));
  return {Vec2(p.x, p.y), u, Vec2(-u.y(), u.x()), HalfLength(cls), HalfWidth(cls)};
}
bool Overlap(const Box& a, const Box& b) {
  const Vec2 d = b.c - a.c;
  for (const Vec2& n : {a.u, a.v, b.u, b.v}) {
    const double r = a.hl * std::abs(n.dot(a.u)) + a.hw * std::abs(n.dot(a.v)) + b.hl * std::abs(n.dot(b.u)) +
                     b.hw * std::abs(n.dot(b.v));
    if (std::abs(n.dot(d)) > r) return false;
  }
  return true;
}
bool Inside(const Vec2& p, const Box& b) {
  const Vec2 d = p - b.c;
  return std::abs(d.dot(b.u)) <= b.hl + 1e-9 && std::abs(d.dot(b.v)) <= b.hw + 1e-9;
}
// Where two just-overlapping boxes touch: the mean of the corners of each
// inside the other (the midpoint of the centres if none is).
Vec2 ContactPoint(const Box& a, const Box& b) {
  Vec2 sum = Vec2::Zero();
  int n = 0;
  for (const Box* x : {&a, &b}) {
    const Box& other = x == &a ? b : a;
    for (const double su : {-1.0, 1.0}) {
      for (const double sv : {-1.0, 1.0}) {
        const Vec2 corner = x->c + su * x->hl * x->u + sv * x->hw * x->v;
        if (Inside(corner, other)) sum += corner, ++n;
      }
    }
  }
  return n ? Vec2(sum / n) : Vec2((a.c + b.c) / 2);
}

}  // namespace

ImpactArea FaceAt(const Vec2& point, const Pose2& pose, VehicleClass cls) {
  const Vec2 l = ToLocal(point - pose.position(), pose.yaw);
  const double fx = std::abs(l.x()) / HalfLength(cls), fy = std::abs(l.y()) / HalfWidth(cls);
  if (fx >= fy) return l.x() > 0 ? ImpactArea::kFront : ImpactArea::kRear;
  return l.y() > 0 ? ImpactArea::kLeft : ImpactArea::kRight;
}
bool TouchesArea(const Vec2& point, const Pose2& pose, VehicleClass cls, ImpactArea area) {
  if (area == ImpactArea::kUnknown) return true;
  const Vec2 l = ToLocal(point - pose.position(), pose.yaw);
  const double hl = HalfLength(cls), hw = HalfWidth(cls);
  const bool front = l.x() > hl - kFaceTolerance, rear = l.x() < -hl + kFaceTolerance;
  const bool left = l.y() > hw - kFaceTolerance, right = l.y() < -hw + kFaceTolerance;
  const ImpactArea face = FaceAt(point, pose, cls);
  if (AreaIncludes(area, face)) return true;
  return (AreaIncludes(area, ImpactArea::kFront) && front) || (AreaIncludes(area, ImpactArea::kRear) && rear) ||
         (AreaIncludes(area, ImpactArea::kLeft) && left) || (AreaIncludes(area, ImpactArea::kRight) && right);
}

nlohmann::json ToJson(const ImminentCollisionState& s) {
  nlohmann::json bodies = nlohmann::json::array();
  for (const auto& b : s.bodies) {
    bodies.push_back({{"id", b.id},
                      {"x", b.pose.x},
                      {"y", b.pose.y},
                      {"yaw", b.pose.yaw},
                      {"vx", b.velocity.x()},
                      {"vy", b.velocity.y()},
                      {"yaw_rate", b.yaw_rate}});
  }
  return {{"time", s.time}, {"bodies", bodies}};
}

PlannedCrash TimeParameterise(const ImpactConfiguration& c, const LaneCombination& k, const PlannerConfig& config,
                              uint64_t seed) {
  const CrashDescription& d = c.description;
  const size_t n = d.vehicles.size();
  if (k.paths.size() != n) throw std::invalid_argument("combination: one path per vehicle expected");
  PlannedCrash p;
  p.impact = c;
  p.combination = k.label;
  const Limits lim = LimitsFor(config, k.map.surface);
  const double T = config.impact_time, horizon = config.impact_time + config.after_impact;
  const RoadMap map(k.map);
  for (size_t i = 0; i < n; ++i) {
    const auto& v = d.vehicles[i];
    const VehiclePath& vp = k.paths[i];
    p.ids.push_back(v.id);
    p.classes.push_back(v.vehicle_class.value);
    SpeedProfile prof{c.start_speed[i], c.impact_speed[i], T, 1.0};
    // Through a curve the speed is capped by the lateral limit.
    double kappa = 0.0;
    const double reach = std::max(prof.v0, prof.v1) * T + 5.0;
    for (double s = vp.impact_s - reach; s <= vp.impact_s + 2.0; s += 0.5) {
      if (s > 0.0) kappa = std::max(kappa, CurvatureAt(vp.path, s));
    }
    if (kappa > 1e-4) {
      const double cap = std::sqrt(lim.lateral / kappa);
      if (prof.v1 > cap || prof.v0 > cap) {
        p.impact.description.notes.push_back(v.id + ".speed: " + Fmt("%.1f m/s", std::max(prof.v0, prof.v1)) +
                                             " exceeds the lateral limit on its path; planned " +
                                             Fmt("%.1f m/s", cap));
        prof.v0 = std::min(prof.v0, cap);
        prof.v1 = std::min(prof.v1, cap);
        p.impact.impact_speed[i] = prof.v1;
        p.impact.start_speed[i] = prof.v0;
      }
    }
    // Slowing on a slippery road: it began from no faster than the surface
    // lets it shed within the plan ("began to slow down" on ice).
    const double shed = lim.decel * (T - 0.2) / 1.5;
    if (prof.v0 > prof.v1 + shed) {
      p.impact.description.notes.push_back(v.id + ": slows from " + Fmt("%.1f m/s", prof.v0) +
                                           " beyond the surface's braking within the plan; starts at " +
                                           Fmt("%.1f m/s", prof.v1 + shed));
      prof.v0 = prof.v1 + shed;
      p.impact.start_speed[i] = prof.v0;
    }
    const double dv = std::abs(prof.v1 - prof.v0);
    const double a_lim = prof.v1 > prof.v0 ? lim.accel : lim.decel;
    prof.tau = std::clamp(std::max(1.5 * dv / a_lim, std::sqrt(6.0 * dv / lim.jerk)), 0.5, T - 0.2);
    if (prof.PeakAccel() > a_lim * 1.001 || prof.PeakJerk() > lim.jerk * 1.001) {
      throw std::invalid_argument("plan: " + v.id + " cannot change speed from " + Fmt("%.1f", prof.v0) + " to " +
                                  Fmt("%.1f m/s", prof.v1) + " within the acceleration and jerk limits");
    }
    // The striker's shift moves its arrival: later arrival = start further back.
    const double shift = static_cast<int>(i) == c.striker ? k.striker_shift : 0.0;
    const double s0 = vp.impact_s - prof.S(T) - shift * prof.v1;
    if (s0 < 0.0) {
      throw std::invalid_argument("plan: " + v.id + "'s approach (" + Fmt("%.0f m", prof.S(T)) +
                                  ") is longer than the planned road");
    }
    std::vector<TrajectoryPoint> pts;
    for (int j = 0; j * config.dt <= horizon + 1e-9; ++j) {
      const double t = j * config.dt, s = s0 + prof.S(t);
      const Vec2 q = vp.path.PointAt(s);
      // A vehicle backing along its path faces against it and moves at -v.
      pts.push_back({t, q.x(), q.y(), WrapAngle(HeadingNear(vp.path, s) + (vp.reverse ? kPi : 0.0)),
                     vp.reverse ? -prof.V(t) : prof.V(t)});
      if (t <= T) {
        if (!vp.off_road && !map.OnRoad(q)) {
          throw std::invalid_argument("plan: " + v.id + " leaves the drivable area at " + Fmt("%.2f s", t));
        }
        p.peak_lateral_accel = std::max(p.peak_lateral_accel, prof.V(t) * prof.V(t) * CurvatureAt(vp.path, s));
      }
    }
    p.peak_accel = std::max(p.peak_accel, prof.PeakAccel());
    p.peak_jerk = std::max(p.peak_jerk, prof.PeakJerk());
    p.trajectories.emplace_back(std::move(pts));
  }
  if (p.peak_lateral_accel > lim.lateral * 1.1) {
    throw std::invalid_argument("plan: lateral acceleration " + Fmt("%.1f m/s^2", p.peak_lateral_accel) +
                                " exceeds the limit");
  }
  // Collision criteria on the planned footprints: the first overlap is the
  // described pair, not too early, with the described faces.
  double t_impact = -1.0;
  int first_i = -1, first_j = -1;
  std::vector<size_t> cursor(n, 0);
  for (double t = 0.0; t <= horizon && t_impact < 0.0; t += 0.01) {
    std::vector<Box> boxes;
    for (size_t i = 0; i < n; ++i) boxes.push_back(BoxOf(p.trajectories[i].Sample(t, &cursor[i]), p.classes[i]));
    for (size_t i = 0; i < n && t_impact < 0.0; ++i) {
      for (size_t j = i + 1; j < n; ++j) {
        if (Overlap(boxes[i], boxes[j])) {
          t_impact = t, first_i = static_cast<int>(i), first_j = static_cast<int>(j);
          break;
        }
      }
    }
  }
  if (t_impact < 0.0) throw std::invalid_argument("plan: the planned paths never bring the vehicles together");
  const auto pair = std::minmax(c.striker, c.struck);
  if (first_i != pair.first || first_j != pair.second) {
    throw std::invalid_argument("plan: " + p.ids[static_cast<size_t>(first_i)] + " and " +
                                p.ids[static_cast<size_t>(first_j)] + " would touch first");
  }
  if (t_impact < config.min_approach_time) {
    throw std::invalid_argument("plan: the vehicles would touch at " + Fmt("%.2f s", t_impact) +
                                ", before the approach");
  }
  const TrajectoryPoint ta = p.trajectories[static_cast<size_t>(c.striker)].Sample(t_impact);
  const TrajectoryPoint tb = p.trajectories[static_cast<size_t>(c.struck)].Sample(t_impact);
  const VehicleClass cla = p.classes[static_cast<size_t>(c.striker)], clb = p.classes[static_cast<size_t>(c.struck)];
  const Vec2 contact = ContactPoint(BoxOf(ta, cla), BoxOf(tb, clb));
  if (!TouchesArea(contact, Pose2{ta.x, ta.y, ta.yaw}, cla, c.striker_area)) {
    throw std::invalid_argument("plan: the striker would hit with its " +
                                std::string(ToString(FaceAt(contact, Pose2{ta.x, ta.y, ta.yaw}, cla))));
  }
  if (!TouchesArea(contact, Pose2{tb.x, tb.y, tb.yaw}, clb, c.struck_area)) {
    throw std::invalid_argument("plan: the struck vehicle would be hit on its " +
                                std::string(ToString(FaceAt(contact, Pose2{tb.x, tb.y, tb.yaw}, clb))));
  }

  // The imminent-collision state S.
  p.state.time = t_impact;
  for (size_t i = 0; i < n; ++i) {
    const Trajectory& tr = p.trajectories[i];
    const TrajectoryPoint q = tr.Sample(t_impact);
    const double h = config.dt;
    const double yaw_rate = WrapAngle(tr.Sample(t_impact + h).yaw - tr.Sample(t_impact - h).yaw) / (2 * h);
    p.state.bodies.push_back({p.ids[i], Pose2{q.x, q.y, q.yaw}, q.v * Vec2(std::cos(q.yaw), std::sin(q.yaw)),
                              yaw_rate});
  }
  // Described roles (the check compares against the description).
  const int ds = d.IndexOf(d.striker.value), dt = d.IndexOf(d.struck.value);
  p.striker_id = d.striker.value;
  p.struck_id = d.struck.value;
  p.striker_area = d.vehicles[static_cast<size_t>(ds)].impact_area.value;
  p.struck_area = d.vehicles[static_cast<size_t>(dt)].impact_area.value;

  // The scenario: the described struck vehicle is the ego (the one a policy
  // should learn to save), every other vehicle an NPC on its reference.
  Scenario& s = p.scenario;
  s.name = d.source_id.empty() ? "reconstruction" : "reconstruction_" + d.source_id;
  s.family = ScenarioFamily::kReconstructed;
  s.seed = seed;
  s.time_limit = horizon;
  s.map = k.map;
  // A single vehicle is the ego itself.
  const size_t ego = static_cast<size_t>(c.obstacle ? ds : dt);
  const Trajectory& te = p.trajectories[ego];
  const TrajectoryPoint e0 = te.Sample(0.0);
  s.ego.id = p.ids[ego];
  s.ego.vehicle_class = p.classes[ego];
  s.ego.start = Pose2{e0.x, e0.y, e0.yaw};
  s.ego.speed = e0.v;
  s.ego.target_speed = std::max(e0.v, c.impact_speed[ego]);
  {
    const Polyline& path = k.paths[ego].path;
    const double s0 = path.Project(Vec2(e0.x, e0.y)).s;
    std::vector<Vec2> route;
    for (double u = s0; u <= std::min(path.length(), s0 + 200.0); u += 2.0) route.push_back(path.PointAt(u));
    if (route.size() < 2) route.push_back(path.PointAt(s0 + 20.0));
    s.ego.route = Polyline(route);
  }
  for (size_t i = 0; i < n; ++i) {
    if (i != ego) s.npcs.push_back({p.ids[i], p.classes[i], p.trajectories[i], PostCollisionSource::kPhysics, {}});
  }
  s.provenance = {{"source_report", d.source_id},
                  {"generator", "reconstruction"},
                  {"crash_type", std::string(ToString(c.type))},
                  {"combination", k.label},
                  {"planned_impact_time", t_impact},
                  {"striker", p.striker_id},
                  {"struck", p.struck_id},
                  {"striker_area", std::string(ToString(p.striker_area))},
                  {"struck_area", std::string(ToString(p.struck_area))},
                  {"imminent_collision_state", ToJson(p.state)},
                  {"description", ToJson(p.impact.description)},
                  {"notes", p.impact.description.notes},
                  {"warnings", p.impact.description.warnings},
                  {"peak_lateral_accel", p.peak_lateral_accel},
                  {"peak_accel", p.peak_accel},
                  {"peak_jerk", p.peak_jerk},
                  // The ego's planned path, for the reconstruction check.
                  {"ego_reference", ToJson(te)}};
  return p;
}

PlannedCrash PreCollisionPlanner::Plan(const CrashDescription& d, uint64_t seed, const Acceptor& accept) const {
  const ImpactConfiguration c = ResolveImpact(d, seed, config_);       // Phase 1
  const std::vector<LaneCombination> ks = GatherLaneCombinations(c, config_);  // Phase 2
  // Phase 3: the first combination whose plan validates and is accepted;
  // if the acceptor rejects all, the first that validated (its check then
  // says why it falls short).
  std::optional<PlannedCrash> first;
  std::vector<std::string> reasons;
  for (const LaneCombination& k : ks) {
    try {
      PlannedCrash p = TimeParameterise(c, k, config_, seed);
      const std::string why = accept ? accept(p) : "";
      if (why.empty()) return p;
      reasons.push_back(k.label + ": " + why);
      if (!first) first = std::move(p);
    } catch (const std::invalid_argument& e) {
      reasons.push_back(k.label + ": " + e.what());
    }
  }
  if (first) return *first;
  std::string msg = "plan: no lane combination meets the collision criteria (" + reasons.front();
  if (reasons.size() > 1) msg += "; " + reasons[1];
  throw std::invalid_argument(msg + ")");
}

}  // namespace accsim
