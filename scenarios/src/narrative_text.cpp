#include "narrative_reading.h"

#include <algorithm>
#include <cctype>
#include <map>
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
using regex_text::ReplaceWith;

namespace {

// Sentences longer than this are cut (at a comma when possible): std::regex
// backtracks recursively, so bounded inputs keep every rule cheap and safe.
constexpr size_t kMaxSentence = 600;

int NumberWord(const string& w) {
  static const std::map<string, int> kWords = {
      {"one", 1},     {"two", 2},       {"three", 3},    {"four", 4},     {"five", 5},     {"six", 6},
      {"seven", 7},   {"eight", 8},     {"nine", 9},     {"ten", 10},     {"eleven", 11},  {"twelve", 12},
      {"thirteen", 13}, {"fourteen", 14}, {"fifteen", 15}, {"sixteen", 16}, {"seventeen", 17}, {"eighteen", 18},
      {"nineteen", 19}, {"twenty", 20},  {"thirty", 30},   {"forty", 40},   {"fifty", 50},   {"sixty", 60},
      {"seventy", 70}, {"eighty", 80},   {"ninety", 90}};
  const auto it = kWords.find(w);
  return it == kWords.end() ? -1 : it->second;
}

// Applies a table of (pattern, replacement) pairs in order.
template <typename Table>
string ReplaceEach(string s, const Table& table) {
  for (const auto& [re, to] : table) s = std::regex_replace(s, re, to);
  return s;
}

}  // namespace

string Before(const string& s, size_t at, size_t n) { return at > n ? s.substr(at - n, n) : s.substr(0, at); }

