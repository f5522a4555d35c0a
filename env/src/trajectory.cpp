#include "accsim/env/trajectory.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace accsim {

Trajectory::Trajectory(std::vector<TrajectoryPoint> points) : points_(std::move(points)) {
  for (size_t i = 0; i < points_.size(); ++i) {
    const auto& p = points_[i];
    const std::string where = "[" + std::to_string(i) + "]";
    if (!std::isfinite(p.t)) throw std::invalid_argument(where + ".t: not a finite number");
    if (!std::isfinite(p.x)) throw std::invalid_argument(where + ".x: not a finite number");
    if (!std::isfinite(p.y)) throw std::invalid_argument(where + ".y: not a finite number");
    if (!std::isfinite(p.yaw)) throw std::invalid_argument(where + ".yaw: not a finite number");
    if (!std::isfinite(p.v)) throw std::invalid_argument(where + ".v: not a finite number");
    if (i > 0 && !(p.t > points_[i - 1].t)) {
      throw std::invalid_argument(where + ".t: times must be strictly increasing (" +
                                  std::to_string(points_[i - 1].t) + " then " +
                                  std::to_string(p.t) + ")");
    }
  }
}

TrajectoryPoint Trajectory::Sample(double t, size_t* cursor) const {
  if (points_.empty()) return {};
  const auto& first = points_.front();
  const auto& last = points_.back();
  if (t <= first.t) {
    TrajectoryPoint p = first;
    p.t = t;
    return p;
  }
  if (t >= last.t) {
    TrajectoryPoint p = last;
    const double dt = t - last.t;
    p.t = t;
    p.x += last.v * dt * std::cos(last.yaw);
    p.y += last.v * dt * std::sin(last.yaw);
    return p;
  }
  size_t i = cursor ? *cursor : 0;
  if (i + 1 >= points_.size() || points_[i].t > t) i = 0;
  while (points_[i + 1].t < t) ++i;
  if (cursor) *cursor = i;
  const auto& a = points_[i];
  const auto& b = points_[i + 1];
  const double u = (t - a.t) / (b.t - a.t);
  TrajectoryPoint p;
  p.t = t;
  p.x = a.x + u * (b.x - a.x);
  p.y = a.y + u * (b.y - a.y);
  p.yaw = WrapAngle(a.yaw + u * WrapAngle(b.yaw - a.yaw));
  p.v = a.v + u * (b.v - a.v);
  return p;
}

}  // namespace accsim
