#include "narrative_reading.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "regex_text.h"

namespace accsim::narrative {

using std::regex;
using std::smatch;
using std::string;

using regex_text::Has;

namespace {

struct RoadStatement {
  size_t sentence = 0;
  size_t pos = 0;                  // where in the sentence
  int owner = 0;                   // vehicle whose segment states it (0: none)
  std::optional<int> axis;         // 0 = east-west, 1 = north-south, when the phrase names one
  int total = 0, per_direction = 0, directional = 0;
  std::optional<Compass> bound;    // the direction a directional count is of ("3 westbound lanes")
  bool one_way = false;
  bool cross = false;              // said of the cross street ("the cross street is a 2-lane road")
  bool met = false;                // said of the road another meets ("... where it ends at a T-intersection with a 4-lane arterial")
  bool ramp = false;               // said of a ramp ("a single-lane entrance ramp")
  bool centre = false;             // its phrase adds a centre lane ("... separated by a 2-way left-turn lane")
  string name;                     // the named road its clause is about ("route 202 is ... with 1 lane each way")
  string road;                     // the road its clause is about by kind ("the residential street was a 2-lane ...")
  string counted;                  // the road its own noun phrase names ("a 2-lane collector road")
};

// "the road", "the roadway", "the street" name no road in particular.
bool GenericRoad(const string& road) { return road == "road" || road == "roadway" || road == "street"; }

// The same road by its kind, with or without a qualifier: "the arterial"
// is the "city arterial".
bool SameRoad(const string& a, const string& b) {
  auto qualifies = [](const string& longer, const string& shorter) {
    return longer.size() > shorter.size() &&
           longer.compare(longer.size() - shorter.size() - 1, string::npos, " " + shorter) == 0;
  };
  return a == b || (!a.empty() && !b.empty() && !GenericRoad(a) && !GenericRoad(b) &&
                    (qualifies(a, b) || qualifies(b, a)));
}

// Two roads named by kinds that differ ("highway", "county road"), neither
// generic nor one within the other.
bool OtherKindsOfRoad(const string& a, const string& b) {
  return !a.empty() && !b.empty() && !GenericRoad(a) && !GenericRoad(b) && a.find(b) == string::npos &&
         b.find(a) == string::npos;
}

// A statement naming another road than the one `best` counts by its own noun
// ("a six-lane parkway and a two-lane county road. the parkway had 3 lanes
// each way", `best` the county road's count).
bool OfAnotherRoad(const RoadStatement& rs, const RoadStatement& best) {
  return best.road.empty() && !best.counted.empty() && !GenericRoad(best.counted) && !rs.road.empty() &&
         !GenericRoad(rs.road) && rs.road != best.counted;
}

std::optional<int> AxisIn(const string& s) {
  static const regex kAxis(
      R"(\b(east|west)[- ]?(?:/|-|and)?\s*(?:west|east)\b|\b(north|south)[- ]?(?:/|-|and)?\s*(?:south|north)\b|\b(north|south|east|west)[- ]?bound\b|\b(n|s)/(?:s|n)\b|\b(e|w)/(?:w|e)\b|)"
      // "entering from the east is a two-lane residential street".
      R"(\b(?:enter\w*|com(?:es|ing)|came|join\w*|approach\w*|r[ua]ns?|leads?|led|extends?|branch\w*)\s+(?:in\s+)?from\s+the\s+(north|south|east|west)\b|)"
      // "the west leg was a two-lane roadway": a leg runs to its side.
      R"(\b(north|south|east|west)(?:ern)?\s+(?:leg|approach)\b)");
  std::optional<int> last;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), kAxis); it != std::sregex_iterator(); ++it) {
    const smatch& m = *it;
    if (m[1].matched || m[5].matched) last = 0;
    else if (m[2].matched || m[4].matched) last = 1;
    else if (m[3].matched) last = (m[3].str()[0] == 'e' || m[3].str()[0] == 'w') ? 0 : 1;
    else if (m[6].matched) last = (m[6].str()[0] == 'e' || m[6].str()[0] == 'w') ? 0 : 1;
    else if (m[7].matched) last = (m[7].str()[0] == 'e' || m[7].str()[0] == 'w') ? 0 : 1;
  }
  return last;
}

int AxisOf(Compass c) { return (c == Compass::kEast || c == Compass::kWest) ? 0 : 1; }


// The limit a road class usually has in the U.S., for reports that name the
// class but not the limit: freeways 70 mph, parking lots and private roads
// 15, residential streets 25 (30 where the report tells its limits, below),
// rural roads and state or county highways 55,
// urban streets 30 (45 on multi-lane urban arterials: `lanes_total` >= 3),
// one-way streets 30. A road the report describes (`road_described`: its
// lanes were counted) without naming any class gets 55, the statutory limit
// outside towns in most states; with nothing described there is no prior.
// A report that states its limits as a rule (`limits_told`: one quoting the
// NASS coding, whose investigators always give the posted limit) and is
// silent on this one is on an unposted town street: the statutory 30 mph
// however many lanes (the development set's crossing/10, 17 and 19), also
// where the road is counted but named by no class. CIREN
// summaries never state a limit, so there the arterial's 45 stands.
std::optional<double> TypicalLimitMph(const string& scene, int lanes_total, bool road_described, bool limits_told) {
  static const regex kFreeway(R"(\b(?:freeway|interstate|expressway|turnpike|limited[- ]access)\b|\bi-\d{1,3}\b)");
  static const regex kPrivate(
      R"(\b(?:on|in|within|along|of|through) (?:a|an|the) (?:\w+ )?(?:parking (?:lot|area|garage)|private (?:road|drive))\b)");
  // (A "private residential driveway" is no residential street.)
  static const regex kResidential(
      R"(\bresidential\b(?!\s+(?:driveway|drive|property|lot|yard|home|house|garage|parking))|\bsubdivision\b|\bneighborhood street\b)");
  static const regex kRural(R"(\brural\b|\b(?:state|u\.?s\.?|county) (?:highway|route|road)\b)");
  // Street parking and sidewalks are a town's: "parking lanes on both sides".
  static const regex kUrban(
      R"(\b(?:urban|suburban|city|downtown|business district|commercial)\b|\bparking lanes?\b|\b(?:curbside|on-street|parallel|metered) parking\b|\bsidewalks?\b|\bstorefronts?\b)");
  static const regex kOneWayStreet(R"(\boneway (?:\w+ )?(?:road|roadway|street)\b)");
  static const regex kHighway(R"(\bhighway\b)");
  if (Has(scene, kFreeway)) return 70.0;
  if (Has(scene, kPrivate)) return 15.0;
  // (An unposted residential street in a report that tells its limits is
  // the town's statutory 30 as well.)
  if (Has(scene, kResidential)) return limits_told ? 30.0 : 25.0;
  if (Has(scene, kRural)) return 55.0;
  if (Has(scene, kUrban)) return lanes_total >= 3 && !limits_told ? 45.0 : 30.0;
  if (Has(scene, kOneWayStreet)) return 30.0;
  if (Has(scene, kHighway)) return 55.0;
  // Silence where limits are told, on a road named by no class: the town's.
  if (limits_told && road_described) return 30.0;
  if (road_described) return 55.0;
  return std::nullopt;
}

// A road named by its kind, with the word that tells it from the others:
// "side street", "county road", "highway", "stem".
const string& RoadNoun() {
  static const string kNoun =
      R"(((?:(?:county|state|rural|city|residential|local|minor|secondary|through|collector|main|frontage|side|cross|access|service)\s+)?(?:road|roadway|street|highway|avenue|boulevard|parkway|turnpike|route|arterial|collector|stem|freeway|interstate|expressway|crossroad)))";
  return kNoun;
}

// Any road noun, as a word.
const regex& RoadWord() {
  static const regex kWord(R"(\b)" + RoadNoun() + R"(\b)");
  return kWord;
}

// A junction told by the roads that make it: "where carter's mill road
// crosses us-29", "the intersecting residential street", "where the ramp
// meets ...".

// The road the clause holding `pos` is about: its first named road ("the
// side street is a 2-lane road posted at 30 mph" -> "side street").
// `end`, when given, is where that road's words end.
// A clause also starts at a second road with its own verb ("the highway had
// a 45 mph limit and the side road had a 25 mph limit").
string ClauseRoad(const string& s, size_t pos, size_t* end = nullptr) {
  const size_t stop = s.find_last_of(".;:", pos == 0 ? 0 : pos - 1);
  size_t from = stop == string::npos ? 0 : stop + 1;
  static const regex kNextRoadClause(R"(\b(?:and|while|whereas|but)\s+(?=(?:the|a|an)\s+(?:[\w/-]+\s+){0,3}?)" +
                                     RoadNoun() + R"(\s+(?:had|has|was|is|were|are|carried|carries)\b))");
  const string head = s.substr(from, pos - from);
  size_t next = 0;
  for (auto it = std::sregex_iterator(head.begin(), head.end(), kNextRoadClause); it != std::sregex_iterator(); ++it) {
    next = static_cast<size_t>(it->position() + it->length());
  }
  from += next;
  static const regex kFirst(R"(\b(?:the|a|an)\s+(?:[\w/-]+\s+){0,3}?)" + RoadNoun() + R"(\b)");
  smatch m;
  const string clause = s.substr(from, pos - from);
  if (!std::regex_search(clause, m, kFirst)) return {};
  if (end) *end = from + static_cast<size_t>(m.position(1) + m.length(1));
  return m[1].str();
}

// A vehicle's text up to any turn or intention: the road it turns onto is
// not the one it travelled on.
string BeforeTheTurn(const string& t) {
  static const regex kTurnWords(R"(\b(?:intend\w*|to turn|turning|turned|turn|onto)\b)");
  smatch tw;
  return std::regex_search(t, tw, kTurnWords) ? t.substr(0, static_cast<size_t>(tw.position())) : t;
}

// Roads the report names ("kessler lane", "route 202", "us 20"), found in
// every sentence; "at linden" is Linden Street when one named road starts
// with that word. A name told as a place ("at", "with", "onto" it) is not
// what a clause is about; one at the clause's start or after "on" is.
class RoadNames {
 public:
  explicit RoadNames(const std::vector<string>& texts) {
    static const regex kNumbered(
        R"(\b(?:us|sr|state route|state road|state highway|county road|county route|cr|tr|township road|route|rt|highway|interstate|fm|sh)[- ]?\d{1,4}\b|\bi-\d{1,3}\b)");
    static const regex kWorded(
        R"(\b([a-z][a-z']+)(?:\s+([a-z][a-z']+))?\s+(street|avenue|road|drive|lane|boulevard|parkway|pike|highway)\b)");
    static const std::set<string> kNotAName = {
        "a", "an", "the", "and", "or", "of", "on", "onto", "at", "to", "from", "in", "into", "with", "along", "down",
        "up", "for", "by", "its", "his", "her", "their", "this", "that", "same", "other", "another", "each", "both",
        "either", "which", "who", "was", "is", "were", "residential", "rural", "city", "county", "state", "side",
        "cross", "private", "access", "service", "frontage", "local", "divided", "undivided", "paved", "gravel",
        "dirt", "narrow", "wide", "straight", "curved", "curving", "main", "minor", "major", "urban", "suburban",
        "country", "through", "collector", "arterial", "intersecting", "connecting", "oneway", "left", "right",
        "curb", "turn", "travel", "center", "centre", "inside", "outside", "passing", "middle", "median", "bike",
        "parking", "acceleration", "deceleration", "exit", "entrance", "merge", "shoulder", "opposing", "oncoming",
        "adjacent", "opposite", "driving", "traffic", "public", "dead", "end", "via",
        "when", "as", "then", "but", "not", "no", "lanes", "lane", "road", "roadway", "street", "highway", "ramp",
        "new", "old", "two", "one", "first", "second", "third", "near", "far", "hov", "bus", "emergency", "fast", "slow",
        "way"};
    auto ok_word = [&](const string& w) {
      return !w.empty() && !kNotAName.count(w) && w.find("bound") == string::npos && w.find("'s") == string::npos;
    };
    for (const string& t : texts) {
      for (auto it = std::sregex_iterator(t.begin(), t.end(), kNumbered); it != std::sregex_iterator(); ++it) {
        Add(Canonical(it->str()), "");
      }
      for (auto it = std::sregex_iterator(t.begin(), t.end(), kWorded); it != std::sregex_iterator(); ++it) {
        const smatch& m = *it;
        const size_t at = static_cast<size_t>(m.position());
        // "2-way road", "an east/west road"
        if (at > 0 && (t[at - 1] == '-' || t[at - 1] == '/' || std::isdigit(static_cast<unsigned char>(t[at - 1])))) continue;
        const string w1 = m[1].str(), w2 = m[2].matched ? m[2].str() : string();
        if (!ok_word(w1) || (!w2.empty() && !ok_word(w2))) {
          if (w2.empty() || !ok_word(w2)) continue;
          Add(w2 + " " + m[3].str(), w2);  // "the kessler lane" -> "kessler lane"
          continue;
        }
        Add(m.str(), w1);
      }
    }
    if (names_.empty()) return;
    std::vector<string> alts(names_.begin(), names_.end());
    for (const auto& [alias, name] : aliases_) {
      if (!alias_clash_.count(alias)) alts.push_back(alias);
    }
    std::sort(alts.begin(), alts.end(), [](const string& a, const string& b) { return a.size() > b.size(); });
    string alt;
    for (const auto& a : alts) {
      string e = EscapeRegex(a);
      for (size_t k = 0; (k = e.find(' ', k)) != string::npos; k += 5) e.replace(k, 1, "[- ]");
      alt += (alt.empty() ? "" : "|") + e;
    }
    pattern_ = regex(R"(\b()" + alt + R"()\b)");
  }

  // The named road the clause around `pos` is about: the last name before
  // `pos` that is not a place ("at linden", "with route 202").
  string Subject(const string& t, size_t pos) const {
    if (names_.empty()) return {};
    static const regex kPlaceBefore(R"(\b(?:at|with|onto|to|toward|towards|into|past|near|from|across|crosses|crossing|meets|joins|of|and)\s+$)");
    string found;
    const string head = t.substr(0, std::min(pos, t.size()));
    // "... with route 16, a 4-lane highway posted at 55 mph": a name the
    // value's phrase stands in apposition to is its subject wherever it is.
    static const regex kAppositive(R"(^\s*,\s*(?:a|an)\b[^,;]*$)");
    for (auto it = std::sregex_iterator(head.begin(), head.end(), pattern_); it != std::sregex_iterator(); ++it) {
      const size_t at = static_cast<size_t>(it->position());
      const string before = Before(head, at, 20);
      if (Has(before, kPlaceBefore) && !Has(head.substr(at + static_cast<size_t>(it->length())), kAppositive)) continue;
      found = Resolve((*it)[1].str());
    }
    return found;
  }

  bool Mentioned(const string& t) const { return !names_.empty() && Has(t, pattern_); }

