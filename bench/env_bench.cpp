// Google Benchmark: the parts of a CrashEnv step, measured alone.
#include <benchmark/benchmark.h>

#include <cmath>

#include "accsim/env/crash_env.h"
#include "accsim/env/road_map.h"
#include "accsim/env/world.h"

namespace accsim {
namespace {

std::shared_ptr<const Scenario> Example(const char* family) {
  return std::make_shared<const Scenario>(
      LoadScenarioFile(std::string(ACCSIM_SOURCE_DIR) + "/scenarios/examples/" + family + ".json"));
}

void BM_CrashEnvStep(benchmark::State& state, const char* family, int rays) {
  CrashEnvConfig c;
  c.num_rays = rays;
  CrashEnv env(c, {Example(family)});
  env.Reset(0);
  long t = 0;
  for (auto _ : state) {
    const float a[2] = {-0.3f, 0.05f * static_cast<float>(std::sin(0.1 * static_cast<double>(t++)))};
    env.Step(a, 2);
    if (env.needs_reset()) env.Reset();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_CAPTURE(BM_CrashEnvStep, lane_changing_4_vehicles, "lane_changing", 0);
BENCHMARK_CAPTURE(BM_CrashEnvStep, lane_changing_4_vehicles_16_rays, "lane_changing", 16);
BENCHMARK_CAPTURE(BM_CrashEnvStep, left_turn_2_vehicles, "unprotected_left_turn", 0);

void BM_WorldSubstep(benchmark::State& state) {
  World w(WorldConfig{});
  const int n = static_cast<int>(state.range(0));
  for (int i = 0; i < n; ++i) {
    w.AddVehicle(Params(VehicleClass::kCar), Pose2{20.0 * i, 3.5 * (i % 2), 0}, 10.0,
                 i == 0 ? BodyControl::kDriven : BodyControl::kTracking);
  }
  w.Finalize();
  for (auto _ : state) {
    for (int i = 1; i < n; ++i) {
      const auto& s = w.state(i);
      w.SetTrackingTarget(i, Pose2{s.pose.x + 0.1, s.pose.y, 0});
    }
    w.Step();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_WorldSubstep)->Arg(2)->Arg(4)->Arg(8);

void BM_RoadMapLocate(benchmark::State& state) {
  RoadMapSpec spec;
  spec.type = RoadType::kIntersection;
  spec.lanes_per_direction = 2;
  const RoadMap map(spec);
  double x = -60.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(map.Locate(Pose2{1.75, x, kPi / 2}));
    x = x > 60.0 ? -60.0 : x + 0.37;
  }
}
BENCHMARK(BM_RoadMapLocate);

}  // namespace
}  // namespace accsim
