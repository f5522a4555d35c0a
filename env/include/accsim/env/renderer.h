// Top-down renderer (OpenCV): the road map, every vehicle, the ego's route
// and a status line, as RGB images for `render_mode="rgb_array"` and for
// collision videos. OpenCV stays behind this header (pimpl), so users of
// the env library do not compile against it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "accsim/env/crash_env.h"

namespace accsim {

enum class CameraMode {
  kEgo,    // centred on the ego
  kMap,    // the whole map (the scale is chosen to fit)
  kPoint,  // a fixed world point, e.g. the collision point
};
std::string_view ToString(CameraMode m);
CameraMode CameraModeFromString(std::string_view name);  // "ego", "map", "point"

struct RenderOptions {
  int width = 640;                // [px]
  int height = 480;               // [px]
  double metres_per_pixel = 0.12; // [m/px] for kEgo and kPoint
  CameraMode camera = CameraMode::kEgo;
  Vec2 point = Vec2::Zero();      // [m] the camera centre for kPoint
  bool show_route = true;
  bool show_status = true;        // time, ego speed, collision
};

// Not thread-safe; one per thread. Draws without allocating after the
// first frame of a given map.
class Renderer {
 public:
  // Throws std::invalid_argument naming the bad option.
  explicit Renderer(const RenderOptions& options);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  const RenderOptions& options() const { return options_; }
  void set_camera(CameraMode mode, const Vec2& point = Vec2::Zero());
  // Draws the environment's current state into `rgb`: height x width x 3
  // bytes, row-major, RGB order.
  void Render(const CrashEnv& env, uint8_t* rgb);
  std::vector<uint8_t> Render(const CrashEnv& env);

 private:
  struct Impl;
  RenderOptions options_;
  std::unique_ptr<Impl> impl_;
};

// Writes RGB frames to a video file (MP4 via OpenCV's FFmpeg back end).
class VideoWriter {
 public:
  // Throws std::runtime_error naming the path when it cannot be opened.
  VideoWriter(const std::string& path, double fps, int width, int height);
  ~VideoWriter();
  void Write(const uint8_t* rgb);
  // Finishes the file; called by the destructor too.
  void Close();
  int frames() const { return frames_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int frames_ = 0;
};

// Writes one RGB frame as PNG (atomically).
void WritePng(const std::string& path, const uint8_t* rgb, int width, int height);

}  // namespace accsim