  // The named road right after a value: "25 mph (40 kmh) on birch lane".
  string OnAfter(const string& tail) const {
    if (names_.empty()) return {};
    static const regex kOn(R"(^\s*(?:\(\s*\d{2,3}\s*(?:kmh|mph)\s*\)\s*)?(?:on|for|along)\s+(?:the\s+)?)");
    smatch on, m;
    if (!std::regex_search(tail, on, kOn)) return {};
    const string rest = tail.substr(static_cast<size_t>(on.length(0)));
    if (!std::regex_search(rest, m, pattern_, std::regex_constants::match_continuous)) return {};
    return Resolve(m[1].str());
  }

  // The named road a count's own noun phrase ends in ("2-lane township
  // road", "a 2-lane, 2-way kessler lane"): its words follow the count with
  // no other clause between.
  string Modified(const string& after) const {
    if (names_.empty()) return {};
    smatch m;
    const string head = after.substr(0, 40);
    if (!std::regex_search(head, m, pattern_)) return {};
    static const regex kClauseBreak(R"(\b(?:and|or|with|of|at|on|to|from|near|that|which|where)\b|[;:(])");
    if (Has(head.substr(0, static_cast<size_t>(m.position())), kClauseBreak)) return {};
    return Resolve(m[1].str());
  }

  // The named road a vehicle's text puts it on ("was westbound on route 9").
  string TravelledOn(const string& t) const {
    if (names_.empty()) return {};
    const string head = BeforeTheTurn(t);
    static const regex kOnBefore(R"(\b(?:on|along|down|up)\s+(?:the\s+)?$)");
    for (auto it = std::sregex_iterator(head.begin(), head.end(), pattern_); it != std::sregex_iterator(); ++it) {
      const size_t at = static_cast<size_t>(it->position());
      if (Has(Before(head, at, 15), kOnBefore)) return Resolve((*it)[1].str());
    }
    return {};
  }

 private:
  static string Canonical(string n) {
    std::replace(n.begin(), n.end(), '-', ' ');
    return n;
  }
  void Add(const string& name, const string& alias) {
    names_.insert(name);
    if (alias.empty()) return;
    auto [it, inserted] = aliases_.emplace(alias, name);
    if (!inserted && it->second != name) alias_clash_.insert(alias);
  }
  string Resolve(const string& mention) const {
    const string c = Canonical(mention);
    if (names_.count(c)) return c;
    const auto it = aliases_.find(mention);
    return it == aliases_.end() ? c : it->second;
  }
  std::set<string> names_;
  std::map<string, string> aliases_;
  std::set<string> alias_clash_;
  regex pattern_;
};

// The road a count in a clause is said of as its subject ("the residential
// street was a 2-lane road"); not one the count merely follows ("the
// boulevard met a 2-lane street").
string SubjectRoad(const string& s, size_t pos) {
  size_t end = 0;
  const string road = ClauseRoad(s, pos, &end);
  if (road.empty()) return road;
  const string between = s.substr(end, pos - end);
  // "the side street, a residential road, had ...", "the side street
  // approached from the south, had ...".
  static const regex kPredicate(
      R"(^\s*(?:,[^,]*,\s*|\s+[a-z]+ed\b[^,;]{0,30},\s*)?(?:is|was|has|had|carries|carried|consists of|consisted of)\b)");
  static const regex kAnotherRoad(R"(\b)" + RoadNoun() + R"(\b)");
  return Has(between, kPredicate) && !Has(between, kAnotherRoad) ? road : string();
}

// The road a vehicle's text puts it on ("was westbound on the side street").
string RoadTravelledOn(const string& full) {
  const string t = BeforeTheTurn(full);
  // "in the right lane (lane one) of the highway".
  static const regex kOn(R"(\b(?:on|along|down|up|from|onto|lanes?(?:\s*\([^)]*\))? of)\s+(?:the|a|an)\s+(?:[\w/-]+,?\s+){0,3}?)" + RoadNoun() + R"(\b)");
  smatch m;
  return std::regex_search(t, m, kOn) ? m[1].str() : string();
}

// V1's road as the report names it, and what places a road statement: the
// lane and limit rules share it.
struct RoadContext {
  explicit RoadContext(const Reading& rd);

  // A clause split off at ';' or a sentence about "it" ("the north/south
  // roadway was a 2-lane street ...; it had a stop sign and a posted speed
  // limit of 40 kmh") is about the road the sentence before began with.
  std::optional<int> InheritedAxis(size_t i, std::optional<int> axis) const;
  // The named road a clause is about; a sentence naming none and no
  // vehicle ("route 9 is divided ...; the limit was 50") is about the road
  // the sentence before began with.
  string NamedAt(size_t i, size_t pos) const;

  const std::vector<Sentence>& sentences;
  // V1's axis: 0 east-west, 1 north-south, -1 unknown (an int, not an
  // optional: GCC 12 warns falsely on the latter).
  int v1_axis = -1;
  RoadNames names;  // the roads the report names
  // The road V1 is said to be on by its kind ("v1 was westbound on the
  // side street", "on a residential street"; "the road", "the street"
  // name no road in particular) and by name ("on route 9").
  string v1_road, v1_named_road;
  bool distinctive = false;  // v1_road names a kind of road
  bool v1_on_ramp = false;   // V1 was on a ramp ("exiting the ramp", "in the ramp's left-turn lane")
};

std::vector<string> SceneTexts(const std::vector<Sentence>& sentences) {
  std::vector<string> texts;
  for (const Sentence& s : sentences) {
    if (s.kind == Kind::kNarrative || s.kind == Kind::kStatement) texts.push_back(s.text);
  }
  return texts;
}

RoadContext::RoadContext(const Reading& rd) : sentences(rd.sentences), names(SceneTexts(rd.sentences)) {
  const AccidentRecord& r = rd.r;
  const VehicleRecord* v1 = r.vehicles.empty() ? nullptr : &r.vehicles.front();
  v1_axis = v1 && v1->travel.known() && v1->travel.value ? AxisOf(*v1->travel.value) : -1;
  for (const Segment& seg : rd.segments) {
    if (seg.vehicle != 1 || seg.perceived || sentences[seg.sentence].kind != Kind::kNarrative) continue;
    if (v1_road.empty()) v1_road = RoadTravelledOn(seg.text);
    // "v1 (...) and v2 were both westbound on route 9": the coordinated
    // subject's predicate is the sentence's.
    static const regex kCoordinatedEnd(R"(\band\s*$)");
    const string& said = Has(seg.text, kCoordinatedEnd) ? sentences[seg.sentence].text : seg.text;
    if (v1_named_road.empty()) v1_named_road = names.TravelledOn(said);
    if (!v1_road.empty() && !v1_named_road.empty()) break;
  }
  // V1 on a ramp the report counts the lanes of ("entering the freeway
  // from the ramp").
  // (Also "in the left-turn lane of the ramp".)
  static const regex kOnRamp(
      R"(\b(?:on|from|along|down|up|entering|exiting|via|lanes?\s+of)\s+(?:the|a|an)\s+(?:[\w-]+\s+){0,2}?ramp\b|)"
      // ("stopped in the ramp's left-turn lane".)
      R"(\b(?:in|on)\s+the\s+ramp'?s\s+(?:[\w-]+\s+){0,2}?lane\b)");
  for (const Segment& seg : rd.segments) {
    if (seg.vehicle == 1 && !seg.perceived && sentences[seg.sentence].kind != Kind::kCoding && Has(seg.text, kOnRamp)) {
      v1_on_ramp = true;
    }
  }
  // V1 stopped at a stop sign on a road the report does not name for it:
  // the one road the report says a stop sign controls ("the residential
  // street ... was controlled by a stop sign").
  if (v1_road.empty() && v1_named_road.empty()) {
    static const regex kAtTheSign(R"(\b(?:stopped|stop|waiting|sat|paused)\b[^.;]{0,25}?\bstop sign\b)");
    const bool v1_at_sign = std::any_of(rd.segments.begin(), rd.segments.end(),
                                        [&](const Segment& seg) { return rd.V1BeforeImpact(seg) && Has(seg.text, kAtTheSign); });
    static const regex kSignControls(
        R"(\b(?:controlled by|had|has|with|faced)\s+(?:a\s+)?(?:posted\s+|single\s+|standard\s+)?stop signs?\b|\bstop[- ]sign[- ]controlled\b)");
    std::set<string> signed_roads;
    for (const Sentence& s : sentences) {
      if (!v1_at_sign || s.kind != Kind::kNarrative || !s.refs.empty()) continue;
      for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kSignControls); it != std::sregex_iterator(); ++it) {
        const string road = ClauseRoad(s.text, static_cast<size_t>(it->position()));
        if (!road.empty()) signed_roads.insert(road);
      }
      // ... or names it after the sign: "stop sign for the side road".
      static const regex kSignFor(R"(\bstop signs?\s+(?:for|on|at|controlling|governing)\s+(?:the|a|an)\s+(?:[\w/-]+\s+){0,3}?)" +
                                  RoadNoun() + R"(\b)");
      smatch sf;
      if (std::regex_search(s.text, sf, kSignFor)) signed_roads.insert(sf[1].str());
    }
    if (signed_roads.size() == 1) v1_road = *signed_roads.begin();
  }
  // V1's road ends at the other ("southbound on a residential street that
  // ends in a t-intersection with the arterial"): it is the side road the
  // report gives the limit and lanes of ("the side street, 25 mph").
  if (!v1_road.empty() && v1_road.find("side ") == string::npos) {
    static const regex kEndsAtOther(
        R"(\b(?:that|which)\s+(?:ends|ended|terminates|terminated|tees|teed|dead-ends)\s+(?:in|at|into)\s+(?:a|an|the)\s+(?:t-?|3-leg\s+|three-leg\s+)?(?:intersection|junction)\b)");
    static const regex kSideRoad(R"(\bthe\s+(side\s+(?:street|road))\b)");
    bool ends = false;
    for (const Segment& seg : rd.segments) {
      if (seg.vehicle == 1 && !seg.perceived && sentences[seg.sentence].kind == Kind::kNarrative &&
          seg.text.find(v1_road) != string::npos && Has(seg.text, kEndsAtOther)) {
        ends = true;
        break;
      }
    }
    smatch sm;
    for (size_t i = 0; ends && i < sentences.size(); ++i) {
      if (sentences[i].kind == Kind::kNarrative && std::regex_search(sentences[i].text, sm, kSideRoad)) {
        v1_road = sm[1].str();
        break;
      }
    }
  }
  distinctive = !v1_road.empty() && !GenericRoad(v1_road);
}

std::optional<int> RoadContext::InheritedAxis(size_t i, std::optional<int> axis) const {
  static const regex kAnaphoric(R"(^\s*(?:it|its|it's|this (?:road|roadway|street)|that (?:road|roadway|street))\b)");
  if (axis || i == 0 || !Has(sentences[i].text, kAnaphoric)) return axis;
  return AxisIn(sentences[i - 1].text.substr(0, 40));
}

string RoadContext::NamedAt(size_t i, size_t pos) const {
  string n = names.Subject(sentences[i].text, pos);
  if (n.empty() && i > 0 && sentences[i].refs.empty() && !names.Mentioned(sentences[i].text)) {
    n = names.Subject(sentences[i - 1].text, 40);
    // "... where county road 12 crosses us highway 41. the highway ran
    // north/south ...": a sentence opening on another kind of road is
    // not about the name before.
    static const regex kOpensOnRoad(R"(^\s*the\s+(road|roadway|street|highway|avenue|boulevard|route|freeway|interstate)\b)");
    smatch om;
    if (!n.empty() && std::regex_search(sentences[i].text, om, kOpensOnRoad) && n.find(om[1].str()) == string::npos &&
        om[1].str() != "roadway") {
      n.clear();
    }
  }
  return n;
}

// Which vehicle's segment a position in a sentence belongs to.
// A coordinated subject ("v1 and v2 were both traveling northbound on a
// 3-lane oneway roadway") is V1's when it names V1.
int OwnerAt(const Sentence& s, size_t pos) {
  int owner = 0;
  size_t last_end = 0;
  static const regex kAnd(R"(^\s*(?:,\s*)?and\s*$)");
  for (const Ref& ref : s.refs) {
    if (ref.pos > pos) break;
    const bool coordinated =
        owner > 0 && ref.pos >= last_end && Has(s.text.substr(last_end, ref.pos - last_end), kAnd);
    owner = coordinated ? std::min(owner, ref.vehicle) : ref.vehicle;
    last_end = ref.pos + 2;  // "v1"
  }
  return owner;
}

void ReadRoadKind(Reading& rd) {
  AccidentRecord& r = rd.r;
  const std::vector<Sentence>& sentences = rd.sentences;
  string& scene = rd.scene;
  for (const Sentence& s : sentences) {
    if (s.kind == Kind::kNarrative || s.kind == Kind::kStatement) scene += s.text;
  }
  scene = WithoutDistantJunctions(scene);
  static const regex kTJunction(
      R"(\bt[- ]?(?:intersection|junction)|\b3[- ]leg|\btee\b|\btee[sd]?\s+into\b|\bt-shaped|\bthree[- ]leg|\bt-type intersection|)"
      // "a county road that ends at a t with a state route".
      R"(\b(?:at|forms?|forming|makes?|making|ends?\s+in|ending\s+in|ended\s+in)\s+(?:a|the)\s+t\b(?![-'])|\bstem of the t\b)");
  static const regex kIntersection(
      R"(\bintersection\b|(?:^|[^a-z-])junction\b|\b4[- ](?:leg|way)\b|\bcrossroads?\b|\bside (?:road|street)|\bcross (?:road|street)|)" +
      WhereRoadsMeet());
  static const regex kCurve(R"(\bcurv(?:e|ed|ing)\b)");
  if (Has(scene, kTJunction)) r.road.kind.Set(RoadKind::kTJunction, Provenance::kStated);
  else if (Has(scene, kIntersection)) r.road.kind.Set(RoadKind::kIntersection, Provenance::kStated);
  else if (Has(scene, RampWord())) r.road.kind.Set(RoadKind::kRamp, Provenance::kStated);
  else if (Has(scene, DrivewayWord())) r.road.kind.Set(RoadKind::kDriveway, Provenance::kStated);
  else if (Has(scene, kCurve)) r.road.kind.Set(RoadKind::kCurve, Provenance::kStated);
}

bool AtJunction(const AccidentRecord& r) {
  return r.road.kind.value == RoadKind::kIntersection || r.road.kind.value == RoadKind::kTJunction;
}

const regex& OneWayWord() {
  static const regex kOneWay(R"(\boneway\b)");
  return kOneWay;
}

const regex& TwoWayWord() {
  static const regex kTwoWay(R"(\b2[- ]way\b)");
  return kTwoWay;
}

