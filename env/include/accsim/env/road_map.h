// Procedural road maps as a lane graph: straight roads, 4-way intersections
// and T-junctions, right-hand traffic. A RoadMap is immutable once built and
// may be shared (const) by any number of environments and threads.
//
// Layout conventions (all maps axis-aligned, world origin at the map centre):
//   * straight: the road runs along x from -length/2 to +length/2; lanes
//     travelling east (+x) lie at y < 0, lanes travelling west at y > 0.
//   * intersection: arms East (x > 0), North, West, South meet in a square
//     junction box centred at the origin; each arm is `length` long measured
//     from the origin.
//   * t_junction: arms East, West and South (the stem); the through road
//     runs along x.
//   * lane index 0 is the lane next to the centre line (or median); indices
//     grow towards the kerb.
//   * connectors are lanes inside the junction box joining an inbound lane
//     to an outbound lane (straight: same index; left: from index 0 to index
//     0; right: kerb lane to kerb lane). Their centrelines are smooth
//     (tangent-continuous) curves sampled every <= 1 m.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "accsim/env/geometry.h"
#include "accsim/env/physical_tables.h"

namespace accsim {

enum class RoadType { kStraight, kIntersection, kTJunction };
enum class Compass { kEast, kNorth, kWest, kSouth };  // travel directions / arms
enum class Turn { kStraight, kLeft, kRight };
enum class LaneKind { kRoad, kConnector };

std::string_view ToString(RoadType t);
std::string_view ToString(Compass c);
std::string_view ToString(Turn t);
// Throw std::invalid_argument naming the field for unknown names.
RoadType RoadTypeFromString(std::string_view name);
Compass CompassFromString(std::string_view name);
Turn TurnFromString(std::string_view name);
// Yaw of travel in a compass direction (east = 0, north = pi/2, ...).
double CompassYaw(Compass c);

struct RoadMapSpec {
  RoadType type = RoadType::kStraight;
  int lanes_per_direction = 1;  // [1, 4]
  bool divided = false;         // a median separates the two directions
  double lane_width = 3.5;      // [m], (2.5, 5]
  double median_width = 2.0;    // [m], used when divided, [0.5, 20]
  double length = 200.0;        // [m] straight: total length; junctions: arm length from the centre, [20, 2000]
                                // junctions also need length >= junction half size + 10 m
  double speed_limit = 13.89;   // [m/s], (0, 50]
  Surface surface = Surface::kDry;
};

struct Lane {
  int id = -1;
  LaneKind kind = LaneKind::kRoad;
  Polyline centreline;        // in the direction of travel
  double width = 3.5;         // [m]
  double speed_limit = 13.89; // [m/s]
  Compass travel = Compass::kEast;  // road lanes: direction of travel; connectors: at entry
  // Junction maps, road lanes: the arm the lane lies on and whether it leads
  // into the junction. Straight maps: arm == travel, inbound == false.
  Compass arm = Compass::kEast;
  bool inbound = false;
  int index = 0;              // 0 next to the centre line, growing towards the kerb
  Turn turn = Turn::kStraight;  // connectors only
  int from_lane = -1;         // connectors only: the inbound lane
  int to_lane = -1;           // connectors only: the outbound lane
  std::vector<int> successors;
  std::vector<int> predecessors;
};

struct LaneLocation {
  int lane_id = -1;
  double s = 0.0;              // [m] along the lane centreline
  double lateral = 0.0;        // [m] + left of the centreline
  double heading_error = 0.0;  // [rad] pose yaw minus lane heading, wrapped
};

class RoadMap {
 public:
  // Validates the spec; throws std::invalid_argument whose message starts
  // with the field name ("lanes_per_direction: must be in [1, 4], got 7").
  explicit RoadMap(const RoadMapSpec& spec);

  const RoadMapSpec& spec() const { return spec_; }
  const std::vector<Lane>& lanes() const { return lanes_; }
  const Lane& lane(int id) const { return lanes_.at(static_cast<size_t>(id)); }
  double friction() const { return FrictionCoefficient(spec_.surface); }
  // Half the side of the square junction box [m]; 0 for straight roads.
  // lanes_per_direction * lane_width + median_width / 2 (when divided) + 5 m,
  // so kerb-to-kerb right turns are quarter circles of radius lane_width/2 + 5 m.
  double junction_half_size() const { return junction_half_size_; }

  // Road lanes travelling `travel`; for junction maps only those with the
  // given `inbound` flag (ignored on straight maps). Ordered by index.
  std::vector<int> FindLanes(Compass travel, bool inbound) const;
  // The road lane with that travel direction, inbound flag and index; -1 if none.
  int FindLane(Compass travel, bool inbound, int index) const;
  // The connector leaving inbound lane `from_lane` with the given turn; -1 if none.
  int FindConnector(int from_lane, Turn turn) const;

  // The lane whose corridor (|lateral| <= width / 2) holds the pose, preferring
  // the smallest |heading_error|; nullopt when no lane holds it.
  std::optional<LaneLocation> Locate(const Pose2& pose) const;
  // True when the point lies on the drivable area (lanes and junction box;
  // not the median, not beyond the ends of the arms).
  bool OnRoad(const Vec2& p) const;

  // The centrelines of consecutive lanes joined into one polyline (the lanes
  // must be successors of each other; throws std::invalid_argument if not).
  Polyline RouteThrough(const std::vector<int>& lane_ids) const;

 private:
  // Axis-aligned box around a lane's corridor, so Locate skips far lanes
  // without projecting onto them.
  struct LaneBounds {
    double min_x, min_y, max_x, max_y;  // [m]
  };

  RoadMapSpec spec_;
  std::vector<Lane> lanes_;
  std::vector<LaneBounds> lane_bounds_;  // parallel to lanes_
  double junction_half_size_ = 0.0;
};

}  // namespace accsim
