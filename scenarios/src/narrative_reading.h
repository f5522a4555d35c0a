// The narrative extractor's stages and what they share; internal to the
// scenarios library.
//
// NarrativeExtractor::Extract reads a report in stages over one Reading:
//   text      normalise, split into sentences, name the vehicles
//             (narrative_text.cpp, narrative_extractor.cpp);
//   impact    the sentence that tells the contact; the participants;
//   segments  each vehicle's share of every sentence;
//   vehicles  directions, lanes, speeds and movements (narrative_movements.cpp);
//   road      kind, lanes, division, conditions, limit (narrative_roads.cpp);
//   crash     striker and struck, areas, crash type, location (narrative_crash.cpp).
// Each stage reads what the ones before it wrote. docs/extraction.md lists
// the rules.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <regex>
#include <string>
#include <string_view>
#include <vector>

#include "accsim/scenarios/accident_record.h"

namespace accsim::narrative {

using std::string;

inline constexpr double kMphToMps = 0.44704;
inline constexpr double kKmhToMps = 1.0 / 3.6;
inline constexpr int kMaxVehicles = 9;

// ------------------------------------------------------------------- text

// The (at most) n characters of s before position at.
string Before(const string& s, size_t at, size_t n);

// Lower-case ASCII, one space between words, canonical vehicle references
// ("v2") and numbers ("45"). numbered_by_report (when given) says whether the
// report numbers its vehicles itself; "the first car" and "the case vehicle"
// become v1 too, but leave the other vehicles to be named.
string Normalise(std::string_view in, bool* numbered_by_report = nullptr);

// Text whose unnumbered vehicles ("a white sedan ... the sedan") are named
// v1, v2, ... in order of first mention, with their noun phrases. Nothing
// changes in a report that numbers its vehicles.
struct Numbered {
  string text;
  std::map<int, string> descriptions;
};
Numbered NameUnnumberedVehicles(const string& s, bool numbered_by_report);

// What a sentence is: the investigator's account, a driver's statement, the
// quoted NASS coding, or about people (ages, injuries).
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

size_t DistinctVehicles(const std::vector<Ref>& refs);
std::vector<Ref> RefsIn(const string& s);
Kind KindOf(const string& s);
std::vector<string> SplitSentences(const string& s);

VehicleClass ClassOf(const string& description);
// The text without junctions named only as a distance away ("300 ft south
// of the next cross street").
string WithoutDistantJunctions(const string& s);
string EscapeRegex(const string& s);
std::optional<Compass> CompassWord(const string& w);
std::optional<Compass> DirectionIn(const string& s);
// Where the road phrase holding position pos starts.
size_t RoadPhraseStart(const string& s, size_t pos);
bool Opposite(Compass a, Compass b);
bool Perpendicular(Compass a, Compass b);

// Contact verbs ("struck", "collided", "rear-ended", ...).
const std::regex& ContactVerb();
// The text with contacts that did not happen blanked ("could not avoid
// striking", "without hitting any vehicle").
string WithoutAvoidedContacts(const string& text);
// Nouns of an unnumbered vehicle, and of the objects a vehicle strikes.
const std::regex& VehicleNoun();
// How a vehicle stood when it is named for it, one capture group: "the
// (parked) ranger", "the back of the (stalled) v2".
const string& StandingWord();
const std::regex& ObjectNoun();

// Damage-area words of one vehicle ("left rear", "driver's door").
struct AreaWords {
  bool front = false, rear = false, left = false, right = false;
  bool any() const { return front || rear || left || right; }
};
AreaWords ParseArea(const string& w);
string Detail(const AreaWords& a);

// -------------------------------------------------------------- movements

struct MovementEvidence {
  bool stopped = false, stop_cancelled = false, parked = false, leaving_parking = false;
  bool entering_parking = false;  // "began backing in" to a space, "was parallel parking"
  bool turn_left = false, turn_right = false, lane_change = false, merge = false, back = false, pass = false;
  bool slowing = false, straight = false;
  bool coded_turn_left = false, coded_turn_right = false, coded_straight = false, coded_back = false;
  bool coded_lane_change = false, other_says_stopped = false;
  bool other_says_decelerating = false;  // the follower's critical event: this one "traveling ... while decelerating"
  bool coded_adjacent = false;  // its critical event: another vehicle from an adjacent lane, same direction
  bool rolled_stop = false, no_stop = false;
  bool slowed_word = false;   // any slowing told ("slowed", "reduced speed", "rolled")
  bool skipped_stop = false;  // "did not stop at the stop sign / the end of the driveway"
  bool started = false;  // "began moving forward": a stopped vehicle moving off (NASS "starting in traffic lane")
  bool green_start = false;  // "when the signal turned green, v1 started its turn": moving off a red (NASS "starting")
  bool stopped_again = false;  // "moved forward ... then stopped again"
  bool u_turn = false;
  bool in_curve = false;  // "entered the right curve at too great a speed"
  bool drift = false;     // "drifted to the left into the left lane": no lane change meant
  bool intent_left = false, intent_right = false, entered = false;  // "waiting to turn left", then "entered the road"
  bool turn_meant = false;  // a turn meant, its direction untold ("slowing to turn into the driveway")
  // A turn it meant, said by its signal or in words.
  bool meant_turn() const { return intent_left || intent_right || turn_meant; }
  bool any_narrative() const {
    return stopped || stop_cancelled || parked || leaving_parking || entering_parking || turn_left || turn_right || lane_change || merge ||
           back || pass || slowing || straight || in_curve;
  }
};

// A vehicle told parked that then drove off was leaving its parking position.
bool LeftParking(const MovementEvidence& n);
bool Turning(Movement m);

// ------------------------------------------------------------------ roads

// Where roads meet, said without "intersection" ("where the ramp meets").
const string& WhereRoadsMeet();
// "exiting a parking lot driveway", "at the parking lot exit".
bool LeavesDriveway(const string& t);
// Words that name a driveway or lot, and a ramp.
const std::regex& DrivewayWord();
const std::regex& RampWord();

// ------------------------------------------------------------ the reading

// A vehicle's share of a sentence: from where it is the subject of a clause
// to where another vehicle is.
struct Segment {
  int vehicle;
  size_t sentence;
  string text;
  bool perceived = false;  // what another driver saw this vehicle do
};

struct Reading {
  explicit Reading(std::string_view given);

