#include "accsim/env/road_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace accsim {
namespace {

constexpr double kEps = 1e-9;
constexpr double kCornerMargin = 5.0;  // [m] the documented junction clearance

RoadMapSpec Spec(RoadType type, int lanes = 1, bool divided = false) {
  RoadMapSpec spec;
  spec.type = type;
  spec.lanes_per_direction = lanes;
  spec.divided = divided;
  spec.lane_width = 3.5;
  spec.median_width = 3.0;
  spec.length = 120.0;
  return spec;
}

double HalfMedian(const RoadMapSpec& spec) { return spec.divided ? 0.5 * spec.median_width : 0.0; }

double LaneHeading(const Lane& lane, double s) { return lane.centreline.HeadingAt(s); }

Compass LeftOf(Compass c) { return static_cast<Compass>((static_cast<int>(c) + 1) % 4); }
Compass RightOf(Compass c) { return static_cast<Compass>((static_cast<int>(c) + 3) % 4); }

// Expects `fn` to throw std::invalid_argument whose message starts with "<field>:".
template <typename Fn>
void ExpectFieldError(Fn fn, const std::string& field) {
  try {
    fn();
    ADD_FAILURE() << "expected std::invalid_argument for " << field;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(field + ":", 0), 0u) << e.what();
  }
}

// ---------------------------------------------------------------- enums

TEST(RoadMapEnumTest, NamesRoundTrip) {
  for (RoadType t : {RoadType::kStraight, RoadType::kIntersection, RoadType::kTJunction}) {
    EXPECT_EQ(RoadTypeFromString(ToString(t)), t);
  }
  for (Compass c : {Compass::kEast, Compass::kNorth, Compass::kWest, Compass::kSouth}) {
    EXPECT_EQ(CompassFromString(ToString(c)), c);
  }
  for (Turn t : {Turn::kStraight, Turn::kLeft, Turn::kRight}) {
    EXPECT_EQ(TurnFromString(ToString(t)), t);
  }
  EXPECT_EQ(ToString(RoadType::kTJunction), "t_junction");
  EXPECT_EQ(ToString(RoadType::kIntersection), "intersection");
  EXPECT_EQ(ToString(Compass::kSouth), "south");
  EXPECT_EQ(ToString(Turn::kLeft), "left");
}

TEST(RoadMapEnumTest, UnknownNamesNameTheField) {
  ExpectFieldError([] { RoadTypeFromString("foo"); }, "road type");
  ExpectFieldError([] { CompassFromString("up"); }, "compass");
  ExpectFieldError([] { TurnFromString("u_turn"); }, "turn");
  ExpectFieldError([] { RoadTypeFromString("Straight"); }, "road type");  // case matters
  try {
    RoadTypeFromString("foo");
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "road type: unknown 'foo' (expected straight, intersection, t_junction)");
  }
}

TEST(RoadMapEnumTest, CompassYawPointsAlongTheAxes) {
  EXPECT_DOUBLE_EQ(CompassYaw(Compass::kEast), 0.0);
  EXPECT_DOUBLE_EQ(CompassYaw(Compass::kNorth), 0.5 * kPi);
  EXPECT_DOUBLE_EQ(CompassYaw(Compass::kWest), kPi);
  EXPECT_DOUBLE_EQ(CompassYaw(Compass::kSouth), -0.5 * kPi);
}

// ---------------------------------------------------------------- validation

TEST(RoadMapSpecTest, DefaultsAndBoundaryValuesAreAccepted) {
  EXPECT_NO_THROW(RoadMap(RoadMapSpec{}));
  RoadMapSpec spec;
  spec.lane_width = 5.0;
  spec.length = 20.0;
  spec.speed_limit = 50.0;
  spec.divided = true;
  spec.median_width = 0.5;
  spec.lanes_per_direction = 4;
  EXPECT_NO_THROW(RoadMap{spec});
  spec.median_width = 20.0;
  spec.length = 2000.0;
  spec.lanes_per_direction = 1;
  EXPECT_NO_THROW(RoadMap{spec});
  // An undivided road ignores the median width, so 0 ("no median") is fine.
  RoadMapSpec undivided;
  undivided.median_width = 0.0;
  EXPECT_NO_THROW(RoadMap{undivided});
}

