#include "accsim/scenarios/extraction_eval.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace accsim {

const std::vector<std::string>& ExtractionAttributes() {
  static const std::vector<std::string> kNames = {"lane_count",      "speed_limit", "collision_location",
                                                  "driving_actions", "crash_type",  "participant_count"};
  return kNames;
}

namespace {

std::string Get(const nlohmann::json& j, const char* key) {
  return j.is_object() && j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : "";
}

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool StartsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

std::optional<int> LeadingInt(const std::string& s) {
  size_t i = 0;
  while (i < s.size() && s[i] == ' ') ++i;
  if (i >= s.size() || !std::isdigit(static_cast<unsigned char>(s[i]))) return std::nullopt;
  int v = 0;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])) && v < 100000) v = v * 10 + (s[i++] - '0');
  return v;
}

std::optional<int> CountWord(const std::string& s) {
  if (auto n = LeadingInt(s)) return n;
  static const std::vector<std::string> kWords = {"one", "two", "three", "four", "five", "six", "seven", "eight"};
  const std::string l = Lower(s);
  for (size_t i = 0; i < kWords.size(); ++i) {
    if (StartsWith(l, kWords[i].c_str())) return static_cast<int>(i + 1);
  }
  return std::nullopt;
}

// NASS pre-event movement -> Movement. Negotiating a curve, starting in the
// lane and accelerating are all "going straight" along the road; leaving a
// parking position enters the traffic lane, which the record calls merging.
// Other/unknown codes are not scored.
std::optional<Movement> MovementLabel(const std::string& raw) {
  const std::string s = Lower(raw);
  if (StartsWith(s, "going straight") || StartsWith(s, "negotiating a curve") ||
      StartsWith(s, "starting in traffic lane") || StartsWith(s, "accelerating")) {
    return Movement::kStraight;
  }
  if (StartsWith(s, "leaving a parking") || StartsWith(s, "merging") || StartsWith(s, "entering a parking")) {
    return Movement::kMerging;
  }
  if (StartsWith(s, "stopped")) return Movement::kStopped;
  if (StartsWith(s, "decelerating")) return Movement::kSlowing;
  if (StartsWith(s, "turning left") || StartsWith(s, "making a u-turn")) return Movement::kTurnLeft;
  if (StartsWith(s, "turning right")) return Movement::kTurnRight;
  if (StartsWith(s, "changing lanes")) return Movement::kChangingLanes;
  if (StartsWith(s, "backing")) return Movement::kBacking;
  if (StartsWith(s, "passing")) return Movement::kPassing;
  return std::nullopt;
}

// NHTSA (GES/NASS) accident-type code -> CrashType category:
//   1-19 single driver (road departure, forward impact)
//  20-43 same direction rear-end (incl. its forward-impact variants)
//  44-49 same direction sideswipe/angle
//  50-63 opposite direction head-on (incl. forward impact)
//  64-67 opposite direction sideswipe/angle
//  68-75 turn across path; 76-85 turn into path; 86-91 straight paths (angle)
//  92-99 backing / other / unknown: not scored.
std::optional<CrashType> CrashTypeLabel(int code) {
  if (code >= 1 && code <= 19) return CrashType::kSingleVehicle;
  if (code >= 20 && code <= 43) return CrashType::kRearEnd;
  if (code >= 44 && code <= 49) return CrashType::kSideswipeSame;
  if (code >= 50 && code <= 63) return CrashType::kHeadOn;
  if (code >= 64 && code <= 67) return CrashType::kSideswipeOpposite;
  if (code >= 68 && code <= 75) return CrashType::kTurnAcrossPath;
  if (code >= 76 && code <= 85) return CrashType::kTurnIntoPath;
  if (code >= 86 && code <= 91) return CrashType::kAngle;
  return std::nullopt;
}

// NASS relation to junction -> CrashLocation.
std::optional<CrashLocation> LocationLabel(const std::string& raw) {
  const std::string s = Lower(raw);
  if (s.empty() || StartsWith(s, "unknown")) return std::nullopt;
  if (s.find("ramp") != std::string::npos || s.find("interchange area related") != std::string::npos) {
    return CrashLocation::kRamp;
  }
  if (s.find("intersection") != std::string::npos) return CrashLocation::kJunction;
  if (s.find("driveway") != std::string::npos || s.find("alley") != std::string::npos) return CrashLocation::kDriveway;
  if (s.find("non-junction") != std::string::npos) return CrashLocation::kSegment;
  return std::nullopt;
}