// The road nouns that carry an axis in LaneStatements and limits.
const string& AxisRoadNoun() {
  static const string kRoadNoun =
      R"((?:county |state |rural |city |residential |through |collector |main |frontage )?(?:road|roadway|street|highway|avenue|boulevard|route|drive|lane))";
  return kRoadNoun;
}

// Roads named with their axis ("a north/south rural highway and an
// east/west county road") give it to later sentences about them ("the
// county road is a 2-lane road", "the highway is posted at 45 mph").
std::map<string, int> AxesOfNamedRoads(const std::vector<Sentence>& sentences) {
  static const regex kNamedAxis(
      R"(\b(north|south|east|west)(?:/|-|\s+and\s+)(?:north|south|east|west)\s+(?:[\w-]+\s+){0,2}?)" + AxisRoadNoun() + R"(\b)");
  static const regex kTail(AxisRoadNoun() + "$");
  std::map<string, int> axis_of_road;
  for (const Sentence& s : sentences) {
    for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kNamedAxis); it != std::sregex_iterator(); ++it) {
      const string w = (*it)[1].str(), named = it->str();
      smatch nm;
      if (std::regex_search(named, nm, kTail)) axis_of_road[nm.str()] = (w == "east" || w == "west") ? 0 : 1;
    }
  }
  return axis_of_road;
}

// Every statement of a road's lane count ("a 4-lane divided highway", "2
// lanes in each direction", "3 northbound lanes"), in the order told, with
// what places it: the vehicle whose segment states it, the road's axis and
// name, one-way, cross street or ramp.
std::vector<RoadStatement> LaneStatements(const Reading& rd, const RoadContext& ctx) {
  const std::vector<Sentence>& sentences = rd.sentences;
  const string& scene = rd.scene;
  // "2 through lanes plus a left-turn bay in each direction": 3 each way.
  static const regex kPerDir(
      R"(\b(\d)[- ](?:through\s+|travel\s+|moving\s+)?lanes?\s+(?:of\s+(?:traffic|travel)\s+)?(?:(plus|and)\s+(?:a|an|one|1)\s+(?:single\s+|exclusive\s+|separate\s+|dedicated\s+)?(?:left|right)[- ]turn\s+(?:bay|lane)\s+)?(?:in\s+|for\s+|going\s+in\s+)?(?:each|either|both|per|every)\s+(?:the\s+\w+\s+and\s+\w+\s+)?(?:directions?|ways?\b))");
  // "each direction of route 30 has 2 through lanes plus a left-turn bay",
  // "the northbound and southbound roadways each have 2 3.7 m lanes",
  // "a grass median and, in each direction, 2 through lanes and a left-turn lane".
  static const regex kEachHas(
      R"((?:\beach (?:direction|approach|side)\b[^.;]{0,30}?\b(?:has|had)|\b(?:roadways|sides|carriageways|approaches|halves)\s+each\s+(?:has|had|have|carry|carried)|\b(?:in|for)\s+(?:each|either|both)\s+directions?\s*,)\s+(\d)\s+(?:\d+(?:\.\d+)?[- ]?(?:meter|metre|m|foot|ft|feet)[- ](?:wide\s+)?)?(?:through\s+|travel\s+|moving\s+)?lanes?(?:\s+(plus|and)\s+(?:a|an|one|1)\s+(?:single\s+|exclusive\s+|separate\s+|dedicated\s+)?(?:left|right)[- ]turn\s+(?:bay|lane))?)");
  static const regex kDirectional(
      R"(\b(\d)\s+(?:north|south|east|west)bound(?:\s+(?:(?:left|right)[- ]turn(?:[- ]only)?\s+|travel\s+|through\s+)?lanes?\b|(?=\s*(?:[,;.)]|and\b|$)))|\b(\d)\s+lanes?\s+(?:head|go|travel)s?\s+(?:north|south|east|west)|\b(\d)\s+(?:travel\s+|through\s+)?lanes?\s+(?:for\s+|going\s+|heading\s+|carrying\s+)?(?:north|south|east|west)bound\b)");
  static const regex kTotal(
      R"(\b(\d)[- ](?:\d+(?:\.\d+)?[- ]?(?:meter|metre|m|foot|ft|feet)[- ](?:wide\s+)?)?(?:travel\s+|through\s+|traffic\s+)?lanes?\b(?!\s+(?:of\s+(?:traffic|travel)\s+)?(?:lines?|markings?|in each|in both|for each|per|each way|either way|each direction|either direction|both directions|(?:head|go|travel)s?\s+(?:north|south|east|west)|(?:for\s+|going\s+|heading\s+|carrying\s+)?(?:north|south|east|west)bound)))");
  static const regex kSubjectRoad(R"(^(?:the\s+)?)" + AxisRoadNoun() + R"(\b)");
  const std::map<string, int> axis_of_road = AxesOfNamedRoads(sentences);
  std::vector<RoadStatement> roads;
  // A direction the report calls a one-way road ("a northbound one-way
  // roadway"): a count of that direction's lanes is the road's total.
  auto one_way_bound = [&](const std::optional<Compass>& bound) {
    static const std::map<Compass, regex> kOneWayBound = [] {
      std::map<Compass, regex> m;
      for (Compass c : {Compass::kEast, Compass::kNorth, Compass::kWest, Compass::kSouth}) {
        const string dir(ToString(c));
        m.emplace(c, regex(R"(\b)" + dir + R"(bound\s+oneway\b|\boneway\s+(?:[\w-]+\s+)?)" + dir + R"(bound\b)"));
      }
      return m;
    }();
    return bound && Has(scene, kOneWayBound.at(*bound));
  };
  for (size_t i = 0; i < sentences.size(); ++i) {
    const Sentence& s = sentences[i];
    if (s.kind != Kind::kNarrative && s.kind != Kind::kStatement) continue;
    auto add = [&](const smatch& m, size_t pos, int total, int per_dir, int directional) {
      // The count may sit inside its match ("widened from 2 lanes to 3":
      // pos is the "3"); what follows it runs to the match's end at most.
      pos = std::min(pos, s.text.size());
      const size_t match_end = static_cast<size_t>(m.position(0) + m.length(0));
      const size_t len = std::min(s.text.size(), std::max(match_end, pos)) - pos;
      RoadStatement rs;
      rs.sentence = i;
      rs.pos = pos;
      rs.owner = OwnerAt(s, pos);
      // The road V1's meets is not V1's: "v1 was eastbound on a residential
      // street and stopped where the street meets a busy 4-lane roadway".
      static const regex kMetRoad(
          R"(\b(?:meets?|meeting|intersects?|intersecting|crosses|joins|ends at|ending at|tees into)\s+(?:a|an|the)\s+(?:[\w-]+\s+){0,2}$)");
      if (rs.owner > 0 && Has(Before(s.text, pos, 40), kMetRoad)) rs.owner = 0;
      static const regex kMetAtJunction(
          R"(\b(?:meets?|meeting|intersects?|intersecting|joins|ends at|ending at|tees into|terminates at)\s+(?:a|an|the)\s+(?:[\w-]+\s+){0,2}?(?:t-|y-)?(?:intersection|junction)\s+with\s+(?:a|an|the)\s+(?:[\w-]+\s+){0,2}$)");
      rs.met = Has(Before(s.text, pos, 40), kMetRoad) || Has(Before(s.text, pos, 70), kMetAtJunction);

      const size_t from = pos > 60 ? pos - 60 : 0;
      const string around = s.text.substr(from, pos - from + len + 40);
      // The road's axis: named up to the count ("an east-west roadway with
      // two lanes each way"), else after it ("a 4-lane road running
      // north-south"); the next road's ("..., and a northbound one-way")
      // is not this one's.
      const size_t start = RoadPhraseStart(s.text, pos);
      rs.axis = AxisIn(s.text.substr(start, pos - start + len));
      // "..., and mill street, a 2-lane north/south residential street":
      // the count's own noun phrase before the wider window.
      if (!rs.axis) {
        static const regex kOwnPhraseAxis(R"(^[^,;.]{0,12}?\b((?:north|south|east|west)(?:/|-|\s+and\s+)(?:north|south|east|west))\b)");
        smatch am;
        const string own = s.text.substr(pos + len, 30);
        if (std::regex_search(own, am, kOwnPhraseAxis)) rs.axis = AxisIn(am[1].str());
      }
      // (Not the met road's: "on the northbound approach of a street where
      // it ends at a T-intersection with a 4-lane arterial".)
      if (!rs.axis && !rs.met) rs.axis = AxisIn(around);
      // ... or where the clause's verb brings it in: "a 2-lane street
      // posted at 40 kmh (25 mph) enters from the south" (the text is in
      // the past tense by now: "came in from the south").
      if (!rs.axis && !rs.met) {
        static const regex kEntersFrom(
            R"(^(?:(?!\band\s+(?:a|an|the)\b)[^;]){0,70}?\b(?:enter\w*|(?:com(?:es|ing)|came)\s+in|join\w*|branch\w*|tee[sd]?\s+in)\s+from\s+the\s+(?:north|south|east|west)\b)");
        smatch em;
        const string rest = s.text.substr(pos + len);
        if (std::regex_search(rest, em, kEntersFrom)) rs.axis = AxisIn(em.str());
      }
      if (!rs.met) rs.axis = ctx.InheritedAxis(i, rs.axis);
      smatch sm;
      if (!rs.axis && std::regex_search(s.text, sm, kSubjectRoad) && axis_of_road.count(sm.str().substr(sm.str().rfind("the ", 0) == 0 ? 4 : 0))) {
        rs.axis = axis_of_road.at(sm.str().substr(sm.str().rfind("the ", 0) == 0 ? 4 : 0));
      }
      // One-way belongs to this road only when no other road phrase
      // (", and a ...") sits between the count and the word.
      // "a oneway westbound roadway with 3 travel lanes": back to the
      // start of this road's phrase.
      string near_before = Before(s.text, pos, 40);
      const size_t other_road = near_before.rfind(" and ");
      if (other_road != string::npos) near_before = near_before.substr(other_road);
      string near_after = s.text.substr(pos + len, 15);
      // ... but "a 1-lane, oneway roadway" lists adjectives of one road.
      const size_t comma = near_after.rfind(", oneway", 0) == 0 || near_after.rfind(",oneway", 0) == 0
                               ? string::npos
                               : near_after.find(',');
      const size_t stop = std::min(comma, near_after.find(" and "));
      if (stop != string::npos) near_after = near_after.substr(0, stop);
      rs.one_way = Has(near_before, OneWayWord()) || Has(near_after, OneWayWord());
      static const regex kCrossStreet(
          R"(\b(?:cross|crossing|intersecting|side|minor)\s+(?:street|road|roadway|route)\b|\bcrossroad\b|\bthe stem\b)");
      rs.cross = Has(around, kCrossStreet);
      // ... or the sentence before named it: "the intersecting street
      // comes in from the south; it has 1 lane in each direction".
      static const regex kItSubject(R"(^(?:it|this street|this road|that street|that road)\s+(?:has|had|is|was|carries|carried)\b)");
      static const regex kCrossSubject(R"(^(?:the\s+)?(?:cross|crossing|intersecting|side|minor)\s+(?:street|road|roadway|route)\b)");
      if (!rs.cross && !rs.met && i > 0 && Has(s.text, kItSubject) && Has(sentences[i - 1].text, kCrossSubject)) rs.cross = true;
      static const regex kRampAfter(R"(^[\w ,-]{0,30}?\bramp\b)");
      // ... or the sentence is about the ramp: "the ramp was a 1-way roadway
      // that widened from 1 lane to 2 lanes near its end".
      static const regex kRampSubject(
          R"(^(?:(?:at|near|approaching|toward|towards)\s+(?:the|its)\s+(?:[\w-]+\s+){0,2}?)?(?:the|this|that)\s+(?:[\w/-]+\s+){0,3}?ramp\s+(?:was|is|had|has|widened|widens|carried|carries)\b[^;]*$)");
      rs.ramp = Has(s.text.substr(pos + len, 40), kRampAfter) ||
                Has(s.text.substr(0, pos), kRampSubject);
      // The phrase runs on to the next road named ("1 lane in each direction
      // and an east/west 2-way roadway with ... a center left turn lane":
      // the centre lane is the other road's).
      static const regex kCentreLane(
          R"(\b(?:center|centre|continuous|middle)\s+(?:2[- ]way\s+)?(?:left[- ]turn\s+)?lane\b|\b2[- ]way left[- ]turn lane\b)");
      string phrase_after = s.text.substr(pos + len);
      smatch rw;
      if (std::regex_search(phrase_after, rw, RoadWord())) {
        const size_t at = static_cast<size_t>(rw.position());
        const string noun = rw[1].str();
        phrase_after = phrase_after.substr(0, at);
        static const regex kPhraseBreak(R"(\b(?:and|or|with|of|in|on|at|to|for|from|each|per)\b|[;:(])");
        if (at <= 30 && !Has(phrase_after, kPhraseBreak)) rs.counted = noun;
      }
      rs.centre = Has(s.text.substr(start, pos - start) + " " + phrase_after, kCentreLane);
      rs.name = ctx.names.Modified(s.text.substr(pos));
      if (rs.name.empty()) rs.name = ctx.NamedAt(i, pos);
      rs.road = SubjectRoad(s.text, pos);
      rs.total = total;
      rs.per_direction = per_dir;
      rs.directional = directional;
      roads.push_back(rs);
    };
    // The junction's count replaces the totals told before it in the sentence.
    auto replace_totals_before = [&](size_t at) {
      const int owner = OwnerAt(s, at);
      roads.erase(std::remove_if(roads.begin(), roads.end(),
                                 [&](const RoadStatement& o) {
                                   return o.sentence == i && o.pos < at && o.owner == owner && o.total &&
                                          !o.per_direction && !o.directional;
                                 }),
                  roads.end());
    };
    // (A count inside a per-direction phrase is not also a total.)
    std::vector<std::pair<size_t, size_t>> per_spans;
    for (const regex* per_re : {&kPerDir, &kEachHas}) {
      for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), *per_re); it != std::sregex_iterator(); ++it) {
        add(*it, static_cast<size_t>(it->position()), 0, std::stoi((*it)[1].str()) + ((*it)[2].matched ? 1 : 0), 0);
        per_spans.emplace_back(static_cast<size_t>(it->position()), static_cast<size_t>(it->position() + it->length()));
      }
    }
    for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kDirectional); it != std::sregex_iterator();
         ++it) {
      const auto& m = *it;
      // "crossed the 2 eastbound lanes" is not a road's count.
      static const regex kCrossedBefore(R"(\b(?:crossing|crossed|crosses|across|over)\s+(?:the\s+|both\s+)?$)");
      if (Has(Before(s.text, static_cast<size_t>(m.position()), 15), kCrossedBefore)) continue;
      const int n = std::stoi(m[1].matched ? m[1].str() : m[2].matched ? m[2].str() : m[3].str());
      const std::optional<Compass> bound = DirectionIn(m.str());
      if (one_way_bound(bound)) {
        add(m, static_cast<size_t>(m.position()), n, 0, 0);  // "the avenue had 3 southbound lanes", one-way
        roads.back().one_way = true;
        continue;
      }
      add(m, static_cast<size_t>(m.position()), 0, 0, n);
      roads.back().bound = bound;
    }
    for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kTotal); it != std::sregex_iterator(); ++it) {
      const size_t at = static_cast<size_t>(it->position());
      // (Nor is its breakdown: "each approach had 3 lanes at the
      // intersection: 2 through lanes and a left-turn bay".)
      auto in_per_phrase = [&](const std::pair<size_t, size_t>& sp) {
        if (at >= sp.first && at < sp.second) return true;
        if (at < sp.second || at - sp.second > 40) return false;
        const string between = s.text.substr(sp.second, at - sp.second);
        return between.find_first_of(":(") != string::npos && between.find_first_of(".;") == string::npos;
      };
      if (std::any_of(per_spans.begin(), per_spans.end(), in_per_phrase)) continue;
      // "lane 2" / "the 2 lanes to the left" are not road descriptions; "2-lane", "2 lane road" are.
      const string after = it->suffix().str().substr(0, 40);
      const string before = s.text.substr(0, static_cast<size_t>(it->position()));
      static const regex kNotARoadAfter(R"(^\s*(?:to the|of the|lines?))");
      if (Has(after, kNotARoadAfter)) continue;
      // ("in the other 2 lanes": lanes, not the road's count.)
      static const regex kNotARoadBefore(R"(\b(?:crossing|across|all|over|other|remaining)\s+(?:the\s+)?$)");
      if (Has(before.substr(before.size() > 12 ? before.size() - 12 : 0), kNotARoadBefore)) continue;
      // Nor what the road was elsewhere: "200 meters west the road had been
      // a 4-lane section", "widened from 1 lane to 2 lanes".
      static const regex kNotHere(R"(\bhad been\s+(?:a|an)\s+$|\b(?:widen\w*|expand\w*|increas\w*|narrow\w*)\s+from\s+$)");
      if (Has(Before(s.text, static_cast<size_t>(it->position()), 25), kNotHere)) continue;
      // "the eastbound roadway had 3 travel lanes", "the southbound side
      // widened to 3 lanes", "southbound there were 3 lanes", "the
      // eastbound lanes, 2 lanes wide": one direction's count, with its turn bay
      // ("2 through lanes and a left-turn bay").
      static const regex kDirectionSubject(
          R"(\b(?:north|south|east|west)bound\s+(?:roadway|road|street|highway|lanes|side|carriageway|half|direction|approach|traffic)\s+(?:of\s+the\s+(?:[\w-]+\s+){0,2}?(?:roadway|road|street|highway|avenue|boulevard|arterial)\s+)?(?:\w+\s+|(?:at|in|near)\s+(?:this|that|the)\s+(?:\w+\s+)?(?:point|location|area|site|place|section)\s+)?(?:had|has|have|consisted of|consists of|carried|carries|widened to|widens to|narrowed to|narrows to|expanded to|expands to|was|is|were|are)\s+(?:only\s+|just\s+)?(?:(?:a|an|1)\s+(?:left|right)[- ]turn\s+(?:lane|bay)\s+(?:and|plus)\s+|(?:a|an|1)\s+(?:left|right)[- ]turn\s+(?:lane|bay)\b[^.;]{0,50}?\bin addition to\s+(?:its|the)\s+)?$|\b(?:north|south|east|west)bound\s*,?\s+there\s+(?:were|was)\s+(?:only\s+|just\s+)?$|\b(?:north|south|east|west)bound\s+(?:lanes|roadway|side|carriageway)\s*[,:]\s*$)");
      // ("2 through lanes and 2 left-turn lanes at the intersection": 4.)
      static const regex kBayAfter(
          R"(^\s+(?:through\s+|travel\s+)?lanes?\s*,?\s+(?:and|plus)\s+(a|an|\d)\s+(?:(?!and\b)[\w-]+\s+){0,2}?(?:left|right)[- ]turn\s+(?:bays?|lanes?)\b|^\s+(?:and|plus)\s+(a|an|\d)\s+(?:(?!and\b)[\w-]+\s+){0,2}?(?:left|right)[- ]turn\s+(?:bays?|lanes?)\b)");
      const int n = std::stoi((*it)[1].str());
      smatch dm;
      const string near_before = before.substr(before.size() > 120 ? before.size() - 120 : 0);
      if (std::regex_search(near_before, dm, kDirectionSubject)) {
        // ... unless that direction's road is one-way ("a northbound
        // one-way roadway and a westbound one-way roadway. the northbound
        // roadway had 3 travel lanes"): then it is the road's total.
        const string subject = dm.str();
        const std::optional<Compass> bound = DirectionIn(subject);
        if (one_way_bound(bound)) {
          add(*it, static_cast<size_t>(it->position()), n, 0, 0);
          roads.back().one_way = true;
        } else {
          // ... and a turn lane told before the count ("the southbound
          // approach had a left-turn lane and 2 through lanes").
          // ... or after ("had a left-turn lane ... in addition to its 2
          // through lanes").
          static const regex kBayBefore(
              R"(\bturn\s+(?:lane|bay)\s+(?:and|plus)\s+$|\bturn\s+(?:lane|bay)\b[^.;]{0,50}?\bin addition to\s+(?:its|the)\s+$)");
          int bays = Has(subject, kBayBefore) ? 1 : 0;
          if (smatch bm; std::regex_search(after, bm, kBayAfter)) {
            const string k = bm[1].matched ? bm[1].str() : bm[2].str();
            bays = std::isdigit(static_cast<unsigned char>(k[0])) ? std::stoi(k) : 1;
          }
          add(*it, static_cast<size_t>(it->position()), 0, 0, n + bays);
          roads.back().bound = bound;
        }
        continue;
      }
      // "a 2-lane roadway that widened to 3 lanes on each approach to the
      // intersection": the junction's count replaces the totals before it.
      static const regex kWidenedTo(
          R"(\b(?:widen\w*|flare\w*|expand\w*|increas\w*)\s+(?:out\s+)?(?:from\s+\d\s+lanes?\s+)?to\s+$)");
      if (Has(Before(s.text, static_cast<size_t>(it->position()), 35), kWidenedTo)) {
        replace_totals_before(static_cast<size_t>(it->position()));
      }
      add(*it, static_cast<size_t>(it->position()), n, 0, 0);
    }
    // ... also with the noun said once: "the highway widened from 2 lanes to 3".
    static const regex kWidenedFromTo(
        R"(\b(?:widen\w*|expand\w*|increas\w*)\s+from\s+\d\s+lanes?\s+to\s+(\d)\b(?!\s*(?:-|\s)\s*(?:through\s+|travel\s+)?lanes?\b))");
    for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kWidenedFromTo); it != std::sregex_iterator();
         ++it) {
      const size_t at = static_cast<size_t>(it->position(1));
      replace_totals_before(at);
      add(*it, at, std::stoi((*it)[1].str()), 0, 0);
    }
    // "1 northbound lane, 1 southbound lane and a northbound left-turn
    // lane": the road's lanes, listed; their sum is its total (after the
    // other statements: a stated total comes first).
    {
      // Also "2 lanes northbound and 1 lane southbound", "3 lanes for
      // northbound traffic and 2 for southbound traffic".
      static const regex kListed(
          R"(\b(\d|a|an)\s+(?:(?:(?:north|south|east|west)bound\s+(?:(?:left|right)[- ]turn(?:[- ]only)?\s+|through\s+|travel\s+)?|(?:center|centre|middle)\s+(?:2[- ]way\s+)?(?:left[- ]turn\s+)?)lanes?\b|(?:(?:travel\s+|through\s+)?lanes?\s+)?(?:for\s+|going\s+|heading\s+|carrying\s+)?(?:north|south|east|west)bound\b(?:\s+traffic\b)?))");
      static const regex kJoin(R"(^\s*(?:,\s*(?:and\s+)?|and\s+))");
      int sum = 0, items = 0;
      size_t first = 0, last_end = 0;
      smatch lm;
      for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kListed); it != std::sregex_iterator(); ++it) {
        const size_t pos = static_cast<size_t>(it->position());
        if (items > 0 && !Has(s.text.substr(last_end, pos - last_end), kJoin)) {
          if (items >= 2) break;
          sum = 0, items = 0;
        }
        if (items == 0) first = pos, lm = *it;
        const string n = (*it)[1].str();
        sum += std::isdigit(static_cast<unsigned char>(n[0])) ? n[0] - '0' : 1;
        ++items;
        last_end = pos + static_cast<size_t>(it->length());
      }
      // "... separated by a continuous center 2-way left turn lane": the
      // centre lane is one more.
      static const regex kCentreAfterList(
          R"(^\s*,?\s*(?:separated|divided)\s+by\s+(?:a|an)\s+(?:continuous\s+|shared\s+|painted\s+)*(?:center|centre|middle)\s+(?:2[- ]way\s+)?(?:left[- ]turn\s+)?lane\b|^\s*,?\s*(?:separated|divided)\s+by\s+(?:a|an)\s+(?:continuous\s+)?2[- ]way\s+left[- ]turn\s+lane\b)");
      if (items >= 2 && Has(s.text.substr(last_end, 80), kCentreAfterList)) ++sum;
      if (items >= 2) add(lm, first, sum, 0, 0);
    }
  }
  // In the order told: "a 2-lane road ... a 4-lane highway (2 lanes
  // eastbound, 2 lanes westbound)" names the 2-lane road first.
  std::stable_sort(roads.begin(), roads.end(), [](const RoadStatement& a, const RoadStatement& b) {
    return a.sentence != b.sentence ? a.sentence < b.sentence : a.pos < b.pos;
  });
  // "3 through lanes in each direction ...; each direction also has a
  // left-turn bay": the bay is one more lane of each direction, as the coded
  // counts include turn lanes. Said within two sentences of the count.
  static const regex kEachBay(
      R"(\b(?:each|every|both)\s+(?:direction|approach|approaches|side|sides|leg)\s+(?:also\s+)?(?:has|had|have|includes?|included|gets?|got)\s+(?:also\s+)?(?:a|an|1)\s+(?:single\s+|dedicated\s+|exclusive\s+|separate\s+)?(?:left|right)[- ]turn(?:[- ]only)?\s+(?:lane|bay|pocket)\b)");
  for (size_t i = 0; i < sentences.size(); ++i) {
    const Sentence& s = sentences[i];
    smatch m;
    if ((s.kind != Kind::kNarrative && s.kind != Kind::kStatement) || !std::regex_search(s.text, m, kEachBay)) continue;
    const size_t at = static_cast<size_t>(m.position());
    for (auto it = roads.rbegin(); it != roads.rend(); ++it) {
      if (it->sentence > i || (it->sentence == i && it->pos > at)) continue;
      if (i - it->sentence > 2) break;
      if (it->per_direction > 0) {
        ++it->per_direction;
        break;
      }
    }
  }
  return roads;
}
// The lane statement taken for V1's road, and whether V1 is said to use a
// one-way (+1) or a two-way (-1) road (0: not said).
struct V1Lanes {
  const RoadStatement* best = nullptr;
  int v1_way = 0;
};

