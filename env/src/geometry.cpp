#include "accsim/env/geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace accsim {
namespace {

// Points closer than this to the previous kept point are duplicates: a
// near-zero segment would have a meaningless heading.
constexpr double kDuplicateTolerance = 1e-9;  // [m]

// Index of the segment holding arc length s (clamped to the polyline). At an
// interior vertex the segment starting there wins, so headings look ahead.
int SegmentAt(const std::vector<double>& arc_lengths, double s) {
  const int last = static_cast<int>(arc_lengths.size()) - 2;
  const auto it = std::upper_bound(arc_lengths.begin(), arc_lengths.end(), s);
  const int i = static_cast<int>(it - arc_lengths.begin()) - 1;
  return std::clamp(i, 0, last);
}

}  // namespace

Polyline::Polyline(std::vector<Vec2> points) {
  for (size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(points[i].x()) || !std::isfinite(points[i].y())) {
      throw std::invalid_argument("polyline: point [" + std::to_string(i) +
                                  "] is not finite");
    }
  }
  points_.reserve(points.size());
  for (const Vec2& p : points) {
    if (!points_.empty() && (p - points_.back()).norm() <= kDuplicateTolerance) continue;
    points_.push_back(p);
  }
  if (points_.size() < 2) {
    const size_t distinct = points_.size();
    points_.clear();
    throw std::invalid_argument("polyline: needs at least two distinct points, got " +
                                std::to_string(distinct));
  }
  s_.resize(points_.size());
  s_[0] = 0.0;
  for (size_t i = 1; i < points_.size(); ++i) {
    s_[i] = s_[i - 1] + (points_[i] - points_[i - 1]).norm();
  }
}

Vec2 Polyline::PointAt(double s) const {
  if (empty()) return Vec2::Zero();
  s = std::clamp(s, 0.0, length());
  const int i = SegmentAt(s_, s);
  const double seg_len = s_[i + 1] - s_[i];
  const double t = std::clamp((s - s_[i]) / seg_len, 0.0, 1.0);
  return points_[i] + t * (points_[i + 1] - points_[i]);
}

double Polyline::HeadingAt(double s) const {
  if (empty()) return 0.0;
  const int i = SegmentAt(s_, std::clamp(s, 0.0, length()));
  const Vec2 d = points_[i + 1] - points_[i];
  return std::atan2(d.y(), d.x());
}

PolylineProjection Polyline::Project(const Vec2& p, double hint_s, double window) const {
  PolylineProjection out;
  if (empty()) return out;
  const int last_segment = static_cast<int>(points_.size()) - 2;
  int first = 0;
  int last = last_segment;
  // A segment [s_i, s_i+1] overlaps [lo, hi] when s_i+1 >= lo and s_i <= hi.
  if (hint_s >= 0.0 && window >= 0.0) {
    const double lo = hint_s - window;
    const double hi = hint_s + window;
    first = static_cast<int>(std::lower_bound(s_.begin(), s_.end(), lo) - s_.begin()) - 1;
    first = std::clamp(first, 0, last_segment);
    last = static_cast<int>(std::upper_bound(s_.begin(), s_.end(), hi) - s_.begin()) - 1;
    last = std::clamp(last, first, last_segment);
  }

  double best_d2 = std::numeric_limits<double>::infinity();
  int best = first;
  double best_t = 0.0;
  for (int i = first; i <= last; ++i) {
    const Vec2& a = points_[i];
    const Vec2 ab = points_[i + 1] - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    const double d2 = (p - (a + t * ab)).squaredNorm();
    if (d2 < best_d2) {  // strict: ties keep the earliest segment
      best_d2 = d2;
      best = i;
      best_t = t;
    }
  }

  const Vec2& a = points_[best];
  const Vec2 ab = points_[best + 1] - a;
  const double seg_len = s_[best + 1] - s_[best];
  const Vec2 ap = p - a;
  out.segment = best;
  out.s = s_[best] + best_t * seg_len;
  // Offset from the segment's line: equals the signed distance whenever the
  // foot is inside the segment, and stays a lateral error past the ends.
  out.lateral = (ab.x() * ap.y() - ab.y() * ap.x()) / ab.norm();
  out.heading = std::atan2(ab.y(), ab.x());
  out.distance = std::sqrt(best_d2);
  return out;
}

}  // namespace accsim
