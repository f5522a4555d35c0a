#include "accsim/scenarios/narrative_extractor.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <array>
#include <cctype>
#include <cmath>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <utility>
#include <vector>

#include "regex_text.h"

namespace accsim {
namespace {

constexpr double kMphToMps = 0.44704;
constexpr double kKmhToMps = 1.0 / 3.6;
// Sentences longer than this are cut (at a comma when possible): std::regex
// backtracks recursively, so bounded inputs keep every rule cheap and safe.
constexpr size_t kMaxSentence = 600;
constexpr int kMaxVehicles = 9;

using std::regex;
using std::smatch;
using std::string;

using regex_text::Has;
using regex_text::ReplaceWith;

// The (at most) n characters of s before position at.
string Before(const string& s, size_t at, size_t n) { return at > n ? s.substr(at - n, n) : s.substr(0, at); }

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

// Lower-case ASCII, one space between words; every other byte (binary,
// UTF-8) becomes a space so the rules only ever see printable text. Vehicle
// references and numbers get one canonical form ("v2", "45").
// Applies a table of (pattern, replacement) pairs in order.
template <typename Table>
string ReplaceEach(string s, const Table& table) {
  for (const auto& [re, to] : table) s = std::regex_replace(s, re, to);
  return s;
}

string Normalise(std::string_view in) {
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
  static const regex kSingleLane(R"(\bsingle[- ]lane\b)");
  s = std::regex_replace(s, kSingleLane, "1-lane");
  static const regex kSingleTravelLane(R"(\bsingle\s+(travel|through|traffic|(?:north|south|east|west)bound)\s+lane\b)");
  s = std::regex_replace(s, kSingleTravelLane, "1 $1 lane");
  // "the maximum speed allowed", "the legal speed": the limit.
  static const regex kLimitSynonym(
      R"(\b(?:maximum|max\.?)\s+(?:legal\s+|allowed\s+|allowable\s+|permitted\s+|posted\s+)?speed(?:\s+(?:allowed|permitted|limit))?\b|\b(?:legal|lawful)\s+speed(?:\s+limit)?\b)");
  s = std::regex_replace(s, kLimitSynonym, "speed limit");
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
  // Police shorthand: "u2" (unit 2) and "d1" (driver 1), only as whole words.
  static const regex kShortRef(R"(\b[ud]([1-9])\b)" + kNotAUnit);
  s = std::regex_replace(s, kShortRef, "v$1");
  // "the first vehicle", "the 2nd car" (ordinals are digits by now).
  // Not a place in a queue: "the 3rd vehicle in a queue waiting for the light".
  static const regex kOrdinalVehicle(
      R"(\b(?:the\s+)?([1-4])(?:st|nd|rd|th)\s+(?:vehicle|car|unit|auto)\b(?!\s+(?:in\s+(?:a\s+|the\s+)?(?:queue|line)|from\s+the\s+(?:front|light|signal|stop)|stopped|waiting)\b))");
  s = std::regex_replace(s, kOrdinalVehicle, "v$1");
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
  static const regex kNamed(
      R"(\bthe\s+((?:(?:19|20)\d\d\s+)?[a-z](?:(?!\.\s|\bthe\s)[a-z0-9/&'. -]){1,40}?)\s*\(\s*v([1-9])\s*\)(\s*,)?)");
  s = ReplaceWith(s, kNamed, [](const std::smatch& m) {
    const string name = m[1].str();
    const bool year = name.size() > 5 && (name.compare(0, 2, "19") == 0 || name.compare(0, 2, "20") == 0) &&
                      std::isdigit(static_cast<unsigned char>(name[2])) && std::isdigit(static_cast<unsigned char>(name[3])) && name[4] == ' ';
    if (year) return "v" + m[2].str() + ", a " + name + ",";
    return "v" + m[2].str() + (m[3].matched ? m[3].str() : string());
  });
  return s;
}

// Short descriptions number no vehicle ("a red sedan ran the light and
// t-boned a white suv", "my car was stopped when a pickup rear-ended me").
// The narrator's vehicle becomes v1 ("my car", "i", "me"), then each vehicle
// introduced with "a"/"an"/"another" in order of first mention; a later "the
// suv" refers back when only one vehicle has that noun. The noun phrases are
// kept as the vehicles' descriptions.
struct Numbered {
  string text;
  std::map<int, string> descriptions;
};

Numbered NameUnnumberedVehicles(const string& s) {
  static const regex kAnyRef(R"(\bv[1-9]\b)");
  if (Has(s, kAnyRef)) return {s, {}};
  static const string kNoun =
      R"((car|sedan|coupe|hatchback|wagon|suv|jeep|pickup(?: truck)?|truck|van|minivan|motorcycle|motorbike|bus|tractor-trailer|semi|taxi|cab|vehicle))";
  static const string kMakes =
      R"((ford|toyota|honda|chevrolet|chevy|nissan|hyundai|kia|subaru|mazda|dodge|volkswagen|vw|bmw|mercedes|audi|lexus|acura|infiniti|buick|cadillac|gmc|chrysler|pontiac|saturn|mitsubishi|volvo|tesla|lincoln|mercury|plymouth|oldsmobile|suzuki|isuzu|saab|mini|fiat|peugeot|renault|vauxhall|skoda|seat|citroen))";
  static const string kColour =
      R"((?:(?:(?:dark|light|bright)\s+)?(?:white|black|silver|gray|grey|red|blue|green|gold|maroon|tan|beige|brown|yellow|orange|purple|burgundy)\s+))";
  // Group 1: the phrase without its article (noun included); group 2: the noun.
  static const regex kMine(R"(\bmy\s+((?:[a-z0-9-]+\s+){0,2}?)" + kNoun + R"()\b)");
  // "a red suv", "another car", a model year: "a 2010 honda accord", a make
  // with its model: "a white ford explorer", "a toyota corolla" (groups 5, 6),
  // a rider or driver named for the vehicle: "a motorcyclist" (group 7), and,
  // once the narrator is v1, "the car behind me" (groups 8, 9).
  static const regex kIntro(
      R"(\b(?:a|an|another)\s+((?:(?!a\b|an\b|the\b)[a-z0-9-]+\s+){0,3}?)" + kNoun +
      R"()\b|\b(?:a|an)\s+((?:19|20)\d\d\s+([a-z][a-z0-9-]*)(?:\s+(?!was\b|that\b|which\b|who\b|and\b|lost\b|left\b)[a-z][a-z0-9-]*){0,2}))" +
      R"(|\b(?:a|an)\s+()" + kColour + R"(?)" + kMakes +
      R"((?:\s+(?!was\b|were\b|that\b|which\b|who\b|and\b|in\b|on\b|at\b|with\b|driven\b|travel\w*|going\b|heading\b|had\b|hit\b|struck\b)[a-z0-9][a-z0-9-]*)?)\b)" +
      R"(|\b(?:a|an)\s+(motorcyclist|motorist)\b|\bthe\s+(?:other\s+)?()" + kNoun +
      R"()(?=\s+(?:behind|ahead of|in front of) v1\b))");
  // "the sedan, a kia optima," and "it was a nissan altima" describe a
  // vehicle already named.
  static const regex kAppositive(R"((?:\bthe\s+(?:[a-z0-9-]+\s+){0,2}?)" + kNoun + R"(\s*,\s*|\bit (?:was|is)\s+)$)");
  // "a sedan, a kia optima,": a make or model year after an unnamed noun
  // names it (a list of vehicles names a noun each: "a car, a van and ...").
  static const regex kNamedAppositive(R"(\b(?:a|an)\s+(?:[a-z0-9-]+\s+){0,2}?)" + kNoun + R"(\s*,\s*$)");
  static const regex kFirstPerson(R"(\b(?:i|me)\b(?!-))");
  static const regex kMy(R"(\bmy\b)");
  Numbered out{s, {}};
  std::map<string, int> owner;  // head noun -> vehicle, 0 when two share it
  int next = 1;
  auto head_of = [](const string& noun) { return noun.substr(0, noun.find(' ')); };
  smatch m;
  if (std::regex_search(out.text, m, kMine)) {
    owner[head_of(m[2].str())] = 1;
    out.descriptions[1] = m[1].str();
    out.text = std::regex_replace(std::regex_replace(out.text, kMine, "v1"), kFirstPerson, "v1");
    out.text = std::regex_replace(out.text, kMy, "v1's");  // "hit my passenger side", "into my lane"
    next = 2;
  } else if (static const regex kQuoted(R"("[^"]{0,400}")"); Has(std::regex_replace(out.text, kQuoted, " "), kFirstPerson)) {
    // A narrator known only as "i" / "me" drives v1; a quoted "i" is someone
    // else speaking ("'i saw it coming,' a witness said").
    out.text = std::regex_replace(out.text, kFirstPerson, "v1");
    out.text = std::regex_replace(out.text, kMy, "v1's");
    next = 2;
  }
  string rebuilt;
  int motorist = 0;
  auto from = out.text.cbegin();
  for (auto it = std::sregex_iterator(out.text.cbegin(), out.text.cend(), kIntro);
       it != std::sregex_iterator() && next <= 9; ++it) {
    const smatch& im = *it;
    std::vector<string> heads;
    string phrase;
    if (im[3].matched) {
      phrase = im[3].str();
      heads = {im[4].str()};
    } else if (im[5].matched) {
      phrase = im[5].str();
      heads = {im[6].str()};
    } else if (im[7].matched) {
      const bool rider = im[7].str() == "motorcyclist";
      phrase = rider ? "motorcycle" : "car";
      heads = {im[7].str(), phrase};
    } else if (im[8].matched) {
      phrase = im[8].str();
      heads = {};  // "the car behind me" is not what a later "the car" means
    } else {
      phrase = im[1].str();
      heads = {head_of(im[2].str())};
    }
    if (!heads.empty() && heads[0] == "vehicle" && im.str().rfind("another", 0) != 0) continue;  // "a vehicle" is too vague to count
    const size_t at = static_cast<size_t>(im[0].first - out.text.cbegin());
    const size_t back = std::min<size_t>(at, 60);
    if (!im[8].matched && std::regex_search(out.text.substr(at - back, back), kAppositive)) continue;
    const bool follows_numbered = next > 1 && from != out.text.cbegin() && im[0].first - from <= 3;
    if ((im[3].matched || im[5].matched) && follows_numbered &&
        std::regex_search(out.text.substr(at - back, back), kNamedAppositive)) {
      out.descriptions[next - 1] = phrase;
      for (const string& head : heads) owner[head] = owner.count(head) ? 0 : next - 1;
      continue;
    }
    rebuilt.append(from, im[0].first);
    rebuilt += "v" + std::to_string(next);
    out.descriptions[next] = phrase;
    for (const string& head : heads) owner[head] = owner.count(head) ? 0 : next;
    if (im[7].matched && im[7].str() == "motorist") motorist = next;
    ++next;
    from = im[0].second;
  }
  rebuilt.append(from, out.text.cend());
  for (const auto& [head, v] : owner) {
    if (v == 0) continue;
    const regex the(R"(\bthe\s+(?:[a-z0-9-]+\s+){0,2}?)" + head + R"(\b)");
    rebuilt = std::regex_replace(rebuilt, the, "v" + std::to_string(v));
  }
  if (motorist > 0) {
    // "a motorist ... when her car was struck": the motorist's own car.
    static const regex kTheirCar(R"(\b(?:his|her|their)\s+(?:car|vehicle)\b)");
    rebuilt = std::regex_replace(rebuilt, kTheirCar, "v" + std::to_string(motorist));
  }
  out.text = std::move(rebuilt);
  return out;
}

enum class Kind { kNarrative, kStatement, kCoding, kPeople };

struct Ref {
  size_t pos;
  int vehicle;
};

struct Sentence {
  string text;
  Kind kind = Kind::kNarrative;
  std::vector<Ref> refs;
  int focus = 0;  // the vehicle the sentence is about: its first reference, else the previous sentence's
};

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
      R"(hospital|trauma|ambulance|rested|health|alcohol|drugs|\bcited\b|citation|summons|ticket|interview|airbag|air bag|)"
      R"(seat ?belt|belted|occupant|passenger(?!'?s? (?:side|door|corner|fender|quarter)| (?:vehicles?|cars?))|\b(?:his|her) way\b|going home|heading home|errand|medical|license|)"
      R"(towed|driven from the scene|driven away|fled|contact lens|pregnan)");
  static const regex kStatement(
      R"(\b(?:stated|said|says|states|indicated|reported|advised|according to|recalled|estimated|told|admitted|claimed)\b)");
  // Who drove and who rode along is often folded into a motion sentence
  // ("v1, a 1996 cavalier driven by a 17-year old male, was traveling
  // south", "v2, a cr-v with one occupant, was stopped"): such phrases do not
  // make the sentence one about people.
  static const regex kPeoplePhrase(
      R"(\b(?:driven|operated|occupied) by (?:an? |the |its )?[^,;()]{0,40}?\b(?:male|female|man|woman|driver|operator|person|teen\w*|girl|boy)\b(?:\s+with (?:a|an|his|her) [^,;()]{0,30}?\b(?:license|permit)\b)?|\bwith (?:\d+|no|an?|its) (?:\w+ )?(?:occupants?|passengers?)\b|\bwith an? [^,;()]{0,30}?\b(?:driver|operator)\b(?:\s+and\s+(?:\d+|no|an?)\s+(?:\w+\s+)?(?:passengers?|occupants?)\b)?|\b(?:the|its|his|her|v[1-9]'s) driver,\s+an?\s+[^,;()]{0,60},|\bthe\s+\d+[- ]year[- ]old\s+(?:male|female|man|woman)\s+(?:driver|driving|operating)\b|,\s*who had [^,;()]{0,40}?passengers?\s*,|\bpassenger'?s?[- ](?:side|door|front|rear|corner|fender)\b)");
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
      R"(\b(?:the\s+)?(?:nearest|closest)\s+(?:[\w/-]+\s+){0,2}?(?:on-?ramp|off-?ramp|ramp|intersection|junction|cross street|interchange)s?\b[^.;]{0,50})");
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

struct AreaWords {
  bool front = false, rear = false, left = false, right = false;
  bool any() const { return front || rear || left || right; }
};

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

// ------------------------------------------------------------------ roads

struct RoadStatement {
  size_t sentence = 0;
  size_t pos = 0;                  // where in the sentence
  int owner = 0;                   // vehicle whose segment states it (0: none)
  std::optional<int> axis;         // 0 = east-west, 1 = north-south, when the phrase names one
  int total = 0, per_direction = 0, directional = 0;
  std::optional<Compass> bound;    // the direction a directional count is of ("3 westbound lanes")
  bool one_way = false;
  bool cross = false;              // said of the cross street ("the cross street is a 2-lane road")
  bool ramp = false;               // said of a ramp ("a single-lane entrance ramp")
  bool centre = false;             // its phrase adds a centre lane ("... separated by a 2-way left-turn lane")
  string name;                     // the named road its clause is about ("route 202 is ... with 1 lane each way")
  string road;                     // the road its clause is about by kind ("the residential street was a 2-lane ...")
  string counted;                  // the road its own noun phrase names ("a 2-lane collector road")
};

// "the road", "the roadway", "the street" name no road in particular.
bool GenericRoad(const string& road) { return road == "road" || road == "roadway" || road == "street"; }

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
      R"(\b(east|west)[- ]?(?:/|-|and)?\s*(?:west|east)\b|\b(north|south)[- ]?(?:/|-|and)?\s*(?:south|north)\b|\b(north|south|east|west)[- ]?bound\b|\b(n|s)/(?:s|n)\b|\b(e|w)/(?:w|e)\b)");
  std::optional<int> last;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), kAxis); it != std::sregex_iterator(); ++it) {
    const smatch& m = *it;
    if (m[1].matched || m[5].matched) last = 0;
    else if (m[2].matched || m[4].matched) last = 1;
    else if (m[3].matched) last = (m[3].str()[0] == 'e' || m[3].str()[0] == 'w') ? 0 : 1;
  }
  return last;
}

int AxisOf(Compass c) { return (c == Compass::kEast || c == Compass::kWest) ? 0 : 1; }

// -------------------------------------------------------------- movements

struct MovementEvidence {
  bool stopped = false, stop_cancelled = false, parked = false, leaving_parking = false;
  bool turn_left = false, turn_right = false, lane_change = false, merge = false, back = false, pass = false;
  bool slowing = false, straight = false;
  bool coded_turn_left = false, coded_turn_right = false, coded_straight = false, coded_back = false;
  bool coded_lane_change = false, other_says_stopped = false;
  bool other_says_decelerating = false;  // the follower's critical event: this one "traveling ... while decelerating"
  bool coded_adjacent = false;  // its critical event: another vehicle from an adjacent lane, same direction
  bool rolled_stop = false, no_stop = false;
  bool started = false;  // "began moving forward": a stopped vehicle moving off (NASS "starting in traffic lane")
  bool green_start = false;  // "when the signal turned green, v1 started its turn": moving off a red (NASS "starting")
  bool stopped_again = false;  // "moved forward ... then stopped again"
  bool u_turn = false;
  bool in_curve = false;  // "entered the right curve at too great a speed"
  bool drift = false;     // "drifted to the left into the left lane": no lane change meant
  bool intent_left = false, intent_right = false, entered = false;  // "waiting to turn left", then "entered the road"
  bool turn_meant = false;  // a turn meant, its direction untold ("slowing to turn into the driveway")
  bool any_narrative() const {
    return stopped || stop_cancelled || parked || leaving_parking || turn_left || turn_right || lane_change || merge ||
           back || pass || slowing;
  }
};