TEST(RoadMapSpecTest, EachInvalidFieldIsNamed) {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  static constexpr double inf = std::numeric_limits<double>::infinity();
  auto with = [](auto edit) {
    RoadMapSpec spec = Spec(RoadType::kIntersection);
    edit(spec);
    return [spec] { RoadMap map(spec); };
  };
  ExpectFieldError(with([](RoadMapSpec& s) { s.lanes_per_direction = 0; }), "lanes_per_direction");
  ExpectFieldError(with([](RoadMapSpec& s) { s.lanes_per_direction = 5; }), "lanes_per_direction");
  ExpectFieldError(with([](RoadMapSpec& s) { s.lanes_per_direction = -2; }), "lanes_per_direction");
  ExpectFieldError(with([](RoadMapSpec& s) { s.lane_width = 2.5; }), "lane_width");
  ExpectFieldError(with([](RoadMapSpec& s) { s.lane_width = 5.01; }), "lane_width");
  ExpectFieldError(with([](RoadMapSpec& s) { s.lane_width = nan; }), "lane_width");
  ExpectFieldError(with([](RoadMapSpec& s) { s.lane_width = inf; }), "lane_width");
  for (double bad : {0.4, 20.5, nan}) {
    ExpectFieldError(with([bad](RoadMapSpec& s) {
                       s.divided = true;
                       s.median_width = bad;
                     }),
                     "median_width");
  }
  ExpectFieldError(with([](RoadMapSpec& s) { s.median_width = nan; }), "median_width");
  ExpectFieldError(with([](RoadMapSpec& s) { s.length = 19.9; }), "length");
  ExpectFieldError(with([](RoadMapSpec& s) { s.length = 2000.5; }), "length");
  ExpectFieldError(with([](RoadMapSpec& s) { s.length = nan; }), "length");
  ExpectFieldError(with([](RoadMapSpec& s) { s.length = -inf; }), "length");
  ExpectFieldError(with([](RoadMapSpec& s) { s.speed_limit = 0.0; }), "speed_limit");
  ExpectFieldError(with([](RoadMapSpec& s) { s.speed_limit = -3.0; }), "speed_limit");
  ExpectFieldError(with([](RoadMapSpec& s) { s.speed_limit = 50.1; }), "speed_limit");
  ExpectFieldError(with([](RoadMapSpec& s) { s.speed_limit = nan; }), "speed_limit");
  ExpectFieldError(with([](RoadMapSpec& s) { s.type = static_cast<RoadType>(9); }), "type");
  ExpectFieldError(with([](RoadMapSpec& s) { s.surface = static_cast<Surface>(-1); }), "surface");
}

TEST(RoadMapSpecTest, MessageQuotesTheRangeAndTheValue) {
  RoadMapSpec spec;
  spec.lanes_per_direction = 7;
  try {
    RoadMap map(spec);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "lanes_per_direction: must be in [1, 4], got 7");
  }
  spec = RoadMapSpec{};
  spec.lane_width = std::nan("");
  try {
    RoadMap map(spec);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("nan"), std::string::npos) << e.what();
  }
}

TEST(RoadMapSpecTest, JunctionArmsMustReachPastTheBox) {
  // 4 lanes of 5 m plus a 20 m median: half size 4*5 + 10 + 5 = 35 m.
  RoadMapSpec spec = Spec(RoadType::kTJunction, 4, true);
  spec.lane_width = 5.0;
  spec.median_width = 20.0;
  spec.length = 40.0;
  ExpectFieldError([&] { RoadMap map(spec); }, "length");
  spec.length = 45.0;
  EXPECT_NO_THROW(RoadMap{spec});
  // The same length is fine for a straight road.
  spec.type = RoadType::kStraight;
  spec.length = 20.0;
  EXPECT_NO_THROW(RoadMap{spec});
}

// ---------------------------------------------------------------- straight roads

TEST(RoadMapStraightTest, LaneCountsAndLinks) {
  for (int n = 1; n <= 4; ++n) {
    const RoadMap map(Spec(RoadType::kStraight, n));
    ASSERT_EQ(map.lanes().size(), static_cast<size_t>(2 * n));
    EXPECT_EQ(map.junction_half_size(), 0.0);
    for (size_t i = 0; i < map.lanes().size(); ++i) {
      const Lane& lane = map.lanes()[i];
      EXPECT_EQ(lane.id, static_cast<int>(i));
      EXPECT_EQ(lane.kind, LaneKind::kRoad);
      EXPECT_EQ(lane.arm, lane.travel);
      EXPECT_FALSE(lane.inbound);
      EXPECT_TRUE(lane.successors.empty());
      EXPECT_TRUE(lane.predecessors.empty());
      EXPECT_DOUBLE_EQ(lane.centreline.length(), 120.0);
      EXPECT_DOUBLE_EQ(lane.width, 3.5);
      EXPECT_DOUBLE_EQ(lane.speed_limit, map.spec().speed_limit);
    }
    for (Compass c : {Compass::kEast, Compass::kWest}) {
      const std::vector<int> ids = map.FindLanes(c, false);
      ASSERT_EQ(ids.size(), static_cast<size_t>(n));
      EXPECT_EQ(map.FindLanes(c, true), ids);  // the flag is ignored on straight roads
      for (int i = 0; i < n; ++i) {
        EXPECT_EQ(map.lane(ids[i]).index, i);
        EXPECT_EQ(map.lane(ids[i]).travel, c);
        EXPECT_EQ(map.FindLane(c, false, i), ids[i]);
        EXPECT_EQ(map.FindLane(c, true, i), ids[i]);
        EXPECT_EQ(map.FindConnector(ids[i], Turn::kStraight), -1);
      }
      EXPECT_EQ(map.FindLane(c, false, n), -1);
    }
    EXPECT_TRUE(map.FindLanes(Compass::kNorth, false).empty());
    EXPECT_EQ(map.FindLane(Compass::kSouth, false, 0), -1);
  }
}

