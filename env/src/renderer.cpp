#include "accsim/env/renderer.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace accsim {
namespace {

// BGR colours (OpenCV's order); converted to RGB once per frame.
const cv::Scalar kGrass(88, 120, 92);
const cv::Scalar kAsphalt(70, 70, 70);
const cv::Scalar kWhite(235, 235, 235);
const cv::Scalar kYellow(40, 200, 235);
const cv::Scalar kEgo(230, 140, 30);
const cv::Scalar kNpc(200, 200, 200);
const cv::Scalar kHit(40, 40, 230);
const cv::Scalar kRoute(230, 220, 80);

// Polygon of a lane: its centreline offset by half the width on both sides.
std::vector<Vec2> LaneOutline(const Lane& lane) {
  const auto& pts = lane.centreline.points();
  const auto& s = lane.centreline.arc_lengths();
  std::vector<Vec2> left, right;
  for (size_t i = 0; i < pts.size(); ++i) {
    const double h = lane.centreline.HeadingAt(std::min(s[i], lane.centreline.length() - 1e-6));
    const Vec2 n(-std::sin(h), std::cos(h));
    left.push_back(pts[i] + n * lane.width / 2);
    right.push_back(pts[i] - n * lane.width / 2);
  }
  std::vector<Vec2> out(left.begin(), left.end());
  out.insert(out.end(), right.rbegin(), right.rend());
  return out;
}

std::vector<Vec2> OffsetLine(const Lane& lane, double offset) {
  std::vector<Vec2> out;
  const auto& pts = lane.centreline.points();
  const auto& s = lane.centreline.arc_lengths();
  for (size_t i = 0; i < pts.size(); ++i) {
    const double h = lane.centreline.HeadingAt(std::min(s[i], lane.centreline.length() - 1e-6));
    out.push_back(pts[i] + offset * Vec2(-std::sin(h), std::cos(h)));
  }
  return out;
}

}  // namespace

std::string_view ToString(CameraMode m) {
  switch (m) {
    case CameraMode::kEgo: return "ego";
    case CameraMode::kMap: return "map";
    case CameraMode::kPoint: return "point";
  }
  return "unknown";
}

CameraMode CameraModeFromString(std::string_view name) {
  if (name == "ego") return CameraMode::kEgo;
  if (name == "map") return CameraMode::kMap;
  if (name == "point") return CameraMode::kPoint;
  throw std::invalid_argument("camera: unknown '" + std::string(name) + "' (expected ego, map, point)");
}

struct Renderer::Impl {
  cv::Mat canvas;  // BGR
  cv::Mat rgb;
  Vec2 centre = Vec2::Zero();
  double mpp = 0.1;
  std::vector<cv::Point> scratch;

  cv::Point ToPixel(const Vec2& p) const {
    return {static_cast<int>(std::lround((p.x() - centre.x()) / mpp + canvas.cols / 2.0)),
            static_cast<int>(std::lround(canvas.rows / 2.0 - (p.y() - centre.y()) / mpp))};
  }
  void Polygon(const std::vector<Vec2>& pts, const cv::Scalar& colour) {
    scratch.clear();
    for (const auto& p : pts) scratch.push_back(ToPixel(p));
    const cv::Point* data = scratch.data();
    const int n = static_cast<int>(scratch.size());
    cv::fillPoly(canvas, &data, &n, 1, colour, cv::LINE_AA);
  }
  void Line(const std::vector<Vec2>& pts, const cv::Scalar& colour, int thickness, bool dashed) {
    for (size_t i = 1; i < pts.size(); ++i) {
      if (dashed && (i / 2) % 2 == 1) continue;  // ~2 m on, 2 m off for 1 m samples
      cv::line(canvas, ToPixel(pts[i - 1]), ToPixel(pts[i]), colour, thickness, cv::LINE_AA);
    }
  }
};

Renderer::Renderer(const RenderOptions& options) : options_(options), impl_(std::make_unique<Impl>()) {
  if (options_.width < 16 || options_.width > 8192) throw std::invalid_argument("width: must be in [16, 8192] px");
  if (options_.height < 16 || options_.height > 8192) throw std::invalid_argument("height: must be in [16, 8192] px");
  if (!(options_.metres_per_pixel > 0.001 && options_.metres_per_pixel < 100.0)) {
    throw std::invalid_argument("metres_per_pixel: must be in (0.001, 100)");
  }
  impl_->canvas.create(options_.height, options_.width, CV_8UC3);
  impl_->rgb.create(options_.height, options_.width, CV_8UC3);
}

Renderer::~Renderer() = default;

void Renderer::set_camera(CameraMode mode, const Vec2& point) {
  options_.camera = mode;
  options_.point = point;
}

std::vector<uint8_t> Renderer::Render(const CrashEnv& env) {
  std::vector<uint8_t> out(static_cast<size_t>(options_.width) * options_.height * 3);
  Render(env, out.data());
  return out;
}