V1Lanes ChooseV1Statement(Reading& rd, const RoadContext& ctx, const std::vector<RoadStatement>& roads) {
  AccidentRecord& r = rd.r;
  const std::vector<Sentence>& sentences = rd.sentences;
  const std::vector<Segment>& segments = rd.segments;
  const string& scene = rd.scene;
  V1Lanes choice;
  // V1's road: stated in V1's own segment, else the road on V1's axis, else
  // the first road not tied to another vehicle (the crash road is
  // described first).
  // The road V1 turns onto ("waiting to turn left onto the collector
  // road") is not the one it was on: a count of that road comes last.
  string v1_onto;
  for (const Segment& seg : segments) {
    static const regex kOnto(R"(\bonto\s+(?:the|a|an)\s+(?:[\w/-]+\s+){0,3}?)" + RoadNoun() + R"(\b)");
    smatch om;
    if (rd.V1BeforeImpact(seg) && std::regex_search(seg.text, om, kOnto)) {
      v1_onto = om[1].str();
      break;
    }
  }
  // Compared by the head noun: "the cross street" V1 turns onto is the
  // "2-lane east-west street".
  auto head = [](const string& road) { return road.substr(road.rfind(' ') == string::npos ? 0 : road.rfind(' ') + 1); };
  auto counts_road_turned_onto = [&](const RoadStatement& rs) {
    return !v1_onto.empty() && !rs.counted.empty() && (rs.counted == v1_onto || head(rs.counted) == head(v1_onto));
  };
  auto pick = [&](auto pred) -> const RoadStatement* {
    for (const auto& rs : roads) {
      if (pred(rs) && !counts_road_turned_onto(rs)) return &rs;
    }
    for (const auto& rs : roads) {
      if (pred(rs)) return &rs;
    }
    return nullptr;
  };
  // Reports of a one-way road crossing a two-way one say which V1 used
  // ("v1 ... was traveling eastbound on the one-way roadway"); when only the
  // other vehicle is placed on the one-way road, V1 used the two-way one.
  static const regex kOnOneWay(R"(\b(?:on|along|from|down|up|in) (?:the|a|an) (?:\w+ ){0,2}?oneway\b)");
  static const regex kOnTwoWay(
      R"(\b(?:on|along|from|down|up|in) (?:the|a|an) (?:\w+ ){0,2}?2[- ]way (?:road|roadway|street|highway|avenue|trafficway)\b)");
  int& v1_way = choice.v1_way;
  for (const Segment& seg : segments) {
    if (seg.perceived || sentences[seg.sentence].kind == Kind::kCoding) continue;
    // The road it turned onto is not the one it was on ("turned left to
    // travel west on the one-way street").
    const string travelled = BeforeTheTurn(seg.text);
    if (seg.vehicle == 1 && Has(travelled, kOnOneWay)) v1_way = 1;
    else if (seg.vehicle == 1 && Has(travelled, kOnTwoWay) && v1_way == 0) v1_way = -1;
  }
  if (v1_way == 0 && Has(scene, TwoWayWord())) {
    for (const Segment& seg : segments) {
      if (seg.vehicle > 1 && !seg.perceived && Has(seg.text, kOnOneWay)) v1_way = -1;
    }
  }
  const RoadStatement*& best = choice.best;
  if (ctx.v1_on_ramp) best = pick([](const RoadStatement& rs) { return rs.ramp && rs.owner <= 1; });
  if (!best && v1_way != 0) best = pick([&](const RoadStatement& rs) { return rs.owner <= 1 && rs.one_way == (v1_way > 0); });
  if (!best && v1_way > 0) {
    // On a one-way road whose lanes the report does not count: one lane.
    r.road.one_way.Set(true, Provenance::kStated);
    r.road.lanes_total.Set(1, Provenance::kInferred);
    r.road.lanes_per_direction.Set(1, Provenance::kInferred);
  }
  // (Not V1's count of the road it turned onto: "the kia was making a right
  // turn from a side street onto a four-lane arterial".)
  if (!best && v1_way <= 0) {
    best = pick([&](const RoadStatement& rs) { return rs.owner == 1 && !counts_road_turned_onto(rs); });
  }
  if (!best && v1_way <= 0 && !ctx.v1_named_road.empty()) {
    // (Not one counted across V1's course: that sentence named two roads.)
    best = pick([&](const RoadStatement& rs) {
      return rs.owner <= 1 && rs.name == ctx.v1_named_road && !(rs.axis && ctx.v1_axis >= 0 && *rs.axis != ctx.v1_axis);
    });
  }
  if (!best && v1_way <= 0 && ctx.distinctive) {
    best = pick([&](const RoadStatement& rs) { return rs.owner <= 1 && SameRoad(rs.road, ctx.v1_road); });
  }
  // "... between a four-lane divided highway and a two lane county road.
  // v1 was westbound on the county road": the count its own noun phrase
  // names.
  if (!best && v1_way <= 0 && ctx.distinctive) {
    best = pick([&](const RoadStatement& rs) { return rs.owner <= 1 && rs.road.empty() && rs.counted == ctx.v1_road; });
  }
  if (!best && v1_way <= 0 && ctx.v1_axis >= 0) {
    best = pick([&](const RoadStatement& rs) { return rs.owner <= 1 && rs.axis && *rs.axis == ctx.v1_axis; });
  }
  // (The road the crash road meets is not the crash road: "on the
  // approach of a residential street where it ends at a T-intersection with
  // a 4-lane arterial".)
  if (!best && v1_way <= 0) best = pick([](const RoadStatement& rs) { return rs.owner <= 1 && !rs.met; });
  if (!best && v1_way <= 0) best = pick([](const RoadStatement& rs) { return rs.owner <= 1; });
  // Every count told in another vehicle's sentence ("v2 ... was northbound
  // on a 2-lane residential street and stopped ... at an intersection with
  // a 4-lane undivided avenue"; "v1 ... was eastbound in the curb lane of
  // the avenue"): the one that names V1's road.
  bool named_v1s = false;  // (then the axis the count was told on is the other vehicle's, not the road's)
  if (!best && v1_way <= 0 && ctx.distinctive) {
    best = pick([&](const RoadStatement& rs) { return SameRoad(rs.road, ctx.v1_road) || rs.counted == ctx.v1_road; });
    named_v1s = best != nullptr;
  }
  if (!best && v1_way <= 0 && !roads.empty()) best = &roads.front();
  // V1 travelling across the axis of the road described as the through
  // road came from the cross street, when the report describes one.
  if (best && !best->cross && ctx.v1_axis >= 0) {
    const RoadStatement* through = pick([](const RoadStatement& rs) { return !rs.cross && rs.axis.has_value(); });
    const RoadStatement* cross = pick([&](const RoadStatement& rs) {
      return rs.cross && rs.owner <= 1 && (!rs.axis || *rs.axis == ctx.v1_axis);
    });
    if (through && cross && *through->axis != ctx.v1_axis && (!best->axis || *best->axis != ctx.v1_axis)) best = cross;
  }
  // At a junction, V1 travelling across every road the report counts
  // lanes of was on one it does not describe: an ordinary two-lane,
  // two-way road.
  const bool junction = AtJunction(r);
  if (best && junction && ctx.v1_axis >= 0 && best->owner != 1 && !named_v1s &&
      std::all_of(roads.begin(), roads.end(), [&](const RoadStatement& rs) {
        return rs.axis && *rs.axis != ctx.v1_axis && !rs.cross && rs.owner != 1;
      })) {
    r.road.lanes_total.Set(2, Provenance::kInferred);
    r.road.lanes_per_direction.Set(1, Provenance::kInferred);
    best = nullptr;
  }
  // ACCSIM_DEBUG_ROADS=1 lists every lane statement on stderr and marks
  // the one taken for V1's road.
  if (std::getenv("ACCSIM_DEBUG_ROADS")) {
    for (const auto& rs : roads) std::fprintf(stderr, "[road s%zu owner%d axis%d total%d per%d dir%d ow%d cross%d ramp%d road '%s' counted '%s' name '%s']%s\n", rs.sentence, rs.owner, rs.axis ? *rs.axis : -1, rs.total, rs.per_direction, rs.directional, rs.one_way, rs.cross, rs.ramp, rs.road.c_str(), rs.counted.c_str(), rs.name.c_str(), &rs == best ? " <- best" : "");
    std::fprintf(stderr, "[v1 turns onto: %s]\n", v1_onto.c_str());
  }
  return choice;
}