TEST(RoadMapStraightTest, LanePositionsFollowRightHandTraffic) {
  for (bool divided : {false, true}) {
    const RoadMap map(Spec(RoadType::kStraight, 3, divided));
    const double w = 3.5;
    const double half_median = divided ? 1.5 : 0.0;
    for (int i = 0; i < 3; ++i) {
      const Lane& east = map.lane(map.FindLane(Compass::kEast, false, i));
      const Vec2 e0 = east.centreline.points().front();
      const Vec2 e1 = east.centreline.points().back();
      EXPECT_NEAR(e0.x(), -60.0, kEps);
      EXPECT_NEAR(e1.x(), 60.0, kEps);
      EXPECT_NEAR(e0.y(), -(half_median + (i + 0.5) * w), kEps);
      EXPECT_NEAR(e1.y(), e0.y(), kEps);
      EXPECT_NEAR(LaneHeading(east, 10.0), 0.0, kEps);

      const Lane& west = map.lane(map.FindLane(Compass::kWest, false, i));
      const Vec2 w0 = west.centreline.points().front();
      const Vec2 w1 = west.centreline.points().back();
      EXPECT_NEAR(w0.x(), 60.0, kEps);
      EXPECT_NEAR(w1.x(), -60.0, kEps);
      EXPECT_NEAR(w0.y(), half_median + (i + 0.5) * w, kEps);
      EXPECT_NEAR(std::abs(LaneHeading(west, 10.0)), kPi, kEps);
    }
  }
  // The example from the spec: undivided, eastbound index 0 at y = -lane_width / 2.
  RoadMapSpec spec;
  spec.lane_width = 3.0;
  const RoadMap map(spec);
  EXPECT_NEAR(map.lane(map.FindLane(Compass::kEast, false, 0)).centreline.points()[0].y(), -1.5,
              kEps);
}

TEST(RoadMapStraightTest, FrictionComesFromTheSurface) {
  RoadMapSpec spec;
  spec.surface = Surface::kIce;
  const RoadMap map(spec);
  EXPECT_DOUBLE_EQ(map.friction(), FrictionCoefficient(Surface::kIce));
}

TEST(RoadMapStraightTest, OnRoadCoversTheCarriagewaysOnly) {
  const RoadMap undivided(Spec(RoadType::kStraight, 2));
  EXPECT_TRUE(undivided.OnRoad({0.0, 0.0}));  // centre line
  EXPECT_TRUE(undivided.OnRoad({30.0, -1.75}));
  EXPECT_TRUE(undivided.OnRoad({-59.0, 6.9}));
  EXPECT_TRUE(undivided.OnRoad({60.0, 7.0}));  // edges count
  EXPECT_FALSE(undivided.OnRoad({0.0, 7.1}));
  EXPECT_FALSE(undivided.OnRoad({0.0, -7.1}));
  EXPECT_FALSE(undivided.OnRoad({60.1, -1.75}));  // beyond the end
  EXPECT_FALSE(undivided.OnRoad({-61.0, 1.75}));
  EXPECT_FALSE(undivided.OnRoad({std::nan(""), 0.0}));

  const RoadMap divided(Spec(RoadType::kStraight, 2, true));  // median 3 m
  EXPECT_FALSE(divided.OnRoad({0.0, 0.0}));  // on the median
  EXPECT_FALSE(divided.OnRoad({10.0, 1.4}));
  EXPECT_FALSE(divided.OnRoad({10.0, -1.4}));
  EXPECT_TRUE(divided.OnRoad({10.0, 1.5 + 1.75}));
  EXPECT_TRUE(divided.OnRoad({10.0, -(1.5 + 5.25)}));
  EXPECT_FALSE(divided.OnRoad({10.0, -(1.5 + 7.1)}));
}

TEST(RoadMapStraightTest, LocateOnLaneCentres) {
  const RoadMap map(Spec(RoadType::kStraight, 2, true));
  for (const Lane& lane : map.lanes()) {
    for (double s : {0.0, 13.0, 60.0, 119.0, 120.0}) {
      const Vec2 p = lane.centreline.PointAt(s);
      const auto loc = map.Locate({p.x(), p.y(), LaneHeading(lane, s)});
      ASSERT_TRUE(loc.has_value()) << "lane " << lane.id << " s " << s;
      EXPECT_EQ(loc->lane_id, lane.id);
      EXPECT_NEAR(loc->s, s, 1e-9);
      EXPECT_NEAR(loc->lateral, 0.0, 1e-9);
      EXPECT_NEAR(loc->heading_error, 0.0, 1e-9);
    }
  }
}

