#include "accsim/scenarios/narrative_extractor.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "narrative_reading.h"
#include "regex_text.h"

namespace accsim {
namespace narrative {

using std::regex;
using std::smatch;
using std::string;

using regex_text::Has;
using regex_text::ReplaceWith;

Reading::Reading(std::string_view given) : text(given) {
  if (text.size() > NarrativeExtractor::kMaxBytes) {
    r.warnings.push_back("text: longer than " + std::to_string(NarrativeExtractor::kMaxBytes) +
                         " bytes; only the start was read");
    text = text.substr(0, NarrativeExtractor::kMaxBytes);
  }
  const string normalised = Normalise(text, &numbered_by_report);
  Numbered numbered = NameUnnumberedVehicles(normalised, numbered_by_report);
  norm = std::move(numbered.text);
  descriptions = std::move(numbered.descriptions);
  // ACCSIM_DEBUG_TEXT=1 prints the text the rules read: normalised, each
  // vehicle named vN.
  if (std::getenv("ACCSIM_DEBUG_TEXT")) std::fprintf(stderr, "%s\n", norm.c_str());
  for (string& t : SplitSentences(norm)) sentences.push_back({std::move(t), Kind::kNarrative, {}, 0});
  impact = sentences.size();
}

bool Reading::V1BeforeImpact(const Segment& seg) const {
  return seg.vehicle == 1 && !seg.perceived && seg.sentence <= impact && sentences[seg.sentence].kind == Kind::kNarrative;
}

void ReadDescriptions(Reading& rd) {
  std::vector<Sentence>& sentences = rd.sentences;
  std::map<int, string>& descriptions = rd.descriptions;
  std::map<int, string>& bodies = rd.bodies;
  static const regex kDesc(
      R"(^v([1-9])\s*(?:,\s*|\s+-{1,2}\s+|\s+(?:was|is)\s+|\s+\(\s*)(?:(?:was|is)\s+)?(?:an?\s+|the\s+(?=(?:19|20)\d\d\s)|(?=(?:19|20)\d\d\s))((?:(?:19|20)\d\d\s+)?[a-z][^,;()]{1,60}?)(?=\s*[,;()]|\s+(?:was|were|is|that|which|who|driven|operated|travel\w*|going|heading|headed|approach\w*|and|with|in|on|at|stopped|making|attempting|pulling|towing|hauling|carrying|operating|serving|used|loaded|laden|returning|owned|registered|belonging|exiting|leaving|entering|negotiating|proceeding|driving|designated|behind|ahead|parked)\b|\s*$))");
  static const regex kBody(R"(^\s*,\s*([a-z0-9][a-z0-9 -]{1,40}?)\s+(?:was|that|which|were)\b)");
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
    std::set<int> pickups;
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
        // Every word after the make: "the sonoma" for "a gmc sonoma pickup",
        // and every run of them: "the crown victoria" for "a ford crown
        // victoria police interceptor".
        for (size_t k = 1; k < words.size(); ++k) {
          string run;
          for (size_t e = k; e < words.size(); ++e) {
            run += (run.empty() ? "" : " ") + words[e];
            owners[run].insert(v);
          }
        }
      }
      static const std::array<const char*, 7> kClassWord = {"car", "suv", "pickup", "van", "truck", "bus", "motorcycle"};
      const size_t cls = static_cast<size_t>(ClassOf(d + " " + (bodies.count(v) ? bodies[v] : "")));
      owners[kClassWord[cls]].insert(v);
      if (string(kClassWord[cls]) == "pickup") pickups.insert(v);
    }
    // A pickup is "the truck" in its other driver's words ("the truck just
    // turned right in front of me"), unless a truck took part.
    if (!owners.count("truck")) owners["truck"] = pickups;
    // "v2, a 2001 international 9200 tractor pulling a loaded van
    // semitrailer": "the semitrailer", "the trailer" are v2's.
    static const regex kTowedLoad(
        R"(\bv([1-9]),\s+an?\s+[^,;]{0,60}?\b(?:pulling|towing|hauling)\s+(?:an?\s+)?((?:[\w-]+\s+){0,3}?)(semi-?trailer|trailer|camper|boat|wagon|cart|implement)\b)");
    for (const Sentence& s : sentences) {
      for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kTowedLoad); it != std::sregex_iterator(); ++it) {
        const int v = std::stoi((*it)[1].str());
        const string load = (*it)[3].str();
        owners[load].insert(v);
        if (load != "trailer") owners["trailer"].insert(v);
        // ... and by the words before it: "the horse trailer" for "a loaded
        // gooseneck horse trailer".
        for (string modifiers = (*it)[2].str(); !modifiers.empty();) {
          owners[modifiers + load].insert(v);
          const size_t sp = modifiers.find(' ');
          modifiers = sp == string::npos ? string() : modifiers.substr(sp + 1);
        }
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
          // (And the driver's age: "the 23-year-old mazda driver said".)
          R"(\bthe\s+(?:\d{2}[- ]year[- ]old\s+)?(?:(?:19|20)\d\d\s+)?(?:(?:stopped|parked|other|struck|striking|turning|oncoming|lead|leading|following|slower|slow-moving|slowing|disabled|stalled|first|second)\s+)?()" +
          // (Not a place named after one: "the car wash", "the truck stop"; "the
          // van driver" is its driver.)
          // (Nor one parked by the road: "beside the car parked ahead of an
          // open space".)
          alt + R"()\b(?!\s+(?:wash|dealership|dealer|lot|park|port|stop|yard|rental|shop|show|terminal|scale|scales)\b)(?!\s+parked\s+(?:at|along|on|in|beside|behind|ahead|near|next|in front)\b))");
      std::map<string, int> lookup(aliases.begin(), aliases.end());
      for (Sentence& s : sentences) {
        s.text = ReplaceWith(s.text, alias_re, [&](const smatch& m) { return "v" + std::to_string(lookup[m[1].str()]); });
      }
    }
  }
}