// Lower-case ASCII, one space between words; every other byte (binary,
// UTF-8) becomes a space so the rules only ever see printable text. Vehicle
// references and numbers get one canonical form ("v2", "45").
string Normalise(std::string_view in, bool* numbered_by_report) {
  string s;
  s.reserve(in.size());
  bool space = false;
  for (unsigned char c : in) {
    const bool blank = c < 33 || c > 126;
    if (blank) {
      if (!space && !s.empty()) s += ' ';
      space = true;
    } else {
      s += static_cast<char>(std::tolower(c));
      space = false;
    }
  }
  static const regex kMph(R"(\bm\.p\.h\.?|\bmiles? per hour\b|\bmiles? an hour\b)");
  static const regex kKmh(R"(\bkm\s*/\s*hr?\b|\bkph\b|\bkmph\b|\bkm/h\b|\bkilometers per hour\b|\bkilometres per hour\b|\bkm per hour\b)");
  static const regex kOneWay(R"(\bone[- ]way\b)");
  static const regex kNonContact(R"(\bnon[- ]?contact\b)");
  // "40kph (25mph)": a unit written onto its number.
  static const regex kUnitOnNumber(R"((\d)(kph|kmph|kmh|km/hr?|mph)\b)");
  s = std::regex_replace(s, kUnitOnNumber, "$1 $2");
  s = std::regex_replace(s, kMph, "mph");
  s = std::regex_replace(s, kKmh, "kmh");
  s = std::regex_replace(s, kOneWay, "oneway");
  s = std::regex_replace(s, kNonContact, "noncontact");
  // "u.s. 30", "u.s. route 1": the route's name, not a sentence end.
  static const regex kUsRoute(R"(\bu\.\s?s\.\s*(?=\d|route\b|highway\b|hwy\b|rt\b))");
  s = std::regex_replace(s, kUsRoute, "us ");
  // NASS researchers' shorthand: "cpe v1: other vehicle stopped", "cr =
  // inadequate surveillance".
  static const regex kCpe(R"(\bcpe\b)");
  s = std::regex_replace(s, kCpe, "critical precrash event");
  static const regex kCr(R"(\bcr\b(?=\s*(?::|=|was\b|not\b|coded\b|for\b|v[1-9]\b|vehicle\b)))");
  s = std::regex_replace(s, kCr, "critical reason");
  static const regex kCodedEquals(R"((critical (?:precrash event|reason)[^=.;]{0,25}?)\s*=\s*)");
  s = std::regex_replace(s, kCodedEquals, "$1 was ");
  // "the roadway is signed at 80 km/h": posted.
  static const regex kSignedAt(R"(\b(?:sign-?posted|signed)\s+(?:at|for)\s+(?=\d))");
  s = std::regex_replace(s, kSignedAt, "posted at ");
  // "with its four-way flashers on": hazard lights, not a 4-way junction.
  static const regex kFourWayFlashers(R"(\b(?:4|four)[- ]way\s+(?=(?:emergency\s+|hazard\s+)?(?:flashers?|hazards?|lights|blinkers|signals)\b))");
  s = std::regex_replace(s, kFourWayFlashers, "hazard ");
  static const regex kSingleLane(R"(\bsingle[- ]lane\b)");
  s = std::regex_replace(s, kSingleLane, "1-lane");
  static const regex kSingleTravelLane(R"(\bsingle\s+(travel|through|traffic|(?:north|south|east|west)bound)\s+lane\b)");
  s = std::regex_replace(s, kSingleTravelLane, "1 $1 lane");
  // "the maximum speed allowed", "the legal speed": the limit.
  static const regex kLimitSynonym(
      R"(\b(?:maximum|max\.?)\s+(?:legal\s+|allowed\s+|allowable\s+|permitted\s+|posted\s+)?speed(?:\s+(?:allowed|permitted|limit))?\b|\b(?:legal|lawful)\s+speed(?:\s+limit)?\b)");
  s = std::regex_replace(s, kLimitSynonym, "speed limit");
  // Police shorthand for sides and roads: "struck the l side", "turn l",
  // "w/ r signal on", "the lf corner", "w/o", "t-int", "sr 14", "ped".
  static const regex kWithout(R"(\bw/o\b\s*)");
  s = std::regex_replace(s, kWithout, "without ");
  static const regex kWith(R"(\bw/\s*)");
  s = std::regex_replace(s, kWith, "with ");
  static const regex kTurnSide(R"(\b(turn(?:ed|ing|s)?)\s+([lr])\b(?!-))");
  s = ReplaceWith(s, kTurnSide, [](const smatch& m) { return m[1].str() + (m[2].str() == "l" ? " left" : " right"); });
  static const regex kSideWord(
      R"(\b([lr])\s+(?=(?:side|front|rear|door|quarter|fender|lane|turn|signal|blinker|corner|mirror|shoulder|curve)\b))");
  s = ReplaceWith(s, kSideWord, [](const smatch& m) { return string(m[1].str() == "l" ? "left " : "right "); });
  static const regex kCorner(R"(\b(the|its|his|her|their)\s+([lr])/?([fr])\b)");
  s = ReplaceWith(s, kCorner, [](const smatch& m) {
    return m[1].str() + (m[2].str() == "l" ? " left" : " right") + (m[3].str() == "f" ? " front" : " rear");
  });
  static const regex kTInt(R"(\bt-int\b\.?)");
  s = std::regex_replace(s, kTInt, "t-intersection");
  static const regex kRoutes(R"(\b(?:sr|rte|rt)\s*(?=\d))");
  s = std::regex_replace(s, kRoutes, "route ");
  static const regex kPed(R"(\bped\b\.?)");
  s = std::regex_replace(s, kPed, "pedestrian");
  // Police abbreviations ("nb on elm st", "a 4 ln rdwy") and the present
  // tense police narratives are often in ("v1 is traveling north ... v2 has
  // been stopped ... the front of v1 strikes": the rules read the
  // investigators' past tense), whole words, in one pass.
  static const std::map<string, string> kWords = {
      {"nb", "northbound"}, {"sb", "southbound"}, {"eb", "eastbound"},  {"wb", "westbound"},
      {"lns", "lanes"},     {"ln", "lane"},       {"rdwy", "roadway"},  {"intx", "intersection"},
      {"intersec", "intersection"}, {"hwy", "highway"},
      {"is", "was"},        {"are", "were"},      {"has", "had"},       {"have", "had"},
      {"does", "did"},      {"strikes", "struck"}, {"impacts", "impacted"}, {"contacts", "contacted"},
      {"collides", "collided"}, {"comes", "came"}};
  static const regex kWordsPattern = [] {
    string alt;
    for (const auto& [from, to] : kWords) alt += (alt.empty() ? "" : "|") + from;
    return regex(R"(\b()" + alt + R"()\b)");
  }();
  s = ReplaceWith(s, kWordsPattern, [](const smatch& m) { return kWords.at(m[1].str()); });
  static const regex kSays(R"(\b(he|she|driver|it|v[1-9]) (?:states|says)\b)");
  s = std::regex_replace(s, kSays, "$1 stated");
  // Number words: "forty-five" -> 45, "two" -> 2.
  static const regex kCompound(
      R"(\b(twenty|thirty|forty|fifty|sixty|seventy|eighty|ninety)[- ](one|two|three|four|five|six|seven|eight|nine)\b)");
  s = ReplaceWith(s, kCompound, [](const smatch& m) { return std::to_string(NumberWord(m[1]) + NumberWord(m[2])); });
  static const regex kWord(
      R"(\b(one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|thirteen|fourteen|fifteen|sixteen|seventeen|eighteen|nineteen|twenty|thirty|forty|fifty|sixty|seventy|eighty|ninety)\b)");
  s = ReplaceWith(s, kWord, [](const smatch& m) { return std::to_string(NumberWord(m[1])); });
  static const std::array<std::pair<regex, const char*>, 5> kOrdinals = {{
      {regex(R"(\bfirst\b)"), "1st"},
      {regex(R"(\bsecond\b)"), "2nd"},
      {regex(R"(\bthird\b)"), "3rd"},
      {regex(R"(\bfourth\b)"), "4th"},
      {regex(R"(\bfifth\b)"), "5th"},
  }};
  s = ReplaceEach(s, kOrdinals);
  // An approach told by its lanes: "its southbound approach had a left-turn
  // lane and a right-turn lane" (2 southbound lanes), "the northbound side
  // had 2 through lanes and a left-turn lane" (3).
  static const regex kApproachLanes(
      R"(\b(north|south|east|west)bound\s+(approach|side|leg)\s+(had|has|consisted of|included)\s+(?:(\d)\s+(?:through|travel)\s+lanes?|(?:a|an|1)\s+(?:left|right)[- ]turn(?:[- ]only)?\s+lane)\s+(?:and|plus)\s+(?:a|an|1)\s+(?:left|right)[- ]turn(?:[- ]only)?\s+lane\b)");
  s = ReplaceWith(s, kApproachLanes, [](const smatch& m) {
    const int n = (m[4].matched ? std::stoi(m[4].str()) : 1) + 1;
    return m[1].str() + "bound " + m[2].str() + " " + m[3].str() + " " + std::to_string(n) + " " + m[1].str() +
           "bound lanes";
  });
  // Vehicle references: "vehicle #1", "vehicle no. 2", "veh. 3", "v-1", "unit 2".
  // A number followed by a unit ("car 2 mph", "unit 3 lanes") is not a
  // vehicle, nor a body style's ("a honda cr-v 4-door").
  static const string kNotAUnit =
      R"((?!\s*(?:mph|kmh|%|m\b|meters|feet|ft|seconds|minutes?|hours?|miles?|mi\b|lanes?|year|yr|-?doors?\b|-?dr\b)))";
  static const regex kVehicle(
      R"(\b(?:vehicle|veh\.?|unit|v|car|auto|driver)\s*(?:number\s*|no\.\s*|#\s*|-\s*)?([1-9])\b)" + kNotAUnit);
  s = std::regex_replace(s, kVehicle, "v$1");
  // Lettered vehicles ("car a ran the stop sign and t-boned car b", "vehicle
  // a", "unit b"): a to d are v1 to v4 when the text letters at least two
  // with the same noun ("drove the car a short way" letters none).
  static const regex kLettered(R"(\b(vehicle|car|unit|auto|truck|driver)\s+([a-d])\b(?!-))");
  {
    std::map<string, std::set<char>> letters;
    for (auto it = std::sregex_iterator(s.begin(), s.end(), kLettered); it != std::sregex_iterator(); ++it) {
      letters[(*it)[1].str()].insert((*it)[2].str()[0]);
    }
    std::set<string> lettering;
    for (const auto& [noun, used] : letters) {
      if (used.count('a') && used.count('b')) lettering.insert(noun);
    }
    if (!lettering.empty()) {
      s = ReplaceWith(s, kLettered, [&](const smatch& m) {
        if (!lettering.count(m[1].str())) return m[0].str();
        return "v" + std::to_string(m[2].str()[0] - 'a' + 1);
      });
    }
  }
  // Several vehicles named at once: "vehicles 3 and 4", "vehicles #2, #3 and
  // #4" are "v3 and v4", each a reference of its own.
  static const regex kVehicles(R"(\bvehicles\s*#?\s*([1-9])((?:\s*,\s*#?\s*[1-9])*)\s*,?\s*(?:and|&)\s*#?\s*([1-9])\b)" + kNotAUnit);
  s = ReplaceWith(s, kVehicles, [](const smatch& m) {
    string out = "v" + m[1].str();
    const string mid = m[2].str();
    for (char c : mid)
      if (c >= '1' && c <= '9') out += ", v" + string(1, c);
    return out + " and v" + m[3].str();
  });
  // Police shorthand: "u2" (unit 2) and "d1" (driver 1), only as whole words.
  static const regex kShortRef(R"(\b[ud]-?([1-9])\b)" + kNotAUnit);
  s = std::regex_replace(s, kShortRef, "v$1");
  // "the v1 driver told the investigator": the driver of v1.
  static const regex kNumberedDriver(R"(\bthe\s+v([1-9])\s+(driver|operator)\b)");
  s = std::regex_replace(s, kNumberedDriver, "the $2 of v$1");
  static const regex kNumberedRef(R"(\bv[1-9]\b)");
  if (numbered_by_report != nullptr) *numbered_by_report = Has(s, kNumberedRef);
  // "the first vehicle", "the 2nd car" (ordinals are digits by now).
  // Not a place in a queue: "the 3rd vehicle in a queue waiting for the light",
  // "the 4th car in the eastbound queue".
  static const regex kOrdinalVehicle(
      R"(\b((?:a|an|another)\s+)?(?:the\s+)?([1-4])(?:st|nd|rd|th)\s+(?:vehicle|car|unit|auto)\b(?!\s+(?:in\s+(?:a\s+|the\s+)?(?:[\w-]+\s+)?(?:queue|line)|from\s+the\s+(?:front|light|signal|stop)|stopped|waiting)\b))");
  // (Nor "a second car carrying friends": one more car, not the second.)
  s = ReplaceWith(s, kOrdinalVehicle, [](const smatch& m) { return m[1].matched ? m[0].str() : "v" + m[2].str(); });
  // A CIREN summary that never numbers its case vehicle ("the case vehicle,
  // a 2002 toyota camry, ... v2, a 2000 ford f-150"): the case vehicle is v1.
  // Once numbered ("v1 (case vehicle)", "the case vehicle (v1)", "v1, the
  // case vehicle,"), "the driver of the case vehicle stated" is that one's.
  static const regex kCaseDeclared(
      R"(\bv([1-9])\s*(?:\(\s*|,\s*|-\s*)(?:the\s+)?case vehicle\b|\bcase vehicle\s*(?:\(\s*|,\s*)v([1-9])\b)");
  static const regex kCaseAside(R"(\s*,\s*(?:the\s+)?case vehicle\s*,)");
  static const regex kCaseInBrackets(R"(\s*[,-]\s*(?:the\s+)?case vehicle\s*(?=\)))");
  static const regex kCaseVehicle(R"(\b(?:the\s+)?case vehicle\b)");
  static const regex kAnyV1(R"(\bv1\b)");
  if (smatch cm; std::regex_search(s, cm, kCaseDeclared) || !Has(s, kAnyV1)) {
    const string who = cm.empty() ? "v1" : "v" + (cm[1].matched ? cm[1].str() : cm[2].str());
    s = std::regex_replace(s, kCaseAside, ",");
    s = std::regex_replace(s, kCaseInBrackets, "");
    s = std::regex_replace(s, kCaseVehicle, who);
  }
  // "v1 (v1 - case vehicle)" and "the ford taurus (v1)" are one reference.
  static const regex kRepeat(R"(\bv([1-9])\s*\(\s*v\1\b[^()]{0,40}\))");
  s = std::regex_replace(s, kRepeat, "v$1");
  // The name is the last "the" before the number, within its sentence: in
  // "rest in the northbound lanes. the mercury sable (v1) was driven" only
  // "the mercury sable" is v1.
  // A name with its model year is the vehicle's description, kept in the
  // usual form: "the 2002 dodge caravan (v1) was southbound" reads as "v1, a
  // 2002 dodge caravan, was southbound".
  // "the striking vehicle, a 2002 chevrolet tahoe (v2), and the turning
  // vehicle, ...": the role names the vehicle wherever it recurs.
  {
    static const regex kRoleNamed(
        R"(\bthe\s+(striking|struck|turning|other|lead|leading|following|crossing|oncoming|stopped|merging|passing|backing)\s+vehicle\s*,\s*(?:an?\s+)?([^,;()]{3,50}?)\s*\(\s*v([1-9])\s*\))");
    std::map<string, string> roles;
    for (auto it = std::sregex_iterator(s.begin(), s.end(), kRoleNamed); it != std::sregex_iterator(); ++it) {
      const string role = (*it)[1].str(), v = "v" + (*it)[3].str();
      if (roles.count(role) && roles[role] != v) roles[role].clear();  // two vehicles share it: no alias
      else roles[role] = v;
    }
    // ... and is told as a description: "v2, a 2002 chevrolet tahoe".
    s = ReplaceWith(s, kRoleNamed, [](const smatch& m) { return "v" + m[3].str() + ", a " + m[2].str(); });
    for (const auto& [role, v] : roles) {
      if (v.empty()) continue;
      s = std::regex_replace(s, regex(R"(\bthe\s+)" + role + R"(\s+vehicle\b(?!\s*,\s*an?\s))"), v);
    }
  }
  // "the mitsubishi (v1), a 2000 eclipse coupe," names the make first:
  // "v1, a 2000 mitsubishi eclipse coupe,".
  static const regex kMakeThenModel(
      R"(\bthe\s+([a-z][a-z-]+(?:\s+[a-z][a-z-]+)?)\s*\(\s*v([1-9])\s*\)\s*,\s*an?\s+((?:19|20)\d\d)\s+)");
  s = std::regex_replace(s, kMakeThenModel, "v$2, a $3 $1 ");
  // "the volvo, a 1996 850 sedan (v2), had been parked": numbered after its
  // description, "v2, a 1996 volvo 850 sedan, had been parked".
  static const regex kMakeThenDescription(
      R"(\bthe\s+([a-z][a-z-]+)\s*,\s*an?\s+((?:19|20)\d\d)\s+([^,;().]{1,40}?)\s*\(\s*v([1-9])\s*\))");
  s = ReplaceWith(s, kMakeThenDescription, [](const smatch& m) {
    const string make = m[1].str(), rest = m[3].str();
    const bool named = rest.rfind(make, 0) == 0;  // "the honda, a 2004 honda civic (v2)"
    return "v" + m[4].str() + ", a " + m[2].str() + " " + (named ? rest : make + " " + rest);
  });
  // "struck a legally parked, unoccupied 1994 oldsmobile cutlass ciera
  // (v2)": the vehicle with its description and then how it stood, "v2, a
  // 1994 ... ciera, which was legally parked unoccupied,".
  static const regex kDescribedThenNumbered(
      R"(\b(?:a|an)\s+((?:[a-z-]+,?\s+){0,3}?(?:parked|unoccupied),?\s+(?:[a-z-]+,?\s+){0,2}?)((?:19|20)\d\d\s+[a-z][^,;().]{1,40}?)\s*\(\s*v([1-9])\s*\)(\s*,)?)");
  s = ReplaceWith(s, kDescribedThenNumbered, [](const smatch& m) {
    string state = m[1].str();  // "legally parked, unoccupied": how it stood, after what it is
    state.erase(std::remove(state.begin(), state.end(), ','), state.end());
    while (!state.empty() && state.back() == ' ') state.pop_back();
    return "v" + m[3].str() + ", a " + m[2].str() + ", which was " + state + ",";
  });
  static const regex kNamed(
      R"(\bthe\s+((?:(?:19|20)\d\d\s+)?[a-z](?:(?!\.\s|\bthe\s)[a-z0-9/&'. -]){1,40}?)\s*\(\s*v([1-9])\s*\)(\s*,)?)");
  std::map<string, std::set<string>> numbered_names;  // "chevrolet" -> {"1"}
  s = ReplaceWith(s, kNamed, [&](const std::smatch& m) {
    const string name = m[1].str();
    const bool year = name.size() > 5 && (name.compare(0, 2, "19") == 0 || name.compare(0, 2, "20") == 0) &&
                      std::isdigit(static_cast<unsigned char>(name[2])) && std::isdigit(static_cast<unsigned char>(name[3])) && name[4] == ' ';
    if (year) return "v" + m[2].str() + ", a " + name + ",";
    // "the parked ranger (v2)": the ranger, and how it stood.
    static const regex kState("^" + StandingWord() + R"(\s+)");
    smatch sm;
    if (std::regex_search(name, sm, kState)) {
      numbered_names[sm.suffix().str()].insert(m[2].str());
      return "the " + sm[1].str() + " v" + m[2].str() + (m[3].matched ? m[3].str() : string());
    }
    numbered_names[name].insert(m[2].str());
    return "v" + m[2].str() + (m[3].matched ? m[3].str() : string());
  });
  // A report that names its vehicles by make and numbers them only at the
  // end: "the lincoln was coded as v1", "v2, the jetta, had ...", "the van
  // was numbered v2 and the saturn v1". An explicit numbering may name a
  // class word too ("the van").
  std::set<string> declared;
  {
    static const regex kCodedAs(
        R"(\bthe\s+([a-z][a-z0-9-]+(?:\s+[a-z][a-z0-9-]+)?)\s+(?:was|is)\s+(?:coded|numbered|designated|assigned|labell?ed|listed|identified|referred to)\s+(?:as\s+)?v([1-9])\b(?:\s+and\s+the\s+([a-z][a-z0-9-]+)\s+(?:as\s+)?v([1-9])\b)?)");
    static const regex kNumberedThe(R"(\bv([1-9])\s*,\s*the\s+([a-z][a-z0-9-]+)\s*,)");
    static const regex kNotAName(R"(^(?:vehicle|car|driver|other|first|second|third|striking|struck|case|bullet|target|lead|following|front|rear)$)");
    auto declare = [&](const string& name, const string& number) {
      if (Has(name, kNotAName)) return;
      numbered_names[name].insert(number);
      declared.insert(name);
    };
    for (auto it = std::sregex_iterator(s.begin(), s.end(), kCodedAs); it != std::sregex_iterator(); ++it) {
      declare((*it)[1].str(), (*it)[2].str());
      if ((*it)[3].matched) declare((*it)[3].str(), (*it)[4].str());
    }
    for (auto it = std::sregex_iterator(s.begin(), s.end(), kNumberedThe); it != std::sregex_iterator(); ++it) {
      declare((*it)[2].str(), (*it)[1].str());
    }
    // ... and the make of a model so numbered: "the volkswagen, a 2002
    // jetta" when the jetta is v2.
    if (!declared.empty()) {
      static const regex kMakeOfModel(R"(\bthe\s+([a-z][a-z-]+)\s*,\s*an?\s+(?:19|20)\d\d\s+([a-z][a-z0-9-]+)\b)");
      for (auto it = std::sregex_iterator(s.begin(), s.end(), kMakeOfModel); it != std::sregex_iterator(); ++it) {
        const auto model = numbered_names.find((*it)[2].str());
        if (model != numbered_names.end() && model->second.size() == 1 && !numbered_names.count((*it)[1].str())) {
          declare((*it)[1].str(), *model->second.begin());
        }
      }
    }
  }
  // A make or model numbered once ("the xterra (v1) was southbound") names
  // that vehicle wherever else it recurs ("struck the left side of the
  // xterra"); a class word ("the pickup (v2)") may be another's too.
  {
    static const regex kGeneric(
        R"(^(?:(?:\w+\s+)?(?:vehicle|car|truck|pickup|van|minivan|suv|sedan|coupe|wagon|bus|motorcycle|semi|tractor|trailer|taxi|cab|jeep|unit|driver)s?|other|first|second|third|striking|struck)$)");
    for (const auto& [name, numbers] : numbered_names) {
      if (numbers.size() != 1 || name.size() < 3 || (!declared.count(name) && (name.size() < 4 || Has(name, kGeneric)))) {
        continue;
      }
      // (With how it stood: "the parked ranger" is "the parked v2".)
      const regex again(R"(\bthe\s+(?:)" + StandingWord() + R"(\s+)?)" + EscapeRegex(name) + R"(\b(?!\s*\())");
      const string v = "v" + *numbers.begin();
      s = ReplaceWith(s, again, [&v](const smatch& am) { return am[1].matched ? "the " + am[1].str() + " " + v : v; });
    }
  }
  // A vehicle introduced by make and numbered only later ("a 2005 chevrolet
  // malibu was northbound ... the driver of the chevrolet (vehicle 1)"):
  // the introduction is that vehicle's description.
  static const regex kAnyNumberedIntro(R"(\bv[1-9]\s*,\s*an?\s+(?:19|20)\d\d\b)");
  if (!Has(s, kAnyNumberedIntro)) {
    for (const auto& [name, numbers] : numbered_names) {
      if (numbers.size() != 1 || name.size() < 3) continue;
      const regex intro(R"(\b(?:a|an)\s+((?:19|20)\d\d\s+)()" + EscapeRegex(name) +
                        R"(\b[a-z0-9 -]{0,30}?)(?=\s+(?:was|were|had|is)\b))");
      smatch im;
      if (std::regex_search(s, im, intro)) {
        s = im.prefix().str() + "v" + *numbers.begin() + ", a " + im[1].str() + im[2].str() + "," + im.suffix().str();
      }
    }
  }
  return s;
}

