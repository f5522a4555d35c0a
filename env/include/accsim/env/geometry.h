// Planar geometry shared by maps, routes and vehicles.
// Frame: ENU world, x east, y north; yaw counter-clockwise from +x [rad].
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

namespace accsim {

using Vec2 = Eigen::Vector2d;

struct Pose2 {
  double x = 0.0;    // [m]
  double y = 0.0;    // [m]
  double yaw = 0.0;  // [rad]
  Vec2 position() const { return {x, y}; }
};

constexpr double kPi = 3.14159265358979323846;

// Wraps an angle to (-pi, pi].
inline double WrapAngle(double a) {
  a = std::fmod(a + kPi, 2.0 * kPi);
  if (a <= 0.0) a += 2.0 * kPi;
  return a - kPi;
}

// Rotates a world-frame vector into a frame whose x axis points along yaw.
inline Vec2 ToLocal(const Vec2& v, double yaw) {
  const double c = std::cos(yaw), s = std::sin(yaw);
  return {c * v.x() + s * v.y(), -s * v.x() + c * v.y()};
}

// Where a point projects onto a polyline.
struct PolylineProjection {
  double s = 0.0;        // arc length of the foot point from the first vertex [m]
  // Signed distance, + to the left of the travel direction [m]. Measured
  // from the line through the foot segment, so past either end it is the
  // offset from the extended end segment (then |lateral| < distance).
  double lateral = 0.0;
  double heading = 0.0;  // direction of the segment at the foot point [rad]
  double distance = 0.0; // unsigned distance to the foot point [m]
  int segment = 0;       // index of the segment holding the foot point
};

// An open polyline with cumulative arc length. Immutable after construction;
// safe to share between threads.
class Polyline {
 public:
  Polyline() = default;
  // Drops consecutive duplicate points (closer than 1e-9 m); throws
  // std::invalid_argument when fewer than two distinct points remain or a
  // coordinate is not finite.
  explicit Polyline(std::vector<Vec2> points);

  const std::vector<Vec2>& points() const { return points_; }
  const std::vector<double>& arc_lengths() const { return s_; }
  double length() const { return s_.empty() ? 0.0 : s_.back(); }
  bool empty() const { return points_.size() < 2; }

  // Point and heading at arc length s, clamped to [0, length()]. At an
  // interior vertex the heading is that of the segment starting there.
  // None of the queries below allocate.
  Vec2 PointAt(double s) const;
  double HeadingAt(double s) const;
  // Closest point on the polyline (ties go to the earliest segment).
  // `hint_s`, when >= 0, restricts the search to segments overlapping
  // [hint_s - window, hint_s + window] for O(1) tracking queries.
  PolylineProjection Project(const Vec2& p, double hint_s = -1.0, double window = 20.0) const;

 private:
  std::vector<Vec2> points_;
  std::vector<double> s_;
};

}  // namespace accsim