void ClassifySentences(Reading& rd) {
  std::vector<Sentence>& sentences = rd.sentences;
  int& max_v = rd.max_v;
  for (Sentence& s : sentences) {
    s.kind = KindOf(s.text);
    s.refs = RefsIn(s.text);
    for (const Ref& ref : s.refs) max_v = std::max(max_v, ref.vehicle);
  }
  // Of two vehicles, "the two collided front to front", "both vehicles then
  // collided", "the cars came together": the pair, named in order.
  if (max_v == 2) {
    static const regex kThePair(
        R"(\b(?:the\s+(?:two|2)(?:\s+(?:vehicles|cars|trucks))?|both\s+(?:vehicles|cars)|the\s+(?:vehicles|cars))\s+(?=(?:then\s+|subsequently\s+|eventually\s+|ultimately\s+)?(?:collided|impacted each other|struck each other|made contact|came together)\b))");
    for (Sentence& s : sentences) {
      if (s.kind == Kind::kCoding || !Has(s.text, kThePair)) continue;
      s.text = std::regex_replace(s.text, kThePair, "v1 and v2 ");
      s.refs = RefsIn(s.text);
    }
  }
  rd.quotes_coding =
      std::any_of(sentences.begin(), sentences.end(), [](const Sentence& s) { return s.kind == Kind::kCoding; });
}