TEST(RoadMapStraightTest, LocateSignsAndPreferences) {
  const RoadMap map(Spec(RoadType::kStraight, 2));
  const int east0 = map.FindLane(Compass::kEast, false, 0);
  const int east1 = map.FindLane(Compass::kEast, false, 1);
  const int west0 = map.FindLane(Compass::kWest, false, 0);

  // Left of the eastbound kerb lane's centre (north), nose turned left.
  auto loc = map.Locate({0.0, -5.25 + 0.5, 0.2});
  ASSERT_TRUE(loc);
  EXPECT_EQ(loc->lane_id, east1);
  EXPECT_NEAR(loc->lateral, 0.5, 1e-9);
  EXPECT_NEAR(loc->heading_error, 0.2, 1e-9);
  EXPECT_NEAR(loc->s, 60.0, 1e-9);

  loc = map.Locate({-20.0, -5.25 - 0.5, -0.3});
  ASSERT_TRUE(loc);
  EXPECT_EQ(loc->lane_id, east1);
  EXPECT_NEAR(loc->lateral, -0.5, 1e-9);
  EXPECT_NEAR(loc->heading_error, -0.3, 1e-9);

  // On the centre line both index-0 lanes hold the point: heading decides.
  loc = map.Locate({5.0, 0.0, 0.0});
  ASSERT_TRUE(loc);
  EXPECT_EQ(loc->lane_id, east0);
  EXPECT_NEAR(loc->lateral, 1.75, 1e-9);
  loc = map.Locate({5.0, 0.0, kPi});
  ASSERT_TRUE(loc);
  EXPECT_EQ(loc->lane_id, west0);
  EXPECT_NEAR(loc->lateral, 1.75, 1e-9);  // westbound travels -x: south is its left
  loc = map.Locate({5.0, 2.5, kPi});
  ASSERT_TRUE(loc);
  EXPECT_EQ(loc->lane_id, west0);
  EXPECT_NEAR(loc->lateral, -0.75, 1e-9);  // north of a westbound lane is its right

  // Wrong way in the eastbound kerb lane: the only lane holding the point.
  loc = map.Locate({0.0, -5.25, kPi - 0.1});
  ASSERT_TRUE(loc);
  EXPECT_EQ(loc->lane_id, east1);
  EXPECT_NEAR(std::abs(loc->heading_error), kPi - 0.1, 1e-9);
  EXPECT_GT(loc->heading_error, 0.0);
}

TEST(RoadMapStraightTest, LocateRejectsPointsOffTheLanes) {
  const RoadMap map(Spec(RoadType::kStraight, 1, true));  // median 3 m
  EXPECT_FALSE(map.Locate({0.0, 0.0, 0.0}));             // median centre
  EXPECT_FALSE(map.Locate({0.0, 10.0, 0.0}));            // beside the road
  EXPECT_FALSE(map.Locate({60.5, -1.5 - 1.75, 0.0}));    // past the end, on the centreline
  EXPECT_FALSE(map.Locate({-61.0, 1.5 + 1.75, kPi}));
  EXPECT_TRUE(map.Locate({59.9, -1.5 - 1.75, 0.0}));
}

// ---------------------------------------------------------------- junctions

class RoadMapJunctionTest : public ::testing::TestWithParam<std::tuple<RoadType, int, bool>> {
 protected:
  RoadMapJunctionTest()
      : spec_(Spec(std::get<0>(GetParam()), std::get<1>(GetParam()), std::get<2>(GetParam()))),
        map_(spec_) {}
  bool HasArm(Compass c) const {
    return spec_.type == RoadType::kIntersection || c != Compass::kNorth;
  }
  std::vector<Compass> Arms() const {
    std::vector<Compass> arms;
    for (Compass c : {Compass::kEast, Compass::kNorth, Compass::kWest, Compass::kSouth}) {
      if (HasArm(c)) arms.push_back(c);
    }
    return arms;
  }
  RoadMapSpec spec_;
  RoadMap map_;
};

TEST_P(RoadMapJunctionTest, LaneAndConnectorCounts) {
  const int n = spec_.lanes_per_direction;
  int road = 0;
  int connectors = 0;
  for (const Lane& lane : map_.lanes()) (lane.kind == LaneKind::kRoad ? road : connectors)++;
  if (spec_.type == RoadType::kIntersection) {
    EXPECT_EQ(road, 4 * 2 * n);
    EXPECT_EQ(connectors, 4 * (n + 2));  // n straight, one left, one right per approach
  } else {
    EXPECT_EQ(road, 3 * 2 * n);
    // West approach: n straight + right; east: n straight + left; stem: left + right.
    EXPECT_EQ(connectors, 2 * n + 4);
  }
  for (size_t i = 0; i < map_.lanes().size(); ++i) {
    EXPECT_EQ(map_.lanes()[i].id, static_cast<int>(i));
  }
}

TEST_P(RoadMapJunctionTest, JunctionHalfSizeFitsTheLanes) {
  const double h = map_.junction_half_size();
  EXPECT_DOUBLE_EQ(
      h, spec_.lanes_per_direction * spec_.lane_width + HalfMedian(spec_) + kCornerMargin);
}

