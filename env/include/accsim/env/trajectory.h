// Timed planar trajectories: what NPCs follow before (and, when predicted,
// after) the first contact, and what `simulate --out` records.
#pragma once

#include <vector>

#include "accsim/env/geometry.h"

namespace accsim {

struct TrajectoryPoint {
  double t = 0.0;    // [s] from episode start
  double x = 0.0;    // [m]
  double y = 0.0;    // [m]
  double yaw = 0.0;  // [rad]
  double v = 0.0;    // [m/s] speed along the heading (negative: reversing)
};

// Strictly increasing in time. Immutable; safe to share between threads.
class Trajectory {
 public:
  Trajectory() = default;
  // Throws std::invalid_argument naming the point ("[3].t: ...") when times
  // are not strictly increasing or a value is not finite.
  explicit Trajectory(std::vector<TrajectoryPoint> points);

  const std::vector<TrajectoryPoint>& points() const { return points_; }
  bool empty() const { return points_.empty(); }
  double start_time() const { return points_.empty() ? 0.0 : points_.front().t; }
  double end_time() const { return points_.empty() ? 0.0 : points_.back().t; }

  // State at time t: linear in position and speed, shortest-arc in yaw.
  // Before the first point: the first point. After the last: continues at
  // the last speed along the last heading (a stopped vehicle stays put).
  // `cursor` (optional) caches the segment index for O(1) monotone queries.
  TrajectoryPoint Sample(double t, size_t* cursor = nullptr) const;

 private:
  std::vector<TrajectoryPoint> points_;
};

}  // namespace accsim
