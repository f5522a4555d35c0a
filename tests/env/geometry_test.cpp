#include "accsim/env/geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace accsim {
namespace {

constexpr double kEps = 1e-12;

// (0,0) -> (3,0) -> (3,4): east 3 m, then north 4 m.
Polyline LShape() { return Polyline({{0.0, 0.0}, {3.0, 0.0}, {3.0, 4.0}}); }

TEST(GeometryTest, WrapAngleMapsIntoHalfOpenRange) {
  EXPECT_NEAR(WrapAngle(0.3), 0.3, kEps);
  EXPECT_NEAR(WrapAngle(-0.3), -0.3, kEps);
  EXPECT_NEAR(WrapAngle(kPi), kPi, kEps);
  EXPECT_NEAR(WrapAngle(-kPi), kPi, kEps);  // -pi is excluded
  EXPECT_NEAR(WrapAngle(3.0 * kPi), kPi, 1e-9);
  EXPECT_NEAR(WrapAngle(2.0 * kPi + 0.1), 0.1, 1e-9);
  EXPECT_NEAR(WrapAngle(-2.0 * kPi - 0.1), -0.1, 1e-9);
}

TEST(GeometryTest, ToLocalRotatesIntoHeadingFrame) {
  const Vec2 north(0.0, 1.0);
  const Vec2 ahead = ToLocal(north, 0.5 * kPi);  // facing north
  EXPECT_NEAR(ahead.x(), 1.0, kEps);
  EXPECT_NEAR(ahead.y(), 0.0, kEps);
  const Vec2 left = ToLocal(north, 0.0);  // facing east, north is to the left
  EXPECT_NEAR(left.x(), 0.0, kEps);
  EXPECT_NEAR(left.y(), 1.0, kEps);
}

TEST(PolylineTest, CumulativeArcLengths) {
  const Polyline line = LShape();
  ASSERT_EQ(line.points().size(), 3u);
  ASSERT_EQ(line.arc_lengths().size(), 3u);
  EXPECT_DOUBLE_EQ(line.arc_lengths()[0], 0.0);
  EXPECT_DOUBLE_EQ(line.arc_lengths()[1], 3.0);
  EXPECT_DOUBLE_EQ(line.arc_lengths()[2], 7.0);
  EXPECT_DOUBLE_EQ(line.length(), 7.0);
  EXPECT_FALSE(line.empty());
}

TEST(PolylineTest, DropsConsecutiveDuplicates) {
  const Polyline line({{0.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}, {1.0, 1e-12}, {1.0, 2.0}});
  ASSERT_EQ(line.points().size(), 3u);
  EXPECT_DOUBLE_EQ(line.length(), 3.0);
  // A revisited point that is not consecutive is kept.
  const Polyline back({{0.0, 0.0}, {1.0, 0.0}, {0.0, 0.0}});
  EXPECT_EQ(back.points().size(), 3u);
  EXPECT_DOUBLE_EQ(back.length(), 2.0);
}

TEST(PolylineTest, RejectsTooFewDistinctPoints) {
  EXPECT_THROW(Polyline(std::vector<Vec2>{}), std::invalid_argument);
  EXPECT_THROW(Polyline({{1.0, 2.0}}), std::invalid_argument);
  EXPECT_THROW(Polyline({{1.0, 2.0}, {1.0, 2.0}, {1.0, 2.0}}), std::invalid_argument);
}

TEST(PolylineTest, RejectsNonFiniteCoordinates) {
  const double nan = std::nan("");
  const double inf = INFINITY;
  EXPECT_THROW(Polyline({{0.0, 0.0}, {nan, 1.0}}), std::invalid_argument);
  EXPECT_THROW(Polyline({{0.0, inf}, {1.0, 1.0}}), std::invalid_argument);
  EXPECT_THROW(Polyline({{0.0, 0.0}, {1.0, 0.0}, {2.0, -inf}}), std::invalid_argument);
  try {
    Polyline({{0.0, 0.0}, {nan, 1.0}});
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("[1]"), std::string::npos) << e.what();
  }
}

