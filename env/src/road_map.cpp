#include "accsim/env/road_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace accsim {
namespace {

// Clearance between the carriageway edge and the junction box boundary; it is
// also the kerb radius at the corners, so right turns follow a quarter circle
// of radius lane_width / 2 + kCornerMargin.
constexpr double kCornerMargin = 5.0;  // [m]
// Shortest road lane a junction arm may leave outside the box.
constexpr double kMinApproach = 10.0;  // [m]
// Connector sampling: at most 1 m between points, and a small enough angle
// step that the heading jump at either joint stays below ~1.5 degrees.
constexpr double kMaxSampleSpacing = 1.0;  // [m]
constexpr double kMaxSampleAngle = 0.05;   // [rad]
// Slack for points that sit exactly on a lane end or a lane joint.
constexpr double kEndTolerance = 1e-6;  // [m]

constexpr std::array<Compass, 4> kCompasses{Compass::kEast, Compass::kNorth, Compass::kWest,
                                            Compass::kSouth};

std::string Num(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

// Exact unit vectors: cos(pi/2) would leave 6e-17 noise on axis-aligned lanes.
Vec2 Direction(Compass c) {
  switch (c) {
    case Compass::kEast: return {1.0, 0.0};
    case Compass::kNorth: return {0.0, 1.0};
    case Compass::kWest: return {-1.0, 0.0};
    case Compass::kSouth: return {0.0, -1.0};
  }
  return {1.0, 0.0};
}

Vec2 RightNormal(const Vec2& u) { return {u.y(), -u.x()}; }

Compass Rotate(Compass c, int quarter_turns_ccw) {
  return static_cast<Compass>((static_cast<int>(c) + quarter_turns_ccw) % 4);
}
Compass Opposite(Compass c) { return Rotate(c, 2); }
Compass LeftOf(Compass c) { return Rotate(c, 1); }
Compass RightOf(Compass c) { return Rotate(c, 3); }

bool HasArm(RoadType type, Compass arm) {
  return type == RoadType::kIntersection || arm != Compass::kNorth;
}

double HalfMedian(const RoadMapSpec& spec) {
  return spec.divided ? 0.5 * spec.median_width : 0.0;
}

// Distance of lane `index`'s centreline from the road axis, to the right of travel.
double LaneOffset(const RoadMapSpec& spec, int index) {
  return HalfMedian(spec) + (index + 0.5) * spec.lane_width;
}

double JunctionHalfSize(const RoadMapSpec& spec) {
  return spec.lanes_per_direction * spec.lane_width + HalfMedian(spec) + kCornerMargin;
}

void CheckRange(const char* field, double v, double lo, bool lo_open, double hi) {
  const bool above_lo = lo_open ? v > lo : v >= lo;
  if (!(std::isfinite(v) && above_lo && v <= hi)) {  // NaN fails every comparison
    throw std::invalid_argument(std::string(field) + ": must be in " + (lo_open ? "(" : "[") +
                                Num(lo) + ", " + Num(hi) + "], got " + Num(v));
  }
}

void Validate(const RoadMapSpec& spec) {
  const int type = static_cast<int>(spec.type);
  if (type < 0 || type > static_cast<int>(RoadType::kTJunction)) {
    throw std::invalid_argument("type: unknown road type " + std::to_string(type));
  }
  if (spec.lanes_per_direction < 1 || spec.lanes_per_direction > 4) {
    throw std::invalid_argument("lanes_per_direction: must be in [1, 4], got " +
                                std::to_string(spec.lanes_per_direction));
  }
  CheckRange("lane_width", spec.lane_width, 2.5, true, 5.0);
  if (spec.divided) {
    CheckRange("median_width", spec.median_width, 0.5, false, 20.0);
  } else if (!std::isfinite(spec.median_width)) {
    throw std::invalid_argument("median_width: not a finite number, got " +
                                Num(spec.median_width));
  }
  CheckRange("length", spec.length, 20.0, false, 2000.0);
  if (spec.type != RoadType::kStraight) {
    const double min_length = JunctionHalfSize(spec) + kMinApproach;
    if (spec.length < min_length) {
      throw std::invalid_argument("length: must be at least " + Num(min_length) +
                                  " m (junction half size " + Num(JunctionHalfSize(spec)) +
                                  " m + " + Num(kMinApproach) +
                                  " m of approach) for this lane layout, got " +
                                  Num(spec.length));
    }
  }
  CheckRange("speed_limit", spec.speed_limit, 0.0, true, 50.0);
  const int surface = static_cast<int>(spec.surface);
  if (surface < 0 || surface > static_cast<int>(Surface::kIce)) {
    throw std::invalid_argument("surface: unknown surface " + std::to_string(surface));
  }
}

// Points from a to b at most kMaxSampleSpacing apart, both ends included.
std::vector<Vec2> SampleSegment(const Vec2& a, const Vec2& b) {
  const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / kMaxSampleSpacing)));
  std::vector<Vec2> pts;
  pts.reserve(static_cast<size_t>(n) + 1);
  for (int k = 0; k <= n; ++k) pts.push_back(a + (static_cast<double>(k) / n) * (b - a));
  return pts;
}