// V1's road's lanes from the statement chosen and those about the same road.
void CountLanes(Reading& rd, const RoadContext& ctx, const std::vector<RoadStatement>& roads, const V1Lanes& choice) {
  AccidentRecord& r = rd.r;
  const std::vector<Sentence>& sentences = rd.sentences;
  const string& scene = rd.scene;
  const bool junction = AtJunction(r);
  const RoadStatement* best = choice.best;
  const int v1_way = choice.v1_way;
  if (best) {
    // Combine statements about the same road (a total in one sentence, the
    // split per direction in the next).
    int total = best->total, per = best->per_direction, directional = best->directional;
    const RoadStatement* per_told = best;  // the statement `per` comes from
    // A count of V1's own direction ("giving 3 westbound lanes", V1
    // westbound) is its lanes, before one of the other direction's or an
    // each-way count.
    const int v1_dir = r.vehicles.empty() || !r.vehicles[0].travel.value ? -1 : static_cast<int>(*r.vehicles[0].travel.value);
    auto of_v1s_direction = [&](const RoadStatement& rs) { return rs.bound && static_cast<int>(*rs.bound) == v1_dir; };
    bool v1s_direction = directional && of_v1s_direction(*best);
    bool one_way = best->one_way || best->ramp;  // a ramp carries one direction
    // The best statement's own sentence first: the one before may count
    // another road ("a 5-lane road and a 3-lane road. the 3-lane road had
    // 2 lanes northbound and 1 southbound").
    std::vector<const RoadStatement*> near;
    for (const auto& rs : roads) near.push_back(&rs);
    std::stable_sort(near.begin(), near.end(), [&](const RoadStatement* a, const RoadStatement* b) {
      return (a->sentence == best->sentence) > (b->sentence == best->sentence);
    });
    for (const RoadStatement* rp : near) {
      const RoadStatement& rs = *rp;
      if (&rs == best || rs.owner > 1 || rs.one_way != best->one_way || rs.ramp != best->ramp || (rs.met && !best->met) ||
          (rs.axis && best->axis && rs.axis != best->axis)) {
        continue;
      }
      // (A count of V1's own direction may come two sentences on: "a
      // 4-lane divided highway. the highway was divided by a median ... .
      // the northbound side had 3 northbound lanes".)
      // A road that widens at the junction is coded by its lanes there:
      // "each side widened to include a left-turn lane, for a total of 3
      // lanes in each direction at the intersection", "a right-turn lane was
      // added ..., so that there were 3 westbound lanes at the intersection"
      // (told up to two sentences on).
      // (Not on the approach to another junction: "150 meters east of the
      // driveway the road widened to 4 lanes on the approach to a signalized
      // intersection".)
      static const regex kWidened(R"(\b(?:widen\w*|flare\w*|for a total of|(?:was|were) added|so that)\b)");
      static const regex kAnotherJunction(
          R"(^[^.;]{0,60}?\b(?:approach\w*\s+to|toward|towards|before)\s+(?:a|an)\s+(?:[\w-]+\s+){0,2}?(?:intersection|junction)\b)");
      const string& told = sentences[rs.sentence].text;
      const bool widened = rs.sentence != best->sentence &&
                           Has(told.substr(0, std::min(told.size(), rs.pos + 40)), kWidened) &&
                           !Has(told.substr(std::min(told.size(), rs.pos)), kAnotherJunction);
      const size_t reach = (of_v1s_direction(rs) && rs.directional) || widened ? 2 : 1;
      if (rs.sentence > best->sentence + reach || rs.sentence + 1 < best->sentence) continue;
      if (!best->axis && rs.axis && ctx.v1_axis >= 0 && *rs.axis != ctx.v1_axis) continue;  // a road across V1's course
      if (!rs.road.empty() && !best->road.empty() && rs.road != best->road) continue;
      if (OfAnotherRoad(rs, *best)) continue;
      // ... or one whose own noun names another road than best's clause
      // ("the boulevard had 2 lanes each way. ... a 2-lane residential
      // street", best the boulevard's).
      if (rs.road.empty() && OtherKindsOfRoad(rs.counted, best->road)) continue;
      if (widened && rs.per_direction > per) {
        per = rs.per_direction;
        per_told = &rs;
        if (total && total < 2 * per) total = 0;  // the count before the widening
      }
      if (widened && rs.total > total) total = rs.total;
      if (widened && rs.directional > directional && (!v1s_direction || of_v1s_direction(rs))) {
        directional = rs.directional;
        v1s_direction = of_v1s_direction(rs);
      }
      if (!total && rs.total) total = rs.total;
      if (!per && rs.per_direction) {
        per = rs.per_direction;
        per_told = &rs;
      }
      if (rs.directional && (!directional || (!v1s_direction && of_v1s_direction(rs)))) {
        directional = rs.directional;
        v1s_direction = of_v1s_direction(rs);
      }
    }
    static const regex kOneWaySentence(R"(\boneway\b)");
    static const regex kOtherRoadPhrase(R"(\b2[- ]way\b|\band (?:a|an)\b)");
    // "... occurred on a one-way northbound street. the street had 3
    // northbound travel lanes": the same road, told in two sentences.
    // A count of each direction's lanes is a two-way road's ("an undivided
    // avenue, 2 lanes each way, where a one-way street leaves it").
    const bool each_way = best->per_direction > 0;
    for (size_t k = best->sentence > 0 ? best->sentence - 1 : 0; k <= best->sentence && v1_way == 0 && !one_way && !each_way; ++k) {
      const string& t = sentences[k].text;
      if (Has(t, kOneWaySentence) && !Has(t, kOtherRoadPhrase) && !Has(scene, TwoWayWord())) one_way = true;
      // "a southbound one-way avenue and a two-way street. the avenue had
      // 3 travel lanes": the counted road is the one called one-way.
      if (!best->road.empty() && !GenericRoad(best->road) &&
          Has(t, regex(R"(\boneway\s+(?:[\w/-]+\s+){0,2}?)" + EscapeRegex(best->road) + R"(\b)"))) {
        one_way = true;
      }
    }
    if (!one_way && v1_way == 0 && !each_way && Has(sentences[best->sentence].text, kOneWaySentence) &&
        !Has(sentences[best->sentence].text, kOtherRoadPhrase)) {
      one_way = true;
    }
    if (one_way) {
      const int n = total ? total : (directional ? directional : (per ? per : 1));
      r.road.one_way.Set(true, Provenance::kStated);
      r.road.lanes_total.Set(n, Provenance::kStated);
      r.road.lanes_per_direction.Set(n, Provenance::kInferred);
    } else if (per) {
      // "2 through lanes in each direction separated by a continuous
      // two-way left-turn lane": the centre lane is a fifth.
      const int centre = best->centre ? 1 : 0;
      // "2 through lanes in each direction ..., with a left-turn lane for
      // southbound traffic", V1 southbound: its side has the bay too.
      static const regex kBayOfOneDirection(
          R"(\b(?:a|an|1)\s+(?:left|right)[- ]turn\s+(?:lane|bay)\s+for\s+(north|south|east|west)bound\s+traffic\b|\b(?:a|an|1)\s+(?:additional\s+|extra\s+|exclusive\s+|separate\s+|dedicated\s+)?(north|south|east|west)bound\s+(?:left|right)[- ]turn\s+(?:lane|bay)\b)");
      smatch bm;
      const string& per_sentence = sentences[best->sentence].text;
      if (!v1s_direction && !best->centre && v1_dir >= 0 &&
          std::regex_search(per_sentence.cbegin() + static_cast<std::ptrdiff_t>(std::min(best->pos, per_sentence.size())),
                            per_sentence.cend(), bm, kBayOfOneDirection)) {
        const auto bay_dir = CompassWord(bm[1].matched ? bm[1].str() : bm[2].str());
        if (bay_dir && static_cast<int>(*bay_dir) == v1_dir) {
          directional = per + 1;
          v1s_direction = true;
        }
      }
      // "..., and a left-turn bay was cut into the median on each approach
      // to the signalized intersection": each side has the bay there.
      static const regex kBayOnEachApproach(
          R"(\b(?:a|an|1)\s+(?:left|right)[- ]turn\s+(?:lane|bay)\b[^.;]{0,60}?\b(?:on|at|for)\s+(?:each|both|every)\s+(?:approach|approaches|leg|legs)\b)");
      const string& told = sentences[per_told->sentence].text;
      if (!v1s_direction && !per_told->centre && junction &&
          std::regex_search(told.cbegin() + static_cast<std::ptrdiff_t>(std::min(per_told->pos, told.size())),
                            told.cend(), bm, kBayOnEachApproach)) {
        // (Across an undivided road at V1's approach: its own through lanes
        // and bay, and the other side's through lanes leaving the junction;
        // bays in a median: each side's.)
        static const regex kMedian(R"(\bmedian\b|\bdivided\b)");
        total = 2 * per + (Has(told, kMedian) ? 2 : 1);
        per += 1;
      }
      r.road.lanes_per_direction.Set(v1s_direction ? directional : per, Provenance::kStated);
      if (v1s_direction && total < directional + per) {
        r.road.lanes_total.Set(directional + per, Provenance::kInferred);  // V1's side wider than the other's
      } else {
        r.road.lanes_total.Set(total ? total : 2 * per + centre, total ? Provenance::kStated : Provenance::kInferred);
      }
    } else if (total == 1 && Has(sentences[best->sentence].text, TwoWayWord())) {
      // "a two way, one lane roadway": one lane each way.
      r.road.lanes_per_direction.Set(1, Provenance::kStated);
      r.road.lanes_total.Set(2, Provenance::kInferred);
    } else if (total) {
      // "2 northbound and 2 southbound through lanes separated by a
      // raised grass median, with a left turn lane in the median for each
      // direction": each side has the bay at the junction.
      static const regex kBayForEachDirection(
          R"(\b(?:a|an|1)\s+(?:left|right)[- ]turn\s+(?:lane|bay)\b[^.;]{0,40}?\b(?:for|in)\s+(?:each|both|either)\s+directions?\b)");
      const string& told = sentences[best->sentence].text;
      const bool bays = directional && junction && !best->centre &&
                        Has(told.substr(std::min(best->pos, told.size())), kBayForEachDirection);
      r.road.lanes_total.Set(bays ? total + 2 : total, Provenance::kStated);
      r.road.lanes_per_direction.Set(directional ? directional + (bays ? 1 : 0) : std::max(1, total / 2),
                                     directional ? Provenance::kStated : Provenance::kInferred);
    } else if (directional) {
      r.road.lanes_per_direction.Set(directional, Provenance::kStated);
      r.road.lanes_total.Set(2 * directional, Provenance::kInferred);
    }
  }
  if (!best && Has(scene, OneWayWord()) && !Has(scene, TwoWayWord())) {
    r.road.one_way.Set(true, Provenance::kStated);
  }
}