void FindImpact(Reading& rd) {
  const std::vector<Sentence>& sentences = rd.sentences;
  const int max_v = rd.max_v;
  size_t& impact = rd.impact;
  impact = sentences.size();
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
      // Nor is a role's name ("v2, the striking vehicle") a contact.
      static const regex kRoleName(R"(\b(?:striking|struck)\s+(?:vehicle|car|unit|driver)s?\b)");
      if (!Has(std::regex_replace(WithoutAvoidedContacts(s.text), kRoleName, " "), ContactVerb())) continue;
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
        if (s.kind == Kind::kNarrative && Has(s.text, ContactVerb()) && DistinctVehicles(s.refs) >= 2) {
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
    if (std::regex_search(s.text, vm, ContactVerb())) {
      const size_t verb_end = static_cast<size_t>(vm.position() + vm.length());
      const bool object_named = std::any_of(s.refs.begin(), s.refs.end(), [&](const Ref& ref) { return ref.pos > verb_end; });
      // (Or later, when the report opens with the collision and then tells
      // the approach: "the striking vehicle ... and the turning vehicle ...
      // collided at the intersection of ... . v1 was westbound ...".)
      // (When the pair is named, "the fronts of v1 and v2 collided", only a
      // retelling of that pair: "v2 rotated and struck v3" is a later
      // contact.)
      static const regex kPairBefore(R"(\bv([1-9])\s+and\s+(?:the\s+)?v([1-9])\s+(?:\w+\s+)?$)");
      smatch pm;
      const string before_verb = s.text.substr(0, static_cast<size_t>(vm.position(1)));
      const bool pair_named = std::regex_search(before_verb, pm, kPairBefore);
      auto retells_pair = [&](const Sentence& next) {
        if (!pair_named) return true;
        auto has = [&](const string& n) {
          return std::any_of(next.refs.begin(), next.refs.end(), [&](const Ref& ref) { return ref.vehicle == std::stoi(n); });
        };
        return has(pm[1].str()) && has(pm[2].str());
      };
      for (size_t k = impact + 1; !object_named && k < sentences.size() && k <= impact + 12; ++k) {
        const Sentence& next = sentences[k];
        if (next.kind == Kind::kCoding) break;
        if (next.kind == Kind::kNarrative && DistinctVehicles(next.refs) >= 2 && Has(next.text, ContactVerb()) &&
            retells_pair(next)) {
          impact = k;
          break;
        }
      }
    }
  }

  // A struck vehicle that is never numbered ("struck a parked van").
  bool& unnumbered_other = rd.unnumbered_other;
  bool& unnumbered_parked = rd.unnumbered_parked;
  if (impact < sentences.size()) {
    // ("... crossed the highway without striking any vehicle, and its front
    // struck the embankment": the contact is the one that happened.)
    const string s = WithoutAvoidedContacts(sentences[impact].text);
    smatch vm;
    if (std::regex_search(s, vm, ContactVerb())) {
      // What it struck, up to the next clause ("..., then the vehicle rolled").
      static const regex kNextClause(R"(,\s*(?:then|and then|and|before|after|which|where)\b|;)");
      string after = vm.suffix().str().substr(0, 80);
      if (smatch cm; std::regex_search(after, cm, kNextClause)) after = after.substr(0, static_cast<size_t>(cm.position()));
      static const regex kVehicleLike(R"(\bparked\b|\bunoccupied\b|\b(?:19|20)\d\d\s+[a-z])");
      if (DistinctVehicles(sentences[impact].refs) == 1 && (Has(after, VehicleNoun()) || Has(after, kVehicleLike)) &&
          !Has(after.substr(0, 30), ObjectNoun()) &&
          max_v <= 1) {
        unnumbered_other = true;
        static const regex kParkedWord(R"(\bparked\b|\bunoccupied\b)");
        unnumbered_parked = Has(after, kParkedWord);
      }
    }
  }
}