// A quarter-turn connector between axis-aligned lanes: the circle tangent to
// the inbound heading `u` at `start` and to the outbound heading `v` at `end`.
// Its centre shares start's coordinate along u and end's along v; the layout
// places start and end equidistant from it, so the arc is exactly circular.
std::vector<Vec2> SampleQuarterArc(const Vec2& start, const Vec2& u, const Vec2& end,
                                   const Vec2& v) {
  const Vec2 centre = start.dot(u) * u + end.dot(v) * v;
  const double radius = (start - centre).norm();
  const double a0 = std::atan2(start.y() - centre.y(), start.x() - centre.x());
  const double cross = u.x() * v.y() - u.y() * v.x();  // +1 for a left turn
  const double sweep = (cross > 0.0 ? 0.5 : -0.5) * kPi;
  const double arc = radius * std::abs(sweep);
  const int n = std::max({1, static_cast<int>(std::ceil(arc / kMaxSampleSpacing)),
                          static_cast<int>(std::ceil(std::abs(sweep) / kMaxSampleAngle))});
  std::vector<Vec2> pts;
  pts.reserve(static_cast<size_t>(n) + 1);
  pts.push_back(start);
  for (int k = 1; k < n; ++k) {
    const double a = a0 + sweep * k / n;
    pts.push_back(centre + radius * Vec2(std::cos(a), std::sin(a)));
  }
  pts.push_back(end);  // exact, so the joint with the outbound lane is seamless
  return pts;
}

}  // namespace

std::string_view ToString(RoadType t) {
  switch (t) {
    case RoadType::kStraight: return "straight";
    case RoadType::kIntersection: return "intersection";
    case RoadType::kTJunction: return "t_junction";
  }
  return "unknown";
}

std::string_view ToString(Compass c) {
  switch (c) {
    case Compass::kEast: return "east";
    case Compass::kNorth: return "north";
    case Compass::kWest: return "west";
    case Compass::kSouth: return "south";
  }
  return "unknown";
}

std::string_view ToString(Turn t) {
  switch (t) {
    case Turn::kStraight: return "straight";
    case Turn::kLeft: return "left";
    case Turn::kRight: return "right";
  }
  return "unknown";
}

RoadType RoadTypeFromString(std::string_view name) {
  for (RoadType t : {RoadType::kStraight, RoadType::kIntersection, RoadType::kTJunction}) {
    if (name == ToString(t)) return t;
  }
  throw std::invalid_argument("road type: unknown '" + std::string(name) +
                              "' (expected straight, intersection, t_junction)");
}

Compass CompassFromString(std::string_view name) {
  for (Compass c : kCompasses) {
    if (name == ToString(c)) return c;
  }
  throw std::invalid_argument("compass: unknown '" + std::string(name) +
                              "' (expected east, north, west, south)");
}

Turn TurnFromString(std::string_view name) {
  for (Turn t : {Turn::kStraight, Turn::kLeft, Turn::kRight}) {
    if (name == ToString(t)) return t;
  }
  throw std::invalid_argument("turn: unknown '" + std::string(name) +
                              "' (expected straight, left, right)");
}

double CompassYaw(Compass c) {
  switch (c) {
    case Compass::kEast: return 0.0;
    case Compass::kNorth: return 0.5 * kPi;
    case Compass::kWest: return kPi;
    case Compass::kSouth: return -0.5 * kPi;
  }
  return 0.0;
}