void ReadDivision(Reading& rd, const RoadContext& ctx, const std::vector<RoadStatement>& roads, const RoadStatement* best) {
  AccidentRecord& r = rd.r;
  const std::vector<Sentence>& sentences = rd.sentences;
  const bool junction = AtJunction(r);
  // "divided by two solid yellow lines" is paint, not a divided road; a
  // freeway counts when the crash is on it, not "a nearby interstate".
  static const regex kDivided(
      R"(\bdual carriageway\b|\bdivided\b(?!\s+by\s+(?:\w+\s+){0,3}?(?:lines?|stripes?|centerlines?|paint\w*|markings?)\b)|\bmedian\b|\bbarrier wall\b|\b(?:on|along|of|in)\s+(?:a|an|the)\s+(?:[\w-]+[ ,]+){0,4}?(?:interstate|freeway)\b|)"
      // "separated from the northbound lanes by a concrete barrier".
      R"(\bseparated\s+(?:from\s+[^.;,]{0,40}?\s+)?by\s+(?:a|an)\s+(?:[\w-]+\s+){0,3}?(?:barrier|guardrail|guard rail|wall)\b)");
  static const regex kUndivided(
      R"(\bundivided\b|\bnot (?:physically )?divided\b|\bnon-?divided\b|\b(?:no|without (?:a|any)) (?:\w+ )?median\b)");
  // At a junction, a divided road running across V1's course is the other
  // road ("the through roadway ran east/west and was a divided highway").
  // A sentence counting the lanes of a road other than V1's says nothing
  // of V1's ("Grand Avenue ... each direction has 3 through lanes plus a
  // left-turn bay next to the raised median", V1 on the 2-lane street).
  auto other_roads_sentence = [&](size_t k) {
    if (!best || k == best->sentence) return false;
    bool counted = false;
    for (const auto& rs : roads) {
      if (rs.sentence != k) continue;
      counted = true;
      // The same road: on the same axis, or near it with no axis to tell,
      // and not another road by name.
      // (Named by kinds that differ: "the highway had 2 lanes in each
      // direction separated by a grass median", best the county road's.)
      const bool same = (rs.axis && best->axis) ? *rs.axis == *best->axis
                                                : rs.sentence <= best->sentence + 1 && !OfAnotherRoad(rs, *best) &&
                                                      !OtherKindsOfRoad(rs.road, best->road);
      if (same) return false;
    }
    return counted;
  };
  // "a median crossover", "stopped in the median": the other road's median.
  static const regex kMedianPlace(R"(\b(?:in|into|across|through|onto|at|from|out of) the median\b|\bmedian (?:crossover|opening|crossing)\b)");
  // Whether a sentence (its median places blanked) says `word` of V1's
  // road: not of a road across V1's course at a junction, judged by the
  // axis of the phrase that says it ("a north/south divided highway and an
  // east/west county road": the highway's), else the sentence's.
  auto says_of_v1s_road = [&](const Sentence& s, const string& cleaned, const regex& word) {
    smatch dm;
    if (!std::regex_search(cleaned, dm, word)) return false;
    const size_t at = static_cast<size_t>(dm.position());
    // "a 2-lane county road crosses a divided highway", V1 on the county
    // road: the word names another kind of road.
    static const regex kQualifiedRoad(
        R"(^(?:county|state|rural|city|residential|side|cross|access|service|frontage)\s|^crossroad$)");
    if (ctx.distinctive && Has(ctx.v1_road, kQualifiedRoad)) {
      static const regex kNounAfter(R"(^\s*(?:[\w-]+\s+){0,2}?)" + RoadNoun() + R"(\b)");
      // (The word may hold its noun: "of a 6-lane, divided, limited access
      // interstate".)
      smatch nm;
      const string said = dm.str();
      const string after = cleaned.substr(at + static_cast<size_t>(dm.length()));
      if ((std::regex_search(said, nm, RoadWord()) || std::regex_search(after, nm, kNounAfter)) &&
          ctx.v1_road.find(nm[1].str()) == string::npos) {
        return false;
      }
    }
    const size_t from = RoadPhraseStart(cleaned, at);
    string phrase = cleaned.substr(from, at - from + static_cast<size_t>(dm.length()) + 25);
    const size_t next = phrase.find(" and ", at - from + static_cast<size_t>(dm.length()));
    if (next != string::npos) phrase = phrase.substr(0, next);
    // "a 4-lane divided u.s. route and a 2-lane township road", V1 on the
    // township road: the phrase names another road than V1's named one
    // (unless in apposition to it: "route 9, a divided highway").
    if (!ctx.v1_named_road.empty()) {
      const size_t name_at = cleaned.find(ctx.v1_named_road);
      if (name_at != string::npos && Has(phrase, RoadWord())) {
        const size_t name_end = name_at + ctx.v1_named_road.size();
        const bool in_phrase = name_at >= from && name_at < from + phrase.size();
        static const regex kApposition(R"(^\s*,\s*$)");
        const bool appositive = name_end <= from && Has(cleaned.substr(name_end, from - name_end), kApposition);
        if (!in_phrase && !appositive) return false;
      }
    }
    // "a four-lane divided boulevard and a two-lane undivided city
    // street", V1 on the boulevard: the word is the other road's.
    if (ctx.distinctive && phrase.find(ctx.v1_road) == string::npos) {
      const size_t v1_at = cleaned.find(ctx.v1_road);
      const bool before_and = v1_at != string::npos && v1_at < from && cleaned.compare(from, 4, "and ") == 0;
      const bool after_and = v1_at != string::npos && v1_at >= from + phrase.size() && next != string::npos;
      if ((before_and || after_and) && Has(phrase, RoadWord())) return false;
    }
    // "a 4-lane divided highway and a 2-lane undivided cross street", V1's
    // lanes counted on the highway: the cross street's word.
    static const regex kCrossRoadPhrase(R"(\b(?:cross|crossing|side|minor)\s+(?:street|road|roadway|route)\b|\bcrossroad\b)");
    if (junction && best && !best->cross && Has(phrase, kCrossRoadPhrase)) return false;
    std::optional<int> axis = AxisIn(phrase);
    if (!axis) axis = AxisIn(s.text);
    return !(junction && ctx.v1_axis >= 0 && axis && *axis != ctx.v1_axis);
  };
  bool divided = false, undivided = false;
  for (const Sentence& s : sentences) {
    if ((s.kind != Kind::kNarrative && s.kind != Kind::kStatement) ||
        other_roads_sentence(static_cast<size_t>(&s - sentences.data()))) {
      continue;
    }
    const string cleaned = std::regex_replace(s.text, kMedianPlace, " ");
    if (says_of_v1s_road(s, cleaned, kUndivided)) undivided = true;
    if (!says_of_v1s_road(s, cleaned, kDivided)) continue;
    static const regex kRest(R"(\b(?:came to (?:its |their )?(?:final )?rest|final rest|rest(?:ed|ing)? against)\b)");
    if (Has(s.text, kRest)) continue;  // "came to rest against the median curb"
    // In a sentence about a vehicle, a median is where it went ("stopped
    // again in the median"); the road is divided only when said so.
    static const regex kSaysDivided(
        R"(\bdivided\b|\bdual carriageway\b|\bwith an? (?:[\w-]+ ){0,3}median\b|\bseparated (?:from [^.;,]{0,40}? )?by an? (?:[\w-]+ ){0,3}median\b|\bmedian[- ]divided\b|\bmedian (?:wall|barrier|guardrail|guard rail|cable)\b|\b(?:center|centre|concrete|raised) median\b|)"
        R"(\bseparated\s+(?:from\s+[^.;,]{0,40}?\s+)?by\s+(?:a|an)\s+(?:[\w-]+\s+){0,3}?(?:barrier|guardrail|guard rail|wall)\b|)"
        R"(\b(?:on|along|of|in)\s+(?:a|an|the)\s+(?:[\w-]+[ ,]+){0,4}?(?:interstate|freeway)\b)");
    if (!s.refs.empty() && !Has(s.text, kSaysDivided)) continue;
    divided = true;
  }
  if (undivided) r.road.divided.Set(false, Provenance::kStated);
  else if (divided) r.road.divided.Set(true, Provenance::kStated);
  // A divided road whose lanes the report does not count carries more than
  // one lane each way as a rule.
  if (r.road.divided.value && !r.road.one_way.value && !r.road.lanes_per_direction.known()) {
    r.road.lanes_per_direction.Set(2, Provenance::kInferred);
    r.road.lanes_total.Set(4, Provenance::kInferred);
  }
}

void DrivewayLanes(Reading& rd, const RoadStatement* best) {
  AccidentRecord& r = rd.r;
  const std::vector<Sentence>& sentences = rd.sentences;
  const std::vector<Segment>& segments = rd.segments;
  const string& scene = rd.scene;
  const bool case_summary = rd.case_summary;
  // V1 leaving a driveway or parking lot was on it: NMVCCS counts its
  // lanes, a two-way drive of one lane each way unless the report counts
  // them.
  static const regex kMiddleLane(R"(\bmiddle (?:travel |through )?lane\b)");
  bool v1_from_driveway = false, v1_middle_lane = false;
  for (const Segment& seg : segments) {
    if (!rd.V1BeforeImpact(seg)) continue;
    if (LeavesDriveway(seg.text)) v1_from_driveway = true;
    if (Has(seg.text, kMiddleLane)) v1_middle_lane = true;
  }
  // A count in V1's own text is its drive's, unless it is the road's the
  // drive comes out on ("through a driveway on the north side of a 5-lane
  // roadway").
  auto counts_the_drive = [&](const RoadStatement& rs) {
    static const regex kRoadCount(
        R"(^\d[- ]lanes?\b(?:[^.;]{0,40}?\b(?:road|roadway|street|highway|avenue|boulevard|route|trafficway)\b))");
    return rs.owner == 1 && !Has(sentences[rs.sentence].text.substr(rs.pos, 60), kRoadCount);
  };
  // (NMVCCS codes the drive, t/21 and crossing/8; a CIREN case summary
  // the road it enters, as the invented CIREN-style cases of it do, unless
  // it counts the drive's own lanes: "a 2-lane, 2-way driveway".)
  static const regex kDriveCounted(R"(\b\d[- ]lanes?,?\s+(?:[\w-]+,?\s+){0,2}?(?:driveway|drive|alley)\b)");
  if (v1_from_driveway && (!case_summary || Has(scene, kDriveCounted)) && !(best && counts_the_drive(*best))) {
    // ... one lane when the report says the drive is one-way or one lane
    // ("a one-way, exit-only driveway", "a narrow, 1-lane paved alley").
    static const regex kOneLaneDrive(
        R"(\b(?:oneway|1-lane|single[- ]lane|(?:exit|entrance)[- ]only)\b[^.;]{0,30}?\b(?:driveway|drive|alley|access)\b|\b(?:driveway|alley|access)\b[^.;]{0,20}?\b(?:is|was) (?:a )?(?:[\w-]+ )?(?:oneway|1-lane|single[- ]lane)\b)");
    const bool one_lane = Has(scene, kOneLaneDrive);
    r.road.one_way.Set(one_lane, Provenance::kInferred);
    r.road.divided.Set(false, Provenance::kInferred);
    r.road.lanes_total.Set(one_lane ? 1 : 2, Provenance::kInferred);
    r.road.lanes_per_direction.Set(1, Provenance::kInferred);
  }
  // A middle lane, or a stated lane number beyond the count, means more lanes.
  const int lanes_needed = std::max(v1_middle_lane ? 3 : 0, r.vehicles.empty() ? 0 : r.vehicles[0].lane.value);
  if (!v1_from_driveway && lanes_needed > r.road.lanes_per_direction.value) {
    const int extra = lanes_needed - r.road.lanes_per_direction.value;
    // (A stated total with room for V1's lanes and the other side's is a
    // road wider on V1's side: "3 lanes: 2 northbound and 1 southbound".)
    const bool room = r.road.lanes_total.source == Provenance::kStated && !r.road.one_way.value &&
                      r.road.lanes_total.value >= lanes_needed + r.road.lanes_per_direction.value;
    r.road.lanes_per_direction.Set(lanes_needed, Provenance::kInferred);
    if (!room) {
      r.road.lanes_total.Set(r.road.lanes_total.value + (r.road.one_way.value ? extra : 2 * extra),
                             Provenance::kInferred);
    }
  }
}

void ReadLanes(Reading& rd, const RoadContext& ctx) {
  const std::vector<RoadStatement> roads = LaneStatements(rd, ctx);
  const V1Lanes choice = ChooseV1Statement(rd, ctx, roads);
  CountLanes(rd, ctx, roads, choice);
  ReadDivision(rd, ctx, roads, choice.best);
  // "lane two of a three-lane, divided ... interstate": an odd count on a
  // divided road with no side told is one side's.
  RoadRecord& road = rd.r.road;
  if (road.divided.value && !road.one_way.value && road.lanes_total.source == Provenance::kStated &&
      road.lanes_per_direction.source == Provenance::kInferred && road.lanes_total.value >= 3 &&
      road.lanes_total.value % 2 == 1 && road.kind.value != RoadKind::kRamp && !(choice.best && choice.best->ramp)) {
    road.lanes_per_direction.Set(road.lanes_total.value, Provenance::kStated);
    road.lanes_total.Set(2 * road.lanes_total.value, Provenance::kInferred);
  }
  DrivewayLanes(rd, choice.best);
}