TEST_P(RoadMapJunctionTest, RoadLanesRunBetweenTheArmEndAndTheBox) {
  const int n = spec_.lanes_per_direction;
  const double h = map_.junction_half_size();
  for (Compass arm : {Compass::kEast, Compass::kNorth, Compass::kWest, Compass::kSouth}) {
    const Compass in_travel = static_cast<Compass>((static_cast<int>(arm) + 2) % 4);
    const std::vector<int> in = map_.FindLanes(in_travel, true);
    const std::vector<int> out = map_.FindLanes(arm, false);
    if (!HasArm(arm)) {
      EXPECT_TRUE(in.empty());
      EXPECT_TRUE(out.empty());
      EXPECT_EQ(map_.FindLane(arm, false, 0), -1);
      continue;
    }
    ASSERT_EQ(in.size(), static_cast<size_t>(n));
    ASSERT_EQ(out.size(), static_cast<size_t>(n));
    const Vec2 u(std::cos(CompassYaw(arm)), std::sin(CompassYaw(arm)));  // outwards
    const Vec2 right_of_out(u.y(), -u.x());
    for (int i = 0; i < n; ++i) {
      const double offset = HalfMedian(spec_) + (i + 0.5) * spec_.lane_width;
      const Lane& inbound = map_.lane(in[i]);
      EXPECT_EQ(inbound.index, i);
      EXPECT_EQ(inbound.arm, arm);
      EXPECT_TRUE(inbound.inbound);
      EXPECT_EQ(inbound.travel, in_travel);
      EXPECT_TRUE(inbound.predecessors.empty());
      // Every lane goes straight on, except on a T-junction's stem, which has
      // only the left turn (index 0) and the right turn (kerb lane): middle
      // lanes of a 3- or 4-lane stem lead nowhere, and its outbound middle
      // lanes are reached from nowhere.
      const bool stem = spec_.type == RoadType::kTJunction && arm == Compass::kSouth;
      const bool linked = !stem || i == 0 || i == n - 1;
      EXPECT_EQ(inbound.successors.empty(), !linked);
      // Inbound lanes travel towards the centre, on the other side of the axis.
      const Polyline& in_line = inbound.centreline;
      EXPECT_LT((in_line.points().front() - (spec_.length * u - offset * right_of_out)).norm(),
                1e-9);
      EXPECT_LT((in_line.points().back() - (h * u - offset * right_of_out)).norm(), 1e-9);
      EXPECT_NEAR(WrapAngle(LaneHeading(inbound, 1.0) - CompassYaw(in_travel)), 0.0, 1e-12);

      const Lane& outbound = map_.lane(out[i]);
      EXPECT_EQ(outbound.index, i);
      EXPECT_EQ(outbound.arm, arm);
      EXPECT_FALSE(outbound.inbound);
      EXPECT_TRUE(outbound.successors.empty());
      EXPECT_EQ(outbound.predecessors.empty(), !linked);
      const Polyline& out_line = outbound.centreline;
      EXPECT_LT((out_line.points().front() - (h * u + offset * right_of_out)).norm(), 1e-9);
      EXPECT_LT((out_line.points().back() - (spec_.length * u + offset * right_of_out)).norm(),
                1e-9);
      EXPECT_NEAR(outbound.centreline.length(), spec_.length - h, 1e-9);
    }
  }
}