RoadMap::RoadMap(const RoadMapSpec& spec) : spec_(spec) {
  Validate(spec_);
  const int n = spec_.lanes_per_direction;

  auto add_road_lane = [&](Compass travel, Compass arm, bool inbound, int index, double t0,
                           double t1) {
    const Vec2 u = Direction(travel);
    const Vec2 offset = LaneOffset(spec_, index) * RightNormal(u);
    Lane lane;
    lane.id = static_cast<int>(lanes_.size());
    lane.kind = LaneKind::kRoad;
    lane.centreline = Polyline({t0 * u + offset, t1 * u + offset});
    lane.width = spec_.lane_width;
    lane.speed_limit = spec_.speed_limit;
    lane.travel = travel;
    lane.arm = arm;
    lane.inbound = inbound;
    lane.index = index;
    lanes_.push_back(std::move(lane));
  };

  if (spec_.type == RoadType::kStraight) {
    const double half = 0.5 * spec_.length;
    for (Compass travel : {Compass::kEast, Compass::kWest}) {
      for (int i = 0; i < n; ++i) add_road_lane(travel, travel, false, i, -half, half);
    }
  } else {
    junction_half_size_ = JunctionHalfSize(spec_);
    const double h = junction_half_size_;
    const double len = spec_.length;
    // Along travel direction d, an inbound lane on arm Opposite(d) runs from
    // -length to -h; an outbound lane on arm d runs from h to length.
    for (Compass arm : kCompasses) {
      if (!HasArm(spec_.type, arm)) continue;
      for (int i = 0; i < n; ++i) add_road_lane(Opposite(arm), arm, true, i, -len, -h);
      for (int i = 0; i < n; ++i) add_road_lane(arm, arm, false, i, h, len);
    }

    const size_t num_road_lanes = lanes_.size();
    for (size_t from = 0; from < num_road_lanes; ++from) {
      if (!lanes_[from].inbound) continue;
      const Compass travel = lanes_[from].travel;
      const int index = lanes_[from].index;
      struct Move {
        Turn turn;
        Compass out;
        bool allowed;
      };
      const std::array<Move, 3> moves{{
          {Turn::kStraight, travel, true},
          {Turn::kLeft, LeftOf(travel), index == 0},
          {Turn::kRight, RightOf(travel), index == n - 1},
      }};
      for (const Move& m : moves) {
        if (!m.allowed || !HasArm(spec_.type, m.out)) continue;
        // Left turns only leave index 0 and right turns only the kerb lane,
        // so every movement keeps its lane index.
        const int to = FindLane(m.out, false, index);
        const Vec2 start = lanes_[from].centreline.points().back();
        const Vec2 end = lanes_[static_cast<size_t>(to)].centreline.points().front();
        Lane c;
        c.id = static_cast<int>(lanes_.size());
        c.kind = LaneKind::kConnector;
        c.centreline = Polyline(m.turn == Turn::kStraight
                                    ? SampleSegment(start, end)
                                    : SampleQuarterArc(start, Direction(travel), end,
                                                       Direction(m.out)));
        c.width = spec_.lane_width;
        c.speed_limit = spec_.speed_limit;
        c.travel = travel;
        c.arm = lanes_[from].arm;
        c.inbound = false;
        c.index = index;
        c.turn = m.turn;
        c.from_lane = static_cast<int>(from);
        c.to_lane = to;
        c.predecessors.push_back(c.from_lane);
        c.successors.push_back(to);
        lanes_[from].successors.push_back(c.id);
        lanes_[static_cast<size_t>(to)].predecessors.push_back(c.id);
        lanes_.push_back(std::move(c));
      }
    }
  }

  lane_bounds_.reserve(lanes_.size());
  for (const Lane& lane : lanes_) {
    const double r = 0.5 * lane.width;
    LaneBounds b{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                 -std::numeric_limits<double>::infinity(),
                 -std::numeric_limits<double>::infinity()};
    for (const Vec2& p : lane.centreline.points()) {
      b.min_x = std::min(b.min_x, p.x() - r);
      b.min_y = std::min(b.min_y, p.y() - r);
      b.max_x = std::max(b.max_x, p.x() + r);
      b.max_y = std::max(b.max_y, p.y() + r);
    }
    lane_bounds_.push_back(b);
  }
}

std::vector<int> RoadMap::FindLanes(Compass travel, bool inbound) const {
  const bool straight = spec_.type == RoadType::kStraight;
  std::vector<int> ids;
  for (const Lane& lane : lanes_) {
    if (lane.kind == LaneKind::kRoad && lane.travel == travel &&
        (straight || lane.inbound == inbound)) {
      ids.push_back(lane.id);
    }
  }
  std::sort(ids.begin(), ids.end(), [this](int a, int b) { return lane(a).index < lane(b).index; });
  return ids;
}

int RoadMap::FindLane(Compass travel, bool inbound, int index) const {
  const bool straight = spec_.type == RoadType::kStraight;
  for (const Lane& lane : lanes_) {
    if (lane.kind == LaneKind::kRoad && lane.travel == travel && lane.index == index &&
        (straight || lane.inbound == inbound)) {
      return lane.id;
    }
  }
  return -1;
}