std::optional<DamageArea> AreaLabel(const std::string& s) {
  if (s == "Front") return DamageArea::kFront;
  if (s == "Back" || s == "Rear") return DamageArea::kRear;
  if (s == "Left Side" || s == "Left") return DamageArea::kLeft;
  if (s == "Right Side" || s == "Right") return DamageArea::kRight;
  return std::nullopt;
}

// The first vehicle (V1 first) whose label `key` gives a value through `read`.
template <typename T, typename F>
std::optional<T> FirstVehicle(const nlohmann::json& vehicles, const char* key, F&& read) {
  for (const auto& v : vehicles) {
    if (auto x = read(Get(v, key))) return x;
  }
  return std::nullopt;
}

std::optional<double> LimitKmh(const std::string& s) {
  if (auto n = LeadingInt(s)) return static_cast<double>(*n);
  return std::nullopt;
}

// "No Statutory Limit": the road has none (a code, unlike a blank or "Unknown").
std::optional<bool> NoStatutoryLimit(const std::string& s) {
  return Lower(s).find("no statutory") != std::string::npos ? std::optional<bool>(true) : std::nullopt;
}

std::string Fmt(double x) {
  std::ostringstream os;
  os.precision(3);
  os << x;
  return os.str();
}

// A labelled vehicle's number: veh_number (NMVCCS) or veh (CIREN), else its position.
int LabelNumber(const nlohmann::json& v, size_t position) {
  std::optional<int> n = LeadingInt(Get(v, "veh_number"));
  if (!n) n = LeadingInt(Get(v, "veh"));
  return n && *n > 0 ? *n : static_cast<int>(position + 1);
}

// Words of at least three letters or digits, lower case.
std::vector<std::string> Words(const std::string& s) {
  std::vector<std::string> out;
  std::string w;
  for (const char c : s + " ") {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      w += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else {
      if (w.size() >= 3) out.push_back(w);
      w.clear();
    }
  }
  return out;
}

// How well a record vehicle's description ("1994 pontiac grand am") matches
// a coded vehicle: one point each for the model year, the make and the model.
int IdentityMatch(const std::string& description, const nlohmann::json& label) {
  const std::vector<std::string> have = Words(description);
  auto has = [&](const std::string& w) { return std::find(have.begin(), have.end(), w) != have.end(); };
  auto any_of = [&](const std::string& field) {
    for (const auto& w : Words(field)) {
      if (has(w)) return true;
    }
    return false;
  };
  std::string year = Get(label, "model_year");
  if (year.empty()) year = Get(label, "year");
  return (year.size() == 4 && has(year)) + any_of(Get(label, "make")) + any_of(Get(label, "model"));
}