// Reads one piece of text about a vehicle for movement statements.
void ReadMovement(const string& text, MovementEvidence& e) {
  // What a driver saw another vehicle do is that vehicle's movement: "she
  // stated ... the car turned right in front of her".
  static const regex kOtherInFront(
      R"(\b(?:the|a|an|another|some)\s+(?:other\s+)?[a-z-]+\s+(?:[\w-]+\s+){0,5}?in front of (?:him|her|me|them|us)\b)");
  // Nor is what the driver believed another vehicle would do: "she thought
  // v1 was going to turn onto carver road and she began a left turn".
  static const regex kBeliefOfOther(
      R"(\b(?:thought|believed|assumed|expected|figured)\s+(?:that\s+)?(?:v[1-9]|the\s+other\s+(?:car|vehicle|driver|truck|van))\b[^,.;]*?(?=,|\b(?:and|but|so)\s+(?:then\s+)?(?:he|she|i)\b|$))");
  const string t = std::regex_replace(std::regex_replace(text, kOtherInFront, " "), kBeliefOfOther, " ");
  static const regex kStopState(
      R"(\b(?:was|were|had been|is|remained|sat|been|being)\s+(?:\w+\s+)?(?:stopped|stationary|at rest|waiting|sitting still)\b|\bstopped\b|\bwaiting (?:for|to|at|in)\b|\bawaiting\b|\b(?:came|come|coasted|rolled) to a (?:complete |full )?(?:stop|halt)\b|\bstalled\b|\bwas disabled\b|\b(?:brought|bringing)\s+(?:\w+\s+){0,2}?to a (?:complete |full )?stop\b|\bslowed to a stop\b|\bat a stop\b|\b(?:was|were)\s+(?:the\s+)?(?:1st|first|next|2nd|second|3rd|third|last)\s+(?:vehicle\s+)?in (?:line|the queue)\b)");
  static const regex kStopThenGo(
      R"(\bstop(?:ped|s)?\b[^.]{0,90}?\b(?:and|then|before)\s+(?:then\s+)?(?:(?:was|had)\s+(?:just\s+)?)?(?:proceed|continu|pull|start|accelerat|drove|enter|went|attempt|tried|began|cross|moving)\w*)");
  static const regex kParked(R"(\bparked\b|\bunoccupied\b|\b(?:in|from) (?:the|a) (?:\w+ )?parking lane\b)");
  static const regex kRolledStop(
      R"(\brolled (?:through|past)\b|\brolling stop\b|\bslowed\b[^.;]{0,60}?\bbut (?:did not|didn't|failed to|never) (?:come to a (?:complete |full )?)?stop\b)");
  static const regex kNoStop(
      R"(\b(?:failed to|did not|didn't|had not|hadn't|never|without|not able to|unable to|could not|couldn't|too late to)\s+(?:\w+\s+){0,3}?stop(?:ping)?\b|\b(?:did not|didn't|failed to|never|without|not)\s+(?:come|coming|came)\s+to\s+a\s+(?:complete\s+|full\s+)?stop\b|\b(?:had not|hadn't|never|not)\s+(?:fully\s+|completely\s+|yet\s+|even\s+)?stopped\b|\bran (?:the|a|through the) (?:stop|red)\b)");
  static const regex kLeavingParking(
      R"(\b(?:coming|pulling|pulled|leaving|left|exiting)\s+(?:out\s+)?(?:of|from)\s+(?:a|the|his|her)?\s*(?:parking (?:spot|space|position|place)|parked position)|\bfrom (?:a|the) parked position|\bwas parked\b.{0,80}\b(?:entered|pulled|began|attempt))");
  // Crossing the road into a drive on its far side is a left turn (traffic keeps right).
  static const regex kLeft(
      R"(\bturn(?:ed|ing|s)?\s+(?:to\s+(?:the\s+)?)?left\b|\bleft[- ]hand turn|\bleft turn\b|\bturn(?:ed|ing)? left|\b(?:made|make|making)\s+a\s+left\s+(?:onto|into)\b|\bu-?\s?turn|\bcross\w*\s+(?:over\s+)?(?:into|to)\s+(?:a|the)\s+(?:\w+\s+){0,2}?(?:driveway|parking lot|lot|alley)\b)");
  static const regex kRight(R"(\bturn(?:ed|ing|s)?\s+(?:to\s+(?:the\s+)?)?right\b|\bright[- ]hand turn|\bright turn\b|\b(?:made|make|making)\s+a\s+right\s+(?:onto|into)\b)");
  // An intention is not the movement: "waiting to turn left", "intending to turn".
  static const regex kIntention(
      R"(\b(?:intend\w*|intention|plann\w*|prepar\w*|wait\w*|await\w*|signal\w*|going to|about to|wanted to|wanting to|would)\b[^,.]{0,30}?\b(?:turn|left|right)|\bintended\s+(?:left|right)|\bintended\s+(?:path|turn)|)"
      // "to get into position for a right turn into a plaza".
      R"(\bfor (?:a|an|the|his|her|its) (?:[\w-]+ )?(?:left|right) turn\b)");
  static const regex kLaneChange(
      R"(\bchang\w*\s+lanes?\b|\blane change|\b(?:moved|moving|steered|pulled|cut|swung)\s+(?:over\s+)?to the (?:left|right)\s+to (?:reach|take|get to|get into|make|enter|exit|pass|go around|prepare for|set up for|line up for)\b|\b(?:(?:began|started|tried|attempted) to move|moved|moving|steered|steering|swerved|veered|drifted|drifting|merged|pulled|pulling|crossed)\s+(?:from\s+the\s+\w+\s+lane\s+|(?:\w+\s+){0,3}?)into\s+(?:the\s+)?(?:left|right|adjacent|other|next|inside|outside|center|middle|offside|nearside|fast|slow|passing|overtaking|1st|2nd|3rd)\s+(?:travel\s+)?lane|\bre-?entered the roadway from the shoulder)");
  static const regex kMerge(
      R"(\bmerg(?:e|ed|es|ing)\b|\bentering the (?:freeway|interstate|highway) from|\b(?:on|from|along) (?:a|an|the) (?:[\w-]+[ ,]+){0,3}?(?:entrance|on-?) ramp\b)");
  // "traffic was backed up" is a queue, not a vehicle reversing.
  static const regex kBack(
      R"(\bbacking\s+(?:up|out|into|from|toward|across)|(?:^|\b(?!(?:was|were|is|are|been)\s)\w+\s+)backed\s+(?:up|out|into|from|toward|across)|\breversing\b|\bin reverse\b)");
  static const regex kPass(
      R"(\b(?:was|were)\s+(?:\w+\s+)?(?:passing|overtaking)\b|\bin the process of passing\b|\b(?:attempt\w*|began|started|trying|tried) to (?:pass|overtake)\b|\b(?:began|started)\s+(?:passing|overtaking)\b|\bto (?:pass|overtake)\s+(?:a|an)\s+(?:slower|slow|slow-moving)\b|\b(?:pulled|moved|swung|steered|went|crossed|entered)\s+(?:\w+\s+){0,7}?to (?:pass|overtake)\b)");
  static const regex kSlow(
      R"(\b(?:was|were)\s+(?!not\b|never\b)(?:\w+\s+)?(?:and\s+)?(?:slowing|decelerating|braking)\b|)"
      // "was westbound in lane two, slowing from about 50 mph".
      R"(,\s+(?:slowing|decelerating)\s+(?:down\s+)?(?:from|for|to|because|due)\b|\bhad\s+(?:\w+\s+)?(?:slowed|decelerated)\b|\bslowed\s+(?:down\s+)?(?:for|because|due|to\s+(?:about\s+|approximately\s+|around\s+)?\d|to\s+(?:turn|make)\b)|\b(?:began|started)\s+(?:slowing|to slow|decelerating|braking)\b|\bslowed\s+(?:down\s+)?(?:and|,)\s+(?:then\s+)?(?:turned|(?:began|started)\s+(?:to\s+)?(?:turn|make|pull|enter|cross|mov|stop|brak)\w*|made|moved)\b)");
  static const regex kStraight(
      R"(\b(?:going|travel\w*|continu\w*|proceed\w*|drove|driving)\s+straight\b|\bpass(?:ing|ed)? through the intersection|\bcross(?:ing|ed)? (?:the|through the) intersection)");
  // "... impacted the left side of a legally parked and unoccupied van": the
  // parked thing is what the vehicle struck, not the vehicle itself; nor is
  // one it saw ("could see past the parked truck").
  static const regex kParkedObject(
      R"(\b(?:struck|hit|impacted|contacted|collided with|ran into|crashed into|sideswiped|rear[- ]ended|into)\s+(?:the\s+[\w -]{1,20}?\s+of\s+)?(?:a|an|another)\s+(?:\w+\s+){0,3}?(?:parked|unoccupied)\b[^,.;]*|\b(?:the|a|an|another|several|other|many|\d)\s+(?:\w+\s+)?parked\s+(?:[\w-]+\s+)?(?:cars?|trucks?|vans?|vehicles?|suvs?|pickups?|bus|buses|trailers?)\b|\bparked\s+(?:cars|trucks|vans|vehicles)\b)");
  const bool parked = Has(std::regex_replace(t, kParkedObject, " "), kParked);
  if (parked && !Has(t, kLeavingParking)) e.parked = true;
  if (Has(t, kLeavingParking)) e.leaving_parking = true;
  if (Has(t, kRolledStop)) e.rolled_stop = true;
  if (Has(t, kNoStop)) e.no_stop = true;
  // A stop made on seeing the other vehicle is the avoidance, after the
  // critical event: "when he saw the other car coming, he stopped".
  static const regex kAvoidanceStop(R"(\b(?:saw|seeing|noticed|observed|spotted)\b[^.]{0,80}?\b(?:stopped|braked to a stop)\b)");
  // "was almost stopped when he was hit" is no stop.
  static const regex kAlmostStopped(
      R"(\b(?:almost|nearly|virtually|practically)\s+(?:stopped|at a stop|to a stop|come to a stop|came to a stop)\b)");
  // Nor is "to go around the stopped vehicle": a stopped thing it passed.
  static const regex kStoppedObject(
      R"(\b(?:the|a|an|another|other|several)\s+(?:[\w-]+\s+)?stopped\s+(?:[\w-]+\s+)?(?:vehicles?|cars?|trucks?|vans?|minivans?|suvs?|pickups?|sedans?|bus|buses|traffic)\b)");
  // Nor is the queue's stop: "did not recognize that the queue had stopped".
  static const regex kQueueStopped(
      R"(\b(?:the|that)\s+(?:queue|traffic|line of (?:traffic|vehicles|cars))\s+(?:ahead\s+)?(?:had|was|were)\s+(?:already\s+|just\s+)?(?:stopped|come to a stop|at a stop)\b)");
  const string stops = std::regex_replace(
      std::regex_replace(std::regex_replace(t, kAlmostStopped, " "), kStoppedObject, " "), kQueueStopped, " ");
  // "moved forward ... and then stopped again": the last word is the stop.
  static const regex kStoppedAgain(R"(\b(?:stopped|came to a stop|halted)\s+again\b)");
  if (Has(stops, kStoppedAgain)) e.stopped_again = true;
  if (Has(stops, kStopState) && !parked && !Has(t, kNoStop) && !Has(t, kAvoidanceStop)) {
    if (Has(t, kStopThenGo) && !e.stopped_again) {
      e.stop_cancelled = true;
    } else {
      e.stopped = true;
    }
  }
  static const regex kEntered(
      R"(\b(?:entered|began to enter|started to enter|pulled (?:out|into|onto|away|forward|past|across)|proceeded (?:into|onto|to)|drove (?:into|onto|out))\b(?!\s+(?:the|a|an)\s+(?:[\w-]+\s+){0,2}?(?:center|centre|middle|turn|turning|left-turn|right-turn)\s+lane\b)|)"
      R"(\b(?:began|started|initiated|commenced) (?:the|its|his|her|a) (?:left |right )?turn\b)");
  // A lane's name is not a manoeuvre: "in the two-way left turn lane".
  static const regex kTurnLane(
      R"(\b(?:(?:2[- ]way\s+)?(?:left|right)[- ]turn(?:[- ]only)?|turning)\s+(?:only\s+)?lanes?\b|\b(?:left|right)[- ]turn\s+(?:signal|blinker|indicator)s?\b)");
  const string turns = std::regex_replace(t, kTurnLane, " lane ");
  const bool intention = Has(turns, kIntention);
  // "slowing with its right turn signal on to turn into the driveway".
  static const regex kTurnMeant(R"(\bto (?:make a |begin a )?turn\b|\bturn signal\b)");
  if (Has(t, kTurnMeant)) e.turn_meant = true;
  // "slowed with its left turn signal on": the signal tells the intent.
  static const regex kOwnSignal(
      R"(\b(?:with|had|activated|turned on|put on|using)\s+(?:its|his|her|their)\s+(left|right)[- ]turn\s+(?:signal|blinker|indicator)s?\b|\bsignal(?:ed|led|ing)\s+(?:for\s+)?a\s+(left|right)\s+turn\b)");
  if (smatch sm; std::regex_search(t, sm, kOwnSignal)) {
    ((sm[1].matched ? sm[1].str() : sm[2].str()) == "left" ? e.intent_left : e.intent_right) = true;
  }
  if (!intention) {
    if (Has(turns, kLeft)) e.turn_left = true;
    if (Has(turns, kRight)) e.turn_right = true;
  } else {
    if (Has(turns, kLeft)) e.intent_left = true;
    if (Has(turns, kRight)) e.intent_right = true;
  }
  if (Has(t, kEntered)) e.entered = true;
  // "in the lane to v1's right ... moved into v1's lane": from beside it,
  // not across the centre line.
  static const regex kIntoTheirLane(R"(\binto\s+v[1-9]'?s\s+lane\b)");
  static const regex kBeside(R"(\blane to (?:the|v[1-9]'?s|his|her|its|their) (?:left|right)\b|\b(?:adjacent|next) lane\b)");
  // A lane change told as long past is not the pre-crash movement ("his
  // turn signal was still on from moving into the right lane a block earlier").
  static const regex kEarlierMove(
      R"(\b(?:moving|moved|changing|changed|merging|merged)\s+(?:over\s+)?(?:into|to)\s+(?:the\s+)?\w+\s+lane\s+(?:a\s+(?:block|mile|while|few\s+\w+)|(?:\w+\s+)?(?:blocks|miles|minutes))\s+(?:earlier|before|back|ago)\b)");
  // Nor one only meant: "had looked over his shoulder to change lanes and
  // did not see that traffic had stopped", "was checking his mirror before
  // changing lanes".
  static const regex kMeantLaneChange(
      R"(\b(?:look\w*|check\w*|glanc\w*|want\w*|intend\w*|plann\w*|prepar\w*|about)\b[^.;]{0,40}?\b(?:to change|(?:before|prior to) changing) lanes?\b)");
  // Nor the swerve that tried to avoid the crash ("steered left into the
  // inside lane, but the front of v1 struck ..."): that follows the
  // critical event.
  // Nor one it could not make: "he could not change lanes because of traffic".
  static const regex kNoLaneChange(
      R"(\b(?:could not|couldn't|unable to|did not|didn't|not able to|never|without)\s+(?:\w+\s+)?chang\w*\s+lanes?\b)");
  static const regex kEvasive(
      R"(\b(?:steered|swerved|veered|steering|swerving)\b[^.;]{0,60}?(?:,\s*but\b|\bto avoid\b|\bin an (?:attempt|effort) to avoid\b))");
  string lanes = t;
  for (const regex* not_made : {&kEarlierMove, &kMeantLaneChange, &kEvasive, &kNoLaneChange}) {
    lanes = std::regex_replace(lanes, *not_made, " ");
  }
  if (Has(lanes, kLaneChange) || (Has(t, kIntoTheirLane) && Has(t, kBeside))) e.lane_change = true;
  static const regex kDrift(R"(\b(?:drifted|drifting|wandered|wandering)\b)");
  if (e.lane_change && Has(lanes, kDrift)) e.drift = true;
  if (Has(t, kMerge)) e.merge = true;
  static const regex kInCurve(R"(\b(?:entered|entering|negotiat\w+|rounding|round|into)\s+(?:the|a)\s+(?:[\w-]+\s+){0,2}?curve\b)");
  if (Has(t, kInCurve)) e.in_curve = true;
  if (Has(t, kBack)) e.back = true;
  if (Has(t, kPass)) e.pass = true;
  // "she had slowed as she approached the light, but it turned green ...
  // and continued": the slowing was over before the critical event.
  static const regex kSlowThenGo(
      R"(\bslow(?:ed|ing)\b[^.]{0,90}?\b(?:but|then|and)\b[^.]{0,60}?\b(?:continued|proceeded|accelerated|sped up|resumed)\b)");
  // Nor is a speed kept down for the weather ("he had slowed for the ice
  // and was traveling about 35 mph"): it was driving on at that speed.
  static const regex kSlowForConditions(
      R"(\bslowed\s+(?:down\s+)?(?:for|because of|due to)\s+(?:the\s+)?(?:ice|icy|snow\w*|rain|fog\w*|weather|wet|slick|slippery|road conditions|conditions)\b)");
  if (Has(std::regex_replace(t, kSlowForConditions, " "), kSlow) && !Has(t, kSlowThenGo)) e.slowing = true;
  if (Has(t, kStraight)) e.straight = true;
  static const regex kStarted(
      R"(\b(?:began|started)\s+(?:moving|to move|rolling|to roll|forward|to go|to proceed|proceeding|to accelerate|accelerating)\b|\bpulled away\b|\bmoved (?:forward|off)\b|\baccelerated\b)");
  if (Has(t, kStarted)) e.started = true;
  static const regex kOnGreen(
      R"(\b(?:when|once|after|as soon as|as)\s+(?:the\s+)?(?:traffic\s+)?(?:light|signal)\s+(?:for\s+[\w ]{1,30}?\s+)?(?:turned|changed|went|cycled)\s+(?:to\s+)?green\b)");
  if (Has(t, kOnGreen)) e.green_start = true;
  static const regex kUTurn(R"(\bu-?\s?turn)");
  if (!intention && Has(t, kUTurn)) e.u_turn = true;
}

// NHTSA critical-event wording ("this vehicle traveling, turning left at
// intersection", "other motor vehicle in lane, other vehicle stopped").
void ReadCoding(const string& t, MovementEvidence& self, MovementEvidence* other) {
  static const regex kSelfLeft(R"(\bthis vehicle\b[^.]{0,40}?\bturning left)");
  static const regex kSelfRight(R"(\bthis vehicle\b[^.]{0,40}?\bturning right)");
  static const regex kSelfStraight(
      R"(\bthis vehicle\b[^.]{0,40}?\b(?:crossing over|passing through|going straight|over the (?:left |right )?lane line|off the edge|control loss|traveling too fast|over the line)|)"
      // "... was when she began to travel over the lane line".
      R"(\bwhen (?:he|she|it|the (?:driver|vehicle)|v[1-9])\s+(?:(?:began|started) to (?:travel|drift|move|cross)|travell?ed|drifted|moved|crossed)\s+over the (?:left |right )?(?:lane|center|centre) ?line)");
  static const regex kSelfBack(R"(\bthis vehicle\b[^.]{0,40}?\bbacking)");
  static const regex kSelfLane(R"(\bthis vehicle\b[^.]{0,40}?\bchanging lanes)");
  static const regex kOtherStopped(R"(\b(?:other|another) (?:motor )?vehicle\b[^.]{0,40}?\bstopped\b)");
  if (Has(t, kSelfLeft)) self.coded_turn_left = true;
  if (Has(t, kSelfRight)) self.coded_turn_right = true;
  if (Has(t, kSelfStraight)) self.coded_straight = true;
  if (Has(t, kSelfBack)) self.coded_back = true;
  if (Has(t, kSelfLane)) self.coded_lane_change = true;
  static const regex kOtherFromAdjacent(
      R"(\b(?:other|another) (?:motor )?vehicle\b[^.]{0,60}?\bfrom (?:an |the )?adjacent lane\b|\bencroach\w*[^.]{0,40}?\bfrom (?:an |the )?adjacent lane\b)");
  if (Has(t, kOtherFromAdjacent)) self.coded_adjacent = true;
  if (other && Has(t, kOtherStopped)) other->other_says_stopped = true;
  static const regex kOtherDecelerating(R"(\bwhile decelerating\b)");
  if (other && Has(t, kOtherDecelerating)) other->other_says_decelerating = true;
}

struct MovementDecision {
  Movement manoeuvre = Movement::kStraight;  // the path into the crash
  Movement pre_event = Movement::kStraight;  // NASS pre-event movement: what it did before the critical event
  Provenance source = Provenance::kInferred;
};

// A vehicle described parked that then enters the road, turns or pulls
// out was leaving its parking position, not a parked object.
// So is one that backed out of its space (NASS "leaving a parking position":
// its backing is "other than for parking" only off a parking space).
bool LeftParking(const MovementEvidence& n) {
  return n.parked && (n.entered || n.turn_left || n.turn_right || n.merge || n.lane_change || n.back);
}

MovementDecision DecideMovement(const MovementEvidence& n, const MovementEvidence& st) {
  // Narrative statements first; driver statements only when the narrative is silent.
  const MovementEvidence& e = n.any_narrative() ? n : st;
  auto both = [](Movement m, Provenance p) { return MovementDecision{m, m, p}; };
  if (LeftParking(n)) {
    const Movement path = n.turn_left    ? Movement::kTurnLeft
                          : n.turn_right ? Movement::kTurnRight
                          : n.back       ? Movement::kBacking
                                         : Movement::kMerging;
    return MovementDecision{path, Movement::kMerging, Provenance::kStated};
  }
  if (e.parked || n.parked) return both(Movement::kStopped, Provenance::kStated);
  // A back out of a stall before a coded turn out of the lot is not the
  // pre-crash movement: the turn is.
  if ((e.back && !n.coded_turn_left && !n.coded_turn_right) || n.coded_back) {
    return both(Movement::kBacking, Provenance::kStated);
  }
  if (e.leaving_parking) return both(Movement::kMerging, Provenance::kStated);
  // A vehicle the narrative leaves stopped or waiting to turn, whose driver
  // says it then turned, turned.
  // So did one that meant to turn and then entered the road.
  const bool entered = n.entered || st.entered;  // "he ... pulled onto the highway" (a driver's account)
  const bool confirmed_left = (n.stopped && st.turn_left && !st.turn_right) || (n.intent_left && !n.intent_right && entered);
  const bool confirmed_right = (n.stopped && st.turn_right && !st.turn_left) || (n.intent_right && !n.intent_left && entered);
  const bool left = e.turn_left || (!e.turn_right && (n.coded_turn_left || confirmed_left));
  const bool right = !left && (e.turn_right || n.coded_turn_right || confirmed_right);
  if (left || right) {
    // A vehicle that turned after a stop (at a sign, a light, or waiting for
    // a gap) has the stop as its pre-event movement, one that rolled through
    // has its slowing: NASS codes what it did before the critical turn.
    // Statements count here: the narrative often only says "approaching the
    // stop sign ... turned left".
    MovementDecision d{left ? Movement::kTurnLeft : Movement::kTurnRight, Movement::kStraight, Provenance::kStated};
    d.pre_event = d.manoeuvre;
    const bool stopped = n.stopped || n.stop_cancelled || st.stopped || st.stop_cancelled;
    // "did not stop before making the turn": slowed for it.
    const bool rolled = n.rolled_stop || st.rolled_stop || n.no_stop || st.no_stop;
    // Moving off a red when it turned green is NASS "starting in traffic
    // lane", coded here as going on.
    if (stopped && n.green_start) d.pre_event = Movement::kStraight;
    else if (stopped && !rolled) d.pre_event = Movement::kStopped;
    // A U-turn is its own pre-event movement (NASS "making a U-turn").
    else if (n.u_turn || st.u_turn) d.pre_event = Movement::kTurnLeft;
    else if (rolled) d.pre_event = Movement::kSlowing;
    else if (n.slowing || st.slowing) d.pre_event = Movement::kSlowing;
    // Otherwise the turn is its own pre-event movement; the record-level
    // pass codes a turn off a curve or from the wrong lane as going straight.
    return d;
  }
  // A stop before the critical event is the pre-crash movement even when a
  // turn was intended afterwards (how NASS codes it).
  // Unless the investigators coded it still moving: a lead struck "while
  // decelerating" to a stop was going straight (crossing/23, straight/17).
  const bool meant_turn = n.intent_left || n.intent_right || n.turn_meant;
  if (n.other_says_decelerating && !meant_turn) return both(Movement::kStraight, Provenance::kStated);
  if (e.stopped && (!(e.started || n.green_start) || e.stopped_again)) {
    return both(Movement::kStopped, Provenance::kStated);
  }
  // A lane change that is itself the vehicle's coded critical event ("this
  // vehicle traveling over the lane line") was preceded by driving on:
  // NASS codes that as the pre-event movement, as for turns.
  if (e.lane_change || n.coded_lane_change) {
    // So is a drift out of the lane, which nobody meant.
    const Movement before = n.coded_straight || e.drift ? Movement::kStraight : Movement::kChangingLanes;
    return MovementDecision{Movement::kChangingLanes, before, Provenance::kStated};
  }
  // One that lost it in the ramp's curve before the merge was negotiating
  // the curve (NASS codes that, not the merge it never made).
  if (e.merge) return MovementDecision{Movement::kMerging, e.in_curve ? Movement::kStraight : Movement::kMerging, Provenance::kStated};
  // A pass is preceded by going straight, coded or not: the three passes in
  // the development set (straight/0, crossing/21, and straight/5 on a
  // curve) are coded by what came before, none as passing.
  if (e.pass) return MovementDecision{Movement::kPassing, Movement::kStraight, Provenance::kStated};
  if (n.other_says_stopped && !e.stop_cancelled) return both(Movement::kStopped, Provenance::kInferred);
  if (e.slowing || n.rolled_stop || st.rolled_stop) return both(Movement::kSlowing, Provenance::kStated);
  if (e.straight || n.coded_straight || e.stop_cancelled || e.started) return both(Movement::kStraight, Provenance::kStated);
  return both(Movement::kStraight, Provenance::kInferred);
}

