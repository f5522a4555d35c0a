#include "accsim/env/renderer.h"

#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/videoio.hpp>

namespace accsim {
namespace {

std::shared_ptr<const Scenario> Example(const std::string& family) {
  return std::make_shared<const Scenario>(
      LoadScenarioFile(std::string(ACCSIM_SOURCE_DIR) + "/scenarios/examples/" + family + ".json"));
}

const uint8_t* Pixel(const std::vector<uint8_t>& img, int w, int x, int y) {
  return &img[(static_cast<size_t>(y) * w + x) * 3];
}

TEST(RendererTest, EgoCameraPutsTheEgoInTheCentre) {
  CrashEnv env(CrashEnvConfig{}, {Example("straight_obstacle")});
  env.Reset(0);
  Renderer r(RenderOptions{});
  const auto img = r.Render(env);
  ASSERT_EQ(img.size(), 640u * 480u * 3u);
  // The ego is drawn blue (RGB 30, 140, 230); sample just behind its centre
  // to miss the windscreen bar.
  const uint8_t* p = Pixel(img, 640, 320 - 10, 240);
  EXPECT_EQ(p[0], 30);
  EXPECT_EQ(p[1], 140);
  EXPECT_EQ(p[2], 230);
  // A corner of the frame is grass (RGB 92, 120, 88), the road is not.
  const uint8_t* corner = Pixel(img, 640, 2, 470);
  EXPECT_EQ(corner[0], 92);
  EXPECT_EQ(corner[1], 120);
}

TEST(RendererTest, RenderingIsDeterministicAndFollowsTheState) {
  CrashEnv env(CrashEnvConfig{}, {Example("lane_changing")});
  env.Reset(0);
  RenderOptions o;
  o.camera = CameraMode::kMap;
  Renderer r(o);
  const auto a = r.Render(env), b = r.Render(env);
  EXPECT_EQ(a, b);
  const float act[2] = {1.0f, 0.0f};
  for (int i = 0; i < 10; ++i) env.Step(act, 2);
  EXPECT_NE(r.Render(env), a);
}

TEST(RendererTest, VideoHasOneFramePerWrite) {
  CrashEnv env(CrashEnvConfig{}, {Example("right_turn")});
  env.Reset(0);
  RenderOptions o;
  o.width = 320;
  o.height = 240;
  Renderer r(o);
  const std::string path = ::testing::TempDir() + "/clip.mp4";
  {
    VideoWriter video(path, 10.0, o.width, o.height);
    const float act[2] = {0.0f, 0.0f};
    for (int i = 0; i < 12; ++i) {
      video.Write(r.Render(env).data());
      env.Step(act, 2);
    }
    EXPECT_EQ(video.frames(), 12);
  }
  cv::VideoCapture cap(path);
  ASSERT_TRUE(cap.isOpened());
  EXPECT_EQ(static_cast<int>(cap.get(cv::CAP_PROP_FRAME_COUNT)), 12);
  EXPECT_EQ(static_cast<int>(cap.get(cv::CAP_PROP_FRAME_WIDTH)), 320);
}

TEST(RendererTest, BadOptionsAndPathsAreReported) {
  RenderOptions o;
  o.width = 3;
  EXPECT_THROW(Renderer r(o), std::invalid_argument);
  EXPECT_THROW(VideoWriter("/no/such/dir/x.mp4", 10.0, 64, 64), std::runtime_error);
  EXPECT_THROW(CameraModeFromString("drone"), std::invalid_argument);
  std::vector<uint8_t> img(64 * 64 * 3, 0);
  EXPECT_THROW(WritePng("/no/such/dir/x.png", img.data(), 64, 64), std::runtime_error);
}

}  // namespace
}  // namespace accsim