// Reports and descriptions that number no vehicle ("a red sedan ran the
// light and t-boned a white suv", "my car was stopped when a pickup
// rear-ended me", "the trailblazer (2007 chevrolet trailblazer) was
// southbound ... struck a northbound 2004 toyota tundra pickup"). The
// narrator's vehicle becomes v1 ("my car", "i", "me"); "the first car" and
// "the case vehicle" keep the numbers they were given; then each vehicle
// introduced ("a", "an", "another", "the other vehicle, a ...", a make named
// with its model year in brackets, "someone", "my husband's f-150") takes the
// next number in order of first mention. A later "the suv", "the tundra",
// "the truck" refers back when only one vehicle has that word. The noun
// phrases are kept as the vehicles' descriptions.
Numbered NameUnnumberedVehicles(const string& s, bool numbered_by_report) {
  if (numbered_by_report) return {s, {}};
  static const string kNoun =
      R"((car|sedan|coupe|hatchback|wagon|suv|jeep|pickup(?: truck)?|truck|van|minivan|motorcycle|motorbike|bus|tractor-trailer|semi|taxi|cab|vehicle))";
  // Makes, and models no other word is spelled as ("a corolla", "a white
  // f-150"; not "an escape", "a pilot", "a ranger").
  static const string kMakes =
      R"((ford|toyota|honda|chevrolet|chevy|nissan|hyundai|kia|subaru|mazda|dodge|volkswagen|vw|bmw|mercedes|audi|lexus|acura|infiniti|buick|cadillac|gmc|chrysler|pontiac|saturn|mitsubishi|volvo|tesla|lincoln|mercury|plymouth|oldsmobile|suzuki|isuzu|saab|mini|fiat|peugeot|renault|vauxhall|skoda|seat|citroen|)"
      R"(corolla|camry|civic|altima|sentra|maxima|f-150|f-250|f-350|silverado|tahoe|taurus|malibu|impala|cruze|cavalier|jetta|passat|prius|rav4|rav-4|cr-v|highlander|tacoma|tundra|4runner|wrangler|cherokee|outback|forester|impreza|elantra|sonata|optima|caravan|odyssey|sienna|camaro|corvette|equinox|trailblazer|durango|windstar|econoline|lesabre|sportage|sorento|murano|xterra|outlander|tiguan|miata|neon|sebring|cobalt|blazer|s-10|escalade|yukon|explorer|mustang))";
  static const string kColour =
      R"((?:(?:(?:dark|light|bright)\s+)?(?:white|black|silver|gray|grey|red|blue|green|gold|maroon|tan|beige|brown|yellow|orange|purple|burgundy)\s+))";
  static const string kKin =
      R"((?:husband|wife|son|daughter|mom|mother|dad|father|brother|sister|friend|boyfriend|girlfriend|partner|neighbou?r|coworker|boss|grandmother|grandfather|aunt|uncle|cousin)'s)";
  // Words that end a vehicle's name: "a 2004 ford taurus was", "... that".
  static const string kNameEnd =
      R"((?!was\b|were\b|is\b|that\b|which\b|who\b|and\b|lost\b|left\b|in\b|on\b|at\b|with\b|driven\b|travel\w*|going\b|heading\b|headed\b|had\b|hit\b|struck\b|pulling\b|towing\b|hauling\b|from\b|to\b|into\b|for\b|of\b|as\b|by\b|when\b|while\b|but\b|then\b|ran\b|came\b|crossed\b|turned\b|stopped\b))";
  // Group 1: the phrase without its article (noun included); group 2: the noun.
  static const regex kMine(R"(\bmy\s+(?!)" + kKin + R"()((?:[a-z0-9-]+\s+){0,2}?)" + kNoun + R"()\b)");
  // "a red suv", "another car" (groups 1, 2), a model year, after at most
  // two words ("a northbound 2004 toyota tundra pickup", groups 3, 4), a make
  // with its model: "a white ford explorer" (groups 5, 6), a rider or driver
  // named for the vehicle: "a motorcyclist" (group 7), a person: "someone"
  // (group 8), once the narrator is v1, "the car behind me" (groups 9, 10),
  // a name with its model year in brackets: "the trailblazer (2007
  // chevrolet trailblazer)" (groups 11, 12), and a relative's: "my
  // husband's f-150" (group 13).
  // Where another vehicle is, seen from one already named: "the car behind
  // it", "the guy on v1's right", "the truck in the right lane".
  static const string kPlace =
      R"((?:(?:behind|ahead of|in front of|next to|beside|alongside)\s+(?:v1|it|him|her|them|us)\b|(?:on|to)\s+v1's\s+(?:left|right)\b|in\s+the\s+(?:[a-z]+\s+)?lane\b|(?:coming|going|traveling|heading)\s+(?:the\s+other\s+way|in\s+the\s+opposite\s+direction)\b|from\s+the\s+(?:opposite|other)\s+direction\b))";
  static const regex kIntro(
      R"(\b(?:a|an|another)\s+((?:(?!a\b|an\b|the\b)[a-z0-9-]+\s+){0,3}?)" + kNoun +
      // (Not a place named for vehicles: "witnesses in a bus shelter".)
      R"()\b(?!\s+(?:shelter|stop|station|depot|bench|wash|dealership|dealer|lot|garage|repair|shop|park)\b)|\b(?:a|an)\s+(?:(?!a\b|an\b|the\b)[a-z-]+\s+){0,2}?((?:19|20)\d\d\s+([a-z][a-z0-9-]*)(?:\s+)" +
      kNameEnd + R"([a-z0-9][a-z0-9-]*){0,3}))" + R"(|\b(?:a|an)\s+()" + kColour + R"(?)" + kMakes + R"((?:\s+)" +
      kNameEnd + R"([a-z0-9][a-z0-9-]*)?)\b)" +
      R"(|\b(?:a|an)\s+(motorcyclist|motorist)\b|\b(someone|somebody)\b|\bthe\s+(?:other\s+)?)" + kColour +
      R"(?()" + kNoun.substr(0, kNoun.size() - 1) + R"(|guy|man|woman|lady|person|kid))(?=\s+)" + kPlace + R"())" +
      R"(|\bthe\s+([a-z][a-z0-9-]*(?:\s+[a-z][a-z0-9-]*)?)\s*\(\s*((?:19|20)\d\d\s+[a-z][^()]{1,40}?)\s*\))" +
      R"(|\bmy\s+)" + kKin + R"(\s+([a-z0-9-]+(?:\s+)" + kNameEnd + R"([a-z0-9][a-z0-9-]*)?))" +
      R"(|(?:^|[.!?]\s+)(the\s+)" + kColour + R"(?(?:[a-z-]+\s+)??)" + kNoun + R"(\b(?!\s*\()))");
  // "the sedan, a kia optima," and "it was a nissan altima" describe a
  // vehicle already named; "the other vehicle, a 2011 kia forte," names one
  // (group 1: the noun phrase).
  static const regex kAppositive(R"((\bthe\s+(?:[a-z0-9-]+\s+){0,2}?)" + kNoun + R"(\s*,\s*|\bit (?:was|is)\s+)$)");
  // "v1, a 2006 mercury grand marquis," and "v1 was a 2011 nissan altima"
  // describe the vehicle already numbered ("the case vehicle").
  static const regex kNumberedAppositive(R"(\bv([1-9])\s*(?:,|\(|\s+(?:was|is))\s*$)");
  // "a sedan, a kia optima,": a make or model year after an unnamed noun
  // names it (a list of vehicles names a noun each: "a car, a van and ...").
  static const regex kNamedAppositive(R"(\b(?:a|an)\s+(?:[a-z0-9-]+\s+){0,2}?)" + kNoun + R"(\s*,\s*$)");
  static const regex kFirstPerson(R"(\b(?:i|me)\b(?!-))");
  static const regex kMy(R"(\bmy\b)");
  static const regex kRef(R"(\bv([1-9])\b)");
  static const regex kWord(R"([a-z][a-z-]{2,})");
  // Words of a name that are no name of their own: "a 2006 mercury grand
  // marquis" is no "the grand".
  static const regex kNotAHead(
      R"(^(?:grand|town|city|country|sport|land|park|star|new|crew|club|extended|door|wheel|drive|model|series|limited|base|super|special|custom|classic|cargo|box|utility|passenger|four|two|full|size|compact|mid|light|heavy|duty|north\w*|south\w*|east\w*|west\w*|white|black|silver|gray|grey|red|blue|green|gold|maroon|tan|beige|brown|yellow|orange|purple|burgundy|dark|bright|other|older|newer|small|large|big|little|old|parked|unoccupied)$)");
  Numbered out{s, {}};
  std::map<string, int> owner;  // head word -> vehicle, 0 when two share it
  auto own = [&owner](const string& head, int v) {
    if (head.empty()) return;
    const auto at = owner.find(head);
    if (at == owner.end()) owner[head] = v;
    else if (at->second != v) at->second = 0;
  };
  // The words a phrase can be called by later: its class noun (with "truck"
  // for a pickup or a tractor, "car" for a sedan), its make and its model.
  auto heads_of = [&](const string& phrase) {
    std::vector<string> heads;
    for (auto it = std::sregex_iterator(phrase.begin(), phrase.end(), kWord); it != std::sregex_iterator(); ++it) {
      const string w = it->str();
      if (Has(w, kNotAHead)) continue;
      heads.push_back(w);
      if (w == "pickup" || w == "tractor" || w == "tractor-trailer" || w == "semi" || w == "semitrailer") heads.push_back("truck");
      if (w == "sedan" || w == "coupe" || w == "hatchback" || w == "wagon") heads.push_back("car");
    }
    return heads;
  };
  // An unnumbered "a 2011 kia forte sedan" or "a white ford explorer" is
  // later called by its make and model too; "a school bus" by "the bus".
  static const regex kYear(R"(\b(?:19|20)\d\d\s+)");
  static const regex kMakeWord(R"(\b)" + kMakes + R"((?:\s+([a-z][a-z0-9-]*))?)");
  auto name_heads = [&](const string& phrase, const string& noun) {
    smatch nm;
    if (std::regex_search(phrase, nm, kYear)) return heads_of(nm.suffix().str());
    std::vector<string> heads = heads_of(noun);
    if (std::regex_search(phrase, nm, kMakeWord)) {
      for (const string& w : heads_of(nm[0].str())) heads.push_back(w);
    }
    return heads;
  };
  int taken = 0;  // "the first car", "the case vehicle" (v1)
  for (auto it = std::sregex_iterator(s.begin(), s.end(), kRef); it != std::sregex_iterator(); ++it) {
    taken = std::max(taken, (*it)[1].str()[0] - '0');
  }
  int next = taken + 1;
  smatch m;
  if (taken == 0 && std::regex_search(out.text, m, kMine)) {
    own(m[2].str().substr(0, m[2].str().find(' ')), 1);
    out.descriptions[1] = m[1].str();
    out.text = std::regex_replace(std::regex_replace(out.text, kMine, "v1"), kFirstPerson, "v1");
    out.text = std::regex_replace(out.text, kMy, "v1's");  // "hit my passenger side", "into my lane"
    next = 2;
  } else if (static const regex kQuoted(R"("[^"]{0,400}")");
             taken == 0 && Has(std::regex_replace(out.text, kQuoted, " "), kFirstPerson)) {
    // A narrator known only as "i" / "me" drives v1; a quoted "i" is someone
    // else speaking ("'i saw it coming,' a witness said").
    out.text = std::regex_replace(out.text, kFirstPerson, "v1");
    out.text = std::regex_replace(out.text, kMy, "v1's");
    next = 2;
  }
  string rebuilt;
  int person = 0;  // a vehicle known by its driver: "a motorist", "someone"
  bool opened_definite = false;  // v1 was "the blue car" the text opened on
  auto from = out.text.cbegin();
  for (auto it = std::sregex_iterator(out.text.cbegin(), out.text.cend(), kIntro);
       it != std::sregex_iterator() && next <= 9; ++it) {
    const smatch& im = *it;
    std::vector<string> heads;
    string phrase;
    if (im[3].matched) {
      phrase = im[3].str();
      heads = heads_of(phrase.substr(5));
    } else if (im[5].matched) {
      phrase = im[5].str();
      heads = heads_of(phrase);
    } else if (im[7].matched) {
      const bool rider = im[7].str() == "motorcyclist";
      phrase = rider ? "motorcycle" : "car";
      heads = {im[7].str(), phrase};
    } else if (im[8].matched) {
      phrase = "car";
    } else if (im[9].matched) {
      // "the other car in the left lane" is the other one when there is one,
      // and "the truck in the right lane" the truck already met.
      const auto known = owner.find(im[10].str());
      if ((next > 2 && im.str().find("other") != string::npos) || (known != owner.end() && known->second > 1)) continue;
      phrase = im[9].str();
      heads = {};  // "the car behind me" is not what a later "the car" means
      static const regex kPersonWord(R"(^(?:guy|man|woman|lady|person|kid)$)");
      if (Has(im[10].str(), kPersonWord)) {
        phrase = "car";
        person = next;
      }
    } else if (im[14].matched) {
      // "the blue car stopped at the stop sign ...": a text that opens on a
      // vehicle by the definite article has introduced it.
      if (next != 1) continue;
      rebuilt.append(from, im[14].first);
      rebuilt += "v1";
      out.descriptions[1] = im[14].str().substr(4);
      for (const string& head : heads_of(im[14].str().substr(4))) own(head, 1);
      opened_definite = true;
      ++next;
      from = im[14].second;
      continue;
    } else if (im[11].matched) {
      // "the trailblazer (2007 chevrolet trailblazer)": a name once known.
      const auto known = owner.find(im[11].str());
      if (known != owner.end() && known->second > 0) continue;
      phrase = im[12].str();
      heads = heads_of(im[11].str() + " " + phrase.substr(5));
    } else if (im[13].matched) {
      phrase = im[13].str();
      heads = heads_of(phrase);
    } else {
      if (im[2].str() == "vehicle" && im.str().rfind("another", 0) != 0) continue;  // "a vehicle" is too vague to count
      phrase = im[1].str();
      heads = name_heads(phrase, im[2].str());
    }
    const size_t at = static_cast<size_t>(im[0].first - out.text.cbegin());
    const size_t back = std::min<size_t>(at, 60);
    const string before = out.text.substr(at - back, back);
    const bool intro = im[1].matched || im[3].matched || im[5].matched;
    smatch am;
    if (intro && std::regex_search(before, am, kNumberedAppositive)) {
      // "v1, a 2006 mercury grand marquis,": the case vehicle described.
      const int v = am[1].str()[0] - '0';
      if (!out.descriptions.count(v)) out.descriptions[v] = phrase;
      for (const string& head : heads) own(head, v);
      continue;
    }
    if (intro && std::regex_search(before, am, kAppositive)) {
      // "the sedan, a kia optima,": the sedan described; "the other vehicle,
      // a 2011 kia forte sedan,", a vehicle not named before, introduced.
      const string noun = am[2].matched ? am[2].str().substr(0, am[2].str().find(' ')) : string();
      const auto known = owner.find(noun);
      if (noun.empty() || (known != owner.end() && known->second > 0)) {
        if (!noun.empty()) {
          for (const string& head : heads) own(head, known->second);
        }
        continue;
      }
      const auto the = im[0].first - static_cast<std::ptrdiff_t>(am.length(0));
      if (the < from) continue;
      rebuilt.append(from, the);
      rebuilt += "v" + std::to_string(next) + ", ";
      out.descriptions[next] = phrase;
      for (const string& head : heads) own(head, next);
      ++next;
      from = im[0].first;
      continue;
    }
    // "the buick, a 1997 century driven by ...": the make names a vehicle
    // its model year introduces (or describes, when the make is known).
    static const regex kMakeAppositive(R"(\bthe\s+)" + kMakes + R"(\s*,\s*$)");
    if (im[3].matched && std::regex_search(before, am, kMakeAppositive)) {
      const string make = am[1].str();
      const auto known = owner.find(make);
      if (known != owner.end() && known->second > 0) {
        for (const string& head : heads) own(head, known->second);
        continue;
      }
      const auto the = im[0].first - static_cast<std::ptrdiff_t>(am.length(0));
      if (the < from) continue;
      rebuilt.append(from, the);
      rebuilt += "v" + std::to_string(next) + ", ";
      out.descriptions[next] = phrase;
      own(make, next);
      for (const string& head : heads) own(head, next);
      ++next;
      from = im[0].first;
      continue;
    }
    const bool follows_numbered = next > 1 && from != out.text.cbegin() && im[0].first - from <= 3;
    if ((im[3].matched || im[5].matched) && follows_numbered && std::regex_search(before, kNamedAppositive)) {
      out.descriptions[next - 1] = phrase;
      for (const string& head : heads) own(head, next - 1);
      continue;
    }
    rebuilt.append(from, im[0].first);
    rebuilt += "v" + std::to_string(next);
    if (im[11].matched) rebuilt += ", a " + phrase + ",";
    out.descriptions[next] = phrase;
    for (const string& head : heads) own(head, next);
    if ((im[7].matched && im[7].str() == "motorist") || im[8].matched) person = next;
    ++next;
    from = im[0].second;
  }
  rebuilt.append(from, out.text.cend());
  for (const auto& [head, v] : owner) {
    if (v == 0) continue;
    // (Keeping what says it never touched: "the noncontact pickup" is
    // "noncontact v2".)
    const regex the(R"(\bthe\s+((?:[a-z0-9-]+\s+){0,2}?))" + head + R"(\b(?!\s*\())");
    const string name = "v" + std::to_string(v);
    rebuilt = ReplaceWith(rebuilt, the, [&name](const smatch& tm) {
      return tm[1].str().find("noncontact") != string::npos ? "noncontact " + name : name;
    });
  }
  if (person > 0) {
    // "a motorist ... when her car was struck": the motorist's own car;
    // "someone turned ... and v1 hit their passenger side": its side.
    static const regex kTheirCar(R"(\b(?:his|her|their)\s+(?:car|vehicle)\b)");
    static const regex kTheirSide(R"(\b(?:his|her|their)\s+(?=(?:passenger|driver)'?s?[- ]?(?:side|door)\b|(?:front|rear|back|left|right)\b))");
    rebuilt = std::regex_replace(rebuilt, kTheirCar, "v" + std::to_string(person));
    rebuilt = std::regex_replace(rebuilt, kTheirSide, "v" + std::to_string(person) + "'s ");
  }
  if (next == 1 || (next == 2 && opened_definite)) {
    // One vehicle that is never introduced ("he was driving his car north
    // ... and struck a tree", "the driver of the car was westbound when she
    // ran off the road"): its driver and the car itself are v1.
    static const regex kOwnVehicle(R"(\b(?:the|his|her|their)\s+((?:[a-z0-9-]+\s+){0,2}?)" + kNoun + R"()\b)");
    static const regex kDriverPronoun(R"(\b(?:he|she)\b)");
    smatch om;
    if (std::regex_search(rebuilt, om, kOwnVehicle) || opened_definite) {
      if (!opened_definite) out.descriptions[1] = om[1].str() + om[2].str();
      // "he was driving v1 north": the driver's verb moves the vehicle.
      static const regex kDriving(R"(\b(?:he|she|the driver)\s+((?:was\s+)?(?:driving|drove|operating|operated))\s+(?:the|his|her|their)\s+(?:[a-z0-9-]+\s+){0,2}?)" + kNoun + R"(\b)");
      rebuilt = std::regex_replace(rebuilt, kDriving, "v1 was traveling");
      rebuilt = std::regex_replace(rebuilt, kOwnVehicle, "v1");
      rebuilt = std::regex_replace(rebuilt, kDriverPronoun, "v1");
    }
  }
  out.text = std::move(rebuilt);
  return out;
}

// How many different vehicles the references name.
size_t DistinctVehicles(const std::vector<Ref>& refs) {
  std::set<int> distinct;
  for (const Ref& ref : refs) distinct.insert(ref.vehicle);
  return distinct.size();
}

std::vector<Ref> RefsIn(const string& s) {
  static const regex kRef(R"(\bv([1-9])\b)");
  std::vector<Ref> out;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), kRef); it != std::sregex_iterator(); ++it) {
    out.push_back({static_cast<size_t>(it->position()), (*it)[1].str()[0] - '0'});
  }
  return out;
}

