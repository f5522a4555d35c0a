#include "accsim/scenarios/narrative_rewrites.h"

#include <array>
#include <cctype>
#include <initializer_list>
#include <map>
#include <regex>
#include <stdexcept>
#include <utility>

#include "regex_text.h"

namespace accsim {
namespace {

using std::regex;
using std::smatch;
using std::string;

const std::array<const char*, 9> kNumberWords = {"zero", "one", "two", "three", "four", "five", "six", "seven", "eight"};

int NumberOfWord(string w) {
  for (char& c : w) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (size_t i = 0; i < kNumberWords.size(); ++i) {
    if (w == kNumberWords[i]) return static_cast<int>(i);
  }
  return -1;
}

using regex_text::ReplaceWith;

string VehicleWords(const string& s) {
  static const regex kV(R"(\bV([1-8])\b)");
  return ReplaceWith(s, kV, [](const smatch& m) { return string("Vehicle ") + kNumberWords[static_cast<size_t>(m[1].str()[0] - '0')]; });
}

string VehicleNumbers(const string& s) {
  static const regex kNumbered(R"(\b([Vv])ehicle\s*(?:#|No\.\s*|number\s*)?([1-8])\b)");
  static const regex kWorded(R"(\b[Vv]ehicle (one|two|three|four|five|six|seven|eight)\b)", regex::icase);
  const string t = std::regex_replace(s, kNumbered, "V$2");
  return ReplaceWith(t, kWorded, [](const smatch& m) { return "V" + std::to_string(NumberOfWord(m[1].str())); });
}

string MphOnly(const string& s) {
  static const regex kKmhFirst(R"((\d+)\s*(?:km/h|kmph|KMPH|kph|KPH|km/hr|Km/h)\s*\(\s*(\d+)\s*(?:mph|MPH)\s*\))");
  static const regex kMphFirst(R"((\d+)\s*(mph|MPH)\s*\(\s*\d+\s*(?:km/h|kmph|KMPH|kph|KPH|km/hr|Km/h)\s*\))");
  return std::regex_replace(std::regex_replace(s, kKmhFirst, "$2 mph"), kMphFirst, "$1 mph");
}

string KmhOnly(const string& s) {
  // The posted values NASS converts (its km/h codes), so a limit reads as coded.
  static const std::map<int, int> kKmh = {{15, 24}, {20, 32}, {25, 40}, {30, 48}, {35, 56}, {40, 64},
                                          {45, 72}, {50, 80}, {55, 89}, {60, 97}, {65, 105}, {70, 113}};
  static const regex kMph(R"(\b(\d+)\s*(?:mph|MPH)\b)");
  return ReplaceWith(MphOnly(s), kMph, [](const smatch& m) {
    const auto it = kKmh.find(std::stoi(m[1].str()));
    return it == kKmh.end() ? m[0].str() : std::to_string(it->second) + " km/h";
  });
}

string LaneDigits(const string& s) {
  static const regex kWordLanes(R"(\b(one|two|three|four|five|six|seven|eight)([- ])(lanes?)\b)", regex::icase);
  return ReplaceWith(s, kWordLanes, [](const smatch& m) { return std::to_string(NumberOfWord(m[1].str())) + m[2].str() + m[3].str(); });
}

string LaneWords(const string& s) {
  static const regex kDigitLanes(R"(\b([1-8])([- ])(lanes?)\b)");
  return ReplaceWith(s, kDigitLanes, [](const smatch& m) {
    return string(kNumberWords[static_cast<size_t>(m[1].str()[0] - '0')]) + m[2].str() + m[3].str();
  });
}

// Whole words swapped for others in one pass, each also when capitalised
// ("was" -> "is", "Was" -> "Is").
class WordSwap {
 public:
  explicit WordSwap(std::initializer_list<std::pair<string, string>> words) {
    string alt;
    for (const auto& [from, to] : words) {
      for (const bool cap : {false, true}) {
        string f = from, t = to;
        if (cap) {
          f[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(f[0])));
          t[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(t[0])));
        }
        to_[f] = t;
        alt += (alt.empty() ? "" : "|") + f;
      }
    }
    pattern_ = regex(R"(\b()" + alt + R"()\b)");
  }
  string operator()(const string& s) const {
    return ReplaceWith(s, pattern_, [this](const smatch& m) { return to_.at(m[1].str()); });
  }

 private:
  std::map<string, string> to_;
  regex pattern_;
};

string PresentTense(const string& s) {
  static const WordSwap kSwap{{{"was", "is"},
                               {"were", "are"},
                               {"had", "has"},
                               {"struck", "strikes"},
                               {"impacted", "impacts"},
                               {"contacted", "contacts"},
                               {"stated", "states"},
                               {"came", "comes"}}};
  return kSwap(s);
}