void CountParticipants(Reading& rd) {
  AccidentRecord& r = rd.r;
  const string& norm = rd.norm;
  std::map<int, string>& descriptions = rd.descriptions;
  std::map<int, string>& bodies = rd.bodies;
  const int max_v = rd.max_v;
  const bool unnumbered_other = rd.unnumbered_other;
  const bool unnumbered_parked = rd.unnumbered_parked;
  // A numbered vehicle that only comes by after the crash took no part in
  // it ("a third vehicle, a snowplow traveling east about 400 meters behind
  // v2, stopped and the operator radioed for assistance"): the last numbers,
  // when the narrative names them only after the impact and never in a
  // contact, a push, a coded event, damage, a tow or an injury. A vehicle
  // the report does not number ("a car that had been following her stopped
  // and called 911") may be the second; one that "was not struck" took no
  // part in that sentence.
  int counted = max_v;
  {
    const std::vector<Sentence>& sentences = rd.sentences;
    static const regex kTookPart(
        R"(\b(?:push\w*|propell\w*|forced|shoved|knocked|redirect\w*|deflect\w*|into\s+(?:the\s+)?v[1-9]|damage\w*|towed|injur\w*|transported|hospital\w*|airbags?|driver|occupants?|belted|rest)\b)");
    static const regex kNoPart(R"(^(?:\s+[\w'()-]+){0,6}?\s+(?:was|were)\s+not\s+(?:struck|hit|involved|damaged|contacted)\b)");
    const int fewest = rd.numbered_by_report ? 3 : 2;
    // A crash no numbered vehicle's contact tells ("the left side of the
    // vehicle struck a ... utility pole") happened at its first contact.
    size_t impact = rd.impact;
    for (size_t i = 0; i < sentences.size() && impact == sentences.size(); ++i) {
      if (sentences[i].kind == Kind::kNarrative && Has(WithoutAvoidedContacts(sentences[i].text), ContactVerb())) impact = i;
    }
    // "No other vehicles were involved, and a car that had been following
    // stopped": from there on, a vehicle the report did not number is a
    // bystander.
    size_t no_others = sentences.size();
    static const regex kNoOthers(R"(\bno other (?:vehicles? (?:was |were )?involved|vehicles? (?:was|were) involved)\b)");
    for (size_t i = 0; i < sentences.size() && !rd.numbered_by_report; ++i) {
      if (Has(sentences[i].text, kNoOthers)) {
        no_others = i;
        break;
      }
    }
    while (counted >= fewest && impact < sentences.size()) {
      // A vehicle the report calls noncontact ("no critical reason was coded
      // to v1, since the noncontact pickup's entry was the cause") is not
      // one of the crash's, where the report numbered none.
      if (!rd.numbered_by_report && Has(norm, regex(R"(\bnoncontact\s+v)" + std::to_string(counted) + R"(\b)"))) {
        --counted;
        continue;
      }
      bool took_part = false;
      for (size_t i = 0; i < std::min(no_others, sentences.size()) && !took_part; ++i) {
        const Sentence& s = sentences[i];
        // Where the report gave no numbers, only the vehicle's own stretch
        // (from the vehicle named before it to the one named after) tells
        // what it did: "v2's driver ... could not steer clear because of v3
        // beside him" is v2's driver's, not v3's.
        string told;
        for (size_t k = 0; k < s.refs.size(); ++k) {
          const Ref& ref = s.refs[k];
          if (ref.vehicle != counted || Has(s.text.substr(ref.pos + 2), kNoPart)) continue;
          const size_t begin = k > 0 ? s.refs[k - 1].pos : 0;
          const size_t end = k + 1 < s.refs.size() ? s.refs[k + 1].pos : s.text.size();
          told += rd.numbered_by_report ? s.text : s.text.substr(begin, end - begin);
          told += ' ';
        }
        took_part = !told.empty() && (i <= impact || s.kind == Kind::kCoding || Has(told, ContactVerb()) ||
                                      Has(told, kTookPart));
      }
      if (took_part) break;
      --counted;
    }
  }
  if (max_v > 0) {
    r.participant_count.Set(std::max(counted, unnumbered_other ? 2 : 0), Provenance::kStated);
  } else {
    static const regex kCount(R"(\b([1-9])[- ]vehicle\b|\b([1-9]) vehicles\b)");
    smatch m;
    if (std::regex_search(norm, m, kCount)) {
      r.participant_count.Set(std::stoi(m[1].matched ? m[1].str() : m[2].str()), Provenance::kStated);
    } else if (static const regex kSingle(R"(\b(?:single|one|1)[- ]vehicle\b)"); Has(norm, kSingle)) {
      r.participant_count.Set(1, Provenance::kStated);
    } else if (static const regex kAlone(R"(\b(?:rolled|rollover|overturned|flipped|left the road|ran off the road|departed)\b)");
               (Has(norm, ContactVerb()) || Has(norm, kAlone)) && Has(norm, VehicleNoun())) {
      // "the vehicle left the road and struck a tree", "... rolled 2
      // quarter turns": one unnumbered vehicle.
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
}

void SplitSegments(Reading& rd) {
  const std::vector<Sentence>& sentences = rd.sentences;
  const size_t impact = rd.impact;
  // ---- Per-vehicle segments. A segment starts where a vehicle is the
  // subject of a clause ("v1 was traveling", ", and v2 stopped", "the driver
  // of v2 ...") or opens a relative clause ("behind v2, a jetta, which was
  // stopped"), and runs to the next such start of another vehicle or to a
  // mention of an unnumbered vehicle ("a noncontact vehicle slowing to turn"
  // is not this vehicle's movement). Objects ("struck v2", "behind v2") do
  // not start a segment: the clause is still about its subject.
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
      R"(^(?:,?\s*(?:an?\s+)?[^,]{0,50},)?\s*(?:which|that|who)\s+(?:was|were|is|had|has)\b|^,\s*an?\s|)"
      // Police style: "across the path of v2 (1997 jeep cherokee), southbound
      // on route 9", "struck the front of v3 (1995 buick), stopped at the sign".
      R"(^\s*\([^)]{0,60}\)\s*,\s*(?:(?:north|south|east|west)bound|stopped|parked|waiting|stationary|slowing|traveling|travelling|heading|going)\b)");
  // What a driver saw another vehicle do ("she saw v1 waiting to turn") is
  // about that vehicle, but the sentence stays the observer's.
  static const regex kPerceivedBefore(
      R"(\b(?:saw|seen|see|seeing|observed|noticed|notice|watched|realize|realized|recognize|recognized|looked (?:back|up|again|ahead|forward))\s*(?:that\s+)?$)");
  static const regex kPerceivedState(
      R"(^\s+(?:was\s+|had\s+)?(?:stopped|stationary|waiting|sitting|turning|making|pulling|backing|slowing|traveling|travelling|approaching|coming|entering|exiting|changing)\b|^\s+had\s+(?:already\s+|suddenly\s+)?slowed\b)");
  // Other road users end a vehicle's segment, with the state words in front
  // of them ("recognized slowing or stopped traffic ahead").
  static const regex kOtherVehicle(
      R"(\b(?:slowing|slowed|stopped|stationary|waiting|parked)(?:\s+(?:or|and)\s+\w+)?\s+(?:traffic|vehicles|cars)\b|\b(?:noncontact|uninvolved|non-involved|another|other|oncoming|several|opposing|an?)\s+(?:(?![12]\d{3}\b)[\w-]+\s+){0,2}?(?:vehicles?|cars?|trucks?|pickups?|vans?|minivans?|sedans?|coupes?|wagons?|suvs?|buses|bus|motorcycles?|semis?|tractor-trailers?|traffic|emergency vehicle)\b|\b\d+\s+(?:\w+\s+)?(?:vehicles|cars)\b|\b(?:vehicles|cars|trucks)\s+(?:that\s+were\s+|which\s+were\s+)?(?:parked|stopped|queued|waiting|lined)\b|\b(?:vehicles|cars|trucks)\s+(?:were|are)\s+(?:\w+\s+)?(?:parked|lined)\b|\bthe\s+(?:other\s+|stopped\s+|queued\s+)?(?:vehicles|cars)\b|\btraffic\b(?!\s+(?:signals?|lights?|controls?|control devices?|devices?|lanes?))|\bthe\s+(?:non-?contact\s+)?(?:pickup|bus|school bus|city bus|box truck|dump truck|farm tractor|tractor)\b|\b(?:a|an|the)\s+(?:\w+\s+)?(?:witness|pedestrian|bystander|officer|trooper|deputy|flagger|passenger|cyclist|bicyclist|trucker|motorist|passerby)\b|)"
      // (Not its own passengers: "driven by a 38 year-old female with one
      // passenger was traveling southbound".)
      R"(\b(?:two|three|several|\d+)\s+(?:\w+\s+)?(?:witness(?:es)?|pedestrians|bystanders|officers|troopers|deputies|flaggers|cyclists|bicyclists)\b)");
  // Whose driver "she" or "he" is, where the report tells one driver's sex
  // ("v1 ... driven by a 79-year-old female", "the 35-year-old male driver
  // of v2", "v2's driver, a woman"): 'f' or 'm' per vehicle, 0 when told
  // both ways.
  std::map<int, char> sex;
  {
    static const string kSex = R"((?:\d+[- ]year[- ]old\s+)?(male|female|man|woman)\b)";
    static const regex kDrivenBy(R"(\bv([1-9])\b[^.;]{0,80}?\bdriven by (?:a|an)\s+)" + kSex);
    static const regex kDriverOfIs(R"(\b(?:driver|operator) of v([1-9])\s*,\s*(?:a|an)\s+)" + kSex);
    static const regex kVsDriverIs(R"(\bv([1-9])'s\s+(?:driver|operator)\s*,\s*(?:a|an)\s+)" + kSex);
    static const regex kSexDriverOf(R"(\b(?:\d+[- ]year[- ]old\s+)(male|female|man|woman)\s+(?:driver|operator)\s+of\s+v([1-9])\b)");
    auto note = [&](const string& v, const string& word) {
      const char c = word[0] == 'f' || word[0] == 'w' ? 'f' : 'm';
      const int k = std::stoi(v);
      sex[k] = sex.count(k) && sex[k] != c ? 0 : c;
    };
    for (const Sentence& s : sentences) {
      for (const regex* re : {&kDrivenBy, &kDriverOfIs, &kVsDriverIs}) {
        for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), *re); it != std::sregex_iterator(); ++it)
          note((*it)[1].str(), (*it)[2].str());
      }
      for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kSexDriverOf); it != std::sregex_iterator(); ++it)
        note((*it)[2].str(), (*it)[1].str());
    }
  }
  // The one vehicle whose driver a sentence's opening "she"/"he" can be
  // when the running text is about a vehicle whose driver is not of that
  // sex (0: keep the focus).
  auto pronoun_owner = [&](const string& text, int focus_now) {
    static const regex kOpeningPronoun(R"(^\s*(?:then\s+|later\s+)?(she|he)\b)");
    smatch pm;
    if (!std::regex_search(text, pm, kOpeningPronoun)) return 0;
    const char c = pm[1].str() == "she" ? 'f' : 'm';
    if (sex.count(focus_now) && sex[focus_now] == c) return 0;
    int only = 0;
    for (const auto& [v, x] : sex) {
      if (x != c) continue;
      if (only) return 0;
      only = v;
    }
    return only;
  };
  std::vector<Segment>& segments = rd.segments;
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
      // westbound traffic and then pulled out", "was looking over his left
      // shoulder at eastbound traffic ... and was still slowing").
      static const regex kLookedForTraffic(
          R"(\b((?:look|check|watch|glanc)\w*)\s+(?:(?:to|at|over)\s+(?:his|her|the|its|their)\s+(?:left|right)(?:\s+shoulder)?\s+)?(?:for|at)\s+(?:[\w-]+bound\s+|oncoming\s+|approaching\s+|cross\s+|other\s+)?(?:traffic|cars|vehicles)\b(?:\s+(?:on|from|along|in)\s+(?:the\s+)?[\w-]+)?)");
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
        // at the curb blocked her view, and she pulled out past it", "a box
        // truck blocked his view, and that he "inched out"".
        static const regex kDriverResumes(
            R"((?:,\s*(?:and|so|but|then)|\b(?:and|then))\s+(?:that\s+)?(?:then\s+)?"?\s*(?:he|she)\s+"?\s*(?:\w+ly\s+)?(?:was|had|began|started|\w+ed)\b|)"
            // "... had blocked her view, and when the van turned she began her turn".
            R"(,\s*and\s+(?:when|as|after|once)\s+(?:[\w-]+\s+){1,6}?(?:he|she)\s+(?:\w+ly\s+)?(?:was|had|began|started|\w+ed)\b)");
        // So is the next verb of its list after a person it waited for:
        // "stopped at the stop sign, waited for a pedestrian to finish
        // crossing, and then started across".
        // (Read the match before `t` changes: `it` points into it.)
        static const regex kPerson(R"(\b(?:pedestrian|bystander|officer|trooper|deputy|flagger|passenger|cyclist|bicyclist|witness)\b)");
        const bool person = Has(it->str(), kPerson);
        smatch rm;
        const string rest = t.substr(at);
        t = t.substr(0, cut_at);
        static const regex kListResumes(R"(,\s*(?:and\s+)?then\s+\w+|,\s*and\s+(?:then\s+)?(?:\w+ed|began|started)\b)");
        // ... or after a car it waited for or yielded to: "stopped, waited
        // for an eastbound car approaching from his left to pass, looked left
        // again, and pulled out to turn left".
        static const regex kWaitedFor(R"(\b(?:waited|waiting|wait)\s+for\s*$|\b(?:yielded|yielding|yield)\s+to\s*$)");
        const bool waited_for = Has(t, kWaitedFor);
        if (std::regex_search(rest, rm, kDriverResumes)) {
          t += " " + rest.substr(static_cast<size_t>(rm.position()));
        } else if ((person || waited_for) && std::regex_search(rest, rm, kListResumes)) {
          t += " " + rest.substr(static_cast<size_t>(rm.position()));
        }
        break;
      }
      return t;
    };
    if (first > 0) {
      // Coded sentences name their vehicle first ("the critical precrash
      // event for v1 was ... this vehicle ..."); others continue the focus.
      int owner = s.kind == Kind::kCoding && !s.refs.empty() ? s.refs.front().vehicle : focus;
      if (s.kind != Kind::kCoding) {
        if (const int by_sex = pronoun_owner(s.text, focus); by_sex > 0) owner = focus = by_sex;
        // An opening participle is its subject's: "merging onto the freeway
        // from the on-ramp, v1 got squeezed", "while turning left, v2 ...".
        static const regex kOpeningParticiple(
            R"(^\s*(?:(?:while|after|when|upon|before)\s+)?[a-z]+ing\b[^.;:]{0,120},\s*(?:the\s+(?:driver|operator)\s+of\s+)?$)");
        if (!starts.empty() && !starts.front().perceived && Has(s.text.substr(0, first), kOpeningParticiple)) {
          owner = starts.front().vehicle;
        }
      }
      // A sentence about the scene is no vehicle's, whoever was named last
      // ("v2 was a tractor-trailer. location is a divided highway: 2
      // eastbound lanes and 2 westbound lanes").
      static const regex kSceneSubject(
          R"(^\s*(?:(?:the\s+)?(?:crash\s+)?location\b|the\s+(?:posted\s+)?speed limit\b|the\s+(?:\w+\s+){0,2}?(?:road|roadway|highway|street|intersection|trafficway|avenue|boulevard|arterial|freeway|interstate|expressway|parkway)\s+(?:was|is|has|had|runs|ran|curves|curved)\b|(?:the\s+)?(?:weather|sky|pavement|surface|road surface)\s+(?:was|is|were)\b))");
      const bool scene = s.refs.empty() && Has(s.text, kSceneSubject);
      if (owner > 0 && !scene) segments.push_back({owner, i, cut(0, first)});
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
}

void ReadCameraHint(Reading& rd) {
  AccidentRecord& r = rd.r;
  const string& norm = rd.norm;
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
}

}  // namespace narrative

AccidentRecord NarrativeExtractor::Extract(std::string_view text) const {
  narrative::Reading rd(text);
  if (rd.sentences.empty()) {
    rd.r.warnings.push_back("text: no readable sentences; every field is a default");
    return std::move(rd.r);
  }
  narrative::ReadDescriptions(rd);
  narrative::ClassifySentences(rd);
  narrative::FindImpact(rd);
  narrative::CountParticipants(rd);
  narrative::SplitSegments(rd);
  narrative::ReadVehicles(rd);
  narrative::ReadRoad(rd);
  narrative::ReadContact(rd);
  narrative::ClassifyCrash(rd);
  narrative::SetDamagedPlanes(rd);
  narrative::LocateCrash(rd);
  narrative::ReadCameraHint(rd);
  if (!rd.r.participant_count.known() && rd.impact == rd.sentences.size()) {
    rd.r.warnings.push_back("text: no crash description recognised (is it an English crash narrative?)");
  }
  return std::move(rd.r);
}

}  // namespace accsim