Kind KindOf(const string& s) {
  static const regex kCoding(
      R"(critical\s*(?:pre-?\s*crash|precrash|event|reason)|associated factor|\bwas coded\b|\bcoded (?:as|to|for)\b|\bwere coded\b)");
  static const regex kPeople(
      R"(injur|transported|year[- ]old|years old|\b\d+ year\b|medication|lenses|glasses|eyesight|fatigue|treatment|)"
      R"(hospital(?!'?s?\s+(?:road|campus|drive\w*|entrance|exit|parking|lot|access|street|avenue|boulevard|way|lane)\b)|trauma|ambulance|rested|health|alcohol|drugs|\bcited\b|citation|summons|ticket|interview|airbag|air bag|)"
      R"(seat ?belt|belted|occupant|passenger(?!'?s? (?:side|door|corner|fender|quarter)| (?:vehicles?|cars?))|\b(?:his|her) way\b|going home|heading home|errand|medical|license|)"
      R"(towed|driven from the scene|driven away|fled|contact lens|pregnan)");
  static const regex kStatement(
      R"(\b(?:stated|said|says|states|indicated|reported|advised|according to|recalled|estimated|told|admitted|claimed)\b)");
  // Who drove and who rode along is often folded into a motion sentence
  // ("v1, a 1996 cavalier driven by a 17-year old male, was traveling
  // south", "v2, a cr-v with one occupant, was stopped"): such phrases do not
  // make the sentence one about people.
  static const regex kPeoplePhrase(
      R"(\b(?:driven|operated|occupied) by (?:an? |the |its )?[^,;()]{0,40}?\b(?:male|female|man|woman|driver|operator|person|teen\w*|girl|boy|\d+[- ]year[- ]olds|adults|people|persons|students)\b(?:\s+with (?:a|an|his|her) [^,;()]{0,30}?\b(?:license|permit)\b)?|\bwith (?:\d+|no|an?|its) (?:\w+ )?(?:occupants?|passengers?)\b|\bwith an? [^,;()]{0,30}?\b(?:driver|operator)\b(?:\s+and\s+(?:\d+|no|an?)\s+(?:\w+\s+)?(?:passengers?|occupants?)\b)?|\b(?:the|its|his|her|v[1-9]'s) driver,\s+an?\s+[^,;()]{0,60},|\bthe\s+\d+[- ]year[- ]old\s+(?:male|female|man|woman)\s+(?:driver|driving|operating)\b|)"
      // ("driven by a 67-year-old retired farmer, was westbound".)
      R"(\b(?:driven|operated) by (?:an? |the )?\d+[- ]year[- ]old\b[^,;()]{0,30}|)"
      // ... nor the driver's age as the subject of the vehicle's movement
      // ("its 58-year-old driver stopped at the stop sign and began a right turn",
      // "v2's 66-year-old driver had his left signal on and was slowing").
      R"(\b(?:the|its|his|her|v[1-9]'s)\s+\d+[- ]year[- ]old\s+(?:male\s+|female\s+)?(?:driver|operator)(?:\s+of\s+v[1-9])?\s+(?=(?:then\s+)?(?:stopped|began|started|turned|pulled|slowed|braked|backed|accelerated|entered|proceeded|attempted|drove|steered|swerved|merged|changed|failed|did not|allowed|let|lost|drifted|veered|crossed|continued|ran|tried|made|moved|had (?:his|her|its|the) (?:left |right )?(?:turn )?signal on|had (?:just )?(?:stopped|slowed|begun|started|pulled|come|entered|turned|been (?:stopped|traveling|driving|waiting|slowing))|was (?:traveling|driving|going|stopped|slowing|turning|backing|attempting))\b)|,\s*who had [^,;()]{0,40}?passengers?\s*,|)"
      // ... nor who rode along ("was southbound ... with the driver's
      // 10-year-old grandson in the back seat").
      R"(\bwith (?:the driver's |his |her |their |a |an |two |three |\d+ )[^,;()]{0,40}?\b(?:son|daughter|grandson|granddaughter|child|children|kids?|wife|husband|mother|father|friends?|coworkers?|baby|infant|toddler|dog)s?\b(?:\s+(?:in the (?:back|rear|front) seat|aboard|along|on board))?|\bpassenger'?s?[- ](?:side|door|front|rear|corner|fender)\b)");
  if (Has(s, kCoding)) return Kind::kCoding;
  if (Has(s, kStatement)) return Kind::kStatement;
  if (Has(std::regex_replace(s, kPeoplePhrase, " "), kPeople)) return Kind::kPeople;
  return Kind::kNarrative;
}