string British(const string& s) {
  static const WordSwap kSwap{{{"traveling", "travelling"}, {"traveled", "travelled"}, {"center", "centre"}}};
  return kSwap(s);
}

string Road(const string& s) {
  static const WordSwap kSwap{{{"roadway", "road"}}};
  return kSwap(s);
}

string CompassAbbreviations(const string& s) {
  static const std::array<std::pair<regex, const char*>, 4> kBound = {{
      {regex(R"(\bnorthbound\b)", regex::icase), "NB"},
      {regex(R"(\bsouthbound\b)", regex::icase), "SB"},
      {regex(R"(\beastbound\b)", regex::icase), "EB"},
      {regex(R"(\bwestbound\b)", regex::icase), "WB"},
  }};
  string t = s;
  for (const auto& [re, abbreviation] : kBound) t = std::regex_replace(t, re, abbreviation);
  return t;
}

string Upper(string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// After "V1, a 2000 Ford Taurus", later "V1" becomes "the Ford" (only when
// every introduced vehicle has a make of its own).
string Makes(const string& s) {
  static const regex kIntro(R"(\bV([1-8]),? (?:a|an) (?:\d{4}|\d{2}) ([A-Z][a-z]+))");
  std::map<char, std::pair<size_t, string>> intro;  // vehicle -> (end of its introduction, make)
  std::map<string, int> makes;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), kIntro); it != std::sregex_iterator(); ++it) {
    const char v = (*it)[1].str()[0];
    if (intro.count(v)) continue;
    intro[v] = {static_cast<size_t>(it->position() + it->length()), (*it)[2].str()};
    ++makes[(*it)[2].str()];
  }
  if (intro.empty()) return s;
  for (const auto& [make, n] : makes) {
    if (n > 1) return s;
  }
  static const regex kV(R"(\bV([1-8])\b)");
  string out;
  size_t last = 0;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), kV); it != std::sregex_iterator(); ++it) {
    const auto found = intro.find((*it)[1].str()[0]);
    const size_t at = static_cast<size_t>(it->position());
    if (found == intro.end() || at < found->second.first) continue;
    out += s.substr(last, at - last);
    // A sentence's first word is capitalised.
    size_t k = out.find_last_not_of(' ');
    const bool starts = k == string::npos || out[k] == '.' || out[k] == '!' || out[k] == '?';
    out += (starts ? "The " : "the ") + found->second.second;
    last = at + static_cast<size_t>(it->length());
  }
  return out + s.substr(last);
}

struct Entry {
  NarrativeRewrite about;
  string (*apply)(const string&);
};

const std::vector<Entry>& Entries() {
  static const std::vector<Entry> kEntries = {
      {{"vehicle-words", "V1 -> Vehicle one"}, VehicleWords},
      {{"vehicle-numbers", "Vehicle #1, Vehicle 1, Vehicle one -> V1"}, VehicleNumbers},
      {{"mph-only", "48 km/h (30 mph) -> 30 mph"}, MphOnly},
      {{"kmh-only", "30 mph (48 km/h), 30 mph -> 48 km/h"}, KmhOnly},
      {{"lane-digits", "two-lane, four lanes -> 2-lane, 4 lanes"}, LaneDigits},
      {{"lane-words", "2-lane, 4 lanes -> two-lane, four lanes"}, LaneWords},
      {{"road", "roadway -> road"}, Road},
      {{"present-tense", "was traveling, struck -> is traveling, strikes"}, PresentTense},
      {{"british", "traveling, center -> travelling, centre"}, British},
      {{"compass-abbreviations", "northbound -> NB"}, CompassAbbreviations},
      {{"upper", "ALL CAPITALS, as police narratives are often typed"}, [](const string& s) { return Upper(s); }},
      {{"makes", "a later V1 -> the Ford (its make, when each vehicle's is its own)"}, Makes},
  };
  return kEntries;
}

}  // namespace

const std::vector<NarrativeRewrite>& NarrativeRewrites() {
  static const std::vector<NarrativeRewrite> kAll = [] {
    std::vector<NarrativeRewrite> all;
    for (const Entry& e : Entries()) all.push_back(e.about);
    return all;
  }();
  return kAll;
}

std::string RewriteNarrative(std::string_view text, std::string_view name) {
  string known;
  for (const Entry& e : Entries()) {
    if (e.about.name == name) return e.apply(string(text));
    known += (known.empty() ? "" : ", ") + e.about.name;
  }
  throw std::invalid_argument("rewrite: no rewrite called '" + string(name) + "' (known: " + known + ")");
}

}  // namespace accsim