TEST_P(RoadMapJunctionTest, ConnectorsJoinTheirLanesSmoothlyInsideTheBox) {
  const int n = spec_.lanes_per_direction;
  const double h = map_.junction_half_size();
  for (const Lane& c : map_.lanes()) {
    if (c.kind != LaneKind::kConnector) continue;
    SCOPED_TRACE("connector " + std::to_string(c.id) + " " + std::string(ToString(c.travel)) +
                 " " + std::string(ToString(c.turn)));
    const Lane& from = map_.lane(c.from_lane);
    const Lane& to = map_.lane(c.to_lane);
    EXPECT_EQ(from.kind, LaneKind::kRoad);
    EXPECT_TRUE(from.inbound);
    EXPECT_EQ(to.kind, LaneKind::kRoad);
    EXPECT_FALSE(to.inbound);
    EXPECT_EQ(c.travel, from.travel);
    EXPECT_EQ(c.predecessors, std::vector<int>{c.from_lane});
    EXPECT_EQ(c.successors, std::vector<int>{c.to_lane});
    EXPECT_EQ(std::count(from.successors.begin(), from.successors.end(), c.id), 1);
    EXPECT_EQ(std::count(to.predecessors.begin(), to.predecessors.end(), c.id), 1);
    EXPECT_EQ(map_.FindConnector(c.from_lane, c.turn), c.id);

    // Which lanes each movement joins.
    switch (c.turn) {
      case Turn::kStraight:
        EXPECT_EQ(to.travel, from.travel);
        EXPECT_EQ(to.index, from.index);
        break;
      case Turn::kLeft:
        EXPECT_EQ(to.travel, LeftOf(from.travel));
        EXPECT_EQ(from.index, 0);
        EXPECT_EQ(to.index, 0);
        break;
      case Turn::kRight:
        EXPECT_EQ(to.travel, RightOf(from.travel));
        EXPECT_EQ(from.index, n - 1);
        EXPECT_EQ(to.index, n - 1);
        break;
    }

    // Positional and tangent continuity at both joints.
    const Polyline& line = c.centreline;
    EXPECT_LT((line.points().front() - from.centreline.points().back()).norm(), 1e-9);
    EXPECT_LT((line.points().back() - to.centreline.points().front()).norm(), 1e-9);
    EXPECT_NEAR(WrapAngle(line.HeadingAt(0.0) - CompassYaw(from.travel)), 0.0, 0.03);
    EXPECT_NEAR(WrapAngle(line.HeadingAt(line.length()) - CompassYaw(to.travel)), 0.0, 0.03);

    // Sampled every <= 1 m, turning gradually and monotonically, inside the box.
    const auto& pts = line.points();
    double turned = 0.0;
    for (size_t k = 0; k + 1 < pts.size(); ++k) {
      EXPECT_LE((pts[k + 1] - pts[k]).norm(), 1.0 + 1e-9);
      EXPECT_LE(std::abs(pts[k].x()), h + 1e-9);
      EXPECT_LE(std::abs(pts[k].y()), h + 1e-9);
      if (k + 2 < pts.size()) {
        const Vec2 a = pts[k + 1] - pts[k];
        const Vec2 b = pts[k + 2] - pts[k + 1];
        const double dturn = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
        EXPECT_LE(std::abs(dturn), 0.06);
        if (c.turn == Turn::kLeft) {
          EXPECT_GE(dturn, -1e-12);
        }
        if (c.turn == Turn::kRight) {
          EXPECT_LE(dturn, 1e-12);
        }
        turned += dturn;
      }
    }
    const double expected_turn = c.turn == Turn::kLeft    ? 0.5 * kPi
                                 : c.turn == Turn::kRight ? -0.5 * kPi
                                                          : 0.0;
    EXPECT_NEAR(turned, expected_turn, 0.06);  // the end segments carry the rest
  }
}

TEST_P(RoadMapJunctionTest, EachApproachHasTheTurnsTheArmsAllow) {
  for (const Lane& lane : map_.lanes()) {
    if (lane.kind != LaneKind::kRoad || !lane.inbound) continue;
    const bool kerb = lane.index == spec_.lanes_per_direction - 1;
    EXPECT_EQ(map_.FindConnector(lane.id, Turn::kStraight) >= 0, HasArm(lane.travel));
    EXPECT_EQ(map_.FindConnector(lane.id, Turn::kLeft) >= 0,
              lane.index == 0 && HasArm(LeftOf(lane.travel)));
    EXPECT_EQ(map_.FindConnector(lane.id, Turn::kRight) >= 0, kerb && HasArm(RightOf(lane.travel)));
  }
  EXPECT_EQ(map_.FindConnector(-1, Turn::kStraight), -1);
  EXPECT_EQ(map_.FindConnector(100000, Turn::kStraight), -1);
}

TEST_P(RoadMapJunctionTest, LocateFindsEveryLaneAtItsCentre) {
  for (const Lane& lane : map_.lanes()) {
    for (double frac : {0.1, 0.5, 0.9}) {
      const double s = frac * lane.centreline.length();
      const Vec2 p = lane.centreline.PointAt(s);
      const auto loc = map_.Locate({p.x(), p.y(), LaneHeading(lane, s)});
      ASSERT_TRUE(loc.has_value()) << "lane " << lane.id;
      EXPECT_EQ(loc->lane_id, lane.id) << "lane " << lane.id << " frac " << frac;
      EXPECT_NEAR(loc->lateral, 0.0, 1e-9);
      EXPECT_NEAR(loc->s, s, 1e-6);
      // Exact on road lanes; on a connector sample the foot may sit on the
      // neighbouring chord, one sampling angle away.
      EXPECT_NEAR(loc->heading_error, 0.0, lane.kind == LaneKind::kRoad ? 1e-12 : 0.06);
    }
  }
}

TEST_P(RoadMapJunctionTest, LocateAtAJointReturnsOneOfTheJoinedLanes) {
  const int in = map_.FindLane(Compass::kEast, true, 0);  // on the west arm
  const Vec2 joint = map_.lane(in).centreline.points().back();
  const auto loc = map_.Locate({joint.x(), joint.y(), 0.0});
  ASSERT_TRUE(loc);
  const Lane& got = map_.lane(loc->lane_id);
  EXPECT_TRUE(got.id == in || got.from_lane == in) << got.id;
  EXPECT_NEAR(loc->lateral, 0.0, 1e-9);
}

