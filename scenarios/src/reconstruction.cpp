#include "accsim/scenarios/reconstruction.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "accsim/env/world.h"
#include "accsim/scenarios/labelled_case.h"
#include "accsim/scenarios/narrative_extractor.h"

namespace accsim {
namespace {

constexpr double kTimeTolerance = 0.5;  // [s] Bullet contact vs planned impact

struct CheckInput {
  std::vector<std::string> ids;
  std::vector<VehicleClass> classes;
  std::vector<const Trajectory*> refs;
  double planned = 0.0, horizon = 0.0;
  Surface surface = Surface::kDry;
  std::string striker, struck;
  ImpactArea striker_area = ImpactArea::kUnknown, struck_area = ImpactArea::kUnknown;
};

ReconstructionCheck Check(const CheckInput& in) {
  ReconstructionCheck c;
  c.planned_time = in.planned;
  WorldConfig wc;
  wc.tyre_friction = FrictionCoefficient(in.surface);
  World world(wc);
  for (size_t i = 0; i < in.refs.size(); ++i) {
    const TrajectoryPoint p = in.refs[i]->Sample(0.0);
    world.AddVehicle(Params(in.classes[i]), Pose2{p.x, p.y, p.yaw}, p.v, BodyControl::kTracking);
  }
  world.Finalize();
  std::vector<size_t> cursor(in.refs.size(), 0);
  while (world.time() < in.horizon && world.contact_log().empty()) {
    for (size_t i = 0; i < in.refs.size(); ++i) {
      const TrajectoryPoint p = in.refs[i]->Sample(world.time() + wc.physics_dt, &cursor[i]);
      world.SetTrackingTarget(static_cast<int>(i), Pose2{p.x, p.y, p.yaw});
    }
    world.Step();
  }
  if (world.contact_log().empty()) {
    c.reason = "no contact in simulation";
    return c;
  }
  const ContactEvent& e = world.contact_log().front();
  c.contact_time = e.time;
  const std::string& a = in.ids[static_cast<size_t>(e.body_a)];
  const std::string& b = in.ids[static_cast<size_t>(e.body_b)];
  if (!((a == in.striker && b == in.struck) || (a == in.struck && b == in.striker))) {
    c.reason = "first contact is between " + a + " and " + b;
    return c;
  }
  const int is = a == in.striker ? e.body_a : e.body_b, it = is == e.body_a ? e.body_b : e.body_a;
  const VehicleClass cs = in.classes[static_cast<size_t>(is)], ct = in.classes[static_cast<size_t>(it)];
  c.striker_face = FaceAt(e.point, world.state(is).pose, cs);
  c.struck_face = FaceAt(e.point, world.state(it).pose, ct);
  char buf[96];
  if (std::abs(e.time - in.planned) > kTimeTolerance) {
    std::snprintf(buf, sizeof buf, "contact at %.2f s, planned %.2f s", e.time, in.planned);
    c.reason = buf;
    return c;
  }
  if (!TouchesArea(e.point, world.state(is).pose, cs, in.striker_area)) {
    c.reason = in.striker + " struck with its " + std::string(ToString(c.striker_face)) + ", described " +
               std::string(ToString(in.striker_area));
    return c;
  }
  if (!TouchesArea(e.point, world.state(it).pose, ct, in.struck_area)) {
    c.reason = in.struck + " hit on its " + std::string(ToString(c.struck_face)) + ", described " +
               std::string(ToString(in.struck_area));
    return c;
  }
  c.success = true;
  return c;
}

}  // namespace

ReconstructionCheck CheckReconstruction(const PlannedCrash& p) {
  CheckInput in;
  in.ids = p.ids;
  in.classes = p.classes;
  for (const auto& t : p.trajectories) in.refs.push_back(&t);
  in.planned = p.state.time;
  in.horizon = p.scenario.time_limit;
  in.surface = p.scenario.map.surface;
  in.striker = p.striker_id;
  in.struck = p.struck_id;
  in.striker_area = p.striker_area;
  in.struck_area = p.struck_area;
  return Check(in);
}

ReconstructionCheck CheckReconstructedScenario(const Scenario& s) {
  const nlohmann::json& pv = s.provenance;
  for (const char* key : {"ego_reference", "planned_impact_time", "striker", "struck"}) {
    if (!pv.contains(key)) {
      throw std::invalid_argument(std::string("provenance.") + key + ": missing (not a reconstructed scenario)");
    }
  }
  const Trajectory ego = TrajectoryFromJson(pv.at("ego_reference"), "provenance.ego_reference");
  CheckInput in;
  in.ids.push_back(s.ego.id);
  in.classes.push_back(s.ego.vehicle_class);
  in.refs.push_back(&ego);
  for (const auto& n : s.npcs) {
    in.ids.push_back(n.id);
    in.classes.push_back(n.vehicle_class);
    in.refs.push_back(&n.reference);
  }
  in.planned = pv.at("planned_impact_time").get<double>();
  in.horizon = s.time_limit;
  in.surface = s.map.surface;
  in.striker = pv.at("striker").get<std::string>();
  in.struck = pv.at("struck").get<std::string>();
  if (pv.contains("striker_area")) in.striker_area = ImpactAreaFromString(pv.at("striker_area").get<std::string>());
  if (pv.contains("struck_area")) in.struck_area = ImpactAreaFromString(pv.at("struck_area").get<std::string>());
  return Check(in);
}

Reconstruction Reconstruct(const CrashDescription& d, uint64_t seed, const PlannerConfig& config) {
  const PreCollisionPlanner planner(config);
  Reconstruction r;
  r.plan = planner.Plan(d, seed, [](const PlannedCrash& p) { return CheckReconstruction(p).reason; });
  r.check = CheckReconstruction(r.plan);
  return r;
}

double SrrReport::Rate(const std::string& road) const {
  const auto it = attempted.find(road);
  if (it == attempted.end() || it->second == 0) return 0.0;
  const auto ok = succeeded.find(road);
  return ok == succeeded.end() ? 0.0 : static_cast<double>(ok->second) / it->second;
}

SrrReport EvaluateReconstruction(const std::string& dir, DescriptionSource from, uint64_t seed) {
  const std::string path = dir + "/labels.jsonl";
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot open (expected labels.jsonl in the folder)");
  SrrReport rep;
  std::string line;
  const NarrativeExtractor extractor;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.find_first_not_of(" \r\t") == std::string::npos) continue;
    nlohmann::json row;
    try {
      row = nlohmann::json::parse(line);
    } catch (const nlohmann::json::exception& e) {
      throw std::invalid_argument(path + ":" + std::to_string(line_no) + ": not JSON (" + e.what() + ")");
    }
    const std::string file = row.value("file", "line " + std::to_string(line_no));
    const RoadType road = LabelledRoadType(row);
    const std::string group(ToString(road));
    rep.Tally(group, file, seed, [&] {
      CrashDescription d = from == DescriptionSource::kLabels
                               ? DescriptionFromLabels(row)
                               : FromAccidentRecord(extractor.Extract(row.value("narrative", "")), road);
      d.source_id = file;
      return d;
    });
  }
  return rep;
}

void SrrReport::Tally(const std::string& group, const std::string& id, uint64_t seed,
                      const std::function<CrashDescription()>& describe) {
  ++n;
  ++attempted[group];
  try {
    const CrashDescription d = describe();
    if (d.SingleVehicle()) ++single_vehicle[group];
    const Reconstruction r = Reconstruct(d, seed);
    if (r.check.success) {
      ++succeeded[group];
    } else {
      failures.push_back(id + ": " + r.check.reason + " [" + r.plan.combination + "]");
    }
  } catch (const std::exception& e) {
    failures.push_back(id + ": " + e.what());
  }
}

nlohmann::json ToJson(const SrrReport& r) {
  nlohmann::json srr = nlohmann::json::object(), attempted = nlohmann::json::object(),
                 single = nlohmann::json::object();
  for (const auto& [k, n] : r.attempted) {
    srr[k] = r.Rate(k);
    attempted[k] = n;
  }
  for (const auto& [k, n] : r.single_vehicle) single[k] = n;
  return {{"srr", srr},
          {"n", r.n},
          {"attempted", attempted},
          {"single_vehicle", single},
          {"failures", r.failures}};
}

}  // namespace accsim