// Sentences split at '.', '!', '?' or ';' unless inside a number ("2.5"),
// after a common abbreviation, or after a single letter ("u.s.", not the
// end of "cr-v."); run-on
// sentences ("roadway.The driver") split too.
std::vector<string> SplitSentences(const string& s) {
  static const std::set<string> kAbbrev = {"approx", "no", "st", "ave", "mr", "mrs", "ms", "dr", "vs", "etc",
                                           "hwy", "rd", "ft", "jr", "sr", "blvd", "e.g", "i.e", "est", "veh"};
  std::vector<string> out;
  string cur;
  auto flush = [&]() {
    size_t a = cur.find_first_not_of(' ');
    if (a != string::npos) {
      string t = cur.substr(a);
      // Bound the sentence length; cut at the last comma before the limit.
      while (t.size() > kMaxSentence) {
        size_t cut = t.rfind(", ", kMaxSentence);
        if (cut == string::npos || cut < kMaxSentence / 3) cut = t.rfind(' ', kMaxSentence);
        if (cut == string::npos || cut == 0) cut = kMaxSentence;
        out.push_back(t.substr(0, cut) + " ");
        t = t.substr(cut);
      }
      out.push_back(t + " ");
    }
    cur.clear();
  };
  for (size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '.' || c == '!' || c == '?' || c == ';') {
      const bool digit_before = i > 0 && std::isdigit(static_cast<unsigned char>(s[i - 1]));
      const bool digit_after = i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1]));
      if (c == '.' && digit_before && digit_after) {
        cur += c;
        continue;
      }
      if (c == '.') {
        size_t w = cur.size();
        while (w > 0 && (std::isalpha(static_cast<unsigned char>(cur[w - 1])) || cur[w - 1] == '.')) --w;
        const string word = cur.substr(w);
        // A letter ending a hyphenated model ("the cr-v. both ...") is no initial.
        const bool initial = word.size() == 1 && (w == 0 || cur[w - 1] != '-');
        // Dotted initials ("a divided u.s. route", "the u.s.a.").
        static const regex kInitials(R"(^(?:[a-z]\.)+[a-z]$)");
        if (kAbbrev.count(word) || initial || Has(word, kInitials)) {
          cur += c;
          continue;
        }
      }
      flush();
    } else {
      cur += c;
    }
  }
  flush();
  return out;
}