TEST_P(RoadMapJunctionTest, EveryLaneCorridorIsOnRoad) {
  for (const Lane& lane : map_.lanes()) {
    const Polyline& line = lane.centreline;
    for (double s = 0.0; s <= line.length(); s += 0.5) {
      const Vec2 p = line.PointAt(s);
      const double yaw = line.HeadingAt(s);
      const Vec2 left(-std::sin(yaw), std::cos(yaw));
      const double half = 0.5 * lane.width - 1e-6;
      EXPECT_TRUE(map_.OnRoad(p)) << "lane " << lane.id << " s " << s;
      EXPECT_TRUE(map_.OnRoad(p + half * left)) << "lane " << lane.id << " s " << s;
      EXPECT_TRUE(map_.OnRoad(p - half * left)) << "lane " << lane.id << " s " << s;
    }
  }
}

TEST_P(RoadMapJunctionTest, OnRoadExcludesMediansCornersAndBeyondTheArms) {
  const double h = map_.junction_half_size();
  const double len = spec_.length;
  const double outer = HalfMedian(spec_) + spec_.lanes_per_direction * spec_.lane_width;
  EXPECT_TRUE(map_.OnRoad({0.0, 0.0}));
  EXPECT_TRUE(map_.OnRoad({h - 0.1, h - 0.1}));    // the whole box is drivable
  EXPECT_TRUE(map_.OnRoad({-h + 0.1, -h + 0.1}));
  EXPECT_FALSE(map_.OnRoad({h + 2.0, h + 2.0}));   // between two arms
  EXPECT_FALSE(map_.OnRoad({-h - 2.0, -h - 2.0}));
  EXPECT_FALSE(map_.OnRoad({h + 1.0, outer + 0.1}));  // off the east arm's kerb
  EXPECT_TRUE(map_.OnRoad({len - 0.1, -outer + 0.1}));
  EXPECT_FALSE(map_.OnRoad({len + 0.1, -outer + 0.1}));  // past the east arm's end
  EXPECT_FALSE(map_.OnRoad({-len - 0.1, outer - 0.1}));
  EXPECT_FALSE(map_.OnRoad({0.0, -len - 0.1}));
  EXPECT_TRUE(map_.OnRoad({-outer + 0.1, -len + 0.1}));
  EXPECT_EQ(map_.OnRoad({outer - 0.1, h + 3.0}), HasArm(Compass::kNorth));
  EXPECT_EQ(map_.OnRoad({-outer + 0.1, len - 0.1}), HasArm(Compass::kNorth));
  if (spec_.divided) {
    EXPECT_FALSE(map_.OnRoad({h + 5.0, 0.0}));  // medians on the arms
    EXPECT_FALSE(map_.OnRoad({-h - 5.0, 0.0}));
    EXPECT_FALSE(map_.OnRoad({0.0, -h - 5.0}));
    EXPECT_TRUE(map_.OnRoad({0.0, 0.0}));  // but not in the box
  } else {
    EXPECT_TRUE(map_.OnRoad({h + 5.0, 0.0}));
  }
}

TEST_P(RoadMapJunctionTest, RouteThroughJoinsLanesInTravelOrder) {
  const double h = map_.junction_half_size();
  const double len = spec_.length;
  const int in = map_.FindLane(Compass::kEast, true, 0);
  const int straight = map_.FindConnector(in, Turn::kStraight);
  const int out = map_.FindLane(Compass::kEast, false, 0);
  ASSERT_GE(straight, 0);
  const Polyline route = map_.RouteThrough({in, straight, out});
  EXPECT_NEAR(route.length(), 2.0 * len, 1e-9);
  EXPECT_TRUE(route.points().front().isApprox(map_.lane(in).centreline.points().front()));
  EXPECT_TRUE(route.points().back().isApprox(map_.lane(out).centreline.points().back()));
  for (size_t k = 0; k + 1 < route.points().size(); ++k) {
    EXPECT_GT((route.points()[k + 1] - route.points()[k]).norm(), 1e-6);  // no doubled joints
  }
  // The connector's samples are kept: its interior points are in the route.
  EXPECT_EQ(route.points().size(), map_.lane(straight).centreline.points().size() + 2);

  // Eastbound lane 0 turns left into northbound (intersection) or the stem
  // traffic turns left into westbound (T): both are quarter circles of radius h + offset.
  const int left_in =
      spec_.type == RoadType::kIntersection ? in : map_.FindLane(Compass::kNorth, true, 0);
  const int left = map_.FindConnector(left_in, Turn::kLeft);
  ASSERT_GE(left, 0);
  const int left_out = map_.lane(left).to_lane;
  const double radius = h + HalfMedian(spec_) + 0.5 * spec_.lane_width;
  const Polyline turn = map_.RouteThrough({left_in, left, left_out});
  EXPECT_NEAR(turn.length(), 2.0 * (len - h) + 0.5 * kPi * radius, 0.01);
  EXPECT_NEAR(map_.lane(left).centreline.length(), 0.5 * kPi * radius, 0.01);

  const int kerb_in = map_.FindLane(Compass::kEast, true, spec_.lanes_per_direction - 1);
  const int right = map_.FindConnector(kerb_in, Turn::kRight);
  ASSERT_GE(right, 0);
  const double right_radius = 0.5 * spec_.lane_width + kCornerMargin;
  EXPECT_NEAR(map_.lane(right).centreline.length(), 0.5 * kPi * right_radius, 0.01);

  // A single lane is its own route.
  EXPECT_NEAR(map_.RouteThrough({out}).length(), len - h, 1e-9);
}