// NHTSA's critical pre-crash events, when a report quotes them ("the
// critical precrash event for v2 was other vehicle encroachment from
// crossing street, turning into opposite direction"), name the configuration
// the investigators coded. Pairs of events map to crash-type categories:
// turning into a direction -> turn into path; a turn against traffic from the
// opposite direction or an adjacent lane -> turn across path; other vehicle
// stopped, decelerating or slower -> rear-end; crossing paths -> angle (turn
// into path when one of them turned); an adjacent lane -> sideswipe same
// direction; the opposite direction -> head-on or sideswipe by the damage.
std::optional<CrashType> CrashTypeFromCoding(const string& coded, bool turner, bool right_turner, bool lane_change,
                                             bool front_to_front) {
  static const regex kNotInvolved(R"(\bnot involved (?:in )?(?:the )?1st harmful)");  // "first" is normalised to "1st"
  static const regex kIntoPath(R"(\bturning into (?:the )?(?:same|opposite|oppsite) direction)");
  static const regex kTurning(R"(\bturning (?:left|right) at (?:the |an )?intersection|\b(?:began|begin|started) to turn (?:left|right))");
  static const regex kTurningRight(R"(\bturning right at|\bbegan to turn right)");
  static const regex kFromOpposite(R"(\bfrom (?:the )?opposite direction|\b(?:traveling|travelling) in (?:the )?opposite direction)");
  static const regex kAdjacent(
      R"(\bfrom (?:an |the )?adjacent lane|\bsame direction\)? ?-? ?over (?:the )?(?:left|right) lane line)");
  static const regex kRearEnd(
      R"(\bother (?:motor )?vehicle (?:in lane,? )?(?:was )?stopped|\bin lane,? (?:and was |other vehicle )?stopped|\bsame direction,? (?:while decelerating|(?:with |at )?(?:a )?(?:higher|lower|slower)(?: speed)?))");
  static const regex kCrossingPaths(R"(\bcrossing street,? across\b)");
  if (Has(coded, kNotInvolved)) return CrashType::kSingleVehicle;
  if (Has(coded, kIntoPath)) return CrashType::kTurnIntoPath;
  const bool turning = turner || Has(coded, kTurning);
  // A right turn does not cross the opposite lane: one struck by an
  // oncoming vehicle over its left lane line is no turn across path (every
  // 68/69 of the development set is a left turn).
  const bool across = (turner && !right_turner) || (!turner && Has(coded, kTurning) && !Has(coded, kTurningRight));
  if (Has(coded, kFromOpposite) && across) return CrashType::kTurnAcrossPath;
  if (Has(coded, kAdjacent) && ((turner && !lane_change) || Has(coded, kTurningRight))) return CrashType::kTurnAcrossPath;
  if (Has(coded, kRearEnd)) return CrashType::kRearEnd;
  if (Has(coded, kCrossingPaths)) return turning ? CrashType::kTurnIntoPath : CrashType::kAngle;
  if (Has(coded, kAdjacent)) return CrashType::kSideswipeSame;
  if (Has(coded, kFromOpposite)) return front_to_front ? CrashType::kHeadOn : CrashType::kSideswipeOpposite;
  return std::nullopt;
}

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
const string& WhereRoadsMeet() {
  static const string kPattern =
      R"(\bintersecting\s+(?:[\w-]+\s+){0,3}?(?:road|street|roadway|highway|avenue)\b|\bwhere\s+(?:the\s+)?(?:[a-z0-9-]+\s+){1,3}meets\b|\bwhere\s+(?:[\w'-]+\s+){1,3}?(?:road|street|avenue|drive|route|highway|lane|boulevard|pike)(?:\s+\d{1,4}[a-z]?)?\s+(?:crosses|intersects)\b|\bwhere\s+(?:that|the|this|it)\s+(?:[a-z0-9-]+\s+){0,2}?crosses\s+(?:a|an|the)\s+(?:[\w-]+\s+){0,2}?(?:road|street|route|highway|roadway|avenue|boulevard)\b|\bat the crossing\b)";
  return kPattern;
}

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

// "exiting a parking lot driveway", "at the parking lot exit".
bool LeavesDriveway(const string& t) {
  static const regex kFromDriveway(
      R"(\b(?:exit\w*|leav\w*|pull\w* out of|out of) (?:a|an|the|his|her) (?:\w+ ){0,2}?(?:parking lot|driveway|private drive|alley|plaza|shopping center|mall|gas station|service station)\b|\bparking lot (?:exit|driveway)\b|)"
      // "stopped at the mouth of the driveway", "drove south through the exit driveway".
      R"(\b(?:stopped|waiting|sitting|sat|paused|idling|was|were|emerged|emerging)\s+(?:[\w-]+\s+){0,2}?(?:at|in|from) the (?:mouth|end|exit|edge|apron) of (?:a|an|the) (?:[\w-]+ ){0,2}?(?:parking lot|driveway|private drive|alley)\b|)"
      R"(\b(?:through|down|out) (?:a|an|the) (?:[\w-]+ ){0,2}?(?:driveway|alley)\b|)"
      // "was westbound in the driveway".
      R"(\b(?:was|were) (?:[\w-]+ ){0,2}?(?:in|on|within) (?:a|an|the) (?:[\w-]+ ){0,2}?(?:driveway|alley|parking lot)\b|)"
      // "stopped at the plaza exit" (not a freeway's exit ramp).
      R"(\b(?:stopped|waiting|sitting|paused) (?:at|in) (?:a|an|the) (?:[\w-]+ ){0,2}?exit\b(?! ramp))");
  return Has(t, kFromDriveway);
}

// A crash type the report states (investigators' coding, "rear-ended",
// "head-on") fixes how the two vehicles' directions relate. When the
// directions read from the text disagree (reports do contradict themselves:
// "struck the rear of v2" and "v2 had been stopped in the northbound lane"
// with v1 southbound), the later-numbered vehicle's direction is taken to be
// the wrong one; a warning names it.
void ReconcileDirections(AccidentRecord& r, size_t ia, size_t ib) {
  if (ia >= r.vehicles.size() || ib >= r.vehicles.size() || ia == ib) return;
  if (r.crash.type.source != Provenance::kStated) return;
  const auto& ta = r.vehicles[ia].travel;
  const auto& tb = r.vehicles[ib].travel;
  if (!ta.known() || !tb.known() || !ta.value || !tb.value) return;
  const CrashType t = r.crash.type.value;
  const bool want_same = t == CrashType::kRearEnd || t == CrashType::kSideswipeSame;
  const bool want_opposite = t == CrashType::kHeadOn || t == CrashType::kSideswipeOpposite;
  const Compass da = *ta.value, db = *tb.value;
  if (!(want_same && da != db) && !(want_opposite && !Opposite(da, db))) return;
  const size_t wrong = std::max(ia, ib);
  const Compass keep = wrong == ib ? da : db;
  const Compass fixed = want_same ? keep : static_cast<Compass>((static_cast<int>(keep) + 2) % 4);
  auto& travel = r.vehicles[wrong].travel;
  r.warnings.push_back("vehicles[" + std::to_string(wrong) + "].travel: '" + string(ToString(*travel.value)) +
                       "' contradicts the stated crash type " + string(ToString(t)) + "; taken as '" +
                       string(ToString(fixed)) + "'");
  travel.Set(fixed, Provenance::kInferred);
}

// "ran the stop sign", "went through a red light": a controlled junction.
bool RanTrafficControl(const string& t) {
  static const regex kRan(
      R"(\b(?:ran|run|running|blew|went through|drove through|failed to stop (?:at|for)|disregarded)\s+(?:the|a)\s+(?:stop sign|red light|red signal|traffic (?:light|signal)|signal|light)\b)");
  return Has(t, kRan);
}

bool Turning(Movement m) { return m == Movement::kTurnLeft || m == Movement::kTurnRight; }

}  // namespace