// ---------------------------------------------------------------- vehicles

VehicleClass ClassOf(const string& d) {
  static const regex kMotorcycle(R"(motorcycle|motorbike|scooter|moped|harley|kawasaki|\bducati|\byamaha\b.*\b(?:r1|r6)\b)");
  static const regex kBus(R"(\bbus\b|coach|transit)");
  static const regex kPickup(
      R"(pick-?up|\bf-?[1-3]50\b|silverado|\bsierra|\bram\b|\bram \d|tacoma|\branger\b|tundra|dakota|\bs-?10\b|frontier|sonoma|colorado|canyon|avalanche|\bc-?[1-3]500\b|\bk-?[1-3]500\b)");
  static const regex kTruck(
      R"(tractor|semi|trailer|\btruck\b|freightliner|peterbilt|kenworth|\bmack\b|international|\bvolvo (?:vn|truck)|\bdump\b|box truck|\bm/h\b|straight truck)");
  static const regex kVan(
      R"(\bvan\b|minivan|caravan|voyager|windstar|freestar|odyssey|odessy|sienna|montana|trans ?sport|econoline|e-?series|g-?series|express|astro|vandura|savana|\bquest\b|villager|town (?:&|and) country|uplander|venture|safari|silhouette|\bmpv\b)");
  static const regex kSuv(
      R"(\bsuv\b|sport utility|utility vehicle|jeep|explorer|blazer|tahoe|suburban|4-?runner|\bcr-?v\b|rav-?4|expedition|durango|trailblazer|\bescape\b|pathfinder|yukon|envoy|cherokee|wrangler|montero|navajo|sequoia|\bpilot\b|\bmdx\b|forester|highlander|liberty|excursion|rodeo|trooper|bravada|jimmy|sorento|santa fe|xterra|land cruiser|mountaineer|rendezvous|equinox|murano|\belement\b|grand vitara|\bh2\b|hummer|range rover|\bx5\b|\bml ?\d{3}\b)");
  if (Has(d, kMotorcycle)) return VehicleClass::kMotorcycle;
  if (Has(d, kBus)) return VehicleClass::kBus;
  if (Has(d, kPickup)) return VehicleClass::kPickup;
  if (Has(d, kTruck)) return VehicleClass::kTruck;
  if (Has(d, kVan)) return VehicleClass::kVan;
  if (Has(d, kSuv)) return VehicleClass::kSuv;
  return VehicleClass::kCar;
}

