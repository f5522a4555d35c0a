// Seeded random mutations of a valid scenario: the loader either accepts the
// result or rejects it with std::invalid_argument naming a field, and an
// accepted scenario simulates without NaN. Never another exception, never a
// crash (the sanitizer build runs this too).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <random>

#include "accsim/env/crash_env.h"
#include "accsim/env/scenario.h"

namespace accsim {
namespace {

nlohmann::json Example(const std::string& family) {
  std::ifstream in(std::string(ACCSIM_SOURCE_DIR) + "/scenarios/examples/" + family + ".json");
  return nlohmann::json::parse(in);
}

// Collects pointers to every value in the document.
void Collect(nlohmann::json& j, std::vector<nlohmann::json*>& out) {
  out.push_back(&j);
  if (j.is_object() || j.is_array()) {
    for (auto& child : j) Collect(child, out);
  }
}

nlohmann::json RandomValue(std::mt19937_64& rng) {
  switch (rng() % 12) {
    case 0: return nullptr;
    case 1: return "text";
    case 2: return -1;
    case 3: return 0;
    case 4: return 1e308;
    case 5: return -1e308;
    case 6: return std::numeric_limits<double>::quiet_NaN();
    case 7: return nlohmann::json::array();
    case 8: return nlohmann::json::object();
    case 9: return true;
    case 10: return 18446744073709551615ULL;
    default: return static_cast<double>(rng() % 2000) / 10.0 - 100.0;
  }
}

TEST(ScenarioFuzzTest, MutatedScenariosAreRejectedCleanlyOrSimulateCleanly) {
  std::mt19937_64 rng(2024);
  int accepted = 0, rejected = 0;
  const char* families[] = {"straight_obstacle", "unprotected_left_turn", "right_turn", "lane_changing"};
  for (int trial = 0; trial < 1500; ++trial) {
    nlohmann::json j = Example(families[trial % 4]);
    const int mutations = 1 + static_cast<int>(rng() % 3);
    for (int m = 0; m < mutations; ++m) {
      std::vector<nlohmann::json*> nodes;
      Collect(j, nodes);
      nlohmann::json* target = nodes[rng() % nodes.size()];
      if (target == &j) continue;
      switch (rng() % 3) {
        case 0: *target = RandomValue(rng); break;
        case 1:
          if (target->is_object() && !target->empty()) target->erase(target->begin());
          else if (target->is_array() && !target->empty()) target->erase(target->begin());
          break;
        default:
          if (target->is_object()) (*target)["unexpected"] = 1;
          else if (target->is_array()) target->push_back(RandomValue(rng));
          break;
      }
    }
    Scenario s;
    try {
      s = ScenarioFromJson(j);
    } catch (const std::invalid_argument& e) {
      ++rejected;
      EXPECT_NE(std::string(e.what()).find(": "), std::string::npos) << e.what();
      continue;
    }
    ++accepted;
    CrashEnv env(CrashEnvConfig{}, {std::make_shared<const Scenario>(s)});
    env.Reset(0);
    for (int t = 0; t < 30 && !env.needs_reset(); ++t) {
      const float a[2] = {0.5f, 0.1f};
      env.Step(a, 2);
      for (int k = 0; k < env.spec().obs_dim; ++k) {
        ASSERT_TRUE(std::isfinite(env.observation()[k])) << env.spec().obs_names[k] << " in " << j.dump().substr(0, 600);
      }
      ASSERT_TRUE(std::isfinite(env.reward()));
    }
  }
  EXPECT_GT(rejected, 500);
  EXPECT_GT(accepted, 50);
}

}  // namespace
}  // namespace accsim