// Pairs coded vehicle numbers with the record's vehicles. Narratives and
// coded data sometimes number the same two vehicles the other way round;
// when the year/make/model each description gives pairs them strictly
// better than the numbers do, that pairing is used, else the numbering.
// Returns coded number -> record index (-1: the record has no such vehicle).
std::map<int, int> PairVehicles(const nlohmann::json& row, const AccidentRecord& r) {
  std::map<int, nlohmann::json> identity;  // coded number -> the label object carrying year/make/model
  if (row.contains("vehicle_summaries") && row["vehicle_summaries"].is_array()) {
    for (size_t i = 0; i < row["vehicle_summaries"].size(); ++i) {
      identity[LabelNumber(row["vehicle_summaries"][i], i)] = row["vehicle_summaries"][i];
    }
  }
  for (size_t i = 0; i < row["vehicles"].size(); ++i) {
    const nlohmann::json& v = row["vehicles"][i];
    if (!Get(v, "make").empty()) identity[LabelNumber(v, i)] = v;
  }
  std::map<int, int> by_number;
  for (const auto& v : {row["vehicles"], row.value("vehicle_summaries", nlohmann::json::array())}) {
    for (size_t i = 0; i < v.size(); ++i) {
      const int n = LabelNumber(v[i], i);
      by_number[n] = n <= static_cast<int>(r.vehicles.size()) ? n - 1 : -1;
    }
  }
  const size_t k = r.vehicles.size();
  if (identity.size() < 2 || k < 2 || k > 6) return by_number;
  std::vector<int> numbers;
  for (const auto& [n, v] : identity) numbers.push_back(n);
  std::vector<int> order(k);
  for (size_t i = 0; i < k; ++i) order[i] = static_cast<int>(i);
  auto total = [&](const std::vector<int>& perm) {
    int t = 0;
    for (size_t i = 0; i < numbers.size() && i < perm.size(); ++i) {
      t += IdentityMatch(r.vehicles[perm[i]].description.value, identity[numbers[i]]);
    }
    return t;
  };
  std::vector<int> numbered(numbers.size(), -1);  // the numbering, as a permutation to compare against
  for (size_t i = 0; i < numbers.size(); ++i) numbered[i] = by_number.count(numbers[i]) ? by_number[numbers[i]] : -1;
  int base = 0;
  for (size_t i = 0; i < numbers.size(); ++i) {
    if (numbered[i] >= 0) base += IdentityMatch(r.vehicles[numbered[i]].description.value, identity[numbers[i]]);
  }
  int best = base;
  std::vector<int> best_perm;
  do {
    const int t = total(order);
    if (t > best) {
      best = t;
      best_perm = order;
    }
  } while (std::next_permutation(order.begin(), order.end()));
  if (best_perm.empty()) return by_number;
  for (size_t i = 0; i < numbers.size(); ++i) by_number[numbers[i]] = i < best_perm.size() ? best_perm[i] : -1;
  return by_number;
}

}  // namespace

ExtractionScore EvaluateExtraction(const std::string& dir, const NarrativeExtractor& extractor) {
  return EvaluateExtraction(dir, [&extractor](std::string_view t) { return extractor.Extract(t); });
}