void ReadConditions(Reading& rd) {
  AccidentRecord& r = rd.r;
  const string& scene = rd.scene;
  static const regex kIce(R"(\b(?:icy|ice|frost|black ice|frozen)\b)");
  static const regex kSnow(R"(\bsnow(?:y|ing|ed| covered)?\b|\bslush)");
  static const regex kSnowSurface(R"(\b(?:snow|slush)[a-z ]{0,20}(?:covered|road|surface|packed)|\broad\w* (?:was |were )?snow)");
  static const regex kRain(R"(\brain(?:ing|y)?\b|\bdrizzl)");
  static const regex kFog(R"(\bfog(?:gy)?\b|\bmist)");
  static const regex kCloudy(R"(\bcloudy\b|\bovercast\b)");
  static const regex kClear(R"(\bclear\b|\bsunny\b)");
  static const regex kDarkLighted(R"(\bdark(?:,| but| and)? (?:lighted|lit|illuminated)|\bstreet ?lights?\b|\broadway was illuminated)");
  static const regex kDark(R"(\bdark\b|\bnight\b|\bunlighted\b|\bdarkness\b)");
  static const regex kDusk(R"(\bdusk\b)");
  static const regex kDawn(R"(\bdawn\b)");
  static const regex kDaylight(R"(\bdaylight\b|\bdaytime\b)");
  static const regex kUphill(R"(\buphill\b|\bupgrade\b|\bup a hill\b)");
  static const regex kDownhill(R"(\bdownhill\b|\bdowngrade\b|\bdown (?:a |the )?hill\b|\bgrade of -|\b-\s?\d+(?:\.\d+)?\s?% grade)");
  static const regex kLevel(R"(\blevel\b|\bno grade\b|\bflat\b)");
  static const regex kWet(R"(\bwet\b|\braining\b|\brain\b|\bdamp\b)");
  static const regex kDry(R"(\bdry\b)");
  if (Has(scene, kIce)) r.road.surface.Set(Surface::kIce, Provenance::kStated);
  else if (Has(scene, kSnowSurface)) r.road.surface.Set(Surface::kSnow, Provenance::kStated);
  else if (Has(scene, kWet)) r.road.surface.Set(Surface::kWet, Provenance::kStated);
  else if (Has(scene, kDry)) r.road.surface.Set(Surface::kDry, Provenance::kStated);
  if (Has(scene, kRain)) r.road.weather.Set("rain", Provenance::kStated);
  else if (Has(scene, kSnow)) r.road.weather.Set("snow", Provenance::kStated);
  else if (Has(scene, kFog)) r.road.weather.Set("fog", Provenance::kStated);
  else if (Has(scene, kCloudy)) r.road.weather.Set("cloudy", Provenance::kStated);
  else if (Has(scene, kClear)) r.road.weather.Set("clear", Provenance::kStated);
  if (Has(scene, kDarkLighted)) {
    r.road.lighting.Set("dark_lighted", Provenance::kStated);
  } else if (Has(scene, kDark)) {
    r.road.lighting.Set("dark", Provenance::kStated);
  } else if (Has(scene, kDusk)) {
    r.road.lighting.Set("dusk", Provenance::kStated);
  } else if (Has(scene, kDawn)) {
    r.road.lighting.Set("dawn", Provenance::kStated);
  } else if (Has(scene, kDaylight)) {
    r.road.lighting.Set("daylight", Provenance::kStated);
  }
  if (Has(scene, kUphill)) r.road.grade.Set("uphill", Provenance::kStated);
  else if (Has(scene, kDownhill)) r.road.grade.Set("downhill", Provenance::kStated);
  else if (Has(scene, kLevel)) r.road.grade.Set("level", Provenance::kStated);
}

// The posted limit of V1's road.
void ReadSpeedLimit(Reading& rd, const RoadContext& ctx) {
  AccidentRecord& r = rd.r;
  const std::vector<Sentence>& sentences = rd.sentences;
  struct Limit {
    double mps;
    string unit;
    int owner;
    std::optional<int> axis;
    size_t order;
    string road;  // the road its clause is about ("the side street is ..., posted at 30 mph")
    string name;  // the named road its clause is about ("route 202 ... a 50 mph limit")
  };
  std::vector<Limit> limits;
  static const regex kValue(R"(\b(\d{2,3})(?:\s*|-)(kmh|mph)\b)");  // "45 mph", "a 45-mph zone"
  // (Also the number before the word: "route 9 has a 45 limit", "a 25
  // zone".)
  static const regex kBare(
      R"(\b(?:speed limit|limit|posted)\b[^.]{0,30}?\b(\d{2})\b(?!\s*(?:kmh|mph|%|m\b|meters|feet))|\b(?:an?|the)\s+(\d{2})\s+(?:speed\s+)?(?:limit|zone)\b)");
  static const regex kAdvisory(R"((?:advisory|suggested|recommended|warning|curve)[^.]{0,25}$)");
  // A telegraphic list goes on after a semicolon without the limit word
  // ("highway posted 72 kmh (45 mph); side road 40 kmh (25 mph)").
  static const regex kListedRoadLimit(R"(^\s*(?:(?:the|a|an)\s+)?(?:[\w/-]+\s+){0,2}?)" + RoadNoun() +
                                      R"(\s*(?:,|:|-|is|was)?\s*(\d{2,3})\s*(kmh|mph)\b)");
  size_t order = 0;
  size_t last_with_limit = sentences.size();
  // Limits said to be the usual ones ("the normal speed limit is 65 mph;
  // within the work zone the limit is reduced to 45 mph"): a reduction in
  // the next sentences replaces them. (First index in `limits`, sentence.)
  static const regex kUsual(R"(\b(?:normal(?:ly)?|usual(?:ly)?|regular|otherwise)\b)");
  std::optional<std::pair<size_t, size_t>> usual;
  for (const Sentence& s : sentences) {
    if (s.kind == Kind::kCoding || s.kind == Kind::kPeople) continue;
    const size_t index = static_cast<size_t>(&s - sentences.data());
    // Police shorthand lists a road's limit after its lanes, with no limit
    // word: "on millbrook rd (2 lanes, 25 mph)", "grand ave was 4 lanes
    // undivided, 35 mph", "both streets 30 mph".
    static const string kRoadListTail =
        R"((?:(?:\b\d\s*lanes?|\bundivided|\bdivided|\b2-way|\boneway)(?:\s+(?:undivided|divided|each\s+way|(?:in\s+)?each\s+direction|total|2-way|oneway))?\s*[,:;]\s*|\bboth\s+(?:streets|roads|roadways)\s+))";
    static const regex kRoadListValue(kRoadListTail + R"(\d{2,3}\s*(?:kmh|mph)\b)");
    static const regex kRoadListBefore(kRoadListTail + "$");
    const bool road_list = Has(s.text, kRoadListValue);
    const bool tells_limit = s.text.find("limit") != string::npos || s.text.find("posted") != string::npos ||
                             s.text.find(" zone") != string::npos || road_list;
    // The latest such sentence that tells a limit ("the weather was normal"
    // tells none).
    if (tells_limit && Has(s.text, kUsual)) usual = std::make_pair(limits.size(), index);
    if (!tells_limit) {
      smatch m;
      if (last_with_limit + 1 == index && std::regex_search(s.text, m, kListedRoadLimit)) {
        const bool kmh = m[3].str() == "kmh";
        const double value = std::stod(m[2].str());
        const size_t at = static_cast<size_t>(m.position(2));
        if (value >= 5 && value <= 180) {
          limits.push_back({value * (kmh ? kKmhToMps : kMphToMps), kmh ? "km/h" : "mph", OwnerAt(s, at),
                            ctx.InheritedAxis(index, AxisIn(s.text.substr(0, at))), order++, m[1].str(),
                            ctx.NamedAt(index, at)});
          last_with_limit = index;
        }
      }
      continue;
    }
    bool found = false;
    size_t skip_until = 0, last_value_end = 0;
    const size_t sentence_first = limits.size();
    for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kValue); it != std::sregex_iterator(); ++it) {
      const size_t pos = static_cast<size_t>(it->position());
      if (pos < skip_until) continue;
      const string before = s.text.substr(0, pos);
      // A value and its conversion in brackets are one limit.
      const string tail = it->suffix().str();
      smatch conv;
      static const regex kConversion(R"(^\s*\(\s*\d{2,3}\s*(?:kmh|mph)\s*\))");
      if (std::regex_search(tail, conv, kConversion)) {
        skip_until = pos + static_cast<size_t>(it->length(0)) + static_cast<size_t>(conv.length(0));
      }
      if (Has(before.substr(before.size() > 40 ? before.size() - 40 : 0), kAdvisory)) continue;
      // A range is a speed, never a posted limit ("he was doing the speed
      // limit, but the reconstruction put v1 at 60-65 kmh").
      static const regex kRangeBefore(R"(\b\d{1,3}\s*(?:-|to)\s*$)");
      if (Has(Before(s.text, pos, 10), kRangeBefore)) continue;
      // A limit word after the value qualifies it close by ("45 mph (72
      // kmh) posted speed limit"), not one a clause later ("her speed at
      // 72-80 kmh and said she thought the limit was 55 mph").
      const string near_tail = tail.substr(0, 30);
      if (before.find("limit") == string::npos && before.find("posted") == string::npos &&
          before.find("speed zone") == string::npos && near_tail.find("limit") == string::npos &&
          near_tail.find("posted") == string::npos && tail.rfind(" zone", 0) != 0 &&
          tail.rfind(" speed zone", 0) != 0 &&  // "a 45 mph zone", "a 25 mph speed zone"
          !Has(Before(s.text, pos, 40), kRoadListBefore)) {
        continue;
      }
      // After a limit, a vehicle's speed told in the same sentence is not
      // another ("the speed limit is 70 mph and the event data recorder of
      // v1 recorded a pre-crash speed of 68 mph").
      static const regex kVehicleSpeed(R"(\bv[1-9]\b(?!'s)|\bspeed of\b|\brecorded\b|\btravel\w*\b)");
      static const regex kLimitWord(R"(\blimit|\bposted\b|\bzone\b)");
      if (last_value_end > 0 && pos > last_value_end) {
        const string since = s.text.substr(last_value_end, pos - last_value_end);
        if (Has(since, kVehicleSpeed) && !Has(since, kLimitWord)) continue;
      }
      last_value_end = pos + static_cast<size_t>(it->length(0));
      // "the normal 65 mph limit is reduced to a posted 45 mph": the
      // reduced value replaces the one it reduces.
      // (Also "drops from 55 mph to 35 mph".)
      static const regex kReducedTo(
          R"(\b(?:reduced|lowered|dropp?(?:ed|s)|decreas\w+|cut)\s+(?:from\s+\d{2,3}\s*(?:kmh|mph)\s*(?:\(\s*\d{2,3}\s*(?:kmh|mph)\s*\)\s*)?)?to\s+(?:an?\s+)?(?:posted\s+|temporary\s+)?$)");
      if (Has(Before(s.text, pos, 50), kReducedTo)) {
        limits.resize(sentence_first);
        if (usual && usual->first < sentence_first && index - usual->second <= 2) {
          limits.resize(usual->first);
        }
      }
      const bool kmh = (*it)[2].str() == "kmh";
      const double value = std::stod((*it)[1].str());
      if (value < 5 || value > 180) continue;
      // "64 kmh (40 mph) on the north/south roadway and 40 kmh (25 mph) on
      // the east/west roadway", "48 kmh on v1's roadway": the road named
      // after the value is its road.
      static const regex kOnRoadAfter(
          R"(^\s*(?:\(\s*\d{2,3}\s*(?:kmh|mph)\s*\)\s*)?(?:on|for|along)\s+(?:the\s+)?([^,;]{0,30}?)\s*(?:road|roadway|street|highway|approach)\b)");
      static const regex kVehiclesRoad(R"(\bv([1-9])'s\b)");
      smatch on, vm;
      std::optional<int> axis = AxisIn(before);
      int owner = OwnerAt(s, pos);
      if (std::regex_search(tail, on, kOnRoadAfter)) {
        const string named = on[1].str();
        if (const auto a = AxisIn(named)) axis = a;
        if (std::regex_search(named, vm, kVehiclesRoad)) owner = std::stoi(vm[1].str());
      }
      // ... and by its kind: "72 kmh on the through road and 48 kmh on the
      // side road".
      static const regex kOnRoadNounAfter(
          R"(^\s*(?:\(\s*\d{2,3}\s*(?:kmh|mph)\s*\)\s*)?(?:on|for|along)\s+(?:the|a|an)\s+(?:[\w/-]+\s+){0,2}?)" + RoadNoun() +
          R"(\b)");
      // ... or just before it: "and on the side road 48 kmh".
      // (Also in an ellipsis: "the highway was posted at 89 kmh and the
      // crossroad at 56 kmh".)
      // (And "the posted speed limit on the county road was 72 kmh".)
      static const regex kOnRoadNounBefore(R"(\b(?:on|for|along|and)\s+(?:the|a|an)\s+(?:[\w/-]+\s+){0,2}?)" +
                                           RoadNoun() + R"((?:\s*,\s*|\s+at\s+|\s+(?:was|is)\s+|\s*)$)");
      // ... or posted itself: "meets a 4-lane undivided arterial posted at
      // 64 kmh", "with a 4-lane undivided avenue, 2 lanes each way, posted
      // 30 mph".
      static const regex kRoadPostedAt(
          R"(\b)" + RoadNoun() +
          R"((?:\s*,\s*[^,.;()]{1,30}?){0,2}?(?:\s*,\s*|\s+)(?:that was |which was |was |is )?(?:posted|signed|zoned)\s+(?:(?:at|for)\s+)?$)");
      smatch rn;
      const string just_before = Before(s.text, pos, 40), further_before = Before(s.text, pos, 80);
      // (In brackets after a road: "an east-west, 4-lane undivided arterial
      // (2 lanes each way, 35 mph/56 kmh)".)
      static const regex kInRoadsBracket(R"(\b)" + RoadNoun() + R"(\s*\([^()]*$)");
      const string bracket_before = Before(s.text, pos, 60);
      const string road = std::regex_search(bracket_before, rn, kInRoadsBracket) ? rn[1].str()
                          : std::regex_search(tail, rn, kOnRoadNounAfter)          ? rn[1].str()
                          : std::regex_search(just_before, rn, kOnRoadNounBefore) ? rn[1].str()
                          : std::regex_search(further_before, rn, kRoadPostedAt) && !GenericRoad(rn[1].str()) ? rn[1].str()
                                                                                  : ClauseRoad(s.text, pos);
      const string on_named = ctx.names.OnAfter(tail);
      limits.push_back({value * (kmh ? kKmhToMps : kMphToMps), kmh ? "km/h" : "mph", owner,
                        ctx.InheritedAxis(index, axis), order++, road,
                        on_named.empty() ? ctx.NamedAt(index, pos) : on_named});
      found = true;
      last_with_limit = index;
    }
    smatch m;
    // ... a bare number only when it could be a limit in mph ("limit: 00" is none).
    if (!found && std::regex_search(s.text, m, kBare) && std::stoi(m[m[1].matched ? 1 : 2].str()) >= 5) {
      const size_t at = static_cast<size_t>(m.position());
      const int mph = std::stoi(m[m[1].matched ? 1 : 2].str());
      limits.push_back({mph * kMphToMps, "mph", OwnerAt(s, at),
                        ctx.InheritedAxis(index, AxisIn(s.text.substr(0, at))),
                        order++, ClauseRoad(s.text, at), ctx.NamedAt(index, at)});
    }
  }
  // A value in brackets right after a road names that road's limit, with
  // or without a limit word: "a 2-lane side road (35 mph, 56 kmh) ends at
  // a state highway posted at 45 mph".
  {
    static const regex kRoadBracketValue(R"(\b)" + RoadNoun() +
                                         R"(\s*\(\s*(\d{2,3})\s*(kmh|mph)\s*(?:[,/]\s*\d{2,3}\s*(?:kmh|mph)\s*)?\))");
    for (const Sentence& s : sentences) {
      if (s.kind == Kind::kCoding || s.kind == Kind::kPeople) continue;
      const size_t index = static_cast<size_t>(&s - sentences.data());
      for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kRoadBracketValue); it != std::sregex_iterator();
           ++it) {
        const double value = std::stod((*it)[2].str());
        const bool kmh = (*it)[3].str() == "kmh";
        const size_t at = static_cast<size_t>(it->position(2));
        if (value < 5 || value > 180) continue;
        limits.push_back({value * (kmh ? kKmhToMps : kMphToMps), kmh ? "km/h" : "mph", OwnerAt(s, at),
                          ctx.InheritedAxis(index, AxisIn(s.text.substr(0, at))), order++, (*it)[1].str(),
                          ctx.NamedAt(index, at)});
      }
    }
  }
  // No limit word anywhere: a value that describes the road itself ("a
  // 45 mph two-lane road", "the road is two lanes, 45 mph") is its limit;
  // one after a travel word is a vehicle's speed.
  if (limits.empty()) {
    static const regex kRoadValue(
        R"(\b(\d{2,3})\s*(kmh|mph)\s+(?:(?!(?:on|in|along|down|up|at|when|while|as|and|through|into|onto|toward|towards|near|before|after|from|of|with)\b)[\w-]+\s+){0,3}?(?:road|roadway|street|highway|avenue|boulevard|route|zone|stretch|section|freeway|interstate|carriageway)\b)");
    static const regex kRoadSubject(
        R"(^(?:the\s+)?(?:[\w-]+\s+){0,3}?(?:road|roadway|street|highway|avenue|boulevard|route|freeway|interstate|carriageway|rdwy|st|ave|rd|dr)\s+(?:is|was)\b[^.]*?\b(\d{2,3})\s*(kmh|mph)\b)");
    // ... or closes an item of a terse list about the road ("two
    // residential streets, both two-lane two-way, straight and level, 25 mph").
    static const regex kRoadListValue(
        R"(\b(?:roads?|roadways?|streets?|highways?|intersection|lanes?|two-way|level|straight|curve\w*)\b[^.]{0,80}?,\s*(\d{2,3})\s*(kmh|mph)\s*(?:\(\s*\d{2,3}\s*(?:kmh|mph)\s*\)\s*)?(?:[,;]|$))");
    static const regex kTravelWord(
        R"(\b(?:travel\w*|going|driving|doing|moving|speed|estimated|approximately|about|around|between|at)\s+(?:\w+\s+){0,2}$)");
    for (const Sentence& s : sentences) {
      if (s.kind == Kind::kCoding || s.kind == Kind::kPeople) continue;
      smatch m;
      const bool subject = std::regex_search(s.text, m, kRoadSubject) && s.refs.empty();
      const bool listed = !subject && s.refs.empty() && std::regex_search(s.text, m, kRoadListValue);
      if (!subject && !listed && !std::regex_search(s.text, m, kRoadValue)) continue;
      const size_t pos = static_cast<size_t>(m.position(1));
      if (Has(Before(s.text, pos, 30), kTravelWord)) continue;
      const double value = std::stod(m[1].str());
      const bool kmh = m[2].str() == "kmh";
      if (value < 5 || value > 180) continue;
      limits.push_back({value * (kmh ? kKmhToMps : kMphToMps), kmh ? "km/h" : "mph", OwnerAt(s, pos),
                        AxisIn(s.text.substr(0, pos)), order++, ClauseRoad(s.text, pos),
                        ctx.names.Subject(s.text, pos)});
      break;
    }
  }
  // The first limit meeting the most specific test that any meets.
  auto first_limit = [&](auto pred) -> const Limit* {
    for (const auto& l : limits) {
      if (pred(l)) return &l;
    }
    return nullptr;
  };
  // A limit said of a road the report names with its axis ("an east/west
  // 2-lane highway ... the highway is posted at 45 mph") has that axis.
  {
    const std::map<string, int> axis_of_road = AxesOfNamedRoads(sentences);
    for (Limit& l : limits) {
      if (l.axis || l.road.empty()) continue;
      const auto named = axis_of_road.find(l.road);
      if (named != axis_of_road.end()) l.axis = named->second;
    }
  }
  if (std::getenv("ACCSIM_DEBUG_ROADS")) {
    std::fprintf(stderr, "[v1 named road: %s] [v1 road: %s]\n", ctx.v1_named_road.c_str(), ctx.v1_road.c_str());
    for (const auto& l : limits) {
      std::fprintf(stderr, "[limit %.1f kmh owner%d axis%d road '%s' name '%s']\n", l.mps * 3.6, l.owner,
                   l.axis ? *l.axis : -1, l.road.c_str(), l.name.c_str());
    }
  }
  // (Not one V1's sentence tells of the road it meets: "stopped at its
  // intersection with an east-west arterial (2 lanes each way, 35 mph)".)
  const Limit* pick = first_limit([&](const Limit& l) {
    const bool other_road = ctx.distinctive && !l.road.empty() && !GenericRoad(l.road) && !SameRoad(l.road, ctx.v1_road);
    return l.owner == 1 && !other_road;
  });
  // V1 on the ramp: the limit said of the ramp ("the ramp is posted at 56
  // kmh (35 mph)"), not the road it leads to.
  if (!pick && ctx.v1_on_ramp) {
    static const regex kRampLimit(
        R"(\bramp'?s?\s+(?:(?!which\b|that\b|where\b|and\b)[\w ,-]){0,40}?\b(?:is|was|has|had)\s+(?:a\s+)?(?:posted\s+)?(?:speed\s+)?(?:limit\s+(?:of\s+)?)?(?:posted\s+)?(?:at\s+)?(\d{2,3})\s*(kmh|mph)\b|)"
        R"(\bposted\s+(?:at\s+)?(\d{2,3})\s*(kmh|mph)\s*(?:\(\s*\d{2,3}\s*(?:kmh|mph)\s*\)\s*)?on\s+the\s+(?:[\w-]+\s+)?ramp\b)");
    for (const Sentence& s : sentences) {
      if (s.kind != Kind::kNarrative) continue;
      smatch m;
      if (!std::regex_search(s.text, m, kRampLimit)) continue;
      const int g = m[1].matched ? 1 : 3;
      const double value = std::stod(m[g].str());
      const bool kmh = m[g + 1].str() == "kmh";
      const double mps = value * (kmh ? kKmhToMps : kMphToMps);
      pick = first_limit([&](const Limit& l) { return std::abs(l.mps - mps) < 1e-9; });
      if (pick) break;
    }
  }
  if (!pick && !ctx.v1_named_road.empty()) {
    pick = first_limit([&](const Limit& l) { return l.owner <= 1 && l.name == ctx.v1_named_road; });
  }
  if (!pick && ctx.distinctive) pick = first_limit([&](const Limit& l) { return l.owner <= 1 && SameRoad(l.road, ctx.v1_road); });
  // (Told in another vehicle's sentence: "v2 ... stopped ... at an
  // intersection with a 4-lane undivided avenue, 2 lanes each way, posted
  // 30 mph. v1 ... was eastbound in the curb lane of the avenue".)
  if (!pick && ctx.distinctive) pick = first_limit([&](const Limit& l) { return SameRoad(l.road, ctx.v1_road); });
  if (!pick && ctx.v1_axis >= 0) {
    pick = first_limit([&](const Limit& l) { return l.owner <= 1 && l.axis && *l.axis == ctx.v1_axis; });
  }
  // A limit said of a road across V1's course is the other road's.
  if (!pick && ctx.v1_axis >= 0) pick = first_limit([](const Limit& l) { return l.owner <= 1 && !l.axis; });
  if (!pick) pick = first_limit([](const Limit& l) { return l.owner <= 1; });
  // (Every limit told in the other vehicle's sentences: the one on V1's axis.)
  if (!pick && ctx.v1_axis >= 0) pick = first_limit([&](const Limit& l) { return l.axis && *l.axis == ctx.v1_axis; });
  if (!pick && !limits.empty()) pick = &limits.front();
  if (pick) {
    r.road.speed_limit_mps.Set(pick->mps, Provenance::kStated);
    r.road.speed_limit_unit.Set(pick->unit, Provenance::kStated);
  }
}