TEST_P(RoadMapJunctionTest, RouteThroughRejectsBrokenChains) {
  const int in = map_.FindLane(Compass::kEast, true, 0);
  const int out = map_.FindLane(Compass::kEast, false, 0);
  const int straight = map_.FindConnector(in, Turn::kStraight);
  ExpectFieldError([&] { map_.RouteThrough({}); }, "lane_ids");
  ExpectFieldError([&] { map_.RouteThrough({in, out}); }, "lane_ids");  // skips the connector
  ExpectFieldError([&] { map_.RouteThrough({out, straight, in}); }, "lane_ids");  // backwards
  ExpectFieldError([&] { map_.RouteThrough({in, -1}); }, "lane_ids");
  const int past_last = static_cast<int>(map_.lanes().size());
  ExpectFieldError([&] { map_.RouteThrough({in, past_last}); }, "lane_ids");
}

std::string LayoutName(const ::testing::TestParamInfo<std::tuple<RoadType, int, bool>>& info) {
  return std::string(ToString(std::get<0>(info.param))) + "_" +
         std::to_string(std::get<1>(info.param)) + "lanes" +
         (std::get<2>(info.param) ? "_divided" : "");
}

INSTANTIATE_TEST_SUITE_P(RoadMapLayouts, RoadMapJunctionTest,
                         ::testing::Combine(::testing::Values(RoadType::kIntersection,
                                                              RoadType::kTJunction),
                                            ::testing::Values(1, 2, 4), ::testing::Bool()),
                         LayoutName);

TEST(RoadMapTJunctionTest, HasNoNorthArm) {
  const RoadMap map(Spec(RoadType::kTJunction, 2));
  EXPECT_TRUE(map.FindLanes(Compass::kNorth, false).empty());  // nobody leaves northwards
  EXPECT_TRUE(map.FindLanes(Compass::kSouth, true).empty());   // nobody arrives from the north
  EXPECT_EQ(map.FindLanes(Compass::kNorth, true).size(), 2u);  // the stem's inbound lanes
  const int east_in = map.FindLane(Compass::kEast, true, 0);
  const int west_in = map.FindLane(Compass::kWest, true, 0);
  const int stem_in = map.FindLane(Compass::kNorth, true, 0);
  EXPECT_EQ(map.FindConnector(east_in, Turn::kLeft), -1);
  EXPECT_GE(map.FindConnector(west_in, Turn::kLeft), 0);
  EXPECT_EQ(map.FindConnector(stem_in, Turn::kStraight), -1);
  EXPECT_GE(map.FindConnector(stem_in, Turn::kLeft), 0);
  EXPECT_EQ(map.FindConnector(stem_in, Turn::kRight), -1);  // index 0 is not the kerb lane
  EXPECT_GE(map.FindConnector(map.FindLane(Compass::kNorth, true, 1), Turn::kRight), 0);
  EXPECT_EQ(map.lane(map.FindConnector(west_in, Turn::kLeft)).to_lane,
            map.FindLane(Compass::kSouth, false, 0));
}

TEST(RoadMapLocateTest, PrefersTheAlignedConnectorWhereTurnsCross) {
  // Westbound left turn and eastbound straight connector cross inside the box.
  const RoadMap map(Spec(RoadType::kIntersection, 1));
  const int east_in = map.FindLane(Compass::kEast, true, 0);
  const int west_in = map.FindLane(Compass::kWest, true, 0);
  const int straight = map.FindConnector(east_in, Turn::kStraight);
  const int left = map.FindConnector(west_in, Turn::kLeft);
  // Eastbound straight is the line y = -1.75; find where the left turn crosses it.
  const Polyline& arc = map.lane(left).centreline;
  double s_cross = -1.0;
  for (double s = 0.0; s < arc.length(); s += 0.01) {
    if (arc.PointAt(s).y() <= -1.75) {
      s_cross = s;
      break;
    }
  }
  ASSERT_GT(s_cross, 0.0);
  const Vec2 p = arc.PointAt(s_cross);
  auto loc = map.Locate({p.x(), p.y(), 0.0});
  ASSERT_TRUE(loc);
  EXPECT_EQ(loc->lane_id, straight);
  loc = map.Locate({p.x(), p.y(), arc.HeadingAt(s_cross)});
  ASSERT_TRUE(loc);
  EXPECT_EQ(loc->lane_id, left);
}

}  // namespace
}  // namespace accsim
