#include "accsim/scenarios/extraction_eval.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace accsim {
namespace {

std::string Get(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : "";
}

// NASS pre-event movement -> Movement ("negotiating a curve" and
// "starting in traffic lane" are going straight along the road).
Movement MovementLabel(const std::string& s) {
  if (s.rfind("Going straight", 0) == 0 || s.rfind("Negotiating a curve", 0) == 0 ||
      s.rfind("Starting in traffic lane", 0) == 0 || s.rfind("Leaving a parking", 0) == 0 ||
      s.rfind("Accelerating", 0) == 0)
    return Movement::kStraight;
  if (s.rfind("Stopped", 0) == 0) return Movement::kStopped;
  if (s.rfind("Decelerating", 0) == 0) return Movement::kSlowing;
  if (s.rfind("Turning left", 0) == 0) return Movement::kTurnLeft;
  if (s.rfind("Turning right", 0) == 0) return Movement::kTurnRight;
  if (s.rfind("Changing lanes", 0) == 0) return Movement::kChangingLanes;
  if (s.rfind("Merging", 0) == 0) return Movement::kMerging;
  if (s.rfind("Backing", 0) == 0) return Movement::kBacking;
  if (s.rfind("Passing", 0) == 0) return Movement::kPassing;
  return Movement::kUnknown;
}

// NHTSA crash-type code (GES/NASS accident type, 1-99) -> CrashType.
CrashType CrashTypeLabel(int code) {
  if (code >= 1 && code <= 19) return CrashType::kSingleVehicle;
  if (code >= 20 && code <= 43) return CrashType::kRearEnd;
  if (code >= 44 && code <= 49) return CrashType::kSideswipeSame;
  if (code >= 50 && code <= 63) return CrashType::kHeadOn;
  if (code >= 64 && code <= 67) return CrashType::kSideswipeOpposite;
  if (code >= 68 && code <= 75) return CrashType::kTurnAcrossPath;
  if (code >= 76 && code <= 85) return CrashType::kTurnIntoPath;
  if (code >= 86 && code <= 91) return CrashType::kAngle;
  return CrashType::kUnknown;
}

DamageArea AreaLabel(const std::string& s) {
  if (s == "Front") return DamageArea::kFront;
  if (s == "Back") return DamageArea::kRear;
  if (s == "Left Side") return DamageArea::kLeft;
  if (s == "Right Side") return DamageArea::kRight;
  return DamageArea::kUnknown;
}

}  // namespace