AccidentRecord NarrativeExtractor::Extract(std::string_view text) const {
  // Words that name a configuration and its planes at once.
  static const regex kHeadOnPhrase(R"(\bhead[- ]on\b)");
  static const regex kRearEndPhrase(R"(\brear[- ]end(?:ed|ing|s)?\b)");
  AccidentRecord r;
  if (text.size() > kMaxBytes) {
    r.warnings.push_back("text: longer than " + std::to_string(kMaxBytes) + " bytes; only the start was read");
    text = text.substr(0, kMaxBytes);
  }
  const Numbered numbered = NameUnnumberedVehicles(Normalise(text));
  const string& norm = numbered.text;
  std::vector<Sentence> sentences;
  for (string& t : SplitSentences(norm)) sentences.push_back({std::move(t), Kind::kNarrative, {}, 0});
  if (sentences.empty()) {
    r.warnings.push_back("text: no readable sentences; every field is a default");
    return r;
  }

  // ---- Descriptions ("v1, a 2000 pontiac montana minivan,") and aliases ("the pontiac").
  static const regex kDesc(
      R"(^v([1-9])\s*(?:,\s*|\s+(?:was|is)\s+|\s+\(\s*)(?:(?:was|is)\s+)?(?:an?\s+|(?=(?:19|20)\d\d\s))((?:(?:19|20)\d\d\s+)?[a-z][^,;()]{1,60}?)(?=\s*[,;()]|\s+(?:was|were|is|that|which|who|driven|operated|travel\w*|going|heading|headed|approach\w*|and|with|in|on|at|stopped|making|attempting|pulling|towing|exiting|leaving|entering|negotiating|proceeding|driving|designated|behind|ahead|parked)\b|\s*$))");
  static const regex kBody(R"(^\s*,\s*([a-z0-9][a-z0-9 -]{1,40}?)\s+(?:was|that|which|were)\b)");
  std::map<int, string> descriptions = numbered.descriptions, bodies;
  for (const Sentence& s : sentences) {
    for (const Ref& ref : RefsIn(s.text)) {
      if (descriptions.count(ref.vehicle)) continue;
      const string tail = s.text.substr(ref.pos, 200);
      smatch m;
      static const regex kPersonWords(R"(\b(?:male|female|man|woman|driver|year)\b)");
      if (std::regex_search(tail, m, kDesc) && !Has(m[2].str(), kPersonWords)) {
        descriptions[ref.vehicle] = m[2].str();
        smatch b;
        const string after = m.suffix().str();
        if (std::regex_search(after, b, kBody)) bodies[ref.vehicle] = b[1].str();
      }
    }
  }
  // "a 1996 jeep grand cherokee (v1)": the description before the number.
  {
    // "the honda, a 2003 cr-v (v2)": the make named first.
    static const regex kDescBefore(
        R"((?:\bthe\s+([a-z][a-z-]+),\s+)?\b(?:a|an)\s+((?:19|20)\d\d\s+[a-z][a-z0-9 -]{1,40}?)\s*\(\s*v([1-9])\s*\))");
    for (const Sentence& s : sentences) {
      for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kDescBefore); it != std::sregex_iterator(); ++it) {
        const int v = std::stoi((*it)[3].str());
        string d = (*it)[2].str();
        if ((*it)[1].matched) d = d.substr(0, 5) + (*it)[1].str() + " " + d.substr(5);  // "2003 honda cr-v"
        if (!descriptions.count(v)) descriptions[v] = d;
      }
    }
  }
  {
    // Unique aliases: "the ford", "the taurus", "the ford taurus", "the motorcycle".
    static const std::set<string> kGeneric = {"a", "an", "the", "red", "white", "black", "blue", "green", "silver",
                                              "gray", "grey", "gold", "maroon", "tan", "4-door", "2-door", "door",
                                              "unknown", "type", "model", "make", "with", "and", "sedan"};
    std::map<string, std::set<int>> owners;
    for (const auto& [v, d] : descriptions) {
      std::vector<string> words;
      size_t i = 0;
      while (i < d.size()) {
        size_t j = d.find(' ', i);
        if (j == string::npos) j = d.size();
        const string w = d.substr(i, j - i);
        const bool year = w.size() == 4 && std::all_of(w.begin(), w.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
        if (!w.empty() && !year && !kGeneric.count(w)) words.push_back(w);
        i = j + 1;
      }
      if (words.empty()) continue;
      string all;
      for (const auto& w : words) all += (all.empty() ? "" : " ") + w;
      owners[all].insert(v);
      owners[words.front()].insert(v);
      // A make glued to its model number: "the mazda" for "a 2004 mazda3".
      static const regex kGluedModel(R"(^([a-z]{3,})\d{1,2}$)");
      smatch glued;
      if (std::regex_match(words.front(), glued, kGluedModel)) owners[glued[1].str()].insert(v);
      if (words.size() > 1) {
        string model;
        for (size_t k = 1; k < words.size(); ++k) model += (model.empty() ? "" : " ") + words[k];
        owners[model].insert(v);
        // Every word after the make: "the sonoma" for "a gmc sonoma pickup".
        for (size_t k = 1; k < words.size(); ++k) owners[words[k]].insert(v);
      }
      static const std::array<const char*, 7> kClassWord = {"car", "suv", "pickup", "van", "truck", "bus", "motorcycle"};
      owners[kClassWord[static_cast<size_t>(ClassOf(d + " " + (bodies.count(v) ? bodies[v] : "")))]].insert(v);
    }
    // "v2, a 2001 international 9200 tractor pulling a loaded van
    // semitrailer": "the semitrailer", "the trailer" are v2's.
    static const regex kTowedLoad(
        R"(\bv([1-9]),\s+an?\s+[^,;]{0,60}?\b(?:pulling|towing|hauling)\s+(?:an?\s+)?(?:[\w-]+\s+){0,3}?(semi-?trailer|trailer|camper|boat)\b)");
    for (const Sentence& s : sentences) {
      for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kTowedLoad); it != std::sregex_iterator(); ++it) {
        const int v = std::stoi((*it)[1].str());
        owners[(*it)[2].str()].insert(v);
        if ((*it)[2].str() != "trailer") owners["trailer"].insert(v);
      }
    }
    std::vector<std::pair<string, int>> aliases;
    for (const auto& [alias, vs] : owners) {
      if (vs.size() == 1 && alias.size() >= 3) aliases.emplace_back(alias, *vs.begin());
    }
    std::sort(aliases.begin(), aliases.end(), [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
    if (!aliases.empty()) {
      string alt;
      for (const auto& [alias, v] : aliases) alt += (alt.empty() ? "" : "|") + EscapeRegex(alias);
      // "the stopped jetta", "the oncoming ford": a state word may come first.
      const regex alias_re(
          R"(\bthe\s+(?:(?:19|20)\d\d\s+)?(?:(?:stopped|parked|other|struck|striking|turning|oncoming|lead|leading|following|slower|slow-moving|slowing|disabled|stalled|first|second)\s+)?()" +
          // (Not a place named after one: "the car wash", "the truck stop".)
          alt + R"()\b(?!\s+(?:driver|wash|dealership|dealer|lot|park|port|stop|yard|rental|shop|show|terminal|scale|scales)\b))");
      std::map<string, int> lookup(aliases.begin(), aliases.end());
      for (Sentence& s : sentences) {
        s.text = ReplaceWith(s.text, alias_re, [&](const smatch& m) { return "v" + std::to_string(lookup[m[1].str()]); });
      }
    }
  }

  // ---- Kinds, references, focus.
  int max_v = 0;
  for (Sentence& s : sentences) {
    s.kind = KindOf(s.text);
    s.refs = RefsIn(s.text);
    for (const Ref& ref : s.refs) max_v = std::max(max_v, ref.vehicle);
  }
  // An NMVCCS-style report quotes the coded critical events (and states
  // every posted limit); a CIREN case summary does neither.
  const bool quotes_coding =
      std::any_of(sentences.begin(), sentences.end(), [](const Sentence& s) { return s.kind == Kind::kCoding; });

  // ---- The impact: the first sentence with a contact verb between two vehicles.
  static const regex kContact(
      R"(\b(contact(?:ed|ing|s)?|struck|strik(?:e|es|ing)|stuck|impact(?:ed|ing|s)?|collid(?:ed|es|ing)|hit(?:s|ting)?|crashed|rear[- ]end(?:ed|ing)|sideswip(?:ed|ing)|t-?bon(?:ed|ing)|broadsid(?:ed|ing)|ran into|slammed|engaged)\b)");
  size_t impact = sentences.size();
  for (int pass = 0; pass < 3 && impact == sentences.size(); ++pass) {
    for (size_t i = 0; i < sentences.size(); ++i) {
      const Sentence& s = sentences[i];
      if (s.kind == Kind::kCoding || s.kind == Kind::kPeople) continue;
      // A reported sentence usually retells the crash; one that describes the
      // contact plane by plane ("..., but the right side of v1 struck the rear
      // of v2") is the investigator's account.
      static const regex kPlaneContact(
          R"(\bthe\s+(?:front|rear|back|left|right)[a-z -]{0,25}?\s+of\s+v[1-9]\s+(?:\w+\s+)?(?:struck|contacted|impacted|hit)\b)");
      if (pass < 2 && s.kind == Kind::kStatement && !Has(s.text, kPlaneContact)) continue;
      // "could not avoid striking v1" foretells the impact; the sentence that
      // tells it comes next.
      static const regex kAvoided(
          R"(\b(?:avoid\w*|prevent\w*)\s+(?:\w+\s+){0,2}?(?:strik\w*|hit\w*|contact\w*|collid\w*|impact\w*)\b|\bwithout\s+(?:strik\w*|hitting|contact\w*|collid\w*|impact\w*)\b)");
      // Nor is a role's name ("v2, the striking vehicle") a contact.
      static const regex kRoleName(R"(\b(?:striking|struck)\s+(?:vehicle|car|unit|driver)s?\b)");
      if (!Has(std::regex_replace(std::regex_replace(s.text, kAvoided, " "), kRoleName, " "), kContact)) continue;
      const size_t distinct = DistinctVehicles(s.refs);
      if ((pass == 0 && distinct >= 2) || (pass >= 1 && distinct > 0)) {
        impact = i;
        break;
      }
    }
  }

  // "Contact occurred between a jeep (v1) and a honda (v2) at ...": a
  // summary that opens the report; the crash is told where the narrative
  // reaches it.
  if (impact < sentences.size()) {
    static const regex kSummary(R"(\b(?:contact|collision|crash|impact)\s+(?:\w+\s+){0,2}?between\b)");
    if (Has(sentences[impact].text, kSummary)) {
      for (size_t i = impact + 1; i < sentences.size(); ++i) {
        const Sentence& s = sentences[i];
        if (s.kind == Kind::kNarrative && Has(s.text, kContact) && DistinctVehicles(s.refs) >= 2) {
          impact = i;
          break;
        }
      }
    }
  }

  // "... when they collided in the intersection; the front of v1 hit the
  // right side of v2": a contact that names no vehicle after its verb is
  // told again, with the roles, in the next sentence.
  if (impact + 1 < sentences.size()) {
    const Sentence& s = sentences[impact];
    smatch vm;
    if (std::regex_search(s.text, vm, kContact)) {
      const size_t verb_end = static_cast<size_t>(vm.position() + vm.length());
      const bool object_named = std::any_of(s.refs.begin(), s.refs.end(), [&](const Ref& ref) { return ref.pos > verb_end; });
      // (Or later, when the report opens with the collision and then tells
      // the approach: "the striking vehicle ... and the turning vehicle ...
      // collided at the intersection of ... . v1 was westbound ...".)
      for (size_t k = impact + 1; !object_named && k < sentences.size() && k <= impact + 12; ++k) {
        const Sentence& next = sentences[k];
        if (next.kind == Kind::kCoding) break;
        if (next.kind == Kind::kNarrative && DistinctVehicles(next.refs) >= 2 && Has(next.text, kContact)) {
          impact = k;
          break;
        }
      }
    }
  }

  // A struck vehicle that is never numbered ("struck a parked van").
  static const regex kVehicleNoun(
      R"(\b(?:car|van|vehicle|truck|pickup|pick-up|suv|motorcycle|bus|sedan|minivan|jeep|trailer|tractor-trailer)\b)");
  static const regex kObjectNoun(
      R"(\b(?:tree|sapling|stump|shrubs?|bush(?:es)?|hedge\w*|pole|curb|fence|barrier|wall|guardrail|guard rail|ditch|sign|embankment|pedestrian|median|building|mailbox|post|rock|boulder|bridge|culvert|deer|animal|cyclist|bicycle)\b)");
  bool unnumbered_other = false, unnumbered_parked = false;
  if (impact < sentences.size()) {
    const string& s = sentences[impact].text;
    smatch vm;
    if (std::regex_search(s, vm, kContact)) {
      // What it struck, up to the next clause ("..., then the vehicle rolled").
      static const regex kNextClause(R"(,\s*(?:then|and then|and|before|after|which|where)\b|;)");
      string after = vm.suffix().str().substr(0, 80);
      if (smatch cm; std::regex_search(after, cm, kNextClause)) after = after.substr(0, static_cast<size_t>(cm.position()));
      static const regex kVehicleLike(R"(\bparked\b|\bunoccupied\b|\b(?:19|20)\d\d\s+[a-z])");
      if (DistinctVehicles(sentences[impact].refs) == 1 && (Has(after, kVehicleNoun) || Has(after, kVehicleLike)) &&
          !Has(after.substr(0, 30), kObjectNoun) &&
          max_v <= 1) {
        unnumbered_other = true;
        static const regex kParkedWord(R"(\bparked\b|\bunoccupied\b)");
        unnumbered_parked = Has(after, kParkedWord);
      }
    }
  }

  // ---- Participants.
  if (max_v > 0) {
    r.participant_count.Set(std::max(max_v, unnumbered_other ? 2 : 0), Provenance::kStated);
  } else {
    static const regex kCount(R"(\b([1-9])[- ]vehicle\b|\b([1-9]) vehicles\b)");
    smatch m;
    if (std::regex_search(norm, m, kCount)) {
      r.participant_count.Set(std::stoi(m[1].matched ? m[1].str() : m[2].str()), Provenance::kStated);
    } else if (Has(norm, kContact) && Has(norm, kVehicleNoun)) {
      // "the vehicle left the road and struck a tree": one unnumbered vehicle.
      r.participant_count.Set(1, Provenance::kInferred);
    } else {
      r.warnings.push_back("participants: no vehicle references (V1, vehicle one, ...) found");
    }
  }
  const int n_vehicles = std::clamp(r.participant_count.value, 1, kMaxVehicles);
  for (int i = 1; i <= n_vehicles; ++i) {
    VehicleRecord v;
    v.id = "V" + std::to_string(i);
    if (descriptions.count(i)) {
      v.description.Set(descriptions[i], Provenance::kStated);
      v.vehicle_class.Set(ClassOf(descriptions[i] + " " + (bodies.count(i) ? bodies[i] : "")), Provenance::kInferred);
    }
    r.vehicles.push_back(std::move(v));
  }
  if (unnumbered_other && r.vehicles.size() >= 2 && unnumbered_parked) {
    r.vehicles[1].parked.Set(true, Provenance::kStated);
  }

  // ---- Per-vehicle segments. A segment starts where a vehicle is the
  // subject of a clause ("v1 was traveling", ", and v2 stopped", "the driver
  // of v2 ...") or opens a relative clause ("behind v2, a jetta, which was
  // stopped"), and runs to the next such start of another vehicle or to a
  // mention of an unnumbered vehicle ("a noncontact vehicle slowing to turn"
  // is not this vehicle's movement). Objects ("struck v2", "behind v2") do
  // not start a segment: the clause is still about its subject.
  struct Segment {
    int vehicle;
    size_t sentence;
    string text;
    bool perceived = false;  // what another driver saw this vehicle do
  };
  static const regex kSubjectBefore(
      R"((?:^|[,:(.]|\b(?:and|while|when|as|after|before|then|but|whereupon|since|because|until|that|where|so|once|at which time|stated|said|reported|indicated|advised|claimed|explained|admitted|recalled|signal|light|arrow|sign|time|point|moment|curve|crest))\s*(?:the\s+(?:[\w-]+\s+){0,3}?(?:driver|operator|front|rear|back|left|right|side)(?:\s+(?:front|rear|side|left|right))*\s+of\s+)?$)");
  // "just east of the intersection the driver of v1 began to change lanes":
  // a driver followed by a verb is the clause's subject wherever it stands.
  static const regex kDriverOf(R"(\bthe (?:driver|operator) of\s*$)");
  static const regex kVerbAfter(
      R"(^\s+(?:\w+ly\s+)?(?:was|were|had|began|started|then|attempted|tried|intended|turned|pulled|moved|changed|steered|braked|failed|looked|proceeded|continued|drove|decided|did not|could not)\b)");
  // "behind v2, a jetta, which was stopped", and appositives "v2, a parked
  // and unoccupied ciera": both describe that vehicle.
  static const regex kRelativeAfter(
      R"(^(?:,?\s*(?:an?\s+)?[^,]{0,50},)?\s*(?:which|that|who)\s+(?:was|were|is|had|has)\b|^,\s*an?\s)");
  // What a driver saw another vehicle do ("she saw v1 waiting to turn") is
  // about that vehicle, but the sentence stays the observer's.
  static const regex kPerceivedBefore(
      R"(\b(?:saw|seen|see|seeing|observed|noticed|notice|watched|realize|realized|recognize|recognized|looked (?:back|up|again|ahead|forward))\s*(?:that\s+)?$)");
  static const regex kPerceivedState(
      R"(^\s+(?:was\s+|had\s+)?(?:stopped|stationary|waiting|sitting|turning|making|pulling|backing|slowing|traveling|travelling|approaching|coming|entering|exiting|changing)\b|^\s+had\s+(?:already\s+|suddenly\s+)?slowed\b)");
  // Other road users end a vehicle's segment, with the state words in front
  // of them ("recognized slowing or stopped traffic ahead").
  static const regex kOtherVehicle(
      R"(\b(?:slowing|slowed|stopped|stationary|waiting|parked)(?:\s+(?:or|and)\s+\w+)?\s+(?:traffic|vehicles|cars)\b|\b(?:noncontact|uninvolved|non-involved|another|other|oncoming|several|opposing|an?)\s+(?:(?![12]\d{3}\b)[\w-]+\s+){0,2}?(?:vehicles?|cars?|trucks?|pickups?|vans?|suvs?|buses|bus|motorcycles?|semis?|tractor-trailers?|traffic|emergency vehicle)\b|\b\d+\s+(?:\w+\s+)?(?:vehicles|cars)\b|\b(?:vehicles|cars|trucks)\s+(?:that\s+were\s+|which\s+were\s+)?(?:parked|stopped|queued|waiting|lined)\b|\bthe\s+(?:other\s+|stopped\s+|queued\s+)?(?:vehicles|cars)\b|\btraffic\b(?!\s+(?:signals?|lights?|controls?|control devices?|devices?|lanes?))|\bthe\s+(?:non-?contact\s+)?(?:pickup|bus|school bus|city bus|box truck|dump truck|farm tractor|tractor)\b|\b(?:a|an|the)\s+(?:\w+\s+)?(?:witness|pedestrian|bystander|officer|trooper|deputy|flagger|passenger|cyclist|bicyclist)\b)");
  std::vector<Segment> segments;
  int focus = 0;  // the vehicle the running text is about
  for (size_t i = 0; i < sentences.size(); ++i) {
    const Sentence& s = sentences[i];
    const int focus_before = focus;  // who "she stated that ..." is
    struct Start {
      size_t pos;
      int vehicle;
      bool perceived;  // seen by another driver: does not move the focus
    };
    std::vector<Start> starts;
    for (const Ref& ref : s.refs) {
      const string before = Before(s.text, ref.pos, 40);
      const string after = s.text.substr(ref.pos + 2, 80);
      if (Has(before, kSubjectBefore) || Has(after, kRelativeAfter) || (Has(before, kDriverOf) && Has(after, kVerbAfter))) {
        starts.push_back({ref.pos, ref.vehicle, false});
      } else if (Has(before, kPerceivedBefore) && Has(after, kPerceivedState)) {
        starts.push_back({ref.pos, ref.vehicle, true});
      }
    }
    // "the light for v1 turned green and the vehicle started turning": "the
    // vehicle" as a subject is the vehicle named last before it.
    // "v1 struck the back of v2 while it was slowing": a pronoun clause after
    // an object (a vehicle other than the clause's subject) is about the
    // object.
    static const regex kTheVehicle(R"(\bthe vehicle\b(?!'s|\s+(?:of|in|ahead|behind|that|which)\b))");
    static const regex kObjectsClause(R"(\b(?:while|as|when)\s+(?:it|he|she)\s+(?:was|had)\b)");
    auto named_last_before = [&](size_t pos) {
      int last = 0;
      for (const Ref& ref : s.refs) {
        if (ref.pos < pos) last = ref.vehicle;
      }
      return last;
    };
    std::vector<Start> anaphora;
    for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kTheVehicle); it != std::sregex_iterator(); ++it) {
      const size_t pos = static_cast<size_t>(it->position());
      const int last = named_last_before(pos);
      if (last > 0 && Has(Before(s.text, pos, 40), kSubjectBefore)) {
        anaphora.push_back({pos, last, false});
      }
    }
    for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kObjectsClause); it != std::sregex_iterator(); ++it) {
      const size_t pos = static_cast<size_t>(it->position());
      const int last = named_last_before(pos);
      int subject = 0;
      for (const Start& st : starts) {
        if (st.pos < pos) subject = st.vehicle;
      }
      if (last > 0 && subject > 0 && last != subject) anaphora.push_back({pos, last, false});
    }
    if (!anaphora.empty()) {
      starts.insert(starts.end(), anaphora.begin(), anaphora.end());
      std::stable_sort(starts.begin(), starts.end(), [](const Start& a, const Start& b) { return a.pos < b.pos; });
    }
    // Text before the first start belongs to the sentence's focus (pronoun sentences, "as he stopped, ...").
    const size_t first = starts.empty() ? s.text.size() : starts.front().pos;
    // A segment that starts at a vehicle reference skips it; a continuation
    // ("traffic was backed up", "a noncontact car slowed") may be about
    // another road user from its first word.
    auto cut = [&](size_t from, size_t to) {
      string t = s.text.substr(from, to - from);
      // A coded event is the vehicle's own whole ("... for v2 was other
      // vehicle encroachment from adjacent lane").
      if (s.kind == Kind::kCoding) return t;
      size_t skip = from == 0 && (starts.empty() || starts.front().pos > 0) ? 0 : std::min<size_t>(t.size(), 3);
      // The segment's own description ("v2, a pickup truck, was ...") is not
      // another road user.
      static const regex kOwnAppositive(R"(^v[1-9]\s*,\s*an?\s+[^,;]{0,60},)");
      smatch own;
      if (skip > 0 && std::regex_search(t, own, kOwnAppositive)) skip = static_cast<size_t>(own.length(0));
      // "who was watching traffic to his left, started forward": the traffic
      // it watched, told within commas, is not a new subject.
      static const regex kWatchedTraffic(
          R"(\b(watching|watched|checking|checked|looking at|looked at)\s+(?:the\s+)?(?:traffic|cars|vehicles)(?:\s+[\w']+){0,4}\s*,)");
      t = std::regex_replace(t, kWatchedTraffic, "$1,");
      // Nor the traffic it looked out for ("looked to her right for
      // westbound traffic and then pulled out").
      static const regex kLookedForTraffic(
          R"(\b((?:look|check|watch)\w*)\s+(?:(?:to|at)\s+(?:his|her|the|its|their)\s+(?:left|right)\s+)?for\s+(?:[\w-]+bound\s+|oncoming\s+|approaching\s+|cross\s+|other\s+)?(?:traffic|cars|vehicles)\b(?:\s+(?:on|from|along|in)\s+(?:the\s+)?[\w-]+)?)");
      t = std::regex_replace(t, kLookedForTraffic, "$1");
      // What it tows is its own ("a 2004 mack tractor pulling a flatbed
      // semi-trailer was traveling south").
      static const regex kTowing(R"(\b(?:pulling|towing|hauling)\s+$)");
      for (auto it = std::sregex_iterator(t.cbegin() + static_cast<std::ptrdiff_t>(skip), t.cend(), kOtherVehicle);
           it != std::sregex_iterator(); ++it) {
        const size_t at = static_cast<size_t>(it->position()) + skip;
        if (Has(Before(t, at, 20), kTowing)) continue;
        // "did not see any traffic", "saw no other vehicles": nobody there.
        static const regex kNobody(R"(\b(?:any|no)\s+$)");
        if (Has(Before(t, at, 6), kNobody)) continue;
        // Its direction goes with it: "southbound traffic in the curb lane".
        static const regex kBoundBefore(R"(\b(?:north|south|east|west)bound\s+$)");
        smatch bm;
        const string before = Before(t, at, 16);
        const size_t cut_at = std::regex_search(before, bm, kBoundBefore) ? at - static_cast<size_t>(bm.length(0)) : at;
        // The driver's own clause after it is this vehicle's again: "a bus
        // at the curb blocked her view, and she pulled out past it".
        static const regex kDriverResumes(
            R"((?:,\s*(?:and|so|but|then)|\b(?:and|then))\s+(?:then\s+)?(?:he|she)\s+(?:\w+ly\s+)?(?:was|had|began|started|\w+ed)\b)");
        smatch rm;
        const string rest = t.substr(at);
        t = t.substr(0, cut_at);
        if (std::regex_search(rest, rm, kDriverResumes)) t += " " + rest.substr(static_cast<size_t>(rm.position()));
        break;
      }
      return t;
    };
    if (first > 0) {
      // Coded sentences name their vehicle first ("the critical precrash
      // event for v1 was ... this vehicle ..."); others continue the focus.
      const int owner = s.kind == Kind::kCoding && !s.refs.empty() ? s.refs.front().vehicle : focus;
      if (owner > 0) segments.push_back({owner, i, cut(0, first)});
    }
    const auto subject = std::find_if(starts.begin(), starts.end(), [](const Start& st) { return !st.perceived; });
    if (subject != starts.end()) {
      focus = subject->vehicle;
    } else if (s.kind == Kind::kCoding && !s.refs.empty()) {
      focus = s.refs.front().vehicle;
    }
    // Where a segment of vehicle k's ends: at the next start of another vehicle.
    auto end_of = [&](size_t k) {
      for (size_t q = k + 1; q < starts.size(); ++q) {
        if (starts[q].vehicle != starts[k].vehicle) return starts[q].pos;
      }
      return s.text.size();
    };
    // "v2 and v3 were slowing": a coordinated subject shares its predicate,
    // also with its body told after the model ("v2, a 1997 ford mustang,
    // 2-door coupe and v3, ... were traveling south").
    static const regex kCoordinated(
        R"(^v[1-9]\s*(?:,\s*an?\s+[^,;]{1,60}(?:,\s*[^,;]{0,30}\b(?:door|sedan|coupe|pickup|truck|van|minivan|utility vehicle|wagon|hatchback|convertible|motorcycle|bus)\b)?)?\s*(?:,\s*(?:and\s+)?|and\s+)$)");
    for (size_t k = 0; k < starts.size(); ++k) {
      if (k > 0 && starts[k - 1].vehicle == starts[k].vehicle) continue;
      size_t from = starts[k].pos, end = end_of(k);
      for (size_t q = k + 1; q < starts.size(); ++q) {
        if (!Has(s.text.substr(starts[q - 1].pos, starts[q].pos - starts[q - 1].pos), kCoordinated)) break;
        from = starts[q].pos;
        end = end_of(q);
      }
      string seg_text = cut(from, end);
      // What the observer only believed of it ("saw v2 coming but thought it
      // was slowing") is not what it did.
      static const regex kBelief(R"(\b(?:thought|believed|assumed|expected|figured)\b)");
      smatch bm;
      if (starts[k].perceived && std::regex_search(seg_text, bm, kBelief)) {
        seg_text = seg_text.substr(0, static_cast<size_t>(bm.position()));
      }
      // In a driver's account of another vehicle ("she stated that the buick
      // pulled out in front of her and she braked but could not stop"), the
      // teller's own clause is not the other's.
      static const regex kTellerClause(R"(\b(?:and|but|so|then)\s+(?:then\s+)?(?:he|she)\b)");
      static const regex kOpensWithDriver(R"(^\s*(?:the\s+)?(?:driver|operator)\s+of\s*$)");
      const bool named_teller = first == 0 || Has(s.text.substr(0, first), kOpensWithDriver);
      const int teller = named_teller ? starts.front().vehicle : focus_before;
      if (s.kind == Kind::kStatement && teller > 0 && starts[k].vehicle != teller &&
          std::regex_search(seg_text, bm, kTellerClause)) {
        seg_text = seg_text.substr(0, static_cast<size_t>(bm.position()));
      }
      segments.push_back({starts[k].vehicle, i, seg_text, starts[k].perceived});
    }
  }

  // ACCSIM_DEBUG_SEGMENTS=1 lists each vehicle's text on stderr (vehicle,
  // sentence, kind, impact sentence): what the movement rules read.
  if (std::getenv("ACCSIM_DEBUG_SEGMENTS")) {
    for (const auto& sg : segments) {
      std::fprintf(stderr, "[v%d s%zu k%d imp%zu%s] %s\n", sg.vehicle, sg.sentence,
                   static_cast<int>(sentences[sg.sentence].kind), impact, sg.perceived ? " seen" : "", sg.text.c_str());
    }
  }
  // What the narrative itself tells of V1 before the impact (not what
  // another driver saw of it, not a coded or injury sentence).
  auto v1_before_impact = [&](const Segment& seg) {
    return seg.vehicle == 1 && !seg.perceived && seg.sentence <= impact && sentences[seg.sentence].kind == Kind::kNarrative;
  };

  // ---- Directions, lanes, speeds, movements per vehicle.
  static const regex kLaneNo(
      R"(\b(?:in|within|using|from|occupying)\s+(?:the\s+)?(?:lane\s+([1-9])\b|([1-9])(?:st|nd|rd|th)\s+(?:\w+\s+){0,2}?lane))");
  static const regex kSpeed(
      R"(\b(?:travel\w*|going|speed\w*|estimated|at|approximately|about|between|around|driving|doing|less than|no more than)\s+(?:\w+\s+){0,4}?(\d{1,3})(?:\s*(?:-|to)\s*(\d{1,3}))?\s*(kmh|mph)\b)");
  static const regex kLimitWords(R"(limit|posted|advisory|suggested|recommended|speed zone)");
  static const regex kSameDir(R"(\b(?:same direction|also (?:travel\w*|heading|going) (?:north|south|east|west)|behind v[1-9]|followed|following)\b)");
  static const regex kOppositeDir(R"(\b(?:opposite direction|proceeding opposite|oncoming|opposing direction)\b)");
  std::vector<MovementEvidence> narrative(r.vehicles.size() + 1), statement(r.vehicles.size() + 1);
  std::vector<int> relation(r.vehicles.size() + 1, 0);  // +1 same direction as the other, -1 opposite
  std::vector<std::optional<Compass>> late_travel(r.vehicles.size() + 1);
  for (const Segment& seg : segments) {
    if (seg.vehicle < 1 || seg.vehicle > static_cast<int>(r.vehicles.size())) continue;
    const size_t vi = static_cast<size_t>(seg.vehicle);
    VehicleRecord& v = r.vehicles[vi - 1];
    const Kind kind = sentences[seg.sentence].kind;
    // Told after the impact but in the past perfect ("v2 had stopped at the
    // sign before initiating its turn"): still what happened before it.
    static const regex kPastPerfect(
        R"(^\s*(?:v[1-9]|he|she|they|it|the driver(?: of v[1-9])?)\b[^.]{0,80}?\bhad\s+(?:\w+\s+)?(?:been|stopped|slowed|turned|begun|started|come|pulled|entered)\b)");
    const bool pre_impact = seg.sentence <= impact || impact == sentences.size() || Has(seg.text, kPastPerfect);
    // Told after the impact about the time before the manoeuvre ("he did not
    // stop before making the turn"): read as the driver's account.
    static const regex kBeforeTheCrash(
        R"(\b(?:before|prior to)\s+(?:making|starting|beginning|initiating|entering|turning|pulling|the (?:turn|crash|collision|impact)|impact)\b)");
    const bool told_of_before = !pre_impact && Has(seg.text, kBeforeTheCrash);
    // A vehicle first met after the impact, with its state in a relative
    // clause ("was pushed into v3, a honda, which was stopped at the light"),
    // or one said to be parked: that state is from before the crash.
    static const regex kRelativeState(
        R"(^v[1-9]\s*(?:,\s*(?:an?\s+)?[^,]{0,50},)?\s*(?:(?:which|that|who)\s+(?:was|were|had been)\s+(?:\w+\s+)?(?:stopped|parked|stationary|waiting|sitting|standing|slowing)|(?:was|were|had been)\s+(?:legally\s+|lawfully\s+)?(?:parked|unoccupied))\b)");
    // A vehicle introduced after the impact ("v2 was a 1997 dodge pickup that
    // was stopped to make a left turn"): the introduction is background.
    static const regex kIntroduction(R"(^v[1-9]\s+(?:was|is)\s+an?\s+(?:(?:19|20)\d\d|[a-z]+\s+(?:19|20)\d\d)\b)");
    const bool state_in_relative = !pre_impact && (Has(seg.text, kRelativeState) || Has(seg.text, kIntroduction));
    smatch m;
    if (kind == Kind::kNarrative || kind == Kind::kStatement) {
      // After the impact a direction is where the vehicle went ("continued
      // into the southbound lane"); only one told with a travel verb is its
      // course, and only when nothing else gives one (below).
      static const regex kTravelling(
          R"(\b(?:travel\w*|heading|headed|driving|proceeding|going)\s+(?:\w+\s+){0,2}?(?:north|south|east|west)\w*)");
      static const regex kAtRest(R"(\b(?:rest|facing|came to)\b)");  // where it ended up, not its course
      if (!v.travel.known() && pre_impact) {
        if (const auto d = DirectionIn(seg.text)) v.travel.Set(*d, Provenance::kStated);
      } else if (!late_travel[vi] && kind == Kind::kNarrative && Has(seg.text, kTravelling) && !Has(seg.text, kAtRest)) {
        late_travel[vi] = DirectionIn(seg.text);
      }
      if (relation[vi] == 0 && pre_impact) {
        if (Has(seg.text, kOppositeDir)) relation[vi] = -1;
        else if (Has(seg.text, kSameDir)) relation[vi] = 1;
      }
      // Where it came to rest ("came to rest in lane 3") is not its lane,
      // nor is another vehicle's ("thought v2 was in lane 2").
      if (!v.lane.known() && !Has(seg.text, kAtRest) && std::regex_search(seg.text, m, kLaneNo)) {
        const size_t at = static_cast<size_t>(m.position());
        const string lead = Before(seg.text, at, 20);
        static const regex kRefNear(R"(\bv([1-9])\b)");
        smatch rm;
        const bool other = std::regex_search(lead, rm, kRefNear) && std::stoi(rm[1].str()) != seg.vehicle;
        if (!other) v.lane.Set(std::stoi(m[1].matched ? m[1].str() : m[2].str()), Provenance::kStated);
      }
    }
    if (kind != Kind::kCoding && !v.speed_mps.known() && !Has(seg.text, kLimitWords) &&
        std::regex_search(seg.text, m, kSpeed)) {
      const double lo = std::stod(m[1].str());
      const double hi = m[2].matched ? std::stod(m[2].str()) : lo;
      const bool kmh = m[3].str() == "kmh";
      if (hi < 200) {
        v.speed_mps.Set(0.5 * (lo + hi) * (kmh ? kKmhToMps : kMphToMps), Provenance::kStated);
        v.speed_unit.Set(kmh ? "km/h" : "mph", Provenance::kStated);
      }
    }
    static const regex kParkedOnly(R"(\bparked\b)");
    if (kind == Kind::kNarrative && pre_impact && !seg.perceived) {
      ReadMovement(seg.text, narrative[vi]);
    } else if (kind == Kind::kStatement || seg.perceived || (kind == Kind::kPeople && Has(seg.text, kParkedOnly)) ||
               (kind == Kind::kNarrative && (told_of_before || state_in_relative))) {
      ReadMovement(seg.text, statement[vi]);
    } else if (kind == Kind::kCoding) {
      MovementEvidence* other = nullptr;
      if (r.vehicles.size() == 2) other = &narrative[vi == 1 ? 2 : 1];
      ReadCoding(seg.text, narrative[vi], other);
    }
  }
  // "4 passenger vehicles were stopped in the right lane: v5, ..., then v4,
  // ...": every vehicle listed after the colon is in that state.
  {
    static const regex kListState(
        R"(\b(?:\d|all|the|several)\s+(?:\w+\s+)?(?:vehicles|cars)\s+were\s+(?:\w+\s+)?(stopped|stationary|waiting|queued|slowing)\b[^:]*:)");
    // The list may run on over ";"-separated items ("; then v4, a sienna").
    static const regex kListItem(R"(^(?:then|and|followed by)?\s*v[1-9]\b)");
    for (size_t i = 0; i < sentences.size(); ++i) {
      const Sentence& s = sentences[i];
      smatch m;
      if ((s.kind != Kind::kNarrative && s.kind != Kind::kStatement) || !std::regex_search(s.text, m, kListState)) continue;
      auto mark = [&](const Sentence& t, size_t from) {
        for (const Ref& ref : t.refs) {
          if (ref.pos < from || ref.vehicle < 1 || ref.vehicle >= static_cast<int>(statement.size())) continue;
          (m[1].str() == "slowing" ? statement[static_cast<size_t>(ref.vehicle)].slowing
                                   : statement[static_cast<size_t>(ref.vehicle)].stopped) = true;
        }
      };
      mark(s, static_cast<size_t>(m.position() + m.length()));
      for (size_t j = i + 1; j < sentences.size() && Has(sentences[j].text, kListItem); ++j) mark(sentences[j], 0);
    }
  }
  // "When the signal turned green, both vehicles began to move forward":
  // what the vehicles did together before the impact is each one's.
  {
    static const regex kAllSubject(
        R"((?:^|[,;:]\s*|\b(?:and|then|when|as)\s+)(?:both|all|all 3|all 4|the 2|the 3) (?:vehicles|cars|units)\b(?!\s+(?:came|were (?:towed|driven|removed)|rested)\b))");
    for (size_t i = 0; i < sentences.size() && i < impact; ++i) {
      const Sentence& s = sentences[i];
      smatch m;
      if (s.kind != Kind::kNarrative || !std::regex_search(s.text, m, kAllSubject)) continue;
      const string together = m.suffix().str();
      for (size_t k = 1; k < narrative.size(); ++k) ReadMovement(together, narrative[k]);
    }
  }
  // "Both vehicles were traveling north": every vehicle the text gives no
  // direction of its own.
  // So does a list of them: "v1, v2 and v3 were northbound".
  static const regex kAllTravel(
      R"(\b(?:(?:both|all|the 2|the 3) (?:vehicles|cars|units)|(v[1-9](?:\s*,\s*v[1-9])*,?\s+and\s+v[1-9]))\b[^.]{0,30}?\b(?:travel\w*|heading|headed|going|proceeding|driving|were)\s+(?:due\s+)?(north|south|east|west)(?:bound)?\b)");
  for (const Sentence& s : sentences) {
    smatch all;
    if ((s.kind == Kind::kNarrative || s.kind == Kind::kStatement) && std::regex_search(s.text, all, kAllTravel)) {
      std::set<int> listed;
      const string list = all[1].str();
      for (const Ref& ref : RefsIn(list)) listed.insert(ref.vehicle);
      for (size_t i = 0; i < r.vehicles.size(); ++i) {
        VehicleRecord& v = r.vehicles[i];
        const bool named = listed.empty() || listed.count(static_cast<int>(i) + 1);
        if (named && !v.travel.known()) v.travel.Set(CompassWord(all[2].str()), Provenance::kStated);
      }
      break;
    }
  }
  // Inverted: "southbound on the same road were v2, followed by v3, and then
  // v4": every vehicle named after the verb.
  {
    static const regex kInverted(R"(^(?:also\s+)?(north|south|east|west)bound\b[^.]{0,60}?\b(?:was|were)\s+(?=v[1-9]\b))");
    for (const Sentence& s : sentences) {
      smatch m;
      if (s.kind != Kind::kNarrative || !std::regex_search(s.text, m, kInverted)) continue;
      for (const Ref& ref : s.refs) {
        if (ref.pos < static_cast<size_t>(m.length(0)) || ref.vehicle > static_cast<int>(r.vehicles.size())) continue;
        VehicleRecord& v = r.vehicles[static_cast<size_t>(ref.vehicle - 1)];
        if (!v.travel.known()) v.travel.Set(CompassWord(m[1].str()), Provenance::kStated);
      }
    }
  }
  // Directions stated relative to the other vehicle; then those told only
  // after the impact, and the relative ones again.
  auto relative_directions = [&] {
    if (r.vehicles.size() < 2) return;
    for (size_t i = 1; i <= 2; ++i) {
      VehicleRecord& v = r.vehicles[i - 1];
      const VehicleRecord& o = r.vehicles[2 - i];
      if (!v.travel.known() && o.travel.known() && o.travel.value && relation[i] != 0) {
        const Compass c = *o.travel.value;
        v.travel.Set(relation[i] > 0 ? c : static_cast<Compass>((static_cast<int>(c) + 2) % 4), Provenance::kInferred);
      }
    }
  };
  relative_directions();
  for (size_t i = 0; i < r.vehicles.size(); ++i) {
    if (!r.vehicles[i].travel.known() && late_travel[i + 1]) r.vehicles[i].travel.Set(*late_travel[i + 1], Provenance::kStated);
  }
  relative_directions();
  // "v1 failed to slow for stopped traffic, striking v2, which was pushed
  // into v3": the vehicles it ran into were that traffic.
  {
    static const regex kIntoQueue(
        R"(\bv([1-9])\b[^.]{0,40}?\b(?:failed to|did not|didn't|could not|couldn't|was unable to|unable to)\s+(?:\w+\s+)?(?:slow|stop)\w*\s+(?:\w+\s+){0,2}?for\s+(?:the\s+)?(?:(stopped|stationary|queued|backed[- ]up)|slowing|slowed|slower)\s+(?:traffic|vehicles|cars)\b)");
    for (const Sentence& s : sentences) {
      smatch m;
      if ((s.kind != Kind::kNarrative && s.kind != Kind::kStatement) || !std::regex_search(s.text, m, kIntoQueue)) continue;
      const int runner = std::stoi(m[1].str());
      for (size_t i = 1; i < narrative.size(); ++i) {
        if (static_cast<int>(i) == runner || narrative[i].any_narrative() || statement[i].any_narrative()) continue;
        (m[2].matched ? statement[i].stopped : statement[i].slowing) = true;
      }
      break;
    }
  }
  // CIREN case summaries code a vehicle that stopped and then turned by its
  // turn (the development set's one such case, a car stopped in the mouth of
  // a driveway waiting to turn left, is coded turning left); NMVCCS reports,
  // which quote the coded critical events, code the stop.
  // (Read in the text as given: normalising names the case vehicle v1.)
  static const regex kCaseSummary(R"(\bcase\s+(?:vehicle|occupant)\b)", std::regex::icase);
  const bool case_summary = std::regex_search(text.begin(), text.end(), kCaseSummary) && !quotes_coding;
  for (size_t i = 0; i < r.vehicles.size(); ++i) {
    VehicleRecord& v = r.vehicles[i];
    if ((narrative[i + 1].parked || statement[i + 1].parked) && !LeftParking(narrative[i + 1])) {
      v.parked.Set(true, Provenance::kStated);
    }
    MovementDecision d = DecideMovement(narrative[i + 1], statement[i + 1]);
    const bool turned = d.manoeuvre == Movement::kTurnLeft || d.manoeuvre == Movement::kTurnRight;
    if (case_summary && turned && d.pre_event == Movement::kStopped) d.pre_event = d.manoeuvre;
    v.movement.Set(d.manoeuvre, d.source);
    v.pre_event.Set(d.pre_event, d.source);
    if (v.parked.value) {
      v.movement.Set(Movement::kStopped, Provenance::kStated);
      v.pre_event.Set(Movement::kStopped, Provenance::kStated);
    }
  }

  // ---- Road: kind, lanes, division, surface, weather, light, grade, limit.
  string scene;  // narrative and statements only: coded sentences use fixed NHTSA wording
  for (const Sentence& s : sentences) {
    if (s.kind == Kind::kNarrative || s.kind == Kind::kStatement) scene += s.text;
  }
  scene = WithoutDistantJunctions(scene);
  static const regex kTJunction(
      R"(\bt[- ]?(?:intersection|junction)|\b3[- ]leg|\btee\b|\bt-shaped|\bthree[- ]leg|\bt-type intersection)");
  static const regex kIntersection(
      R"(\bintersection\b|(?:^|[^a-z-])junction\b|\b4[- ](?:leg|way)\b|\bcrossroads?\b|\bside (?:road|street)|\bcross (?:road|street)|)" +
      WhereRoadsMeet());
  static const regex kDriveway(
      R"(\bdriveway\b|\bparking lot\b|\bprivate (?:drive|road)\b|\balley\b|\b(?:business|store|restaurant|station|shopping|lot) (?:entrance|exit|driveway)|\bout of (?:a|the) lot\b|\bservice station\b|\bgas(?:oline)? station\b|\b(?:filling|fuel) station\b|\bpetrol station\b|\bcar park\b|\bentrances? (?:of|to|into) (?:a|an|the) (?:[a-z-]+ ){0,2}?(?:station|store|shop|restaurant|business|lot|plaza|mall|center|centre|yard|complex|dealership|bank|school|church|office|farm|market|supermarket)\b)");
  static const regex kRamp(R"(\b(?:on|off|entrance|exit)?[- ]?ramp\b)");
  static const regex kCurve(R"(\bcurv(?:e|ed|ing)\b)");
  if (Has(scene, kTJunction)) r.road.kind.Set(RoadKind::kTJunction, Provenance::kStated);
  else if (Has(scene, kIntersection)) r.road.kind.Set(RoadKind::kIntersection, Provenance::kStated);
  else if (Has(scene, kRamp)) r.road.kind.Set(RoadKind::kRamp, Provenance::kStated);
  else if (Has(scene, kDriveway)) r.road.kind.Set(RoadKind::kDriveway, Provenance::kStated);
  else if (Has(scene, kCurve)) r.road.kind.Set(RoadKind::kCurve, Provenance::kStated);

  const VehicleRecord* v1 = r.vehicles.empty() ? nullptr : &r.vehicles.front();
  // -1: V1's axis is unknown (an int, not an optional: GCC 12 warns falsely on the latter).
  const int v1_axis = v1 && v1->travel.known() && v1->travel.value ? AxisOf(*v1->travel.value) : -1;
  // A clause split off at ';' or a sentence about "it" ("the north/south
  // roadway was a 2-lane street ...; it had a stop sign and a posted speed
  // limit of 40 kmh") is about the road the sentence before began with.
  auto inherited_axis = [&](size_t i, std::optional<int> axis) -> std::optional<int> {
    static const regex kAnaphoric(R"(^\s*(?:it|its|it's|this (?:road|roadway|street)|that (?:road|roadway|street))\b)");
    if (axis || i == 0 || !Has(sentences[i].text, kAnaphoric)) return axis;
    return AxisIn(sentences[i - 1].text.substr(0, 40));
  };
  // Named roads, and the one V1 is said to travel on.
  std::vector<string> scene_texts;
  for (const Sentence& s : sentences) {
    if (s.kind == Kind::kNarrative || s.kind == Kind::kStatement) scene_texts.push_back(s.text);
  }
  const RoadNames road_names(scene_texts);
  // The named road a clause is about; a sentence naming none and no
  // vehicle ("route 9 is divided ...; the limit was 50") is about the road
  // the sentence before began with.
  auto named_at = [&](size_t i, size_t pos) {
    string n = road_names.Subject(sentences[i].text, pos);
    if (n.empty() && i > 0 && sentences[i].refs.empty() && !road_names.Mentioned(sentences[i].text)) {
      n = road_names.Subject(sentences[i - 1].text, 40);
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
  };
  // The road V1 is said to be on by its kind ("v1 was westbound on the
  // side street", "on a residential street"; "the road", "the street"
  // name no road in particular) and by name ("on route 9").
  string v1_road, v1_named_road;
  for (const Segment& seg : segments) {
    if (seg.vehicle != 1 || seg.perceived || sentences[seg.sentence].kind != Kind::kNarrative) continue;
    if (v1_road.empty()) v1_road = RoadTravelledOn(seg.text);
    // "v1 (...) and v2 were both westbound on route 9": the coordinated
    // subject's predicate is the sentence's.
    static const regex kCoordinatedEnd(R"(\band\s*$)");
    const string& said = Has(seg.text, kCoordinatedEnd) ? sentences[seg.sentence].text : seg.text;
    if (v1_named_road.empty()) v1_named_road = road_names.TravelledOn(said);
    if (!v1_road.empty() && !v1_named_road.empty()) break;
  }
  // V1 stopped at a stop sign on a road the report does not name for it:
  // the one road the report says a stop sign controls ("the residential
  // street ... was controlled by a stop sign").
  if (v1_road.empty() && v1_named_road.empty()) {
    static const regex kAtTheSign(R"(\b(?:stopped|stop|waiting|sat|paused)\b[^.;]{0,25}?\bstop sign\b)");
    const bool v1_at_sign = std::any_of(segments.begin(), segments.end(),
                                        [&](const Segment& seg) { return v1_before_impact(seg) && Has(seg.text, kAtTheSign); });
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
  const bool distinctive = !v1_road.empty() && !GenericRoad(v1_road);
  // Which vehicle's segment a position in a sentence belongs to.
  // A coordinated subject ("v1 and v2 were both traveling northbound on a
  // 3-lane oneway roadway") is V1's when it names V1.
  auto owner_at = [&](const Sentence& s, size_t pos) {
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
  };
  {
    // "2 through lanes plus a left-turn bay in each direction": 3 each way.
    static const regex kPerDir(
        R"(\b(\d)[- ](?:through\s+|travel\s+|moving\s+)?lanes?\s+(?:of\s+(?:traffic|travel)\s+)?(?:(plus|and)\s+(?:a|an|one|1)\s+(?:single\s+|exclusive\s+|separate\s+|dedicated\s+)?(?:left|right)[- ]turn\s+(?:bay|lane)\s+)?(?:in\s+|for\s+|going\s+in\s+)?(?:each|either|both|per|every)\s+(?:the\s+\w+\s+and\s+\w+\s+)?(?:directions?|ways?\b))");
    // "each direction of route 30 has 2 through lanes plus a left-turn bay",
    // "a grass median and, in each direction, 2 through lanes and a left-turn lane".
    static const regex kEachHas(
        R"((?:\beach (?:direction|approach|side)\b[^.;]{0,30}?\b(?:has|had)|\b(?:in|for)\s+(?:each|either|both)\s+directions?\s*,)\s+(\d)\s+(?:through\s+|travel\s+|moving\s+)?lanes?(?:\s+(plus|and)\s+(?:a|an|one|1)\s+(?:single\s+|exclusive\s+|separate\s+|dedicated\s+)?(?:left|right)[- ]turn\s+(?:bay|lane))?)");
    static const regex kDirectional(
        R"(\b(\d)\s+(?:north|south|east|west)bound(?:\s+(?:(?:left|right)[- ]turn(?:[- ]only)?\s+|travel\s+|through\s+)?lanes?\b|(?=\s*(?:[,;.)]|and\b|$)))|\b(\d)\s+lanes?\s+(?:head|go|travel)s?\s+(?:north|south|east|west)|\b(\d)\s+(?:travel\s+|through\s+)?lanes?\s+(?:for\s+|going\s+|heading\s+|carrying\s+)?(?:north|south|east|west)bound\b)");
    static const regex kTotal(
        R"(\b(\d)[- ](?:\d+(?:\.\d+)?[- ]?(?:meter|metre|m|foot|ft|feet)[- ](?:wide\s+)?)?(?:travel\s+|through\s+|traffic\s+)?lanes?\b(?!\s+(?:of\s+(?:traffic|travel)\s+)?(?:lines?|markings?|in each|in both|for each|per|each way|either way|each direction|either direction|both directions|(?:head|go|travel)s?\s+(?:north|south|east|west)|(?:for\s+|going\s+|heading\s+|carrying\s+)?(?:north|south|east|west)bound)))");
    static const regex kOneWayHere(R"(\boneway\b)");
    // Roads named with their axis ("a north/south rural highway and an
    // east/west county road") give it to later sentences about them ("the
    // county road is a 2-lane road").
    static const string kRoadNoun = R"((?:county |state |rural |city |residential |through |collector |main |frontage )?(?:road|roadway|street|highway|avenue|boulevard|route|drive|lane))";
    static const regex kNamedAxis(
        R"(\b(north|south|east|west)(?:/|-|\s+and\s+)(?:north|south|east|west)\s+(?:[\w-]+\s+){0,2}?)" + kRoadNoun + R"(\b)");
    static const regex kSubjectRoad(R"(^(?:the\s+)?)" + kRoadNoun + R"(\b)");
    std::map<string, int> axis_of_road;
    for (const Sentence& s : sentences) {
      for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kNamedAxis); it != std::sregex_iterator(); ++it) {
        const string w = (*it)[1].str(), named = it->str();
        static const regex kTail(kRoadNoun + "$");
        smatch nm;
        if (std::regex_search(named, nm, kTail)) axis_of_road[nm.str()] = (w == "east" || w == "west") ? 0 : 1;
      }
    }
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
        RoadStatement rs;
        rs.sentence = i;
        rs.pos = pos;
        rs.owner = owner_at(s, pos);
        const size_t from = pos > 60 ? pos - 60 : 0;
        const string around = s.text.substr(from, pos - from + static_cast<size_t>(m.length(0)) + 40);
        // The road's axis: named up to the count ("an east-west roadway with
        // two lanes each way"), else after it ("a 4-lane road running
        // north-south"); the next road's ("..., and a northbound one-way")
        // is not this one's.
        const size_t start = RoadPhraseStart(s.text, pos);
        rs.axis = AxisIn(s.text.substr(start, pos - start + static_cast<size_t>(m.length(0))));
        // "..., and mill street, a 2-lane north/south residential street":
        // the count's own noun phrase before the wider window.
        if (!rs.axis) {
          static const regex kOwnPhraseAxis(R"(^[^,;.]{0,12}?\b((?:north|south|east|west)(?:/|-|\s+and\s+)(?:north|south|east|west))\b)");
          smatch am;
          const string own = s.text.substr(pos + static_cast<size_t>(m.length(0)), 30);
          if (std::regex_search(own, am, kOwnPhraseAxis)) rs.axis = AxisIn(am[1].str());
        }
        if (!rs.axis) rs.axis = AxisIn(around);
        rs.axis = inherited_axis(i, rs.axis);
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
        string near_after = s.text.substr(pos + static_cast<size_t>(m.length(0)), 15);
        // ... but "a 1-lane, oneway roadway" lists adjectives of one road.
        const size_t comma = near_after.rfind(", oneway", 0) == 0 || near_after.rfind(",oneway", 0) == 0
                                 ? string::npos
                                 : near_after.find(',');
        const size_t stop = std::min(comma, near_after.find(" and "));
        if (stop != string::npos) near_after = near_after.substr(0, stop);
        rs.one_way = Has(near_before, kOneWayHere) || Has(near_after, kOneWayHere);
        static const regex kCrossStreet(
            R"(\b(?:cross|crossing|intersecting|side|minor)\s+(?:street|road|roadway|route)\b|\bcrossroad\b|\bthe stem\b)");
        rs.cross = Has(around, kCrossStreet);
        static const regex kRampAfter(R"(^[\w ,-]{0,30}?\bramp\b)");
        rs.ramp = Has(s.text.substr(pos + static_cast<size_t>(m.length(0)), 40), kRampAfter);
        // The phrase runs on to the next road named ("1 lane in each direction
        // and an east/west 2-way roadway with ... a center left turn lane":
        // the centre lane is the other road's).
        static const regex kCentreLane(
            R"(\b(?:center|centre|continuous|middle)\s+(?:2[- ]way\s+)?(?:left[- ]turn\s+)?lane\b|\b2[- ]way left[- ]turn lane\b)");
        string phrase_after = s.text.substr(pos + static_cast<size_t>(m.length(0)));
        smatch rw;
        if (std::regex_search(phrase_after, rw, RoadWord())) {
          const size_t at = static_cast<size_t>(rw.position());
          const string noun = rw[1].str();
          phrase_after = phrase_after.substr(0, at);
          static const regex kPhraseBreak(R"(\b(?:and|or|with|of|in|on|at|to|for|from|each|per)\b|[;:(])");
          if (at <= 30 && !Has(phrase_after, kPhraseBreak)) rs.counted = noun;
        }
        rs.centre = Has(s.text.substr(start, pos - start) + " " + phrase_after, kCentreLane);
        rs.name = road_names.Modified(s.text.substr(pos));
        if (rs.name.empty()) rs.name = named_at(i, pos);
        rs.road = SubjectRoad(s.text, pos);
        rs.total = total;
        rs.per_direction = per_dir;
        rs.directional = directional;
        roads.push_back(rs);
      };
      for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kPerDir); it != std::sregex_iterator(); ++it) {
        add(*it, static_cast<size_t>(it->position()), 0, std::stoi((*it)[1].str()) + ((*it)[2].matched ? 1 : 0), 0);
      }
      for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kEachHas); it != std::sregex_iterator(); ++it) {
        add(*it, static_cast<size_t>(it->position()), 0, std::stoi((*it)[1].str()) + ((*it)[2].matched ? 1 : 0), 0);
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
        // "lane 2" / "the 2 lanes to the left" are not road descriptions; "2-lane", "2 lane road" are.
        const string after = it->suffix().str().substr(0, 40);
        const string before = s.text.substr(0, static_cast<size_t>(it->position()));
        static const regex kNotARoadAfter(R"(^\s*(?:to the|of the|lines?))");
        if (Has(after, kNotARoadAfter)) continue;
        static const regex kNotARoadBefore(R"(\b(?:crossing|across|all|over)\s+(?:the\s+)?$)");
        if (Has(before.substr(before.size() > 12 ? before.size() - 12 : 0), kNotARoadBefore)) continue;
        // "the eastbound roadway had 3 travel lanes", "the southbound side
        // widened to 3 lanes", "southbound there were 3 lanes", "the
        // eastbound lanes, 2 lanes wide": one direction's count, with its turn bay
        // ("2 through lanes and a left-turn bay").
        static const regex kDirectionSubject(
            R"(\b(?:north|south|east|west)bound\s+(?:roadway|road|street|highway|lanes|side|carriageway|half|direction|approach|traffic)\s+(?:\w+\s+)?(?:had|has|have|consisted of|consists of|carried|carries|widened to|widens to|narrowed to|narrows to|expanded to|expands to|was|is|were|are)\s+(?:only\s+|just\s+)?(?:(?:a|an|1)\s+(?:left|right)[- ]turn\s+(?:lane|bay)\s+(?:and|plus)\s+|(?:a|an|1)\s+(?:left|right)[- ]turn\s+(?:lane|bay)\b[^.;]{0,50}?\bin addition to\s+(?:its|the)\s+)?$|\b(?:north|south|east|west)bound\s*,?\s+there\s+(?:were|was)\s+(?:only\s+|just\s+)?$|\b(?:north|south|east|west)bound\s+(?:lanes|roadway|side|carriageway)\s*,\s*$)");
        static const regex kBayAfter(
            R"(^\s+(?:through\s+|travel\s+)?lanes?\s*,?\s+(?:and|plus)\s+(?:a|an|1)\s+(?:(?!and\b)[\w-]+\s+){0,2}?(?:left|right)[- ]turn\s+(?:bay|lane)\b|^\s+(?:and|plus)\s+(?:a|an|1)\s+(?:(?!and\b)[\w-]+\s+){0,2}?(?:left|right)[- ]turn\s+(?:bay|lane)\b)");
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
            const bool bay = Has(after, kBayAfter) || Has(subject, kBayBefore);
            add(*it, static_cast<size_t>(it->position()), 0, 0, n + (bay ? 1 : 0));
            roads.back().bound = bound;
          }
          continue;
        }
        // "a 2-lane roadway that widened to 3 lanes on each approach to the
        // intersection": the junction's count replaces the totals before it.
        static const regex kWidenedTo(R"(\b(?:widen\w*|flare\w*|expand\w*|increas\w*)\s+(?:out\s+)?to\s+$)");
        if (Has(Before(s.text, static_cast<size_t>(it->position()), 20), kWidenedTo)) {
          const size_t at = static_cast<size_t>(it->position());
          const int owner = owner_at(s, at);
          roads.erase(std::remove_if(roads.begin(), roads.end(),
                                     [&](const RoadStatement& o) {
                                       return o.sentence == i && o.pos < at && o.owner == owner && o.total &&
                                              !o.per_direction && !o.directional;
                                     }),
                      roads.end());
        }
        add(*it, static_cast<size_t>(it->position()), n, 0, 0);
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
    // V1's road: stated in V1's own segment, else the road on V1's axis, else
    // the first road not tied to another vehicle (the crash road is
    // described first).
    // The road V1 turns onto ("waiting to turn left onto the collector
    // road") is not the one it was on: a count of that road comes last.
    string v1_onto;
    for (const Segment& seg : segments) {
      static const regex kOnto(R"(\bonto\s+(?:the|a|an)\s+(?:[\w/-]+\s+){0,3}?)" + RoadNoun() + R"(\b)");
      smatch om;
      if (v1_before_impact(seg) && std::regex_search(seg.text, om, kOnto)) {
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
    int v1_way = 0;  // +1 one-way, -1 two-way, 0 not said
    for (const Segment& seg : segments) {
      if (seg.perceived || sentences[seg.sentence].kind == Kind::kCoding) continue;
      // The road it turned onto is not the one it was on ("turned left to
      // travel west on the one-way street").
      const string travelled = BeforeTheTurn(seg.text);
      if (seg.vehicle == 1 && Has(travelled, kOnOneWay)) v1_way = 1;
      else if (seg.vehicle == 1 && Has(travelled, kOnTwoWay) && v1_way == 0) v1_way = -1;
    }
    static const regex kTwoWay(R"(\b2[- ]way\b)");
    if (v1_way == 0 && Has(scene, kTwoWay)) {
      for (const Segment& seg : segments) {
        if (seg.vehicle > 1 && !seg.perceived && Has(seg.text, kOnOneWay)) v1_way = -1;
      }
    }
    // V1 on a ramp the report counts the lanes of ("entering the freeway
    // from the ramp").
    static const regex kOnRamp(R"(\b(?:on|from|along|down|up|entering|exiting|via)\s+(?:the|a|an)\s+(?:[\w-]+\s+){0,2}?ramp\b)");
    bool v1_on_ramp = false;
    for (const Segment& seg : segments) {
      if (seg.vehicle == 1 && !seg.perceived && sentences[seg.sentence].kind != Kind::kCoding && Has(seg.text, kOnRamp)) {
        v1_on_ramp = true;
      }
    }
    const RoadStatement* best = nullptr;
    if (v1_on_ramp) best = pick([](const RoadStatement& rs) { return rs.ramp && rs.owner <= 1; });
    if (!best && v1_way != 0) best = pick([&](const RoadStatement& rs) { return rs.owner <= 1 && rs.one_way == (v1_way > 0); });
    if (!best && v1_way > 0) {
      // On a one-way road whose lanes the report does not count: one lane.
      r.road.one_way.Set(true, Provenance::kStated);
      r.road.lanes_total.Set(1, Provenance::kInferred);
      r.road.lanes_per_direction.Set(1, Provenance::kInferred);
    }
    if (!best && v1_way <= 0) best = pick([](const RoadStatement& rs) { return rs.owner == 1; });
    if (!best && v1_way <= 0 && !v1_named_road.empty()) {
      best = pick([&](const RoadStatement& rs) { return rs.owner <= 1 && rs.name == v1_named_road; });
    }
    if (!best && v1_way <= 0 && distinctive) {
      best = pick([&](const RoadStatement& rs) { return rs.owner <= 1 && rs.road == v1_road; });
    }
    // "... between a four-lane divided highway and a two lane county road.
    // v1 was westbound on the county road": the count its own noun phrase
    // names.
    if (!best && v1_way <= 0 && distinctive) {
      best = pick([&](const RoadStatement& rs) { return rs.owner <= 1 && rs.road.empty() && rs.counted == v1_road; });
    }
    if (!best && v1_way <= 0 && v1_axis >= 0) {
      best = pick([&](const RoadStatement& rs) { return rs.owner <= 1 && rs.axis && *rs.axis == v1_axis; });
    }
    if (!best && v1_way <= 0) best = pick([](const RoadStatement& rs) { return rs.owner <= 1; });
    if (!best && v1_way <= 0 && !roads.empty()) best = &roads.front();
    // V1 travelling across the axis of the road described as the through
    // road came from the cross street, when the report describes one.
    if (best && !best->cross && v1_axis >= 0) {
      const RoadStatement* through = pick([](const RoadStatement& rs) { return !rs.cross && rs.axis.has_value(); });
      const RoadStatement* cross = pick([&](const RoadStatement& rs) {
        return rs.cross && rs.owner <= 1 && (!rs.axis || *rs.axis == v1_axis);
      });
      if (through && cross && *through->axis != v1_axis && (!best->axis || *best->axis != v1_axis)) best = cross;
    }
    // At a junction, V1 travelling across every road the report counts
    // lanes of was on one it does not describe: an ordinary two-lane,
    // two-way road.
    const bool junction = r.road.kind.value == RoadKind::kIntersection || r.road.kind.value == RoadKind::kTJunction;
    if (best && junction && v1_axis >= 0 && best->owner != 1 &&
        std::all_of(roads.begin(), roads.end(), [&](const RoadStatement& rs) {
          return rs.axis && *rs.axis != v1_axis && !rs.cross && rs.owner != 1;
        })) {
      r.road.lanes_total.Set(2, Provenance::kInferred);
      r.road.lanes_per_direction.Set(1, Provenance::kInferred);
      best = nullptr;
    }
    // ACCSIM_DEBUG_ROADS=1 lists every lane statement on stderr and marks
    // the one taken for V1's road.
    if (std::getenv("ACCSIM_DEBUG_ROADS")) {
      for (const auto& rs : roads) std::fprintf(stderr, "[road s%zu owner%d axis%d total%d per%d dir%d ow%d cross%d ramp%d road '%s' counted '%s']%s\n", rs.sentence, rs.owner, rs.axis ? *rs.axis : -1, rs.total, rs.per_direction, rs.directional, rs.one_way, rs.cross, rs.ramp, rs.road.c_str(), rs.counted.c_str(), &rs == best ? " <- best" : "");
      std::fprintf(stderr, "[v1 turns onto: %s]\n", v1_onto.c_str());
    }
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
        if (&rs == best || rs.owner > 1 || rs.one_way != best->one_way || rs.ramp != best->ramp ||
            (rs.axis && best->axis && rs.axis != best->axis)) {
          continue;
        }
        // (A count of V1's own direction may come two sentences on: "a
        // 4-lane divided highway. the highway was divided by a median ... .
        // the northbound side had 3 northbound lanes".)
        const size_t reach = of_v1s_direction(rs) && rs.directional ? 2 : 1;
        if (rs.sentence > best->sentence + reach || rs.sentence + 1 < best->sentence) continue;
        if (!best->axis && rs.axis && v1_axis >= 0 && *rs.axis != v1_axis) continue;  // a road across V1's course
        if (!rs.road.empty() && !best->road.empty() && rs.road != best->road) continue;
        if (OfAnotherRoad(rs, *best)) continue;
        // ... or one whose own noun names another road than best's clause
        // ("the boulevard had 2 lanes each way. ... a 2-lane residential
        // street", best the boulevard's).
        if (rs.road.empty() && OtherKindsOfRoad(rs.counted, best->road)) continue;
        if (!total && rs.total) total = rs.total;
        if (!per && rs.per_direction) {
          per = rs.per_direction;
          per_told = &rs;
        }
        // A road that widens at the junction is coded by its lanes there:
        // "each side widened to include a left-turn lane, for a total of 3
        // lanes in each direction at the intersection".
        static const regex kWidened(R"(\b(?:widen\w*|flare\w*|for a total of)\b)");
        const string& widened_text = sentences[rs.sentence].text;
        if (rs.per_direction > per && rs.sentence != best->sentence &&
            Has(widened_text.substr(0, std::min(widened_text.size(), rs.pos + 40)), kWidened)) {
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
        if (Has(t, kOneWaySentence) && !Has(t, kOtherRoadPhrase) && !Has(scene, kTwoWay)) one_way = true;
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
          per += 1;
          total = 2 * per;
        }
        r.road.lanes_per_direction.Set(v1s_direction ? directional : per, Provenance::kStated);
        if (v1s_direction && total < directional + per) {
          r.road.lanes_total.Set(directional + per, Provenance::kInferred);  // V1's side wider than the other's
        } else {
          r.road.lanes_total.Set(total ? total : 2 * per + centre, total ? Provenance::kStated : Provenance::kInferred);
        }
      } else if (total == 1 && Has(sentences[best->sentence].text, kTwoWay)) {
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
    if (!best && Has(scene, kOneWayHere) && !Has(scene, kTwoWay)) {
      r.road.one_way.Set(true, Provenance::kStated);
    }
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
      if (distinctive && Has(v1_road, kQualifiedRoad)) {
        static const regex kNounAfter(R"(^\s*(?:[\w-]+\s+){0,2}?)" + RoadNoun() + R"(\b)");
        // (The word may hold its noun: "of a 6-lane, divided, limited access
        // interstate".)
        smatch nm;
        const string said = dm.str();
        const string after = cleaned.substr(at + static_cast<size_t>(dm.length()));
        if ((std::regex_search(said, nm, RoadWord()) || std::regex_search(after, nm, kNounAfter)) &&
            v1_road.find(nm[1].str()) == string::npos) {
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
      if (!v1_named_road.empty()) {
        const size_t name_at = cleaned.find(v1_named_road);
        if (name_at != string::npos && Has(phrase, RoadWord())) {
          const size_t name_end = name_at + v1_named_road.size();
          const bool in_phrase = name_at >= from && name_at < from + phrase.size();
          static const regex kApposition(R"(^\s*,\s*$)");
          const bool appositive = name_end <= from && Has(cleaned.substr(name_end, from - name_end), kApposition);
          if (!in_phrase && !appositive) return false;
        }
      }
      // "a four-lane divided boulevard and a two-lane undivided city
      // street", V1 on the boulevard: the word is the other road's.
      if (distinctive && phrase.find(v1_road) == string::npos) {
        const size_t v1_at = cleaned.find(v1_road);
        const bool before_and = v1_at != string::npos && v1_at < from && cleaned.compare(from, 4, "and ") == 0;
        const bool after_and = v1_at != string::npos && v1_at >= from + phrase.size() && next != string::npos;
        if ((before_and || after_and) && Has(phrase, RoadWord())) return false;
      }
      std::optional<int> axis = AxisIn(phrase);
      if (!axis) axis = AxisIn(s.text);
      return !(junction && v1_axis >= 0 && axis && *axis != v1_axis);
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

    // V1 leaving a driveway or parking lot was on it: NMVCCS counts its
    // lanes, a two-way drive of one lane each way unless the report counts
    // them.
    static const regex kMiddleLane(R"(\bmiddle (?:travel |through )?lane\b)");
    bool v1_from_driveway = false, v1_middle_lane = false;
    for (const Segment& seg : segments) {
      if (!v1_before_impact(seg)) continue;
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
          R"(\b(?:oneway|1-lane|(?:exit|entrance)[- ]only)\b[^.;]{0,30}?\b(?:driveway|drive|alley)\b|\b(?:driveway|alley)\b[^.;]{0,20}?\b(?:is|was) (?:a )?(?:oneway|1-lane)\b)");
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
      r.road.lanes_per_direction.Set(lanes_needed, Provenance::kInferred);
      r.road.lanes_total.Set(r.road.lanes_total.value + (r.road.one_way.value ? extra : 2 * extra), Provenance::kInferred);
    }
  }
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

  // Speed limit: the posted limit of V1's road.
  {
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
    static const regex kBare(R"(\b(?:speed limit|limit|posted)\b[^.]{0,30}?\b(\d{2})\b(?!\s*(?:kmh|mph|%|m\b|meters|feet)))");
    static const regex kAdvisory(R"((?:advisory|suggested|recommended|warning|curve)[^.]{0,25}$)");
    // A telegraphic list goes on after a semicolon without the limit word
    // ("highway posted 72 kmh (45 mph); side road 40 kmh (25 mph)").
    static const regex kListedRoadLimit(R"(^\s*(?:(?:the|a|an)\s+)?(?:[\w/-]+\s+){0,2}?)" + RoadNoun() +
                                        R"(\s*(?:,|:|-|is|was)?\s*(\d{2,3})\s*(kmh|mph)\b)");
    size_t order = 0;
    size_t last_with_limit = sentences.size();
    for (const Sentence& s : sentences) {
      if (s.kind == Kind::kCoding || s.kind == Kind::kPeople) continue;
      const size_t index = static_cast<size_t>(&s - sentences.data());
      if (s.text.find("limit") == string::npos && s.text.find("posted") == string::npos &&
          s.text.find(" zone") == string::npos) {
        smatch m;
        if (last_with_limit + 1 == index && std::regex_search(s.text, m, kListedRoadLimit)) {
          const bool kmh = m[3].str() == "kmh";
          const double value = std::stod(m[2].str());
          const size_t at = static_cast<size_t>(m.position(2));
          if (value >= 5 && value <= 180) {
            limits.push_back({value * (kmh ? kKmhToMps : kMphToMps), kmh ? "km/h" : "mph", owner_at(s, at),
                              inherited_axis(index, AxisIn(s.text.substr(0, at))), order++, m[1].str(),
                              named_at(index, at)});
            last_with_limit = index;
          }
        }
        continue;
      }
      bool found = false;
      size_t skip_until = 0;
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
        // A limit word after the value qualifies it close by ("45 mph (72
        // kmh) posted speed limit"), not one a clause later ("her speed at
        // 72-80 kmh and said she thought the limit was 55 mph").
        const string near_tail = tail.substr(0, 30);
        if (before.find("limit") == string::npos && before.find("posted") == string::npos &&
            before.find("speed zone") == string::npos && near_tail.find("limit") == string::npos &&
            near_tail.find("posted") == string::npos && tail.rfind(" zone", 0) != 0 &&
            tail.rfind(" speed zone", 0) != 0) {  // "a 45 mph zone", "a 25 mph speed zone"
          continue;
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
        int owner = owner_at(s, pos);
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
        static const regex kOnRoadNounBefore(R"(\b(?:on|for|along|and)\s+(?:the|a|an)\s+(?:[\w/-]+\s+){0,2}?)" +
                                             RoadNoun() + R"(\s*(?:,\s*|\s+at\s+)?$)");
        // ... or posted itself: "meets a 4-lane undivided arterial posted at 64 kmh".
        static const regex kRoadPostedAt(R"(\b)" + RoadNoun() +
                                         R"(\s+(?:that was |which was |was |is )?(?:posted|signed|zoned)\s+(?:at|for)\s+$)");
        smatch rn;
        const string just_before = Before(s.text, pos, 40);
        const string road = std::regex_search(tail, rn, kOnRoadNounAfter)          ? rn[1].str()
                            : std::regex_search(just_before, rn, kOnRoadNounBefore) ? rn[1].str()
                            : std::regex_search(just_before, rn, kRoadPostedAt) && !GenericRoad(rn[1].str()) ? rn[1].str()
                                                                                    : ClauseRoad(s.text, pos);
        const string on_named = road_names.OnAfter(tail);
        limits.push_back({value * (kmh ? kKmhToMps : kMphToMps), kmh ? "km/h" : "mph", owner,
                          inherited_axis(index, axis), order++, road,
                          on_named.empty() ? named_at(index, pos) : on_named});
        found = true;
        last_with_limit = index;
      }
      smatch m;
      // ... a bare number only when it could be a limit in mph ("limit: 00" is none).
      if (!found && std::regex_search(s.text, m, kBare) && std::stoi(m[1].str()) >= 5) {
        const size_t at = static_cast<size_t>(m.position());
        limits.push_back({std::stoi(m[1].str()) * kMphToMps, "mph", owner_at(s, at),
                          inherited_axis(index, AxisIn(s.text.substr(0, at))),
                          order++, ClauseRoad(s.text, at), named_at(index, at)});
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
      static const regex kTravelWord(
          R"(\b(?:travel\w*|going|driving|doing|moving|speed|estimated|approximately|about|around|between|at)\s+(?:\w+\s+){0,2}$)");
      for (const Sentence& s : sentences) {
        if (s.kind == Kind::kCoding || s.kind == Kind::kPeople) continue;
        smatch m;
        const bool subject = std::regex_search(s.text, m, kRoadSubject) && s.refs.empty();
        if (!subject && !std::regex_search(s.text, m, kRoadValue)) continue;
        const size_t pos = static_cast<size_t>(m.position(1));
        if (Has(Before(s.text, pos, 30), kTravelWord)) continue;
        const double value = std::stod(m[1].str());
        const bool kmh = m[2].str() == "kmh";
        if (value < 5 || value > 180) continue;
        limits.push_back({value * (kmh ? kKmhToMps : kMphToMps), kmh ? "km/h" : "mph", owner_at(s, pos),
                          AxisIn(s.text.substr(0, pos)), order++, ClauseRoad(s.text, pos),
                          road_names.Subject(s.text, pos)});
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
    if (std::getenv("ACCSIM_DEBUG_ROADS")) {
      std::fprintf(stderr, "[v1 named road: %s] [v1 road: %s]\n", v1_named_road.c_str(), v1_road.c_str());
      for (const auto& l : limits) {
        std::fprintf(stderr, "[limit %.1f kmh owner%d axis%d road '%s' name '%s']\n", l.mps * 3.6, l.owner,
                     l.axis ? *l.axis : -1, l.road.c_str(), l.name.c_str());
      }
    }
    const Limit* pick = first_limit([](const Limit& l) { return l.owner == 1; });
    if (!pick && !v1_named_road.empty()) {
      pick = first_limit([&](const Limit& l) { return l.owner <= 1 && l.name == v1_named_road; });
    }
    if (!pick && distinctive) pick = first_limit([&](const Limit& l) { return l.owner <= 1 && l.road == v1_road; });
    if (!pick && v1_axis >= 0) {
      pick = first_limit([&](const Limit& l) { return l.owner <= 1 && l.axis && *l.axis == v1_axis; });
    }
    // A limit said of a road across V1's course is the other road's.
    if (!pick && v1_axis >= 0) pick = first_limit([](const Limit& l) { return l.owner <= 1 && !l.axis; });
    if (!pick) pick = first_limit([](const Limit& l) { return l.owner <= 1; });
    if (!pick && !limits.empty()) pick = &limits.front();
    if (pick) {
      r.road.speed_limit_mps.Set(pick->mps, Provenance::kStated);
      r.road.speed_limit_unit.Set(pick->unit, Provenance::kStated);
    }
  }
  if (!r.road.speed_limit_mps.known()) {
    // The typical limit of V1's road as its own text describes it ("a
    // 4-lane, 2-way urban road"), else as the scene does (which may describe
    // only the other road: "a residential street that meets ...").
    string v1_text;
    for (const Segment& seg : segments) {
      if (v1_before_impact(seg)) {
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

  // ---- Striker, struck and damage areas.
  std::map<int, AreaWords> area_words;
  int striker = 0, struck = 0;
  bool struck_object = false;
  if (impact < sentences.size()) {
    const string& s = sentences[impact].text;
    smatch vm;
    std::regex_search(s, vm, kContact);
    const size_t verb_pos = vm.empty() ? s.size() : static_cast<size_t>(vm.position());
    static const regex kPassive(
        R"(\b(?:was|were|is|been|being|got|get|gets)\s+(?:\w+\s+)?(?:contacted|struck|impacted|hit|rear[- ]ended|sideswiped|t-?boned|broadsided)\b)");
    const bool passive = Has(s.substr(0, std::min(s.size(), verb_pos + 20)), kPassive);
    const std::vector<Ref>& refs = sentences[impact].refs;
    int object = 0, subject = 0;
    // "struck a pole with the front of v1": the instrument is the striker's own.
    static const regex kInstrument(R"(\b(?:with|using)\s+(?:the|its)\s+[a-z -]{2,30}?\s+of\s+(?:the\s+)?$)");
    for (const Ref& ref : refs) {
      if (ref.pos > verb_pos && !Has(s.substr(verb_pos, ref.pos - verb_pos), kInstrument)) {
        object = ref.vehicle;
        break;
      }
    }
    for (const Ref& ref : refs) {
      if (ref.pos < verb_pos && ref.vehicle != object) subject = ref.vehicle;
    }
    if (!subject && object) {
      for (const Ref& ref : refs) {
        if (ref.vehicle != object) {
          subject = ref.vehicle;
          break;
        }
      }
    }
    if (!subject && !object && !refs.empty()) subject = refs.front().vehicle;
    // "v1 and v2 collided": no object after the verb; the first named is
    // taken as the striker, the other as struck.
    // "v1 had slowed when v2 struck it": a pronoun object is the other
    // vehicle named before the verb.
    static const regex kPronounObject(R"(^\s*(?:\w+\s+)?(?:it|him|her|them)\b)");
    const bool pronoun_object = vm.empty() ? false : Has(vm.suffix().str(), kPronounObject);
    if (!object && subject && pronoun_object) {
      for (const Ref& ref : refs) {
        if (ref.pos < verb_pos && ref.vehicle != subject) object = ref.vehicle;
      }
    }
    if (!object && subject) {
      std::vector<int> before;
      for (const Ref& ref : refs) {
        if (ref.pos < verb_pos && std::find(before.begin(), before.end(), ref.vehicle) == before.end()) {
          before.push_back(ref.vehicle);
        }
      }
      if (before.size() >= 2) {
        subject = before[0];
        object = before[1];
      }
    }
    if (passive && object && s.find(" by ", verb_pos) != string::npos) {
      striker = object;
      struck = subject;
    } else if (passive) {
      striker = object;
      struck = subject;
    } else {
      striker = subject;
      struck = object;
    }
    if (!striker && subject) striker = subject;
    if (striker == struck) struck = 0;
    if (striker && !struck && r.vehicles.size() >= 2) {
      const string after = s.substr(verb_pos, 80);
      if (unnumbered_other || (r.vehicles.size() == 2 && !Has(after, kObjectNoun))) {
        struck = striker == 1 ? 2 : 1;
      } else {
        struck_object = true;
      }
    } else if (striker && !struck) {
      struck_object = true;
    }
    // Areas named with a vehicle: "the left rear of v2", "v2's right front",
    // "v1 on the right side", "with its front" (the striker's), "was struck
    // in the left side" (the struck vehicle's).
    // "driver"/"passenger" name a side only with a part after them ("the
    // driver's door"): "the driver of v1" is a person.
    static const string kArea =
        R"(((?:(?:left|right|front|rear|back)(?:[- ]|\s)*(?:hand\s+)?){1,3}(?:side|end|corner|quarter(?:\s+panel)?|bumper|door|fender|plane|panel|area|portion|wheel|tire|half)?s?|(?:driver|passenger)'?s?[- ]?(?:side|door|front|rear)(?:[- ]|\s)*(?:side|door|fender|corner|quarter(?:\s+panel)?)?s?))";
    static const regex kOfV(kArea + R"(\s+(?:side\s+)?of\s+(?:the\s+)?v([1-9])\b)");
    static const regex kVs(R"(\bv([1-9])'?s\s+)" + kArea);
    static const regex kVOn(R"(\bv([1-9])\s+(?:(?!v[1-9]\b)\w+\s+){0,2}?(?:on|in|at)\s+(?:the|its|it's|his|her)\s+)" + kArea);
    // "with its front" is the striker's; "with the rear of v2" names v2's.
    static const regex kWithIts(R"(\b(?:with|using)\s+(?:its|it's|the|his|her|their)\s+)" + kArea +
                                R"(\b(?!\s*(?:side\s+)?of\b))");
    static const regex kStruckIn(
        R"(\b(?:contacted|struck|impacted|hit|stuck)\s+(?:\w+\s+){0,3}?(?:on|in|at)\s+(?:the|its|it's|his|her)\s+)" + kArea);
    static const regex kItsArea(R"(\b(?:its|it's)\s+)" + kArea +
                                R"(\s+(?:was|were|struck|impacted|contacted|hit|sideswiped|collided|scraped))");
    auto note = [&](int v, const string& words) {
      const AreaWords a = ParseArea(words);
      if (v > 0 && a.any() && !area_words.count(v)) area_words[v] = a;
    };
    // The clause of the contact first: "the rear of v1 slid out and it
    // rotated into the eastbound lane, where the front of v2 struck the right
    // side of v1" names v1's struck side after "where".
    // So does "..., and the front of v2 struck the right side of v1".
    static const regex kClauseStart(R"(\b(?:where|whereupon)\b|;|,\s*and\b)");
    size_t clause = 0;
    {
      const string upto = s.substr(0, std::min(verb_pos, s.size()));
      for (auto it = std::sregex_iterator(upto.begin(), upto.end(), kClauseStart); it != std::sregex_iterator(); ++it) {
        clause = static_cast<size_t>(it->position());
      }
    }
    for (const string& part : {s.substr(clause), s}) {
      for (auto it = std::sregex_iterator(part.begin(), part.end(), kOfV); it != std::sregex_iterator(); ++it) {
        note(std::stoi((*it)[2].str()), (*it)[1].str());
      }
      for (auto it = std::sregex_iterator(part.begin(), part.end(), kVs); it != std::sregex_iterator(); ++it) {
        note(std::stoi((*it)[1].str()), (*it)[2].str());
      }
      for (auto it = std::sregex_iterator(part.begin(), part.end(), kVOn); it != std::sregex_iterator(); ++it) {
        note(std::stoi((*it)[1].str()), (*it)[2].str());
      }
    }
    smatch am;
    if (std::regex_search(s, am, kWithIts)) note(striker, am[1].str());
    if (std::regex_search(s, am, kStruckIn)) note(struck, am[1].str());
    if (std::regex_search(s, am, kItsArea)) note(passive ? struck : striker, am[1].str());
    static const regex kFrontToFront(R"(\bfront[- ]to[- ]front\b)");
    static const regex kFrontToRear(R"(\bfront[- ]to[- ](?:rear|back)\b)");
    if (Has(s, kHeadOnPhrase) || Has(s, kFrontToFront)) {
      // "collided front to front, offset toward the driver's side": the
      // fronts, whatever corner is named too.
      for (const int v : {striker, struck}) {
        if (v > 0) area_words[v].front = true;
      }
    }
    if (Has(s, kFrontToRear)) {
      note(striker, "front");
      note(struck, "rear");
    }
    static const regex kFromBehind(R"(\b(?:from behind|from the rear|in the rear)\b)");
    if (Has(s, kRearEndPhrase) || Has(s, kFromBehind)) {
      note(striker, "front");
      note(struck, "rear");
    }
    // The next sentence often names the struck area ("... hit him in the door").
    if (!area_words.count(struck) && struck > 0) {
      for (size_t k = impact + 1; k < std::min(sentences.size(), impact + 3); ++k) {
        const string& t = sentences[k].text;
        if (!Has(t, kContact)) continue;
        smatch tm;
        static const regex kHitIn(R"(\b(?:hit|struck|impacted|contacted)\s+(?:him|her|them|it|v[1-9])\s+(?:in|on)\s+the\s+)" + kArea);
        if (std::regex_search(t, tm, kHitIn)) note(struck, tm[1].str());
        static const regex kInTheDoor(R"(\bin the door\b)");
        if (std::regex_search(t, tm, kInTheDoor)) note(struck, "left");
      }
    }
  } else if (r.participant_count.known()) {
    r.warnings.push_back("crash: no sentence describes a contact (struck, contacted, collided, ...)");
  }
  const bool parked_struck =
      struck > 0 && struck <= static_cast<int>(r.vehicles.size()) && r.vehicles[static_cast<size_t>(struck - 1)].parked.value;

  // A vehicle that strikes with its front was moving: a stop read only from
  // driver statements or the other vehicle's coding (paragraphs that switch
  // drivers without naming them) does not stand against that.
  if (striker > 0 && striker <= static_cast<int>(r.vehicles.size())) {
    VehicleRecord& sv = r.vehicles[static_cast<size_t>(striker - 1)];
    const AreaWords w = area_words.count(striker) ? area_words[striker] : AreaWords{};
    if (sv.movement.value == Movement::kStopped && !narrative[static_cast<size_t>(striker)].stopped &&
        !sv.parked.value && (w.front || !w.any())) {
      const MovementEvidence& e = narrative[static_cast<size_t>(striker)];
      const Movement moving = e.turn_left || e.coded_turn_left    ? Movement::kTurnLeft
                              : e.turn_right || e.coded_turn_right ? Movement::kTurnRight
                                                                   : Movement::kStraight;
      sv.movement.Set(moving, Provenance::kInferred);
      sv.pre_event.Set(moving, Provenance::kInferred);
    }
  }

  // A vehicle leaving a driveway or lot before the impact ("pulled out of a
  // private driveway"): its access is the crash location, and its path
  // crosses the road's.
  const bool from_driveway = std::any_of(segments.begin(), segments.end(), [&](const Segment& seg) {
    return !seg.perceived && seg.sentence <= impact && sentences[seg.sentence].kind == Kind::kNarrative &&
           LeavesDriveway(seg.text);
  });

  // ---- Crash type: coded critical-event wording, then geometry and movements.
  // The coded events of the first harmful event's pair: in a chain of
  // crashes another vehicle's ("other vehicle stopped" for the third car)
  // is a later event's. A coded sentence naming no vehicle ("her critical
  // precrash event was ...") is about the vehicle the text is on.
  string coded;
  {
    static const regex kSubjectFirst(R"(^(?:the\s+(?:driver|operator|rider)\s+of\s+)?v([1-9])\b)");
    int on = 0;
    for (const Sentence& s : sentences) {
      smatch m;
      if (std::regex_search(s.text, m, kSubjectFirst)) on = std::stoi(m[1].str());
      else if (s.kind == Kind::kCoding && !s.refs.empty()) on = s.refs.front().vehicle;
      const bool pair = r.vehicles.size() <= 2 || on == 0 || on == striker || on == struck || striker == 0;
      if (s.kind == Kind::kCoding && pair) coded += s.text;
    }
  }
  const VehicleRecord* a = striker > 0 && striker <= static_cast<int>(r.vehicles.size()) ? &r.vehicles[static_cast<size_t>(striker - 1)] : nullptr;
  const VehicleRecord* b = struck > 0 && struck <= static_cast<int>(r.vehicles.size()) ? &r.vehicles[static_cast<size_t>(struck - 1)] : nullptr;
  if (!a && r.vehicles.size() >= 2) {
    a = &r.vehicles[0];
    b = &r.vehicles[1];
  }
  const AreaWords sa = striker && area_words.count(striker) ? area_words[striker] : AreaWords{};
  const AreaWords sb = struck && area_words.count(struck) ? area_words[struck] : AreaWords{};
  CrashType type = CrashType::kUnknown;
  Provenance type_src = Provenance::kInferred;
  const string impact_text = impact < sentences.size() ? sentences[impact].text : "";
  if (r.participant_count.value <= 1 || !b || struck_object || parked_struck) {
    type = CrashType::kSingleVehicle;
  } else {
    const bool dirs = a->travel.known() && b->travel.known() && a->travel.value && b->travel.value;
    const Compass da = dirs ? *a->travel.value : Compass::kNorth, db = dirs ? *b->travel.value : Compass::kNorth;
    const bool same = dirs && da == db, opposite = dirs && Opposite(da, db), perpendicular = dirs && Perpendicular(da, db);
    const bool a_turn = Turning(a->movement.value), b_turn = Turning(b->movement.value);
    const VehicleRecord* turner = a_turn ? a : (b_turn ? b : nullptr);
    static const regex kLaneChangeNow(R"(\bchang\w*\s+lanes?\b|\blane change|\bmerg(?:e|ed|es|ing)\b)");
    const bool lane_change_at_impact = Has(impact_text, kLaneChangeNow) ||
                                       a->movement.value == Movement::kChangingLanes ||
                                       b->movement.value == Movement::kChangingLanes ||
                                       a->movement.value == Movement::kMerging || b->movement.value == Movement::kMerging;
    const bool struck_plain_rear = sb.rear && !sb.left && !sb.right;
    // A turner from a side road, driveway or parking lot enters the other's
    // path (turn into path); one turning off the road crosses it (turn across path).
    static const regex kFromSide(
        R"(\b(?:from|out of|exiting|leaving|pulling out|pulled out|entered the (?:road|roadway|street|highway) from)\b[^.]{0,40}?\b(?:side (?:road|street)|driveway|parking|lot|private|alley|station|stop sign|minor road|intersecting))");
    // "turned left onto oak ave" enters a road; when the other vehicle came
    // the opposite way on the road the turner left, the turn crosses its path.
    static const regex kOnto(R"(\bonto\b)");
    static const regex kOncoming(
        R"(\b(?:the other way|the opposite way|oncoming|(?:from|in) the opposite direction|opposing (?:traffic|direction))\b)");
    bool turner_from_side = false;
    if (turner) {
      const VehicleRecord* other = turner == a ? b : a;
      // A turner whose only direction is the road it turns onto ("pulled out
      // to turn left onto eastbound route 30") did not come the opposite way.
      static const regex kOntoBound(R"(\bonto\s+(?:the\s+)?(north|south|east|west)bound\b)");
      bool destination_only = false;
      for (const Segment& seg : segments) {
        smatch om;
        if (seg.vehicle == std::stoi(turner->id.substr(1)) && std::regex_search(seg.text, om, kOntoBound) &&
            turner->travel.value && CompassWord(om[1].str()) == *turner->travel.value) {
          destination_only = true;
        }
      }
      bool other_oncoming = opposite && !destination_only;
      for (const Segment& seg : segments) {
        if (seg.vehicle == std::stoi(other->id.substr(1)) && seg.sentence <= impact && Has(seg.text, kOncoming)) {
          other_oncoming = true;
        }
      }
      const size_t ti = static_cast<size_t>(turner->id[1] - '0');
      for (const Segment& seg : segments) {
        if (seg.vehicle == static_cast<int>(ti) && seg.sentence <= impact && sentences[seg.sentence].kind != Kind::kCoding &&
            (Has(seg.text, kFromSide) || (!other_oncoming && !same && Has(seg.text, kOnto)))) {
          turner_from_side = true;
        }
      }
    }
    auto pulls_out_of_parking = [&](const VehicleRecord* v) {
      const size_t k = static_cast<size_t>(std::stoi(v->id.substr(1)));
      // Also when it meant to turn around ("pulled out of the parking space
      // and attempted to make a U-turn"): NASS 72/73 still.
      return k < narrative.size() && (narrative[k].leaving_parking || LeftParking(narrative[k])) &&
             (!Turning(v->movement.value) || narrative[k].u_turn);
    };
    static const regex kBroadside(R"(\bt-?bon(?:ed|ing|e)\b|\bbroadsid(?:ed|ing|e)\b)");
    // Front corners count as fronts here: investigators code "the front left
    // of v2 with its front left" as a head-on.
    const bool front_to_front = sa.front && (sb.front || !sb.any());
    // Paths that cross: a junction, a vehicle running a sign or light, or one
    // pulling out of a drive.
    const bool crossing_paths = r.road.kind.value == RoadKind::kIntersection ||
                                r.road.kind.value == RoadKind::kTJunction || RanTrafficControl(scene) || from_driveway;
    if (const auto from_coding =
            CrashTypeFromCoding(coded, turner != nullptr, turner && turner->movement.value == Movement::kTurnRight,
                                Has(impact_text, kLaneChangeNow), front_to_front)) {
      type = *from_coding;
      type_src = Provenance::kStated;
    } else if (Has(impact_text, kRearEndPhrase)) {
      type = CrashType::kRearEnd;
    } else if (Has(impact_text, kHeadOnPhrase)) {
      type = CrashType::kHeadOn;
    } else if (struck_plain_rear && sa.front && turner == b && turner_from_side) {
      // Struck in the back just after turning onto the striker's road from
      // a side road or drive: NASS codes the turn into its path (78/79).
      type = CrashType::kTurnIntoPath;
    } else if (struck_plain_rear && sa.front && !opposite && !lane_change_at_impact) {
      type = CrashType::kRearEnd;
    } else if ((pulls_out_of_parking(a) || pulls_out_of_parking(b)) && !opposite) {
      type = CrashType::kTurnAcrossPath;  // NASS: leaving a parking position across a lane, initially the same way
    } else if (lane_change_at_impact && !opposite && !turner_from_side) {
      type = CrashType::kSideswipeSame;
    } else if (turner) {
      if (turner_from_side) type = CrashType::kTurnIntoPath;
      else if (perpendicular) type = CrashType::kTurnIntoPath;
      else type = CrashType::kTurnAcrossPath;
    } else if (Has(impact_text, kBroadside) && !(opposite && !crossing_paths)) {
      // (Not between vehicles meeting on one road: one that spun across the
      // centerline and was broadsided is coded in the opposite-direction
      // group.)
      type = CrashType::kAngle;  // "t-boned", "broadsided": a front into a side, paths crossing
    } else if (opposite) {
      const bool fronts = sa.front && (sb.front || !sb.any());
      type = fronts && !(sb.left || sb.right) ? CrashType::kHeadOn : CrashType::kSideswipeOpposite;
      if (sb.front) type = CrashType::kHeadOn;
    } else if (perpendicular) {
      type = CrashType::kAngle;
    } else if (same) {
      // A front into the back corner of a vehicle stopped in the lane is a
      // rear-end ("struck the left rear of v2", stalled ahead).
      const bool into_stopped_corner = sb.rear && sa.front && !sa.left && !sa.right &&
                                       b->movement.value == Movement::kStopped;
      type = (sb.left || sb.right || sa.left || sa.right) && !into_stopped_corner ? CrashType::kSideswipeSame
                                                                                   : CrashType::kRearEnd;
    } else if (b->movement.value == Movement::kStopped || b->movement.value == Movement::kSlowing || sb.rear) {
      type = CrashType::kRearEnd;
    } else if (sa.front && sb.front) {
      type = CrashType::kHeadOn;
    } else if (sb.left || sb.right) {
      type = crossing_paths ? CrashType::kAngle : CrashType::kSideswipeSame;
    } else if (crossing_paths && (sa.front || !sa.any())) {
      type = CrashType::kAngle;  // "struck by a pickup that ran the red light"
    } else {
      type_src = Provenance::kDefaulted;
    }
  }
  // A merge from an entrance ramp into the through lanes: NMVCCS codes it
  // as a turn into the other's path ("turn into path: specifics other", the
  // development set's straight/1); CIREN case summaries as a sideswipe
  // ("merging to left").
  static const regex kEntranceRamp(R"(\b(?:entrance|on-?)\s*ramp\b|\bacceleration lane\b|\bramp\b[^.]{0,60}?\b(?:merg|join))");
  const bool merger = a && b && (a->movement.value == Movement::kMerging || b->movement.value == Movement::kMerging);
  if (type == CrashType::kSideswipeSame && !case_summary && merger && Has(scene, kEntranceRamp)) {
    type = CrashType::kTurnIntoPath;
  }
  r.crash.type.Set(type, type == CrashType::kUnknown ? Provenance::kDefaulted : type_src);
  if (a && b) {
    ReconcileDirections(r, static_cast<size_t>(a - r.vehicles.data()), static_cast<size_t>(b - r.vehicles.data()));
  }
  // A vehicle struck from behind while slowing in its lane is coded by the
  // way it was going: the slowing is the striker's critical event ("other
  // vehicle in lane, traveling in same direction while decelerating"), the
  // development set's crossing/23 and straight/17. One slowing for its own
  // turn is decelerating.
  if (type == CrashType::kRearEnd && b && b->pre_event.value == Movement::kSlowing && !Turning(b->movement.value)) {
    const size_t bi = static_cast<size_t>(b - r.vehicles.data());
    if (!narrative[bi + 1].intent_left && !narrative[bi + 1].intent_right && !narrative[bi + 1].turn_meant) {
      r.vehicles[bi].pre_event.Set(Movement::kStraight, Provenance::kInferred);
    }
  }
  // A vehicle about to turn that another, going its way, passes or
  // encroaches on from the next lane is coded going straight, whatever it did
  // before its turn (straight/0: "she had stopped prior to turning";
  // crossing/21): the other vehicle's move is the critical event.
  for (size_t i = 0; i < r.vehicles.size(); ++i) {
    VehicleRecord& v = r.vehicles[i];
    const MovementEvidence& told = narrative[i + 1];
    const bool about_to_turn = Turning(v.movement.value) || told.intent_left || told.intent_right || told.turn_meant;
    if (!about_to_turn || told.coded_turn_left || told.coded_turn_right || told.coded_straight) continue;
    bool passed = told.coded_adjacent;
    for (size_t j = 0; j < r.vehicles.size(); ++j) {
      const VehicleRecord& o = r.vehicles[j];
      if (j != i && narrative[j + 1].pass && o.travel.value && o.travel.value == v.travel.value) passed = true;
    }
    if (passed) v.pre_event.Set(Movement::kStraight, Provenance::kInferred);
  }
  // A turn with nothing told before it (no stop, no slowing) is its own
  // pre-event movement (t/8, straight/12), except where NASS codes what the
  // road made the vehicle do first: a turn off a curve ("a 5% downhill grade
  // and a curve-left", t/7: negotiating the curve), and a turn across a lane
  // of its own direction, from the wrong lane (crossing/17, 19, 21: going
  // straight).
  {
    static const regex kRoadCurves(R"(\bcurv(?:e|es|ed|ing)\b)");
    bool road_curves = false;
    for (const Sentence& s : sentences) {
      if (s.kind == Kind::kNarrative && s.refs.empty() && Has(s.text, kRoadCurves)) road_curves = true;
    }
    for (size_t i = 0; i < r.vehicles.size(); ++i) {
      VehicleRecord& v = r.vehicles[i];
      const MovementEvidence& told = narrative[i + 1];
      if (!Turning(v.pre_event.value) || v.pre_event.value != v.movement.value ||
          !(told.coded_turn_left || told.coded_turn_right)) {
        continue;
      }
      const bool wrong_lane = std::any_of(r.vehicles.begin(), r.vehicles.end(), [&](const VehicleRecord& o) {
        return &o != &v && o.travel.value && o.travel.value == v.travel.value && !o.parked.value;
      });
      if (road_curves || wrong_lane) v.pre_event.Set(Movement::kStraight, Provenance::kInferred);
    }
  }

  // ---- Damaged planes, now that the configuration is known.
  auto plane = [&](const AreaWords& w, bool is_striker) -> DamageArea {
    if (w.front && (w.left || w.right)) {
      // A front corner is the front plane for the striker and in frontal
      // configurations; a struck vehicle's front corner hit from the side is
      // its side (how investigators code it).
      if (is_striker || type == CrashType::kHeadOn || type == CrashType::kTurnAcrossPath ||
          type == CrashType::kRearEnd) {
        return DamageArea::kFront;
      }
      return w.left ? DamageArea::kLeft : DamageArea::kRight;
    }
    if (w.rear && (w.left || w.right)) {
      if (type == CrashType::kRearEnd || (type == CrashType::kSingleVehicle && !is_striker)) return DamageArea::kRear;
      return w.left ? DamageArea::kLeft : DamageArea::kRight;
    }
    if (w.front) return DamageArea::kFront;
    if (w.rear) return DamageArea::kRear;
    if (w.left) return DamageArea::kLeft;
    if (w.right) return DamageArea::kRight;
    return DamageArea::kUnknown;
  };
  if (striker) {
    r.crash.striking.Set("V" + std::to_string(striker), Provenance::kStated);
    if (area_words.count(striker)) {
      r.crash.striking_area.Set(plane(area_words[striker], true), Provenance::kStated);
      r.crash.striking_detail.Set(Detail(area_words[striker]), Provenance::kStated);
    } else {
      r.crash.striking_area.Set(DamageArea::kFront, Provenance::kInferred);
    }
  }
  if (struck) {
    r.crash.struck.Set("V" + std::to_string(struck), Provenance::kStated);
    if (area_words.count(struck)) {
      r.crash.struck_area.Set(plane(area_words[struck], false), Provenance::kStated);
      r.crash.struck_detail.Set(Detail(area_words[struck]), Provenance::kStated);
    }
  } else if (struck_object) {
    r.crash.struck.Set("object", Provenance::kInferred);
  }
  if (!r.crash.struck_area.known() && struck) {
    const VehicleRecord* sv = &r.vehicles[static_cast<size_t>(struck - 1)];
    const VehicleRecord* kv = striker ? &r.vehicles[static_cast<size_t>(striker - 1)] : nullptr;
    if (type == CrashType::kHeadOn) r.crash.struck_area.Set(DamageArea::kFront, Provenance::kInferred);
    else if (type == CrashType::kRearEnd) r.crash.struck_area.Set(DamageArea::kRear, Provenance::kInferred);
    else if (kv && kv->travel.known() && sv->travel.known() && kv->travel.value && sv->travel.value &&
             Perpendicular(*kv->travel.value, *sv->travel.value)) {
      // The striker comes from the side it is heading away from: heading
      // west it arrives from the east, which is the right of a northbound car.
      const int from = (static_cast<int>(*kv->travel.value) + 2) % 4;
      const int heading = static_cast<int>(*sv->travel.value);
      r.crash.struck_area.Set((from - heading + 4) % 4 == 1 ? DamageArea::kLeft : DamageArea::kRight,
                              Provenance::kInferred);
    }
  }

  // ---- Location relative to a junction.
  {
    // Narrative up to and including the impact, and what a later sentence
    // tells in the past perfect ("v2 had been stopped, intending to turn into
    // the parking lot").
    static const regex kHadBefore(R"(\bhad\s+(?:\w+\s+)?(?:been|stopped|slowed|begun|started|pulled|entered)\b)");
    string pre;
    for (size_t i = 0; i < sentences.size(); ++i) {
      const bool before = i <= impact || impact == sentences.size() || Has(sentences[i].text, kHadBefore);
      if (sentences[i].kind == Kind::kNarrative && before) pre += sentences[i].text;
    }
    pre = WithoutDistantJunctions(pre);
    // Where the ramp it was on ends is not where it crashed: "a 1-lane exit
    // ramp that loops to the right ... and ends at a signalized intersection".
    static const regex kRampEndsAt(
        R"(\bramp\b[^.;]{0,80}?\b(?:ends|ended|terminates|terminated)\s+at\s+(?:a|an|the)\s+(?:[\w-]+\s+){0,3}?(?:intersection|junction)\b)");
    pre = std::regex_replace(pre, kRampEndsAt, " ramp ");
    // Where a road meets or crosses another is a weaker sign than "in the
    // intersection": a ramp "that meets a surface street at a signal" still
    // holds a crash in its queue.
    // (A median crossover is coded as an intersection.)
    static const regex kAtIntersectionStrong(
        R"(\b(?:in|at|within|into|entered|entering|through|crossing|crossed|approaching|near|toward)\s+(?:the|an|a)\s+(?:\w+[- ]?){0,4}?(?:intersection|junction|crossover)\b|\bintersection of\b)");
    static const regex kAtIntersection(
        R"(\b(?:in|at|within|into|entered|entering|through|crossing|crossed|approaching|near|toward)\s+(?:the|an|a)\s+(?:\w+[- ]?){0,4}?(?:intersection|junction)\b|\bside (?:road|street)|\bcross street|\bintersection of\b|)" + WhereRoadsMeet());
    // A vehicle leaving a driveway or lot puts the crash at its access, even
    // where the drive forms a leg of an intersection (NASS "driveway, alley
    // access").
    static const regex kIntersectionWord(R"(\bintersection\b)");
    // (A named drive beside a midblock crash places it; "missed the entrance
    // to a restaurant" does not.)
    static const regex kDrivewayWord(R"(\bdriveway\b|\balley\b|\bparking lot\b)");
    // Nor does a drive some other vehicle was turning into ("a vehicle
    // ahead of v1 had stopped to turn left into an alley").
    static const regex kOthersDrive(
        R"(\b(?:a|an|another)\s+(?:[\w-]+\s+){0,2}?(?:vehicle|car|truck|van|pickup|suv)\b[^.;]{0,80}?\b(?:into|out of|from)\s+(?:a|an|the)\s+(?:[\w-]+\s+){0,2}?(?:driveway|alley|parking lot)\b)");
    // A crash on a ramp leading to an intersection is on the ramp.
    static const regex kOnTheRamp(R"(\b(?:on|onto|along|of|in)\s+(?:the|a|an)\s+(?:[\w-]+\s+){0,2}?ramp\b)");
    // Nor a drive people got off at: "a school bus stopped to let two
    // children off at their driveway".
    static const regex kPeoplesDrive(
        R"(\b(?:children|kids|students|pupils|passengers?|child|riders?)\s+(?:\w+\s+){0,3}?(?:at|to|near)\s+(?:their|his|her|a|the)\s+(?:\w+\s+)?driveways?\b|)"
        // Nor one it drove past: "had passed the entrance to a shopping plaza".
        R"(\b(?:passed|missed|past|overshot)\s+(?:the|a|an)\s+(?:entrance|driveway|drive)\b[^.;,]{0,40})");
    static const regex kMidblock(
        R"(\bmid-?block\b|\bnon-?junction\b|\bnot (?:at|in|near) (?:an|the) (?:intersection|junction)\b|)"
        // "at a location with no median opening or intersection".
        R"(\blocation with no\s+(?:(?!at\b|in\b|near\b)[\w-]+\s+){0,3}?(?:or\s+)?(?:intersection|junction)\b)");
    if (from_driveway) {
      r.crash.location.Set(CrashLocation::kDriveway, Provenance::kInferred);
    } else if (Has(pre, kMidblock) && !Has(std::regex_replace(pre, kOthersDrive, " "), kDrivewayWord)) {
      r.crash.location.Set(CrashLocation::kSegment, Provenance::kStated);
    } else if (Has(WithoutDistantJunctions(impact_text), kIntersectionWord) || Has(pre, kAtIntersectionStrong) ||
               RanTrafficControl(pre) || (Has(pre, kAtIntersection) && !Has(pre, kOnTheRamp))) {
      r.crash.location.Set(CrashLocation::kJunction, Provenance::kInferred);
    } else if (Has(std::regex_replace(pre, kPeoplesDrive, " "), kDriveway)) {
      r.crash.location.Set(CrashLocation::kDriveway, Provenance::kInferred);
    } else if (Has(pre, kOnTheRamp)) {
      r.crash.location.Set(CrashLocation::kRamp, Provenance::kInferred);
    } else if (r.road.kind.value == RoadKind::kIntersection || r.road.kind.value == RoadKind::kTJunction) {
      r.crash.location.Set(CrashLocation::kJunction, Provenance::kInferred);
    } else if (Has(pre, kRamp)) {
      r.crash.location.Set(CrashLocation::kRamp, Provenance::kInferred);
    } else if (impact < sentences.size()) {
      r.crash.location.Set(CrashLocation::kSegment, Provenance::kInferred);
    }
    if (r.crash.location.value == CrashLocation::kDriveway && r.road.kind.value == RoadKind::kStraight) {
      r.road.kind.Set(RoadKind::kDriveway, Provenance::kInferred);
    }
  }

  // ---- Camera hint: only when the text asks for a viewpoint.
  {
    static const regex kAsks(R"(\b(?:view|views|viewed|viewpoint|camera|perspective|angle|shot|render|show|video|seen|watch)\b)");
    if (Has(norm, kAsks)) {
      static const regex kOverheadView(R"(\bbird'?s[- ]eye|\boverhead\b|\btop[- ]down\b|\baerial\b|\bfrom above\b)");
      static const regex kBehindView(R"(\b(?:from\s+)?behind\s+v([1-9])\b|\bfollowing\s+v([1-9])\b|\bchase\b)");
      static const regex kDriverView(R"(\b(?:driver'?s?|dash ?cam|first[- ]person|inside|cockpit)\b[^.]{0,30}?(?:v([1-9]))?)");
      static const regex kSideView(R"(\bfrom the side\b|\bside view\b|\bbroadside view\b)");
      smatch m;
      if (Has(norm, kOverheadView)) {
        r.camera_hint.Set("overhead", Provenance::kStated);
      } else if (std::regex_search(norm, m, kBehindView)) {
        r.camera_hint.Set("behind V" + (m[1].matched ? m[1].str() : m[2].matched ? m[2].str() : string("1")),
                          Provenance::kStated);
      } else if (std::regex_search(norm, m, kDriverView)) {
        r.camera_hint.Set("driver V" + (m[1].matched ? m[1].str() : string("1")), Provenance::kStated);
      } else if (Has(norm, kSideView)) {
        r.camera_hint.Set("side", Provenance::kStated);
      }
    }
  }
  if (!r.participant_count.known() && impact == sentences.size()) {
    r.warnings.push_back("text: no crash description recognised (is it an English crash narrative?)");
  }
  return r;
}

}  // namespace accsim