ExtractionScore EvaluateExtraction(const std::string& dir, const ExtractFn& extract) {
  const std::string path = dir + "/labels.jsonl";
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot open (expected labels.jsonl in the folder)");
  ExtractionScore score;
  std::map<std::string, double> hits;
  std::map<std::string, std::map<std::string, double>> group_hits;
  std::map<std::string, std::map<std::string, int>> group_scored;
  double area_hits = 0;
  int area_scored = 0;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.find_first_not_of(" \r\t") == std::string::npos) continue;
    const std::string where = path + ":" + std::to_string(line_no);
    nlohmann::json row;
    try {
      row = nlohmann::json::parse(line);
    } catch (const nlohmann::json::parse_error& e) {
      throw std::invalid_argument(where + ": malformed JSON (" + e.what() + ")");
    }
    if (!row.is_object()) throw std::invalid_argument(where + ": expected a JSON object");
    if (!row.contains("narrative") || !row["narrative"].is_string()) {
      throw std::invalid_argument(where + ": field 'narrative' is missing or not a string");
    }
    if (!row.contains("vehicles") || !row["vehicles"].is_array() || row["vehicles"].empty()) {
      throw std::invalid_argument(where + ": field 'vehicles' is missing or not a non-empty array");
    }
    const std::string file = Get(row, "file");
    const std::string id = file.empty() ? "line " + std::to_string(line_no) : file;
    const size_t slash = file.find('/');
    const std::string group =
        slash != std::string::npos && file.find('/', slash + 1) == std::string::npos ? file.substr(0, slash) : "all";
    const AccidentRecord r = extract(row["narrative"].get<std::string>());
    // Coded vehicles paired with the narrative's; "V1's" road labels are
    // those of the coded vehicle paired with the narrative's V1.
    const std::map<int, int> pairing = PairVehicles(row, r);
    auto record_index = [&](int number) {
      const auto it = pairing.find(number);
      return it == pairing.end() ? number - 1 : it->second;
    };
    nlohmann::json vehicles = nlohmann::json::array();
    for (size_t i = 0; i < row["vehicles"].size(); ++i) {
      if (record_index(LabelNumber(row["vehicles"][i], i)) == 0) vehicles.push_back(row["vehicles"][i]);
    }
    for (size_t i = 0; i < row["vehicles"].size(); ++i) {
      if (record_index(LabelNumber(row["vehicles"][i], i)) != 0) vehicles.push_back(row["vehicles"][i]);
    }
    for (const auto& [number, index] : pairing) {
      if (index >= 0 && index != number - 1) {
        score.pairings.push_back(id + ": coded V" + std::to_string(number) + " is the narrative's V" +
                                 std::to_string(index + 1) + " (year, make, model)");
      }
    }
    std::map<std::string, double> got;
    auto miss = [&](const std::string& attr, const std::string& want, const std::string& have) {
      score.mismatches.push_back(id + ": " + attr + ": want " + want + ", got " + have);
    };

    // Participant count: vehcount (NMVCCS) or the vehicles summarised (CIREN).
    std::optional<int> want_count = LeadingInt(Get(row, "vehcount"));
    if (!want_count && row.contains("vehicle_summaries") && row["vehicle_summaries"].is_array()) {
      want_count = static_cast<int>(row["vehicle_summaries"].size());
    }
    if (!want_count) want_count = static_cast<int>(vehicles.size());
    got["participant_count"] = *want_count == r.participant_count.value;
    if (!got["participant_count"]) {
      miss("participant_count", std::to_string(*want_count), std::to_string(r.participant_count.value));
    }

    // Speed limit: V1's posted limit (the next vehicle's when V1 has none
    // coded), within 3 km/h. "No statutory limit" coded for every vehicle is
    // right when the record has no limit; a blank or unknown code is not scored.
    std::optional<double> want_kmh = FirstVehicle<double>(vehicles, "speed_limit_kmph", LimitKmh);
    if (!want_kmh) want_kmh = FirstVehicle<double>(vehicles, "posted_speed_limit_kmph", LimitKmh);
    const bool no_limit_coded = FirstVehicle<bool>(vehicles, "speed_limit_kmph", NoStatutoryLimit).has_value() ||
                                FirstVehicle<bool>(vehicles, "posted_speed_limit_kmph", NoStatutoryLimit).has_value();
    const double got_kmh = r.road.speed_limit_mps.value * 3.6;
    if (want_kmh) {
      got["speed_limit"] = r.road.speed_limit_mps.known() && std::abs(got_kmh - *want_kmh) <= 3.0;
    } else if (no_limit_coded) {
      got["speed_limit"] = !r.road.speed_limit_mps.known();
    }
    if (got.count("speed_limit") && !got["speed_limit"]) {
      miss("speed_limit", want_kmh ? Fmt(*want_kmh) : "none", r.road.speed_limit_mps.known() ? Fmt(got_kmh) : "none");
    }

    // Lane count: V1's travel lanes as NASS counts them: all lanes of a
    // one-way road, V1's direction on a divided road, both directions
    // otherwise. Only V1's own code: another vehicle's is another road's
    // (at a junction), so V1 coded unknown is not scored.
    const nlohmann::json v1_only = nlohmann::json::array({vehicles.front()});
    std::optional<int> want_lanes = FirstVehicle<int>(v1_only, "num_travel_lanes_code", LeadingInt);
    if (!want_lanes) want_lanes = FirstVehicle<int>(v1_only, "travel_lanes", CountWord);
    if (want_lanes) {
      const int got_lanes = r.road.one_way.value   ? r.road.lanes_total.value
                            : r.road.divided.value ? r.road.lanes_per_direction.value
                                                   : r.road.lanes_total.value;
      got["lane_count"] = *want_lanes == got_lanes;
      if (!got["lane_count"]) miss("lane_count", std::to_string(*want_lanes), std::to_string(got_lanes));
    }

    // Collision location: V1's relation to junction.
    if (auto want = FirstVehicle<CrashLocation>(vehicles, "relation_to_junction", LocationLabel)) {
      got["collision_location"] = *want == r.crash.location.value;
      if (!got["collision_location"]) {
        miss("collision_location", std::string(ToString(*want)), std::string(ToString(r.crash.location.value)));
      }
    }

    // Driving actions: each vehicle's coded pre-event movement, averaged
    // over the vehicles that have one.
    {
      double ok = 0.0;
      int n = 0;
      for (size_t i = 0; i < vehicles.size(); ++i) {
        const auto want = MovementLabel(Get(vehicles[i], "pre_event_movement"));
        if (!want) continue;
        ++n;
        const int number = LabelNumber(vehicles[i], i);
        const int k = record_index(number);
        const Movement have =
            k >= 0 && k < static_cast<int>(r.vehicles.size()) ? r.vehicles[k].pre_event.value : Movement::kUnknown;
        ok += *want == have;
        if (*want != have) {
          miss("driving_actions V" + std::to_string(number), std::string(ToString(*want)), std::string(ToString(have)));
        }
      }
      if (n > 0) got["driving_actions"] = ok / n;
    }

    // Crash type: V1's NHTSA crash-type code (CIREN: the code leading "87 87 T-BONE ..."), by category.
    if (auto want = FirstVehicle<CrashType>(vehicles, "crash_type_code", [](const std::string& s) {
          auto c = LeadingInt(s);
          return c ? CrashTypeLabel(*c) : std::nullopt;
        })) {
      got["crash_type"] = *want == r.crash.type.value;
      if (!got["crash_type"]) miss("crash_type", std::string(ToString(*want)), std::string(ToString(r.crash.type.value)));
    } else if (!vehicles[0].contains("crash_type_code")) {
      if (auto w = FirstVehicle<CrashType>(vehicles, "crash_type", [](const std::string& s) {
            auto c = LeadingInt(s);
            return c ? CrashTypeLabel(*c) : std::nullopt;
          })) {
        got["crash_type"] = *w == r.crash.type.value;
        if (!got["crash_type"]) miss("crash_type", std::string(ToString(*w)), std::string(ToString(r.crash.type.value)));
      }
    }

    // Extra: damaged planes of both vehicles in the first vehicle-to-vehicle event.
    if (row.contains("events") && row["events"].is_array()) {
      for (const auto& e : row["events"]) {
        std::string hit = Get(e, "object_hit");
        if (hit.empty()) hit = Get(e, "contacted");
        if (!StartsWith(hit, "Vehicle#")) continue;
        std::string first = Get(e, "striker_vehicle");
        if (first.empty()) first = Get(e, "veh");
        std::optional<DamageArea> a1 = AreaLabel(Get(e, "striker_area_damage"));
        if (!a1) a1 = AreaLabel(Get(e, "area_of_damage"));
        std::optional<DamageArea> a2 = AreaLabel(Get(e, "hit_area_damage"));
        if (!a2) a2 = AreaLabel(Get(e, "contacted_area_of_damage"));
        const std::string second = hit.substr(8);
        for (const auto& [veh, want] : {std::pair{first, a1}, std::pair{second, a2}}) {
          if (!want) continue;
          const std::optional<int> number = LeadingInt(veh);
          const DamageArea have = number ? r.AreaOf("V" + std::to_string(record_index(*number) + 1)) : DamageArea::kUnknown;
          ++area_scored;
          area_hits += have == *want;
          if (have != *want) {
            miss("impact_area V" + veh, std::string(ToString(*want)), std::string(ToString(have)));
          }
        }
        break;
      }
    }

    ++score.n;
    ++score.group_sizes[group];
    for (const auto& [k, v] : got) {
      hits[k] += v;
      ++score.scored[k];
      group_hits[group][k] += v;
      ++group_scored[group][k];
    }
  }
  if (score.n == 0) throw std::invalid_argument(path + ": no labelled cases");
  for (const auto& a : ExtractionAttributes()) {
    const int n = score.scored.count(a) ? score.scored.at(a) : 0;
    score.scored[a] = n;
    score.attributes[a] = n ? hits[a] / n : 0.0;
  }
  if (area_scored) score.extra["impact_areas"] = area_hits / area_scored;  // absent when no event codes areas
  for (const auto& [g, h] : group_hits) {
    for (const auto& a : ExtractionAttributes()) {
      const int n = group_scored[g].count(a) ? group_scored[g][a] : 0;
      score.by_group[g][a] = n ? (h.count(a) ? h.at(a) : 0.0) / n : 0.0;
    }
  }
  return score;
}

nlohmann::json ToJson(const ExtractionScore& s) {
  nlohmann::json groups = nlohmann::json::object();
  for (const auto& [g, attrs] : s.by_group) groups[g] = {{"attributes", attrs}, {"n", s.group_sizes.at(g)}};
  return {{"attributes", s.attributes}, {"n", s.n},         {"scored", s.scored},
          {"extra", s.extra},           {"groups", groups}, {"pairings", s.pairings}};
}

}  // namespace accsim