TEST(PolylineTest, DefaultConstructedIsEmptyAndSafe) {
  const Polyline line;
  EXPECT_TRUE(line.empty());
  EXPECT_EQ(line.length(), 0.0);
  EXPECT_EQ(line.PointAt(3.0), Vec2::Zero());
  EXPECT_EQ(line.HeadingAt(3.0), 0.0);
  const PolylineProjection proj = line.Project({1.0, 1.0});
  EXPECT_EQ(proj.s, 0.0);
  EXPECT_EQ(proj.segment, 0);
}

TEST(PolylineTest, PointAtInterpolatesAndClamps) {
  const Polyline line = LShape();
  EXPECT_TRUE(line.PointAt(1.5).isApprox(Vec2(1.5, 0.0)));
  EXPECT_TRUE(line.PointAt(3.0).isApprox(Vec2(3.0, 0.0)));
  EXPECT_TRUE(line.PointAt(5.0).isApprox(Vec2(3.0, 2.0)));
  EXPECT_TRUE(line.PointAt(7.0).isApprox(Vec2(3.0, 4.0)));
  EXPECT_TRUE(line.PointAt(-1.0).isApprox(Vec2(0.0, 0.0)));
  EXPECT_TRUE(line.PointAt(100.0).isApprox(Vec2(3.0, 4.0)));
}

TEST(PolylineTest, HeadingAtFollowsSegmentsAndLooksAheadAtVertices) {
  const Polyline line = LShape();
  EXPECT_NEAR(line.HeadingAt(1.0), 0.0, kEps);
  EXPECT_NEAR(line.HeadingAt(3.0), 0.5 * kPi, kEps);  // the segment starting there
  EXPECT_NEAR(line.HeadingAt(6.0), 0.5 * kPi, kEps);
  EXPECT_NEAR(line.HeadingAt(-5.0), 0.0, kEps);
  EXPECT_NEAR(line.HeadingAt(50.0), 0.5 * kPi, kEps);
  const Polyline west({{0.0, 0.0}, {-2.0, 0.0}});
  EXPECT_NEAR(std::abs(west.HeadingAt(1.0)), kPi, kEps);
}

TEST(PolylineTest, ProjectInteriorGivesArcLengthAndSignedLateral) {
  const Polyline line = LShape();
  const PolylineProjection left = line.Project({1.0, 1.0});
  EXPECT_NEAR(left.s, 1.0, kEps);
  EXPECT_NEAR(left.lateral, 1.0, kEps);  // north of an eastward segment is left
  EXPECT_NEAR(left.distance, 1.0, kEps);
  EXPECT_NEAR(left.heading, 0.0, kEps);
  EXPECT_EQ(left.segment, 0);

  const PolylineProjection right = line.Project({1.0, -0.5});
  EXPECT_NEAR(right.s, 1.0, kEps);
  EXPECT_NEAR(right.lateral, -0.5, kEps);
  EXPECT_NEAR(right.distance, 0.5, kEps);

  // Second segment travels north: east of it is to the right.
  const PolylineProjection second = line.Project({4.0, 2.0});
  EXPECT_NEAR(second.s, 5.0, kEps);
  EXPECT_NEAR(second.lateral, -1.0, kEps);
  EXPECT_NEAR(second.heading, 0.5 * kPi, kEps);
  EXPECT_EQ(second.segment, 1);

  const PolylineProjection on = line.Project({3.0, 2.5});
  EXPECT_NEAR(on.s, 5.5, kEps);
  EXPECT_NEAR(on.lateral, 0.0, kEps);
  EXPECT_NEAR(on.distance, 0.0, kEps);
}

TEST(PolylineTest, ProjectClampsAtTheEnds) {
  const Polyline line = LShape();
  const PolylineProjection before = line.Project({-2.0, 1.0});
  EXPECT_NEAR(before.s, 0.0, kEps);
  EXPECT_NEAR(before.distance, std::sqrt(5.0), kEps);
  EXPECT_NEAR(before.lateral, 1.0, kEps);  // offset from the extended first segment
  EXPECT_EQ(before.segment, 0);

  const PolylineProjection after = line.Project({3.0, 6.0});
  EXPECT_NEAR(after.s, 7.0, kEps);
  EXPECT_NEAR(after.distance, 2.0, kEps);
  EXPECT_NEAR(after.lateral, 0.0, kEps);
  EXPECT_EQ(after.segment, 1);
}