int RoadMap::FindConnector(int from_lane, Turn turn) const {
  if (from_lane < 0 || static_cast<size_t>(from_lane) >= lanes_.size()) return -1;
  for (int id : lanes_[static_cast<size_t>(from_lane)].successors) {
    const Lane& c = lane(id);
    if (c.kind == LaneKind::kConnector && c.turn == turn) return id;
  }
  return -1;
}

std::optional<LaneLocation> RoadMap::Locate(const Pose2& pose) const {
  const Vec2 p = pose.position();
  std::optional<LaneLocation> best;
  double best_abs_heading = std::numeric_limits<double>::infinity();
  double best_abs_lateral = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < lanes_.size(); ++i) {
    const LaneBounds& b = lane_bounds_[i];
    if (!(p.x() >= b.min_x && p.x() <= b.max_x && p.y() >= b.min_y && p.y() <= b.max_y)) {
      continue;
    }
    const Lane& lane = lanes_[i];
    const PolylineProjection proj = lane.centreline.Project(p);
    const double abs_lateral = std::abs(proj.lateral);
    if (abs_lateral > 0.5 * lane.width) continue;
    // Past either end the foot is clamped to the end vertex; the along-track
    // part of the offset then says how far the point overshoots the lane.
    const bool at_end = proj.s <= 0.0 || proj.s >= lane.centreline.length();
    const double along2 = proj.distance * proj.distance - proj.lateral * proj.lateral;
    if (at_end && along2 > kEndTolerance * kEndTolerance) continue;

    const double heading_error = WrapAngle(pose.yaw - proj.heading);
    const double abs_heading = std::abs(heading_error);
    // Prefer the lane we are aligned with; between equally aligned lanes
    // (a joint, a shared lane edge) the one we are closer to the middle of.
    constexpr double kTie = 1e-9;
    const bool better = abs_heading < best_abs_heading - kTie ||
                        (abs_heading <= best_abs_heading + kTie && abs_lateral < best_abs_lateral);
    if (!better) continue;
    best_abs_heading = abs_heading;
    best_abs_lateral = abs_lateral;
    best = LaneLocation{lane.id, proj.s, proj.lateral, heading_error};
  }
  return best;
}

bool RoadMap::OnRoad(const Vec2& p) const {
  const double inner = HalfMedian(spec_);
  const double outer = inner + spec_.lanes_per_direction * spec_.lane_width;
  const double x = p.x();
  const double y = p.y();
  const double ax = std::abs(x);
  const double ay = std::abs(y);
  if (spec_.type == RoadType::kStraight) {
    return ax <= 0.5 * spec_.length && ay >= inner && ay <= outer;
  }
  const double h = junction_half_size_;
  const double len = spec_.length;
  if (ax <= h && ay <= h) return true;
  // East-west arms (both maps), then the north and south arms.
  if (ax >= h && ax <= len && ay >= inner && ay <= outer) return true;
  const bool north_ok = HasArm(spec_.type, Compass::kNorth);
  if ((y <= -h || (north_ok && y >= h)) && ay <= len && ax >= inner && ax <= outer) return true;
  return false;
}

Polyline RoadMap::RouteThrough(const std::vector<int>& lane_ids) const {
  if (lane_ids.empty()) throw std::invalid_argument("lane_ids: empty route");
  for (size_t k = 0; k < lane_ids.size(); ++k) {
    if (lane_ids[k] < 0 || static_cast<size_t>(lane_ids[k]) >= lanes_.size()) {
      throw std::invalid_argument("lane_ids: [" + std::to_string(k) + "] = " +
                                  std::to_string(lane_ids[k]) + " is not a lane of this map (" +
                                  std::to_string(lanes_.size()) + " lanes)");
    }
    if (k > 0) {
      const auto& succ = lane(lane_ids[k - 1]).successors;
      if (std::find(succ.begin(), succ.end(), lane_ids[k]) == succ.end()) {
        throw std::invalid_argument("lane_ids: lane " + std::to_string(lane_ids[k]) +
                                    " does not succeed lane " + std::to_string(lane_ids[k - 1]));
      }
    }
  }
  std::vector<Vec2> pts;
  for (int id : lane_ids) {
    for (const Vec2& q : lane(id).centreline.points()) {
      // Successive lanes share their joint point; keep it once.
      if (!pts.empty() && (q - pts.back()).norm() <= kEndTolerance) continue;
      pts.push_back(q);
    }
  }
  return Polyline(std::move(pts));
}

}  // namespace accsim