// A junction named only as a distance away ("300 ft south of the next cross
// street", "halfway between 2 cross streets") is not where the crash was.
string WithoutDistantJunctions(const string& s) {
  static const regex kDistant(
      R"(\b\d+\s*(?:ft|feet|foot|m|meters?|metres?|yards?|yds?|miles?)\s+(?:north|south|east|west|before|after|past|beyond|short)\s+(?:of\s+|from\s+)?(?:the\s+|an?\s+)?(?:next\s+|nearest\s+)?(?:cross street|intersection|junction)\b|\b(?:halfway\s+|midway\s+)?between\s+(?:the\s+)?(?:2|two)\s+(?:cross streets|intersections|junctions)\b|\b(?:at|for|toward|towards|approaching|to|before)\s+the\s+next\s+(?:\w+\s+)?(?:intersection|junction|cross street)\b|\b(?:away from|not near|nowhere near|far from)\s+(?:any|an?|the)\s+[^.;,]{0,40})"
      // "there was no intersection or traffic control device at the crash
      // location", "not at an intersection".
      R"(|\b(?:no|not at an?|not at the|not within an?)\s+(?:intersection|junction|cross street)s?\b[^.;]{0,50})"
      // "the nearest ramp was about 700 meters away".
      // "having entered by way of an exit ramp approximately 5 km to the east".
      R"(|\b(?:ramp|interchange)\s+(?:approximately\s+|about\s+|some\s+|roughly\s+|nearly\s+)?\d+(?:\.\d+)?\s*(?:km|kilometers?|kilometres?|mi|miles?|m|meters?|metres?|ft|feet)\b[^.;]{0,25}|)"
      R"(\b(?:the\s+)?(?:nearest|closest)\s+(?:[\w/-]+\s+){0,2}?(?:on-?ramp|off-?ramp|ramp|intersection|junction|cross street|interchange)s?\b[^.;]{0,50}|)"
      // "backing toward the property's driveway, which was about 40 m
      // behind him".
      // ("turn right into a mall entrance about 60 m ahead".)
      R"(\b(?:driveway|entrance|exit)\s*,?\s+(?:(?:which|that)\s+(?:was|lay|sat|is)\s+)?(?:located\s+)?(?:approximately\s+|about\s+|some\s+|roughly\s+|nearly\s+)?\d+(?:\.\d+)?\s*(?:m|meters?|metres?|ft|feet|yards?)\s+(?:behind|ahead|away|back|beyond|further|farther)\b)");
  // A queue stopped for the light there is at it (intersection related):
  // "stopped for a red signal at the next intersection, 30 meters ahead".
  static const regex kQueuedForIt(
      R"(\b((?:stopped|waiting|queued|backed up|stopping)\s+(?:\w+\s+){0,3}?for\s+(?:a|the)\s+(?:red\s+)?(?:traffic\s+)?(?:light|signal)\s+at\s+the\s+)next\s+)");
  // One told far ahead of the crash: "slowing for congestion at a
  // signalized intersection about 600 meters ahead" (100 m or more).
  static const regex kFarAhead(
      R"(\b(?:intersection|junction|cross street)\s+(?:located\s+|situated\s+)?(?:approximately\s+|about\s+|some\s+|roughly\s+|nearly\s+|over\s+|more than\s+)?(\d+(?:\.\d+)?)\s*(km|kilomet\w+|mi|miles?|m|meters?|metres?|ft|feet|yards?|yds?)\s+(?:ahead|away|further on|farther on|down the road|up the road|beyond)\b)");
  const string far = ReplaceWith(s, kFarAhead, [](const smatch& m) {
    const double n = std::stod(m[1].str());
    const string unit = m[2].str();
    const double metres = unit[0] == 'k'               ? n * 1000
                          : unit.rfind("mi", 0) == 0   ? n * 1609
                          : unit[0] == 'f'             ? n * 0.3048
                          : unit[0] == 'y'             ? n * 0.9144
                                                       : n;
    return metres >= 100 ? string(" ") : m.str();
  });
  return std::regex_replace(std::regex_replace(far, kQueuedForIt, "$1"), kDistant, " ");
}

string EscapeRegex(const string& s) {
  string out;
  for (char c : s) {
    if (std::string_view("\\^$.|?*+()[]{}/").find(c) != std::string_view::npos) out += '\\';
    out += c;
  }
  return out;
}

