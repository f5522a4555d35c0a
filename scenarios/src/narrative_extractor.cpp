#include "accsim/scenarios/narrative_extractor.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <regex>

namespace accsim {
namespace {

constexpr double kMphToMps = 0.44704;
constexpr double kKmhToMps = 1.0 / 3.6;

// Lower-case ASCII; every other byte (binary, UTF-8) becomes a space so the
// rules below only ever see printable text.
std::string Normalise(std::string_view in) {
  std::string s;
  s.reserve(in.size());
  for (unsigned char c : in) {
    if (c == '\n' || c == '\t' || c == '\r') s += ' ';
    else if (c < 32 || c > 126) s += ' ';
    else s += static_cast<char>(std::tolower(c));
  }
  // Number words and vehicle references in one canonical form.
  s = std::regex_replace(s, std::regex(R"(\bone[- ]way\b)"), "oneway");
  static const std::array<std::pair<std::regex, const char*>, 14> kRewrites = {{
      {std::regex(R"(\bnon[- ]?contact\b)"), "noncontact"},
      {std::regex(R"(\bvehicle\s*(?:number\s*|no\.?\s*|#\s*)?one\b)"), "v1"},
      {std::regex(R"(\bvehicle\s*(?:number\s*|no\.?\s*|#\s*)?two\b)"), "v2"},
      {std::regex(R"(\bvehicle\s*(?:number\s*|no\.?\s*|#\s*)?three\b)"), "v3"},
      {std::regex(R"(\bvehicle\s*(?:number\s*|no\.?\s*|#\s*)?four\b)"), "v4"},
      {std::regex(R"(\b(?:vehicle|veh\.?|v)\s*(?:number\s*|no\.?\s*|#\s*|-\s*)?([1-9])\b)"), "v$1"},
      {std::regex(R"(\bone\b)"), "1"},
      {std::regex(R"(\btwo\b)"), "2"},
      {std::regex(R"(\bthree\b)"), "3"},
      {std::regex(R"(\bfour\b)"), "4"},
      {std::regex(R"(\bfive\b)"), "5"},
      {std::regex(R"(\bsix\b)"), "6"},
      {std::regex(R"(\bseven\b)"), "7"},
      {std::regex(R"(\beight\b)"), "8"},
  }};
  for (const auto& [re, to] : kRewrites) s = std::regex_replace(s, re, to);
  return s;
}

// Sentences: split at '.', '!' or '?' unless between digits ("2.5"),
// so run-together sentences ("roadway.The driver") split too.
std::vector<std::string> Sentences(const std::string& s) {
  std::vector<std::string> out;
  std::string cur;
  for (size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    const bool decimal = c == '.' && i > 0 && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i - 1])) &&
                         std::isdigit(static_cast<unsigned char>(s[i + 1]));
    if ((c == '.' || c == '!' || c == '?' || c == ';') && !decimal) {
      if (cur.find_first_not_of(' ') != std::string::npos) out.push_back(cur + " ");
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (cur.find_first_not_of(' ') != std::string::npos) out.push_back(cur + " ");
  return out;
}

// Sentences about people rather than vehicle motion.
bool AboutPeople(const std::string& s) {
  static const std::regex re(
      R"(critical|associated factor|injur|transported|year[- ]old|years old|medication|lenses|wearing|fatigue|)"
      R"(treatment|hospital|rested|health|alcohol|cited|police report|interview|his way|her way|going home|heading home|)"
      R"(unable|contact lens)");
  return std::regex_search(s, re);
}

bool IsContactSentence(const std::string& s) {
  static const std::regex re(
      R"(\b(contact(ed|ing)?|struck|strik(e|es|ing)|impact(ed|ing)?|collided|collision with|hit|crashed into|rear[- ]ended|sideswiped)\b)");
  return std::regex_search(s, re);
}

std::optional<Compass> DirectionIn(const std::string& s) {
  static const std::regex re(
      R"(\b(north|south|east|west)(?:bound|ward)\b|\b(?:travel(?:l)?ing|traveled|travelled|heading|headed|going|proceeding|driving)\s+(north|south|east|west)\b)");
  std::smatch m;
  if (!std::regex_search(s, m, re)) return std::nullopt;
  const std::string w = m[1].matched ? m[1].str() : m[2].str();
  return CompassFromString(w);
}

// The text segments that talk about each vehicle: from a mention of "vN"
// to the next mention of another vehicle, within a sentence.
struct Segment {
  int vehicle;
  size_t sentence;
  std::string text;
};

std::vector<Segment> Segments(const std::vector<std::string>& sentences) {
  static const std::regex ref(R"(\bv([1-9])\b)");
  std::vector<Segment> out;
  for (size_t i = 0; i < sentences.size(); ++i) {
    const std::string& s = sentences[i];
    std::vector<std::pair<size_t, int>> marks;
    for (auto it = std::sregex_iterator(s.begin(), s.end(), ref); it != std::sregex_iterator(); ++it) {
      marks.emplace_back(static_cast<size_t>(it->position()), std::stoi((*it)[1].str()));
    }
    for (size_t k = 0; k < marks.size(); ++k) {
      const size_t end = k + 1 < marks.size() ? marks[k + 1].first : s.size();
      if (k + 1 < marks.size() && marks[k + 1].second == marks[k].second) continue;  // merge repeats
      out.push_back({marks[k].second, i, s.substr(marks[k].first, end - marks[k].first)});
    }
  }
  return out;
}

Movement MovementIn(const std::string& t) {
  static const std::regex left(R"(turn(?:ed|ing|s)?\s+(?:to\s+(?:the\s+)?)?left|left[- ]turn|left\s+onto|turn left)");
  static const std::regex right(R"(turn(?:ed|ing|s)?\s+(?:to\s+(?:the\s+)?)?right|right[- ]turn|right\s+onto)");
  static const std::regex lanes(R"(chang(?:e|ed|es|ing)\s+lanes?|lane\s+change|changing\s+lanes)");
  static const std::regex merge(R"(\bmerg(?:e|ed|es|ing)\b)");
  static const std::regex back(R"(\bback(?:ed|ing)\s+(?:up|out|into|from)|\breversing\b|\bin reverse\b)");
  static const std::regex pass(R"(\b(?:pass|passed|passing|overtak\w*)\s+(?:a|an|the|v[1-9])\b)");
  static const std::regex stop(R"(\bstopped\b|\bstationary\b|\bwaiting\b|\bat rest\b|\bparked\b|\bcame to a (?:complete |full )?stop\b)");
  // Braking is usually the avoidance manoeuvre, not the pre-crash movement.
  static const std::regex slow(R"(\bslow(?:ed|ing)\b|\bdecelerat\w*)");
  // "stopped, waiting to turn left": the intention is not the movement.
  static const std::regex intention(
      R"(\b(?:wait\w*|to|for|intend\w*(?:\s+on)?|prepar\w*|signal\w*|plann\w*)\s+(?:to\s+)?(?:make\s+|complete\s+)?(?:a\s+|the\s+)?(?:left|right)?[- ]?turn)");
  const bool stopped = std::regex_search(t, stop);
  if (stopped && std::regex_search(t, intention)) return Movement::kStopped;
  if (std::regex_search(t, left)) return Movement::kTurnLeft;
  if (std::regex_search(t, right)) return Movement::kTurnRight;
  if (std::regex_search(t, lanes)) return Movement::kChangingLanes;
  if (std::regex_search(t, merge)) return Movement::kMerging;
  if (std::regex_search(t, back)) return Movement::kBacking;
  if (std::regex_search(t, pass)) return Movement::kPassing;
  if (stopped) return Movement::kStopped;
  if (std::regex_search(t, slow)) return Movement::kSlowing;
  return Movement::kUnknown;
}

int Rank(Movement m) {  // which statement wins when a vehicle does several things
  switch (m) {
    case Movement::kTurnLeft:
    case Movement::kTurnRight: return 6;
    case Movement::kChangingLanes:
    case Movement::kMerging:
    case Movement::kBacking:
    case Movement::kPassing: return 5;
    case Movement::kStopped: return 4;
    case Movement::kSlowing: return 3;
    case Movement::kStraight: return 1;
    case Movement::kUnknown: return 0;
  }
  return 0;
}

DamageArea AreaOf(const std::string& words) {
  const bool front = words.find("front") != std::string::npos;
  const bool rear = words.find("rear") != std::string::npos || words.find("back") != std::string::npos;
  const bool left = words.find("left") != std::string::npos;
  const bool right = words.find("right") != std::string::npos;
  // Front corners count as the front plane; rear corners as the side
  // (how investigators code a rear-quarter hit).
  if (front) return DamageArea::kFront;
  if (left) return DamageArea::kLeft;
  if (right) return DamageArea::kRight;
  if (rear) return DamageArea::kRear;
  return DamageArea::kUnknown;
}

VehicleClass ClassOf(const std::string& d) {
  auto has = [&](const char* w) { return std::regex_search(d, std::regex(w)); };
  if (has(R"(motorcycle|motorbike|scooter|moped|harley)")) return VehicleClass::kMotorcycle;
  if (has(R"(\bbus\b|school bus|transit)")) return VehicleClass::kBus;
  if (has(R"(tractor|semi|trailer|box truck|dump truck|straight truck|freightliner|peterbilt|kenworth|mack\b)"))
    return VehicleClass::kTruck;
  if (has(R"(pickup|pick-up|f-?150|f-?250|silverado|sierra|ram\b|tacoma|ranger|tundra|dakota|s-?10\b)"))
    return VehicleClass::kPickup;
  if (has(R"(\bvan\b|minivan|caravan|windstar|odyssey|sienna|montana|trans sport|econoline|express|astro)"))
    return VehicleClass::kVan;
  if (has(R"(suv|sport utility|utility vehicle|jeep|explorer|blazer|tahoe|suburban|4runner|cr-v|rav4|expedition|durango|trailblazer|escape|pathfinder|yukon)"))
    return VehicleClass::kSuv;
  return VehicleClass::kCar;
}

bool Opposite(Compass a, Compass b) { return (static_cast<int>(a) + 2) % 4 == static_cast<int>(b); }
bool Perpendicular(Compass a, Compass b) { return (static_cast<int>(a) + static_cast<int>(b)) % 2 == 1; }

}  // namespace