ExtractionScore EvaluateExtraction(const std::string& dir, const NarrativeExtractor& extractor) {
  const std::string path = dir + "/labels.jsonl";
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot open (expected labels.jsonl in the folder)");
  ExtractionScore score;
  std::map<std::string, double> hits;
  std::map<std::string, std::map<std::string, double>> group_hits;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.find_first_not_of(" \r\t") == std::string::npos) continue;
    nlohmann::json row;
    try {
      row = nlohmann::json::parse(line);
    } catch (const nlohmann::json::parse_error& e) {
      throw std::invalid_argument(path + ":" + std::to_string(line_no) + ": malformed JSON (" + e.what() + ")");
    }
    if (!row.contains("narrative") || !row["narrative"].is_string() || !row.contains("vehicles") ||
        !row["vehicles"].is_array() || row["vehicles"].empty()) {
      throw std::invalid_argument(path + ":" + std::to_string(line_no) + ": needs 'narrative' and 'vehicles'");
    }
    const std::string id = Get(row, "file").empty() ? "line " + std::to_string(line_no) : Get(row, "file");
    const std::string group = id.find('/') != std::string::npos ? id.substr(0, id.find('/')) : "all";
    const AccidentRecord r = extractor.Extract(row["narrative"].get<std::string>());
    const nlohmann::json& v1 = row["vehicles"][0];
    std::map<std::string, double> got;
    auto miss = [&](const std::string& attr, const std::string& want, const std::string& have) {
      score.mismatches.push_back(id + ": " + attr + ": want " + want + ", got " + have);
    };

    // Participant count: the coded number of vehicles.
    const int want_count = std::atoi(Get(row, "vehcount").c_str());
    got["participant_count"] = want_count == r.participant_count.value;
    if (!got["participant_count"]) miss("participant_count", std::to_string(want_count), std::to_string(r.participant_count.value));

    // Speed limit: V1's coded km/h within 3 km/h; "no statutory limit" is
    // right when the text states none.
    const std::string limit = Get(v1, "speed_limit_kmph");
    const double got_kmh = r.road.speed_limit_mps.value * 3.6;
    if (!limit.empty() && std::isdigit(static_cast<unsigned char>(limit[0]))) {
      got["speed_limit"] = r.road.speed_limit_mps.known() && std::abs(got_kmh - std::stod(limit)) <= 3.0;
    } else {
      got["speed_limit"] = !r.road.speed_limit_mps.known();
    }
    if (!got["speed_limit"]) miss("speed_limit", limit, r.road.speed_limit_mps.known() ? std::to_string(got_kmh) : "none");

    // Lane count: V1's coded travel lanes: both directions on undivided
    // roads, V1's direction on divided roads, all lanes on one-way roads.
    const int want_lanes = std::atoi(Get(v1, "num_travel_lanes_code").c_str());
    const bool coded_divided = Get(v1, "trafficway_flow").rfind("Divided", 0) == 0;
    const int got_lanes = (r.road.divided.value || coded_divided) && !r.road.one_way.value
                              ? r.road.lanes_per_direction.value
                              : r.road.lanes_total.value;
    got["lane_count"] = want_lanes == got_lanes;
    if (!got["lane_count"]) miss("lane_count", std::to_string(want_lanes), std::to_string(got_lanes));

    // Collision location: the first harmful event's striker and struck
    // areas (Front / Back / Left Side / Right Side); an uncoded area (not a
    // motor vehicle, noncollision) is not scored.
    if (row.contains("events") && row["events"].is_array() && !row["events"].empty()) {
      const auto& e = row["events"][0];
      const DamageArea ws = AreaLabel(Get(e, "striker_area_damage")), wh = AreaLabel(Get(e, "hit_area_damage"));
      const std::string striker = "V" + Get(e, "striker_vehicle");
      bool ok = true;
      DamageArea gs = r.crash.striking_area.value, gh = r.crash.struck_area.value;
      if (r.crash.striking.value != striker && r.crash.struck.value == striker) std::swap(gs, gh);
      if (ws != DamageArea::kUnknown) ok = ok && ws == gs;
      if (wh != DamageArea::kUnknown) ok = ok && wh == gh;
      got["collision_location"] = ok;
      if (!ok) {
        miss("collision_location", std::string(ToString(ws)) + "/" + std::string(ToString(wh)),
             std::string(ToString(gs)) + "/" + std::string(ToString(gh)));
      }
    } else {
      got["collision_location"] = 1.0;
    }

    // Driving actions: each vehicle's coded pre-event movement, averaged.
    double actions = 0.0;
    int scored = 0;
    for (size_t i = 0; i < row["vehicles"].size(); ++i) {
      const Movement want = MovementLabel(Get(row["vehicles"][i], "pre_event_movement"));
      if (want == Movement::kUnknown) continue;
      ++scored;
      const Movement have = i < r.vehicles.size() ? r.vehicles[i].movement.value : Movement::kUnknown;
      actions += want == have;
      if (want != have) miss("driving_actions V" + std::to_string(i + 1), std::string(ToString(want)), std::string(ToString(have)));
    }
    got["driving_actions"] = scored ? actions / scored : 1.0;

    // Crash type: V1's NHTSA crash-type code, by category.
    const CrashType want_type = CrashTypeLabel(std::atoi(Get(v1, "crash_type_code").c_str()));
    got["crash_type"] = want_type == CrashType::kUnknown || want_type == r.crash.type.value;
    if (!got["crash_type"]) miss("crash_type", std::string(ToString(want_type)), std::string(ToString(r.crash.type.value)));

    ++score.n;
    ++score.group_sizes[group];
    for (const auto& [k, v] : got) {
      hits[k] += v;
      group_hits[group][k] += v;
    }
  }
  if (score.n == 0) throw std::invalid_argument(path + ": no labelled cases");
  for (const auto& a : ExtractionAttributes()) score.attributes[a] = hits[a] / score.n;
  for (const auto& [g, h] : group_hits) {
    for (const auto& a : ExtractionAttributes()) score.by_group[g][a] = h.count(a) ? h.at(a) / score.group_sizes[g] : 0.0;
  }
  return score;
}

nlohmann::json ToJson(const ExtractionScore& s) {
  nlohmann::json groups = nlohmann::json::object();
  for (const auto& [g, attrs] : s.by_group) groups[g] = {{"attributes", attrs}, {"n", s.group_sizes.at(g)}};
  return {{"attributes", s.attributes}, {"n", s.n}, {"groups", groups}};
}

}  // namespace accsim