  std::string_view text;  // as given (up to NarrativeExtractor::kMaxBytes)
  AccidentRecord r;       // what the stages fill in
  string norm;            // normalised, vehicles numbered
  bool numbered_by_report = false;  // the report's own numbers, not ones given to "a pickup"
  std::vector<Sentence> sentences;
  std::map<int, string> descriptions, bodies;  // "2000 pontiac montana", "minivan"
  int max_v = 0;                               // the highest vehicle number referenced
  // An NMVCCS-style report quotes the coded critical events (and states
  // every posted limit); a CIREN case summary does neither.
  bool quotes_coding = false;
  bool case_summary = false;  // a CIREN case summary ("the case vehicle")
  size_t impact = 0;          // the sentence that tells the contact (sentences.size(): none)
  bool unnumbered_other = false, unnumbered_parked = false;  // "struck a parked van"
  std::vector<Segment> segments;
  // Per vehicle (index = vehicle number): what the narrative and what the
  // drivers' statements tell of its movement.
  std::vector<MovementEvidence> narrative, statement;
  string scene;  // narrative and statements: coded sentences use fixed NHTSA wording

  // The contact.
  std::map<int, AreaWords> area_words;
  int striker = 0, struck = 0;
  bool struck_object = false, parked_struck = false;
  bool from_driveway = false;  // a vehicle left a driveway or lot before the impact

  // What the narrative itself tells of V1 before the impact (not what
  // another driver saw of it, not a coded or injury sentence).
  bool V1BeforeImpact(const Segment& seg) const;
  string ImpactText() const { return impact < sentences.size() ? sentences[impact].text : string(); }
};

// The stages, in order.
void ReadDescriptions(Reading& rd);   // "v1, a 2000 pontiac montana minivan," and aliases ("the pontiac")
void ClassifySentences(Reading& rd);  // kinds, references
void FindImpact(Reading& rd);
void CountParticipants(Reading& rd);
void SplitSegments(Reading& rd);
void ReadVehicles(Reading& rd);  // directions, lanes, speeds, movements
void ReadRoad(Reading& rd);
void ReadContact(Reading& rd);  // striker, struck, damage areas
void ClassifyCrash(Reading& rd);
void SetDamagedPlanes(Reading& rd);  // now that the configuration is known
void LocateCrash(Reading& rd);
void ReadCameraHint(Reading& rd);

}  // namespace accsim::narrative