AccidentRecord NarrativeExtractor::Extract(std::string_view text) const {
  AccidentRecord r;
  if (text.size() > kMaxBytes) {
    r.warnings.push_back("text: longer than " + std::to_string(kMaxBytes) + " bytes; only the start was read");
    text = text.substr(0, kMaxBytes);
  }
  const std::string norm = Normalise(text);
  const std::vector<std::string> sentences = Sentences(norm);
  if (sentences.empty()) {
    r.warnings.push_back("text: no readable sentences; every field is a default");
    return r;
  }

  // Participants: the highest vehicle number mentioned.
  static const std::regex ref(R"(\bv([1-9])\b)");
  int max_v = 0;
  for (auto it = std::sregex_iterator(norm.begin(), norm.end(), ref); it != std::sregex_iterator(); ++it) {
    max_v = std::max(max_v, std::stoi((*it)[1].str()));
  }
  if (max_v > 0) {
    r.participant_count.Set(max_v, Provenance::kStated);
  } else {
    std::smatch m;
    static const std::regex count(R"(\b([1-9])[- ]vehicle\b|\b([1-9]) vehicles\b)");
    if (std::regex_search(norm, m, count)) {
      r.participant_count.Set(std::stoi(m[1].matched ? m[1].str() : m[2].str()), Provenance::kStated);
    } else {
      r.warnings.push_back("participants: no vehicle references (V1, vehicle one, ...) found");
    }
  }
  for (int i = 1; i <= std::max(1, r.participant_count.value); ++i) {
    VehicleRecord v;
    v.id = "V" + std::to_string(i);
    r.vehicles.push_back(v);
  }

  // Road: kind, lanes, division, surface, light, grade, speed limit.
  static const std::regex t_junction(R"(\bt[- ]?(?:intersection|junction)|\bthree[- ]leg|\b3[- ]leg|\btee\b|t-type)");
  static const std::regex intersection(R"(\bintersection\b)");
  if (std::regex_search(norm, t_junction)) r.road.kind.Set(RoadKind::kTJunction, Provenance::kStated);
  else if (std::regex_search(norm, intersection)) r.road.kind.Set(RoadKind::kIntersection, Provenance::kStated);
  else if (std::regex_search(norm, std::regex(R"(\bramp\b)"))) r.road.kind.Set(RoadKind::kRamp, Provenance::kStated);
  else if (std::regex_search(norm, std::regex(R"(\bdriveway\b)"))) r.road.kind.Set(RoadKind::kDriveway, Provenance::kStated);
  else if (std::regex_search(norm, std::regex(R"(\bcurve)"))) r.road.kind.Set(RoadKind::kCurve, Provenance::kStated);

  {
    static const std::regex per_dir(R"(\b([1-9])[- ](?:through\s+|travel\s+)?lanes?\s+(?:in\s+|for\s+)?(?:each|either|both|per)\s+direction)");
    static const std::regex dir_lanes(R"(\b([1-9])\s+(?:north|south|east|west)bound\s+(?:travel\s+)?lanes?\b)");
    static const std::regex total(R"(\b([1-9])[- ]lanes?\b)");
    std::smatch m;
    for (const auto& s : sentences) {
      if (!r.road.lanes_per_direction.known() && std::regex_search(s, m, per_dir)) {
        r.road.lanes_per_direction.Set(std::stoi(m[1].str()), Provenance::kStated);
        continue;  // "2 lanes in each direction" is not a total of 2
      }
      if (!r.road.lanes_total.known() && std::regex_search(s, m, total)) {
        r.road.lanes_total.Set(std::stoi(m[1].str()), Provenance::kStated);
      }
      if (!r.road.lanes_per_direction.known() && std::regex_search(s, m, dir_lanes)) {
        r.road.lanes_per_direction.Set(std::stoi(m[1].str()), Provenance::kStated);
      }
    }
    if (std::regex_search(norm, std::regex(R"(\boneway\b)"))) r.road.one_way.Set(true, Provenance::kStated);
    if (std::regex_search(norm, std::regex(R"((?:^|[^n])\b(?:divided|median|barrier)\b)")) &&
        !std::regex_search(norm, std::regex(R"(\bundivided\b|not (?:physically )?divided|non-divided)"))) {
      r.road.divided.Set(true, Provenance::kStated);
    }
    if (r.road.lanes_total.known() && !r.road.lanes_per_direction.known()) {
      const int per = r.road.one_way.value ? r.road.lanes_total.value : std::max(1, r.road.lanes_total.value / 2);
      r.road.lanes_per_direction.Set(per, Provenance::kInferred);
    } else if (!r.road.lanes_total.known() && r.road.lanes_per_direction.known()) {
      r.road.lanes_total.Set(r.road.lanes_per_direction.value * (r.road.one_way.value ? 1 : 2), Provenance::kInferred);
    }
  }
  if (std::regex_search(norm, std::regex(R"(\b(?:icy|ice|frost|black ice)\b)"))) r.road.surface.Set(Surface::kIce, Provenance::kStated);
  else if (std::regex_search(norm, std::regex(R"(\bsnow|slush)"))) r.road.surface.Set(Surface::kSnow, Provenance::kStated);
  else if (std::regex_search(norm, std::regex(R"(\bwet\b|\braining\b|\brain\b)"))) r.road.surface.Set(Surface::kWet, Provenance::kStated);
  else if (std::regex_search(norm, std::regex(R"(\bdry\b)"))) r.road.surface.Set(Surface::kDry, Provenance::kStated);
  {
    std::smatch m;
    if (std::regex_search(norm, m, std::regex(R"(\b(daylight|dark(?: but lighted| and lighted|, lighted)?|dusk|dawn|night)\b)"))) {
      r.road.lighting.Set(m[1].str(), Provenance::kStated);
    }
    if (std::regex_search(norm, m, std::regex(R"(\b(uphill|downhill|level)\b)"))) r.road.grade.Set(m[1].str(), Provenance::kStated);
  }

  // Vehicles: description, class, direction, lane, movement, speed.
  const std::vector<Segment> segments = Segments(sentences);
  size_t impact_sentence = sentences.size();
  for (size_t i = 0; i < sentences.size(); ++i) {
    if (!AboutPeople(sentences[i]) && IsContactSentence(sentences[i])) {
      impact_sentence = i;
      break;
    }
  }
  static const std::regex desc(R"(^v[1-9]\s*(?:,|was|is|\()\s*(?:was\s+|is\s+)?(?:a|an)\s+([^,()]*?)(?:,|\)|\s+(?:was|that|which|driven|operated|travel|going|heading|approach|and)\b|$))");
  static const std::regex lane_no(R"(\b(?:in|within|using)\s+(?:the\s+)?(?:lane\s+([1-9])|([1-9])(?:st|nd|rd|th)\s+(?:\w+\s+)?lane))");
  static const std::regex speed(R"(\b(\d{1,3})(?:\s*-\s*(\d{1,3}))?\s*(km/?h|kmph|kph|mph|miles per hour|kilometers per hour))");
  std::vector<int> best_rank(r.vehicles.size() + 1, -1);
  for (const Segment& seg : segments) {
    if (seg.vehicle < 1 || seg.vehicle > static_cast<int>(r.vehicles.size())) continue;
    VehicleRecord& v = r.vehicles[static_cast<size_t>(seg.vehicle - 1)];
    std::smatch m;
    if (!v.description.known() && std::regex_search(seg.text, m, desc)) {
      v.description.Set(m[1].str(), Provenance::kStated);
      v.vehicle_class.Set(ClassOf(m[1].str()), Provenance::kInferred);
    }
    const bool people = AboutPeople(sentences[seg.sentence]);
    if (!people && !v.travel.known()) {
      if (const auto d = DirectionIn(seg.text)) v.travel.Set(*d, Provenance::kStated);
    }
    if (!people && !v.lane.known() && std::regex_search(seg.text, m, lane_no)) {
      v.lane.Set(std::stoi(m[1].matched ? m[1].str() : m[2].str()), Provenance::kStated);
    }
    if (!v.speed_mps.known() && std::regex_search(seg.text, m, speed) &&
        seg.text.find("limit") == std::string::npos) {
      const double lo = std::stod(m[1].str());
      const double hi = m[2].matched ? std::stod(m[2].str()) : lo;
      const bool kmh = m[3].str()[0] == 'k';
      v.speed_mps.Set(0.5 * (lo + hi) * (kmh ? kKmhToMps : kMphToMps), Provenance::kStated);
    }
    if (!people && seg.sentence <= impact_sentence) {
      const Movement mv = MovementIn(seg.text);
      const int rank = Rank(mv);
      if (rank > best_rank[static_cast<size_t>(seg.vehicle)] && mv != Movement::kUnknown) {
        best_rank[static_cast<size_t>(seg.vehicle)] = rank;
        v.movement.Set(mv, Provenance::kStated);
      }
    }
  }
  for (auto& v : r.vehicles) {
    if (!v.movement.known()) v.movement.Set(Movement::kStraight, Provenance::kInferred);
  }
  // Speed limit: the posted limit, preferring the one stated for V1's direction.
  {
    struct Limit {
      double mps;
      std::string unit;
      std::optional<Compass> dir;
    };
    std::vector<Limit> limits;
    static const std::regex limit_value(R"((\d{1,3})\s*(km/?h|kmph|kph|mph|miles per hour|kilometers per hour))");
    for (const auto& s : sentences) {
      const size_t at = s.find("limit");
      if (at == std::string::npos && s.find("posted") == std::string::npos) continue;
      std::smatch m;
      std::string rest = s;
      while (std::regex_search(rest, m, limit_value)) {
        const bool kmh = m[2].str()[0] == 'k';
        const std::string before = rest.substr(0, static_cast<size_t>(m.position()));
        limits.push_back({std::stod(m[1].str()) * (kmh ? kKmhToMps : kMphToMps), kmh ? "km/h" : "mph",
                          DirectionIn(before)});
        // A value and its conversion in brackets state one limit.
        const std::string tail = m.suffix().str();
        std::smatch conv;
        if (std::regex_search(tail, conv, std::regex(R"(^\s*\(\s*\d{1,3}\s*(?:km/?h|kmph|kph|mph)\s*\))"))) {
          rest = conv.suffix().str();
        } else {
          rest = tail;
        }
      }
    }
    if (!limits.empty()) {
      const auto& v1_dir = r.vehicles.front().travel;
      const Limit* pick = &limits.front();
      for (const auto& l : limits) {
        if (v1_dir.known() && l.dir && *l.dir == *v1_dir.value) {
          pick = &l;
          break;
        }
      }
      r.road.speed_limit_mps.Set(pick->mps, Provenance::kStated);
      r.road.speed_limit_unit.Set(pick->unit, Provenance::kStated);
    }
  }

  // The impact: who struck whom, with which areas.
  if (impact_sentence < sentences.size()) {
    const std::string& s = sentences[impact_sentence];
    static const std::string kArea = R"(((?:(?:left|right|front|rear|back)[- ]?\s*)+(?:side|end|corner|quarter|bumper|door|fender|plane|panel|area|portion)?(?:\s+(?:side|plane|area))?))";
    static const std::regex verb(
        R"(\b(contact(?:ed|ing)?|struck|strik(?:e|es|ing)|impact(?:ed|ing)?|collided|hit|crashed|rear[- ]ended|sideswiped)\b)");
    std::smatch vm;
    std::regex_search(s, vm, verb);
    const size_t verb_pos = vm.empty() ? s.size() : static_cast<size_t>(vm.position());
    const bool passive =
        std::regex_search(s, std::regex(R"(\b(?:was|were|is|been|being|got)\s+(?:\w+\s+)?(?:contacted|struck|impacted|hit|rear[- ]ended|sideswiped)\b)"));
    // Subject: the vehicle named last before the verb; object: the first after it.
    std::vector<std::pair<size_t, int>> refs;
    for (auto it = std::sregex_iterator(s.begin(), s.end(), ref); it != std::sregex_iterator(); ++it) {
      refs.emplace_back(static_cast<size_t>(it->position()), std::stoi((*it)[1].str()));
    }
    int subject = 0, object = 0;
    for (const auto& [pos, n] : refs) {
      if (pos < verb_pos) subject = n;
    }
    for (const auto& [pos, n] : refs) {
      if (pos > verb_pos && n != subject) {
        object = n;
        break;
      }
    }
    int striker = passive ? object : subject, struck = passive ? subject : object;
    // Areas named with a vehicle: "the front of V1", "V1's front",
    // "V2 on the right side", "with its front" (the striker's), "was struck
    // in the left side" (the struck vehicle's).
    std::map<int, DamageArea> area;
    auto note = [&](int v, const std::string& words) {
      const DamageArea d = AreaOf(words);
      if (v > 0 && d != DamageArea::kUnknown && !area.count(v)) area[v] = d;
    };
    const std::regex of_v(kArea + R"(\s+(?:of\s+(?:the\s+)?)v([1-9])\b)");
    const std::regex v_s(R"(\bv([1-9])'?s\s+)" + kArea);
    const std::regex v_on(R"(\bv([1-9])\s+(?:on|in|at)\s+(?:the|its|it's|his|her)\s+)" + kArea);
    const std::regex with_its(R"(\b(?:with|using)\s+(?:its|it's|the|his|her)?\s*)" + kArea);
    const std::regex struck_in(R"(\b(?:contacted|struck|impacted|hit)\s+(?:on|in|at)\s+(?:the|its|it's)\s+)" + kArea);
    const std::regex its_area(R"(\bits\s+)" + kArea + R"(\s+(?:was|were))");
    for (auto it = std::sregex_iterator(s.begin(), s.end(), of_v); it != std::sregex_iterator(); ++it) {
      note(std::stoi((*it)[2].str()), (*it)[1].str());
    }
    for (auto it = std::sregex_iterator(s.begin(), s.end(), v_s); it != std::sregex_iterator(); ++it) {
      note(std::stoi((*it)[1].str()), (*it)[2].str());
    }
    for (auto it = std::sregex_iterator(s.begin(), s.end(), v_on); it != std::sregex_iterator(); ++it) {
      note(std::stoi((*it)[1].str()), (*it)[2].str());
    }
    std::smatch am;
    if (std::regex_search(s, am, with_its)) note(striker, am[1].str());
    if (std::regex_search(s, am, struck_in)) note(struck, am[1].str());
    if (std::regex_search(s, am, its_area)) note(passive ? struck : striker, am[1].str());
    if (striker && striker == struck) struck = 0;
    if (striker) {
      const bool named = area.count(striker);
      r.crash.striking.Set("V" + std::to_string(striker), Provenance::kStated);
      r.crash.striking_area.Set(named ? area[striker] : DamageArea::kFront,
                                named ? Provenance::kStated : Provenance::kInferred);
    }
    if (struck) {
      r.crash.struck.Set("V" + std::to_string(struck), Provenance::kStated);
      if (area.count(struck)) r.crash.struck_area.Set(area[struck], Provenance::kStated);
    } else if (striker && r.participant_count.value <= 1) {
      r.crash.struck.Set("object", Provenance::kInferred);
    }
    if (std::regex_search(s, std::regex(R"(intersection|junction|turn|crossing|driveway)")) &&
        (r.road.kind.value == RoadKind::kIntersection || r.road.kind.value == RoadKind::kTJunction)) {
      r.crash.location.Set(CrashLocation::kJunction, Provenance::kInferred);
    }
  } else {
    r.warnings.push_back("crash: no sentence describes a contact (struck, contacted, collided, ...)");
  }
  if (r.crash.location.source == Provenance::kDefaulted &&
      (r.road.kind.value == RoadKind::kIntersection || r.road.kind.value == RoadKind::kTJunction)) {
    r.crash.location.Set(CrashLocation::kJunction, Provenance::kInferred);
  }

  // Crash type from movements, directions and areas.
  auto vehicle = [&](const Field<std::string>& id) -> const VehicleRecord* {
    for (const auto& v : r.vehicles) {
      if (id.known() && v.id == id.value) return &v;
    }
    return nullptr;
  };
  const VehicleRecord* a = vehicle(r.crash.striking);
  const VehicleRecord* b = vehicle(r.crash.struck);
  if (!a && !r.vehicles.empty()) a = &r.vehicles[0];
  if (!b && r.vehicles.size() > 1) b = &r.vehicles[a == &r.vehicles[0] ? 1 : 0];
  CrashType type = CrashType::kUnknown;
  if (r.participant_count.value <= 1 || !b) {
    type = CrashType::kSingleVehicle;
  } else {
    const auto turning = [](const VehicleRecord* v) {
      return v->movement.value == Movement::kTurnLeft || v->movement.value == Movement::kTurnRight;
    };
    const bool dirs = a->travel.known() && b->travel.known() && a->travel.value && b->travel.value;
    const Compass da = dirs ? *a->travel.value : Compass::kNorth, db = dirs ? *b->travel.value : Compass::kNorth;
    const DamageArea sa = r.crash.striking_area.value, sb = r.crash.struck_area.value;
    const bool side_hit = sb == DamageArea::kLeft || sb == DamageArea::kRight;
    if (turning(a) || turning(b)) {
      if (dirs && Perpendicular(da, db)) type = CrashType::kTurnIntoPath;
      else type = CrashType::kTurnAcrossPath;
    } else if (a->movement.value == Movement::kChangingLanes || b->movement.value == Movement::kChangingLanes ||
               a->movement.value == Movement::kMerging || b->movement.value == Movement::kMerging) {
      type = CrashType::kSideswipeSame;
    } else if (dirs && Perpendicular(da, db)) {
      type = CrashType::kAngle;
    } else if (dirs && Opposite(da, db)) {
      type = (sa == DamageArea::kFront && (sb == DamageArea::kFront || sb == DamageArea::kUnknown))
                 ? CrashType::kHeadOn
                 : CrashType::kSideswipeOpposite;
    } else if (sb == DamageArea::kRear || b->movement.value == Movement::kStopped ||
               b->movement.value == Movement::kSlowing) {
      type = CrashType::kRearEnd;
    } else if (side_hit && dirs) {
      type = CrashType::kSideswipeSame;
    } else if (side_hit) {
      type = CrashType::kAngle;
    } else if (sa == DamageArea::kFront && sb == DamageArea::kFront) {
      type = CrashType::kHeadOn;
    }
  }
  r.crash.type.Set(type, type == CrashType::kUnknown ? Provenance::kDefaulted : Provenance::kInferred);
  if (!r.crash.struck_area.known()) {
    if (type == CrashType::kHeadOn) r.crash.struck_area.Set(DamageArea::kFront, Provenance::kInferred);
    if (type == CrashType::kRearEnd) r.crash.struck_area.Set(DamageArea::kRear, Provenance::kInferred);
  }

  static const std::regex camera(R"(\b(?:view(?:ed)?|camera|viewpoint|perspective|seen)\s+from\s+(?:the\s+)?([a-z0-9' ]{3,40}))");
  std::smatch cm;
  if (std::regex_search(norm, cm, camera)) r.camera_hint.Set(cm[1].str(), Provenance::kStated);
  if (!r.participant_count.known() && impact_sentence == sentences.size()) {
    r.warnings.push_back("text: no crash description recognised (is it an English crash narrative?)");
  }
  return r;
}

}  // namespace accsim