void Renderer::Render(const CrashEnv& env, uint8_t* rgb) {
  Impl& m = *impl_;
  const World& w = env.world();
  const RoadMap& map = env.map();
  switch (options_.camera) {
    case CameraMode::kEgo:
      m.centre = w.state(0).pose.position();
      m.mpp = options_.metres_per_pixel;
      break;
    case CameraMode::kPoint:
      m.centre = options_.point;
      m.mpp = options_.metres_per_pixel;
      break;
    case CameraMode::kMap: {
      const double extent = map.spec().type == RoadType::kStraight ? map.spec().length : 2.0 * map.spec().length;
      m.centre = Vec2::Zero();
      m.mpp = extent / std::min(options_.width, options_.height) * 1.05;
      break;
    }
  }
  m.canvas.setTo(kGrass);
  if (map.junction_half_size() > 0.0) {
    const double h = map.junction_half_size();
    m.Polygon({Vec2(-h, -h), Vec2(h, -h), Vec2(h, h), Vec2(-h, h)}, kAsphalt);
  }
  for (const Lane& lane : map.lanes()) m.Polygon(LaneOutline(lane), kAsphalt);
  for (const Lane& lane : map.lanes()) {
    if (lane.kind != LaneKind::kRoad) continue;
    // Left edge: the centre line (yellow) for lane 0, dashed white between lanes.
    m.Line(OffsetLine(lane, lane.width / 2), lane.index == 0 ? kYellow : kWhite, 1, lane.index != 0);
    if (lane.index == map.spec().lanes_per_direction - 1) m.Line(OffsetLine(lane, -lane.width / 2), kWhite, 1, false);
  }
  if (options_.show_route) m.Line(env.route().points(), kRoute, 1, false);
  for (int i = w.num_vehicles() - 1; i >= 0; --i) {
    const VehicleState& s = w.state(i);
    const VehicleParams& p = w.params(i);
    const Vec2 u(std::cos(s.pose.yaw), std::sin(s.pose.yaw)), v(-u.y(), u.x());
    const Vec2 c = s.pose.position();
    const double hl = p.length / 2, hw = p.width / 2;
    const cv::Scalar colour = i == 0 ? kEgo : (w.has_contacted(i) ? kHit : kNpc);
    m.Polygon({c + u * hl + v * hw, c - u * hl + v * hw, c - u * hl - v * hw, c + u * hl - v * hw}, colour);
    // Windscreen: a dark bar across the front third, so the heading reads at a glance.
    m.Polygon({c + u * (hl * 0.55) + v * hw * 0.8, c + u * (hl * 0.25) + v * hw * 0.8,
               c + u * (hl * 0.25) - v * hw * 0.8, c + u * (hl * 0.55) - v * hw * 0.8},
              cv::Scalar(40, 40, 40));
    if (i == 0 && w.has_contacted(0)) {
      m.Line({c + u * hl + v * hw, c - u * hl + v * hw, c - u * hl - v * hw, c + u * hl - v * hw, c + u * hl + v * hw},
             kHit, 2, false);
    }
  }
  if (options_.show_status) {
    char text[160];
    std::snprintf(text, sizeof text, "t %.1f s  ego %.1f m/s  %s", env.time(), w.state(0).speed(),
                  env.info().ego_collision ? "COLLISION" : "");
    cv::putText(m.canvas, text, cv::Point(8, 20), cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(255, 255, 255), 1,
                cv::LINE_AA);
  }
  cv::Mat out(options_.height, options_.width, CV_8UC3, rgb);
  cv::cvtColor(m.canvas, out, cv::COLOR_BGR2RGB);
}

struct VideoWriter::Impl {
  cv::VideoWriter writer;
  cv::Mat bgr;
  int width = 0, height = 0;
};

VideoWriter::VideoWriter(const std::string& path, double fps, int width, int height)
    : impl_(std::make_unique<Impl>()) {
  if (!(fps > 0.0 && fps <= 240.0)) throw std::invalid_argument("fps: must be in (0, 240]");
  impl_->width = width;
  impl_->height = height;
  if (!impl_->writer.open(path, cv::VideoWriter::fourcc('m', 'p', '4', 'v'), fps, cv::Size(width, height))) {
    throw std::runtime_error(path + ": cannot open a video writer (is the folder writable and the extension .mp4?)");
  }
}

VideoWriter::~VideoWriter() { Close(); }

void VideoWriter::Write(const uint8_t* rgb) {
  if (!impl_->writer.isOpened()) throw std::logic_error("video: Write() after Close()");
  const cv::Mat in(impl_->height, impl_->width, CV_8UC3, const_cast<uint8_t*>(rgb));
  cv::cvtColor(in, impl_->bgr, cv::COLOR_RGB2BGR);
  impl_->writer.write(impl_->bgr);
  ++frames_;
}

void VideoWriter::Close() {
  if (impl_ && impl_->writer.isOpened()) impl_->writer.release();
}

void WritePng(const std::string& path, const uint8_t* rgb, int width, int height) {
  const cv::Mat in(height, width, CV_8UC3, const_cast<uint8_t*>(rgb));
  cv::Mat bgr;
  cv::cvtColor(in, bgr, cv::COLOR_RGB2BGR);
  std::vector<uint8_t> buf;
  if (!cv::imencode(".png", bgr, buf)) throw std::runtime_error(path + ": PNG encoding failed");
  const std::string tmp = path + ".tmp";
  FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw std::runtime_error(path + ": cannot write");
  const bool ok = std::fwrite(buf.data(), 1, buf.size(), f) == buf.size();
  std::fclose(f);
  if (!ok || std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot write");
  }
}

}  // namespace accsim
