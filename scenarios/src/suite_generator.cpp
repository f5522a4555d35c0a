#include "accsim/scenarios/suite_generator.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

#include "accsim/env/json_fields.h"
#include "accsim/env/rollout.h"
#include "accsim/env/scripted_drivers.h"

namespace accsim {
namespace {

constexpr ScenarioFamily kFamilies[] = {ScenarioFamily::kStraightObstacle, ScenarioFamily::kUnprotectedLeftTurn,
                                        ScenarioFamily::kRightTurn, ScenarioFamily::kLaneChanging};
constexpr VehicleCount kCounts[] = {VehicleCount::kTwo, VehicleCount::kThree, VehicleCount::kMany};
constexpr int kNumCells = 12;

// Stable 64-bit mixing (splitmix64) for per-cell seeds.
uint64_t Mix(uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

struct CellJob {
  int cell = 0;
  int target = 0;
  const std::vector<ReportSeed>* reports = nullptr;
  uint64_t seed = 0;
  std::vector<Scenario> out;
  CellStats stats;
};

void RunCell(CellJob& job, const SuiteOptions& o, const std::function<void()>& tick) {
  std::mt19937_64 rng(job.seed);
  const ScenarioFamily family = kFamilies[job.cell / 3];
  const VehicleCount count = kCounts[job.cell % 3];
  job.stats.family = family;
  job.stats.count = count;
  const long max_candidates = static_cast<long>(job.target) * o.max_attempts_per_scenario + 20;
  long candidates = 0;
  while (static_cast<int>(job.out.size()) < job.target && candidates++ < max_candidates) {
    const ReportSeed& r = (*job.reports)[rng() % job.reports->size()];
    const FamilyParams p = SampleFamilyParams(family, count, r, rng);
    Scenario s;
    try {
      s = BuildFamilyScenario(p);
    } catch (const std::invalid_argument&) {
      ++job.stats.build_failures;
      continue;
    }
    const ScenarioCheck check = CheckScenario(s);
    if (!check.dangerous) {
      ++job.stats.dropped_harmless;
      continue;
    }
    if (!check.avoidable) {
      ++job.stats.dropped_unavoidable;
      continue;
    }
    s.provenance["avoided_by"] = check.avoiding_manoeuvre;
    job.out.push_back(std::move(s));
    ++job.stats.kept;
    tick();
  }
}

SuiteSplit GenerateSplit(const std::vector<ReportSeed>& reports, int total, uint64_t seed, const SuiteOptions& o,
                         const std::function<void()>& tick) {
  SuiteSplit split;
  for (const auto& r : reports) split.reports.push_back(r.source_id);
  std::vector<CellJob> jobs(kNumCells);
  for (int c = 0; c < kNumCells; ++c) {
    jobs[c].cell = c;
    jobs[c].target = total / kNumCells + (c < total % kNumCells ? 1 : 0);
    jobs[c].reports = &reports;
    jobs[c].seed = Mix(seed ^ Mix(static_cast<uint64_t>(c) + 1));
  }
  const int threads = std::max(1, o.threads > 0 ? o.threads : static_cast<int>(std::thread::hardware_concurrency()));
  std::atomic<int> next{0};
  auto worker = [&] {
    for (int c = next++; c < kNumCells; c = next++) RunCell(jobs[c], o, tick);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  // Interleave the cells so every prefix of the suite is balanced.
  for (size_t k = 0;; ++k) {
    bool any = false;
    for (auto& j : jobs) {
      if (k < j.out.size()) {
        split.scenarios.push_back(std::move(j.out[k]));
        any = true;
      }
    }
    if (!any) break;
  }
  for (auto& j : jobs) split.cells.push_back(j.stats);
  return split;
}

nlohmann::json CellsJson(const std::vector<CellStats>& cells) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& c : cells) {
    a.push_back({{"family", std::string(ToString(c.family))},
                 {"vehicle_count", std::string(ToString(c.count))},
                 {"kept", c.kept},
                 {"dropped_unavoidable", c.dropped_unavoidable},
                 {"dropped_harmless", c.dropped_harmless},
                 {"build_failures", c.build_failures}});
  }
  return a;
}

void WriteJsonl(const std::vector<Scenario>& scenarios, const std::string& path) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path + ": cannot write");
    for (const auto& s : scenarios) out << ToJson(s).dump() << "\n";
    if (!out.flush()) throw std::runtime_error(path + ": write failed");
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace

std::vector<Manoeuvre> AvoidanceManoeuvres() {
  std::vector<Manoeuvre> m;
  for (double onset : {0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0}) {
    m.push_back({"brake@" + std::to_string(onset).substr(0, 3),
                 [onset](const CrashEnv& e) { return BrakePolicy(e, onset); }});
  }
  for (double onset : {0.0, 1.0}) {
    m.push_back({"half_brake@" + std::to_string(onset).substr(0, 3), [onset](const CrashEnv& e) -> Action {
                   if (e.time() + 1e-9 < onset) return HoldPolicy(e);
                   return {-0.5f, RouteSteering(e)};
                 }});
  }
  for (double side : {1.0, -1.0}) {
    for (double onset : {0.5, 1.5}) {
      m.push_back({std::string(side > 0 ? "swerve_left@" : "swerve_right@") + std::to_string(onset).substr(0, 3),
                   [side, onset](const CrashEnv& e) -> Action {
                     if (e.time() + 1e-9 < onset) return HoldPolicy(e);
                     const double width = e.map().spec().lane_width;
                     return {SpeedKeeping(e, e.scenario().ego.target_speed), RouteSteering(e, side * width)};
                   }});
    }
    m.push_back({std::string(side > 0 ? "swerve_left_brake" : "swerve_right_brake"),
                 [side](const CrashEnv& e) -> Action {
                   return {-0.5f, RouteSteering(e, side * e.map().spec().lane_width)};
                 }});
  }
  m.push_back({"accelerate", [](const CrashEnv& e) -> Action { return {1.0f, RouteSteering(e)}; }});
  return m;
}

ScenarioCheck CheckScenario(const Scenario& scenario, const CrashEnvConfig& config) {
  ScenarioCheck c;
  CrashEnv env(config, {std::make_shared<const Scenario>(scenario)});
  const EpisodeResult hold = RunEpisode(env, [](const CrashEnv& e) { return HoldPolicy(e); }, 0, 0);
  ++c.episodes;
  c.dangerous = hold.collision.has_value();
  if (!c.dangerous) return c;
  for (const Manoeuvre& m : AvoidanceManoeuvres()) {
    const EpisodeResult r = RunEpisode(env, m.policy, 0, 0);
    ++c.episodes;
    if (!r.collision && r.outcome != "off_road") {
      c.avoidable = true;
      c.avoiding_manoeuvre = m.name;
      return c;
    }
  }
  return c;
}

ReportSeed ReportSeedFromScenario(const Scenario& s) {
  ReportSeed r;
  r.source_id = s.provenance.contains("source_report") && s.provenance["source_report"].is_string()
                    ? s.provenance["source_report"].get<std::string>()
                    : s.name;
  r.speed_limit = s.map.speed_limit;
  r.lanes_per_direction = s.map.lanes_per_direction;
  r.divided = s.map.divided;
  r.surface = s.map.surface;
  r.struck_class = s.ego.vehicle_class;
  r.struck_speed = s.ego.speed;
  if (!s.npcs.empty()) {
    r.striking_class = s.npcs.front().vehicle_class;
    double vmax = 0.0;
    for (const auto& p : s.npcs.front().reference.points()) vmax = std::max(vmax, p.v);
    r.striking_speed = vmax;
  }
  return r;
}

Suite GenerateSuite(const std::vector<ReportSeed>& reports, const SuiteOptions& o) {
  if (reports.size() < 2) {
    throw std::invalid_argument("reports: need at least 2 source reports to keep train and test disjoint");
  }
  if (o.train < 0 || o.test < 0) throw std::invalid_argument("train/test: counts must not be negative");
  const auto start = std::chrono::steady_clock::now();
  // Split the reports (deterministically for the seed) so that train and
  // test never share a source report.
  std::vector<ReportSeed> shuffled = reports;
  std::sort(shuffled.begin(), shuffled.end(), [](const ReportSeed& a, const ReportSeed& b) { return a.source_id < b.source_id; });
  std::mt19937_64 rng(Mix(o.seed));
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  const size_t n_test = std::clamp<size_t>(
      static_cast<size_t>(std::lround(o.test_fraction_of_reports * static_cast<double>(shuffled.size()))), 1,
      shuffled.size() - 1);
  const std::vector<ReportSeed> test_reports(shuffled.begin(), shuffled.begin() + static_cast<long>(n_test));
  const std::vector<ReportSeed> train_reports(shuffled.begin() + static_cast<long>(n_test), shuffled.end());

  std::mutex mu;
  int done = 0;
  const int total = o.train + o.test;
  auto tick = [&] {
    std::lock_guard<std::mutex> lock(mu);
    ++done;
    if (o.progress) o.progress(done, total);
  };
  Suite suite;
  suite.train = GenerateSplit(train_reports, o.train, Mix(o.seed ^ 0x7472ULL), o, tick);
  suite.test = GenerateSplit(test_reports, o.test, Mix(o.seed ^ 0x7465ULL), o, tick);
  suite.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const size_t kept = suite.train.scenarios.size() + suite.test.scenarios.size();
  suite.seconds_per_scenario = kept ? suite.seconds / static_cast<double>(kept) : 0.0;
  return suite;
}

nlohmann::json StatsJson(const Suite& suite, const SuiteOptions& o) {
  return {{"seed", o.seed},
          {"requested", {{"train", o.train}, {"test", o.test}}},
          {"train", {{"scenarios", suite.train.scenarios.size()}, {"reports", suite.train.reports}, {"cells", CellsJson(suite.train.cells)}}},
          {"test", {{"scenarios", suite.test.scenarios.size()}, {"reports", suite.test.reports}, {"cells", CellsJson(suite.test.cells)}}},
          {"seconds", suite.seconds},
          {"seconds_per_scenario", suite.seconds_per_scenario}};
}

void WriteSuite(const Suite& suite, const std::string& dir, const SuiteOptions& o) {
  std::filesystem::create_directories(dir);
  WriteJsonl(suite.train.scenarios, dir + "/train.jsonl");
  WriteJsonl(suite.test.scenarios, dir + "/test.jsonl");
  SaveJsonFile(StatsJson(suite, o), dir + "/stats.json");
}

std::vector<Scenario> LoadSuite(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot open file");
  std::vector<Scenario> out;
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    try {
      out.push_back(ScenarioFromJson(nlohmann::json::parse(line)));
    } catch (const nlohmann::json::parse_error& e) {
      throw std::invalid_argument(path + ":" + std::to_string(n) + ": malformed JSON (" + e.what() + ")");
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(path + ":" + std::to_string(n) + ": " + e.what());
    }
  }
  if (out.empty()) throw std::invalid_argument(path + ": no scenarios in the file");
  return out;
}

std::vector<std::shared_ptr<const Scenario>> LoadScenarioSet(const std::vector<std::string>& paths) {
  std::vector<std::shared_ptr<const Scenario>> out;
  for (const auto& p : paths) {
    if (p.size() > 6 && p.compare(p.size() - 6, 6, ".jsonl") == 0) {
      for (auto& s : LoadSuite(p)) out.push_back(std::make_shared<const Scenario>(std::move(s)));
    } else {
      out.push_back(std::make_shared<const Scenario>(LoadScenarioFile(p)));
    }
  }
  if (out.empty()) throw std::invalid_argument("scenario: no scenario files given");
  return out;
}

}  // namespace accsim