std::optional<Compass> CompassWord(const string& w) {
  if (w.rfind("north", 0) == 0) return Compass::kNorth;
  if (w.rfind("south", 0) == 0) return Compass::kSouth;
  if (w.rfind("east", 0) == 0) return Compass::kEast;
  if (w.rfind("west", 0) == 0) return Compass::kWest;
  return std::nullopt;
}

// The first direction of travel stated in a piece of text about one vehicle.
std::optional<Compass> DirectionIn(const string& s) {
  static const regex kDir(
      R"(\b(north|south|east|west)[- ]?bound\b|\b(?:travel+(?:ing|ed|s)?|heading|headed|going|proceeding|proceeded|driving|moving|facing|approaching from the|turn(?:ing|ed)?)\s+(?:due\s+)?(north|south|east|west)\b(?![/-]?(?:east|west))|\bin an? (north|south|east|west)(?:erly|ern)? direction)");
  // "in its westbound lane traveling east": a lane's direction is where the
  // vehicle is, a verb of travel says where it goes; the verb wins.
  static const regex kBoundLane(R"(^\w+[- ]?bound\s+(?:travel\s+|through\s+)?lanes?\b)");
  // "intending to turn left and travel west", "to go east": where it meant
  // to go, not how it came.
  static const regex kIntended(
      R"(\b(?:intend\w*|intention|plann\w*|wanted|to turn|turn (?:left|right) and|to (?:go|travel|head|proceed))\b[^.,;]{0,30}$)");
  // "waiting for westbound traffic to clear": the others' direction.
  static const regex kOthersTraffic(R"(^\w+[- ]?bound\s+(?:[\w-]+\s+)?(?:traffic|vehicles|cars)\b)");
  static const regex kWaitedFor(
      R"(\b(?:waiting|waited|wait|yield\w*|watching|looking)\s+(?:for|to|at)\s+(?:the\s+|any\s+)?(?:oncoming\s+)?$)");
  std::optional<Compass> lane_direction;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), kDir); it != std::sregex_iterator(); ++it) {
    const smatch& m = *it;
    const size_t at = static_cast<size_t>(m.position());
    if (m[2].matched && Has(Before(s, at, 50) + m[0].str(), kIntended)) continue;
    if (m[1].matched && (Has(s.substr(at, 40), kOthersTraffic) || Has(Before(s, at, 40), kWaitedFor))) continue;
    // "waiting to turn left to go westbound": where the turn would take it.
    static const regex kToGo(R"(\b(?:to\s+(?:go|travel|head|proceed|continue)|turn(?:ing|ed|s)?\s+(?:left|right)(?:\s+to\s+go)?)\s+$)");
    if (m[1].matched && Has(Before(s, at, 40), kToGo)) continue;
    // "pulled out into the westbound lane to pass": the lane it moved into,
    // the other direction's.
    // (Also "eased across the stopped eastbound lanes", "had crossed the
    // northbound lanes".)
    static const regex kMovedInto(
        R"(\b(?:into|onto|across|over|crossed|crossing|crosses)\s+(?:the\s+|both\s+)?(?:(?:stopped|queued|near|far|opposing|other|two|three|both|[1-9])\s+)?$)");
    if (m[1].matched && Has(s.substr(at, 40), kBoundLane) && Has(Before(s, at, 30), kMovedInto)) continue;
    // Nor the lane the contact was in: "the fronts of v1 and v2 collided in
    // the westbound lane".
    static const regex kContactIn(
        R"(\b(?:collided|struck|hit|impacted|contacted|crashed|met|occurred)\b(?:\s+[\w-]+){0,4}?\s+(?:in|within)\s+(?:the\s+)?$)");
    if (m[1].matched && Has(s.substr(at, 40), kBoundLane) && Has(Before(s, at, 50), kContactIn)) continue;
    for (int g = 1; g <= 3; ++g) {
      if (!m[g].matched) continue;
      const bool turn = m[0].str().rfind("turn", 0) == 0;
      if (g == 1 && Has(s.substr(static_cast<size_t>(m.position()), 40), kBoundLane)) {
        if (!lane_direction) lane_direction = CompassWord(m[g].str());
      } else if (turn && lane_direction) {
        return lane_direction;
      } else {
        return CompassWord(m[g].str());
      }
    }
  }
  return lane_direction;
}

// Where the road phrase holding `pos` starts: after the previous road's
// (", and a ..."), however far back ("the north/south roadway, which formed
// the south leg of the intersection, was a 2-lane ...").
size_t RoadPhraseStart(const string& s, size_t pos) {
  // "... with 2 lanes each way, and mill street, a 2-lane ...": a road
  // named after ", and" starts one too.
  static const regex kNextRoad(R"(\band\s+(?:a|an|the)\s+|,\s*and\s+(?=[a-z]+(?:\s+[a-z]+)?\s+(?:street|avenue|road|drive|lane|boulevard|parkway|pike|highway)\s*,))");
  size_t start = 0;
  const string upto = s.substr(0, std::min(pos, s.size()));
  for (auto it = std::sregex_iterator(upto.begin(), upto.end(), kNextRoad); it != std::sregex_iterator(); ++it) {
    start = static_cast<size_t>(it->position());
  }
  return start;
}

bool Opposite(Compass a, Compass b) { return (static_cast<int>(a) + 2) % 4 == static_cast<int>(b); }
bool Perpendicular(Compass a, Compass b) { return (static_cast<int>(a) + static_cast<int>(b)) % 2 == 1; }

// ------------------------------------------------------------ damage areas

AreaWords ParseArea(const string& w) {
  AreaWords a;
  a.front = w.find("front") != string::npos;
  a.rear = w.find("rear") != string::npos || w.find("back") != string::npos;
  // In the U.S. the driver sits on the left.
  a.left = w.find("left") != string::npos || w.find("driver") != string::npos;
  a.right = w.find("right") != string::npos || w.find("passenger") != string::npos;
  if (a.left && a.right) a.right = false;
  return a;
}

string Detail(const AreaWords& a) {
  if (a.front && (a.left || a.right)) return a.left ? "front-left" : "front-right";
  if (a.rear && (a.left || a.right)) return a.left ? "left-rear" : "right-rear";
  if (a.front) return "front";
  if (a.rear) return "rear";
  if (a.left) return "left";
  if (a.right) return "right";
  return "";
}

const regex& ContactVerb() {
  // (Not a compound's tail: "pre-impact skid marks", "post-impact travel".)
  static const regex kContact(
      R"((?:^|[^\w-])(contact(?:ed|ing|s)?|struck|strik(?:e|es|ing)|stuck|impact(?:ed|ing|s)?|collid(?:ed|es|ing)|hit(?:s|ting)?|crashed|rear[- ]end(?:ed|ing)|sideswip(?:ed|ing)|swiped|raked|scraped|grazed|clipped|t-?bon(?:ed|ing)|broadsid(?:ed|ing)|ran into|slammed|smashed|smacked|rammed|plowed into|ploughed into|bumped into|engaged|(?:rolled|crept|creep|creeping|coasted|moved)\s+(?:forward\s+|ahead\s+|back(?:ward)?\s+)?into(?=\s+(?:the\s+)?v[1-9]'s\s+(?:rear|back|front|side|left|right|bumper)))\b)");
  return kContact;
}

string WithoutAvoidedContacts(const string& text) {
  static const regex kAvoided(
      R"(\b(?:avoid\w*|prevent\w*)\s+(?:\w+\s+){0,2}?(?:strik\w*|hit\w*|contact\w*|collid\w*|impact\w*)\b|\bwithout\s+(?:strik\w*|hitting|contact\w*|collid\w*|impact\w*)\b|)"
      // ... and contacts denied: "v3 behind v2 was not struck".
      R"(\b(?:was|were)\s+not\s+(?:struck|hit|contacted|impacted)\b|\b(?:did|does)\s+not\s+(?:strike|hit|contact|collide|impact)\b)");
  return std::regex_replace(text, kAvoided, " ");
}

const string& StandingWord() {
  static const string kStanding = R"((parked|unoccupied|disabled|abandoned|stalled))";
  return kStanding;
}

const regex& VehicleNoun() {
  static const regex kVehicleNoun(
      R"(\b(?:car|van|vehicle|truck|pickup|pick-up|suv|motorcycle|bus|sedan|minivan|jeep|trailer|tractor-trailer)\b)");
  return kVehicleNoun;
}

const regex& ObjectNoun() {
  static const regex kObjectNoun(
      R"(\b(?:tree|sapling|stump|shrubs?|bush(?:es)?|hedge\w*|pole|curb|fence|barrier|wall|guardrail|guard rail|ditch|sign|embankment|pedestrian|median|building|mailbox|post|rock|boulder|bridge|culvert|deer|animal|cyclist|bicycle)\b)");
  return kObjectNoun;
}

}  // namespace accsim::narrative