TEST(PolylineTest, ProjectTiesGoToTheEarliestSegment) {
  const Polyline line = LShape();
  // (2, 1) is 1 m from both segments.
  const PolylineProjection proj = line.Project({2.0, 1.0});
  EXPECT_EQ(proj.segment, 0);
  EXPECT_NEAR(proj.s, 2.0, kEps);
  // The vertex itself: segment 0 at its end.
  const PolylineProjection corner = line.Project({3.0, 0.0});
  EXPECT_EQ(corner.segment, 0);
  EXPECT_NEAR(corner.s, 3.0, kEps);
}

TEST(PolylineTest, ProjectedFootLiesOnThePolyline) {
  const Polyline line = LShape();
  for (const Vec2& p : {Vec2(1.0, 1.0), Vec2(4.0, 2.0), Vec2(2.5, 0.3), Vec2(-1.0, -1.0)}) {
    const PolylineProjection proj = line.Project(p);
    EXPECT_NEAR((line.PointAt(proj.s) - p).norm(), proj.distance, 1e-9);
    EXPECT_NEAR(line.HeadingAt(proj.s), proj.heading, 1e-9) << p.transpose();
  }
}

// A 300 m sine-shaped road sampled every ~0.5 m.
Polyline Wiggle() {
  std::vector<Vec2> pts;
  for (int i = 0; i <= 600; ++i) {
    const double x = 0.5 * i;
    pts.emplace_back(x, 5.0 * std::sin(x / 20.0));
  }
  return Polyline(std::move(pts));
}

TEST(PolylineTest, HintWindowGivesTheSameResultAsTheFullSearch) {
  const Polyline line = Wiggle();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> along(0.0, line.length());
  std::uniform_real_distribution<double> offset(-3.0, 3.0);
  std::uniform_real_distribution<double> drift(-5.0, 5.0);
  for (int trial = 0; trial < 500; ++trial) {
    const double s = along(rng);
    const double yaw = line.HeadingAt(s);
    const double d = offset(rng);
    const Vec2 p = line.PointAt(s) + d * Vec2(-std::sin(yaw), std::cos(yaw));
    const PolylineProjection full = line.Project(p);
    const PolylineProjection hinted = line.Project(p, std::max(0.0, s + drift(rng)), 20.0);
    EXPECT_EQ(hinted.segment, full.segment) << "trial " << trial;
    EXPECT_DOUBLE_EQ(hinted.s, full.s);
    EXPECT_DOUBLE_EQ(hinted.lateral, full.lateral);
    EXPECT_DOUBLE_EQ(hinted.distance, full.distance);
    EXPECT_DOUBLE_EQ(hinted.heading, full.heading);
  }
}

TEST(PolylineTest, HintWindowRestrictsTheSearch) {
  // A hairpin: out along y = 0, back along y = 2.
  const Polyline line({{0.0, 0.0}, {100.0, 0.0}, {100.0, 2.0}, {0.0, 2.0}});
  const Vec2 p(10.0, 1.2);
  const PolylineProjection full = line.Project(p);
  EXPECT_NEAR(full.s, 192.0, 1e-9);  // the return leg is closer
  EXPECT_NEAR(full.lateral, 0.8, 1e-9);
  const PolylineProjection tracked = line.Project(p, 10.0, 20.0);
  EXPECT_EQ(tracked.segment, 0);
  EXPECT_NEAR(tracked.s, 10.0, 1e-9);
  EXPECT_NEAR(tracked.lateral, 1.2, 1e-9);
  // A hint past the end still searches the last segment.
  const PolylineProjection late = line.Project({50.0, 2.5}, 1e6, 1.0);
  EXPECT_EQ(late.segment, 2);
  EXPECT_NEAR(late.s, 152.0, 1e-9);
  // A negative hint means "no hint".
  EXPECT_NEAR(line.Project(p, -1.0, 1.0).s, 192.0, 1e-9);
}

}  // namespace
}  // namespace accsim