void InferSpeedLimit(Reading& rd) {
  AccidentRecord& r = rd.r;
  const std::vector<Segment>& segments = rd.segments;
  const string& scene = rd.scene;
  const bool quotes_coding = rd.quotes_coding;
  // A report that says no limit was posted ("no speed limit signs were
  // posted along this road", "there was no posted speed limit on the ramp")
  // is coded "no statutory limit" (the development set's t/11).
  static const regex kNoLimit(
      R"(\b(?:no|not|without)\s+(?:a\s+|any\s+)?(?:posted\s+)?speed\s+limit\b|\bno\s+(?:posted\s+)?(?:speed\s+)?limit\s+signs?\b|\bspeed limit\s+(?:was|is)\s+not\s+posted\b|\bunposted\b|)"
      // "neither street had a posted speed limit", "neither road was posted".
      R"(\bneither\s+(?:\w+\s+){0,3}?(?:had|has|was|is)\s+(?:a\s+)?(?:posted\s+)?(?:speed\s+limit|posted)\b|\bno\s+limit\s+(?:was|is)\s+posted\b)");
  if (Has(scene, kNoLimit)) return;
  if (!r.road.speed_limit_mps.known()) {
    // The typical limit of V1's road as its own text describes it ("a
    // 4-lane, 2-way urban road"), else as the scene does (which may describe
    // only the other road: "a residential street that meets ...").
    string v1_text;
    for (const Segment& seg : segments) {
      if (rd.V1BeforeImpact(seg)) {
        v1_text = BeforeTheTurn(seg.text);
        break;
      }
    }
    auto mph = TypicalLimitMph(v1_text, r.road.lanes_total.value, false, quotes_coding);
    if (!mph) mph = TypicalLimitMph(scene, r.road.lanes_total.value, r.road.lanes_total.known(), quotes_coding);
    if (mph) {
      r.road.speed_limit_mps.Set(*mph * kMphToMps, Provenance::kInferred);
      r.road.speed_limit_unit.Set("mph", Provenance::kInferred);
    }
  }
}

}  // namespace

const string& WhereRoadsMeet() {
  static const string kPattern =
      R"(\bintersecting\s+(?:[\w-]+\s+){0,3}?(?:road|street|roadway|highway|avenue)\b|\bwhere\s+(?:the\s+)?(?:[a-z0-9-]+\s+){1,3}meets\b|\bwhere\s+(?:[\w'-]+\s+){1,3}?(?:road|street|avenue|drive|route|highway|lane|boulevard|pike)(?:\s+\d{1,4}[a-z]?)?\s+(?:crosses|intersects)\b|\bwhere\s+(?:that|the|this|it)\s+(?:[a-z0-9-]+\s+){0,2}?crosses\s+(?:a|an|the)\s+(?:[\w-]+\s+){0,2}?(?:road|street|route|highway|roadway|avenue|boulevard)\b|\bat the crossing\b)";
  return kPattern;
}

// "exiting a parking lot driveway", "at the parking lot exit".
bool LeavesDriveway(const string& t) {
  // (Also "pulled out of a bank's two-lane, two-way exit driveway", "left
  // a shopping center", not "left a gap at the driveway".)
  static const regex kFromDriveway(
      R"(\bleft (?:a|an|the|his|her) (?:(?!(?:at|of|in|for|to|on|by|near)\b)[\w'-]+ ){0,2}?(?:parking lot|driveway|private drive|plaza|shopping center|mall|gas station|service station|parking garage|parking deck|parking structure)\b|)"
      R"(\b(?:exit\w*|leav\w*|pull\w* out of|out of) (?:a|an|the|his|her) (?:[\w'-]+,? ){0,4}?(?:parking lot|driveway|private drive|alley|plaza|shopping center|mall|gas station|service station|garage|parking deck|parking structure|field|pasture|farm lane|field access|field entrance)\b|\b(?:parking lot|garage) (?:exit|driveway)\b|)"
      // "stopped at the mouth of the driveway", "drove south through the exit driveway".
      R"(\b(?:stopped|waiting|sitting|sat|paused|idling|was|were|emerged|emerging)\s+(?:[\w-]+\s+){0,2}?(?:at|in|from) the (?:mouth|end|exit|edge|apron) of (?:a|an|the) (?:[\w-]+ ){0,2}?(?:parking lot|driveway|private drive|alley)\b|)"
      R"(\b(?:through|down|out) (?:a|an|the) (?:[\w-]+ ){0,2}?(?:driveway|alley)\b|)"
      // "was westbound in the driveway".
      R"(\b(?:was|were) (?:[\w-]+ ){0,2}?(?:in|on|within) (?:a|an|the) (?:[\w-]+ ){0,2}?(?:driveway|alley|parking lot)\b|)"
      // "stopped at the plaza exit" (not a freeway's exit ramp).
      R"(\b(?:stopped|waiting|sitting|paused) (?:at|in) (?:a|an|the) (?:[\w-]+ ){0,2}?exit\b(?! ramp))");
  return Has(t, kFromDriveway);
}

const regex& DrivewayWord() {
  static const regex kDriveway(
      R"(\bdriveway\b|\bparking lot\b|\bprivate (?:drive|road|lane)\b|\b(?:farm|field|ranch|pasture) (?:lane|entrance|access|drive|gate)\b|\balley\b|\b(?:business|store|restaurant|station|shopping|lot|plaza|mall|center|centre|market|supermarket|school|church|bank|dealership|complex|office) (?:entrance|exit|driveway)|\bout of (?:a|the) lot\b|\bservice station\b|\bgas(?:oline)? station\b|\b(?:filling|fuel) station\b|\bpetrol station\b|\bcar park\b|\bparking (?:garage|deck|structure)\b|\bgarage (?:exit|entrance|driveway)\b|\bentrances? (?:of|to|into) (?:a|an|the) (?:[a-z-]+ ){0,2}?(?:station|store|shop|restaurant|business|lot|plaza|mall|center|centre|yard|complex|dealership|bank|school|church|office|farm|market|supermarket)\b)");
  return kDriveway;
}

const regex& RampWord() {
  static const regex kRamp(R"(\b(?:on|off|entrance|exit)?[- ]?ramp\b)");
  return kRamp;
}

void ReadRoad(Reading& rd) {
  ReadRoadKind(rd);
  const RoadContext ctx(rd);
  ReadLanes(rd, ctx);
  ReadConditions(rd);
  ReadSpeedLimit(rd, ctx);
  InferSpeedLimit(rd);
}

}  // namespace accsim::narrative
