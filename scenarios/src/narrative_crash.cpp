#include "narrative_reading.h"

#include <algorithm>
#include <map>
#include <optional>
#include <regex>
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

// A turn coded as a critical event: "this vehicle traveling, turning left at
// intersection", "when he began to turn right".
const regex& CodedTurn() {
  static const regex kTurning(R"(\bturning (?:left|right) at (?:the |an )?intersection|\b(?:began|begin|started) to turn (?:left|right))");
  return kTurning;
}

// crossing street, turning into opposite direction"), name the configuration
// the investigators coded. Pairs of events map to crash-type categories:
// turning into a direction -> turn into path; a turn against traffic from the
// opposite direction or an adjacent lane -> turn across path; other vehicle
// stopped, decelerating or slower -> rear-end; crossing paths -> angle (turn
// into path when one of them turned); an adjacent lane -> sideswipe same
// direction; the opposite direction -> head-on or sideswipe by the damage.
std::optional<CrashType> CrashTypeFromCoding(const string& coded, bool turner, bool right_turner, bool lane_change,
                                             bool front_to_front, bool parallel_turns) {
  static const regex kNotInvolved(R"(\bnot involved (?:in )?(?:the )?1st harmful)");  // "first" is normalised to "1st"
  static const regex kIntoPath(R"(\bturning into (?:the )?(?:same|opposite|oppsite) direction)");
  static const regex kTurningRight(R"(\bturning right at|\bbegan to turn right)");
  static const regex kFromOpposite(R"(\bfrom (?:the )?opposite direction|\b(?:traveling|travelling) in (?:the )?opposite direction)");
  static const regex kAdjacent(
      R"(\bfrom (?:an |the )?adjacent lane|\bsame direction\)? ?-? ?over (?:the )?(?:left|right) lane line)");
  static const regex kRearEnd(
      R"(\bother (?:motor )?vehicle (?:in lane,? )?(?:was )?stopped|\bin lane,? (?:and was |other vehicle )?stopped|\bsame direction,? (?:while decelerating|(?:with |at )?(?:a )?(?:higher|lower|slower)(?: speed)?))");
  static const regex kCrossingPaths(R"(\bcrossing street,? across\b)");
  if (Has(coded, kNotInvolved)) return CrashType::kSingleVehicle;
  if (Has(coded, kIntoPath)) return CrashType::kTurnIntoPath;
  const bool coded_turn = Has(coded, CodedTurn());
  const bool turning = turner || coded_turn;
  // A right turn does not cross the opposite lane: one struck by an
  // oncoming vehicle over its left lane line is no turn across path (every
  // 68/69 of the development set is a left turn).
  const bool across = (turner && !right_turner) || (!turner && coded_turn && !Has(coded, kTurningRight));
  if (Has(coded, kFromOpposite) && across) return CrashType::kTurnAcrossPath;
  // Two vehicles turning the same way side by side (a double turn lane),
  // one drifting over the line between them, sideswipe.
  // (Not a turn coded as the critical event: that one turned across.)
  const bool side_by_side = parallel_turns && !coded_turn;
  if (Has(coded, kAdjacent) && !side_by_side && ((turner && !lane_change) || Has(coded, kTurningRight))) {
    return CrashType::kTurnAcrossPath;
  }
  if (Has(coded, kRearEnd)) return CrashType::kRearEnd;
  if (Has(coded, kCrossingPaths)) return turning ? CrashType::kTurnIntoPath : CrashType::kAngle;
  if (Has(coded, kAdjacent)) return CrashType::kSideswipeSame;
  if (Has(coded, kFromOpposite)) return front_to_front ? CrashType::kHeadOn : CrashType::kSideswipeOpposite;
  return std::nullopt;
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

// Words that name a configuration and its planes at once.
const regex& HeadOnPhrase() {
  static const regex kHeadOnPhrase(R"(\bhead[- ]on\b)");
  return kHeadOnPhrase;
}

const regex& RearEndPhrase() {
  static const regex kRearEndPhrase(R"(\brear[- ]end(?:ed|ing|s)?\b)");
  return kRearEndPhrase;
}


}  // namespace

void ReadContact(Reading& rd) {
  AccidentRecord& r = rd.r;
  const std::vector<Sentence>& sentences = rd.sentences;
  const size_t impact = rd.impact;
  const std::vector<Segment>& segments = rd.segments;
  std::vector<MovementEvidence>& narrative = rd.narrative;
  const bool unnumbered_other = rd.unnumbered_other;
  std::map<int, AreaWords>& area_words = rd.area_words;
  int& striker = rd.striker;
  int& struck = rd.struck;
  bool& struck_object = rd.struck_object;
  if (impact < sentences.size()) {
    const string& s = sentences[impact].text;
    smatch vm;
    std::regex_search(s, vm, ContactVerb());
    const size_t verb_pos = vm.empty() ? s.size() : static_cast<size_t>(vm.position(1));
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
    // "its driver allowed it to drift ..., where it struck v2 head-on": of
    // two vehicles, a pronoun subject is the other one.
    static const regex kPronounSubject(R"(\b(?:it|its|he|his|she|her)\b)");
    if (!subject && object && r.vehicles.size() == 2 && Has(s.substr(0, verb_pos), kPronounSubject)) {
      subject = object == 1 ? 2 : 1;
    }
    // "v1 and v2 collided": no object after the verb; the first named is
    // taken as the striker, the other as struck.
    // "v1 had slowed when v2 struck it": a pronoun object is the other
    // vehicle named before the verb.
    // (Also "..., the front of v2 struck its left side".)
    static const regex kPronounObject(
        R"(^\s*(?:\w+\s+)?(?:it|him|her|them)\b|^\s*(?:its|their)\s+(?:left|right|front|rear|back|side|driver|passenger)\b)");
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
      if (unnumbered_other || (r.vehicles.size() == 2 && !Has(after, ObjectNoun()))) {
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
    // (Also "the back of the parked v2"; the vehicle's number is the last group.)
    static const regex kOfV(kArea + R"(\s+(?:side\s+)?of\s+(?:the\s+(?:(?:legally\s+|illegally\s+)?)" + StandingWord() +
                            R"(\s+)?)?v([1-9])\b)");
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
    const string contact_clause = s.substr(clause);
    // "the fronts of v1 and v2 collided": both vehicles' fronts.
    static const regex kBothOf(
        R"(\b(fronts|front ends|rears|rear ends|left sides|right sides)\s+of\s+(?:the\s+)?v([1-9])\s+and\s+(?:the\s+)?v([1-9])\b)");
    if (smatch bm; std::regex_search(contact_clause, bm, kBothOf)) {
      note(std::stoi(bm[2].str()), bm[1].str());
      note(std::stoi(bm[3].str()), bm[1].str());
    }
    // Tires that left marks are evidence, not a contact ("braked hard (14
    // meters of skid marks were measured from v1's rear tires), and struck
    // the rear of v2").
    static const regex kMarks(R"(\b(?:marks?|skid\w*|tracks?|furrows?|gouges?)\b)");
    static const regex kTireWords(R"(\b(?:tires?|wheels?)\b)");
    auto marks_left_by = [&](const string& part, const smatch& m, size_t area_group) {
      const size_t pos = static_cast<size_t>(m.position(0));
      return Has(m[area_group].str(), kTireWords) && Has(Before(part, pos, 60), kMarks);
    };
    for (const string* part_of : {&contact_clause, &s}) {
      const string& part = *part_of;
      for (auto it = std::sregex_iterator(part.begin(), part.end(), kOfV); it != std::sregex_iterator(); ++it) {
        if (!marks_left_by(part, *it, 1)) note(std::stoi((*it)[it->size() - 1].str()), (*it)[1].str());
      }
      for (auto it = std::sregex_iterator(part.begin(), part.end(), kVs); it != std::sregex_iterator(); ++it) {
        if (!marks_left_by(part, *it, 2)) note(std::stoi((*it)[1].str()), (*it)[2].str());
      }
      for (auto it = std::sregex_iterator(part.begin(), part.end(), kVOn); it != std::sregex_iterator(); ++it) {
        note(std::stoi((*it)[1].str()), (*it)[2].str());
      }
      // "the rear of the pickup came around ..., where its left side struck
      // the guardrail": the contact clause's own words first.
      if (smatch cm; clause > 0 && part_of == &contact_clause && std::regex_search(part, cm, kItsArea)) {
        note(passive ? struck : striker, cm[1].str());
      }
    }
    smatch am;
    if (std::regex_search(s, am, kWithIts)) note(striker, am[1].str());
    if (std::regex_search(s, am, kStruckIn)) note(struck, am[1].str());
    // "the front of v2 struck its left side", "v2 ran into its back end".
    static const regex kStruckIts(
        R"(\b(?:contacted|struck|impacted|hit|sideswiped|striking|hitting|(?:ran|run|running|crashed|slammed|smashed|plowed|rammed|bumped)\s+into)\s+(?:its|their)\s+)" +
        kArea);
    if (!passive && std::regex_search(s, am, kStruckIts)) note(struck, am[1].str());
    // "the front of v1 struck the right side of the other vehicle": of two,
    // the other is the one struck.
    static const regex kOfTheOther(
        R"(\b(?:contacted|struck|impacted|hit|sideswiped|striking|hitting)\s+the\s+)" + kArea +
        R"(\s+of\s+the\s+other\s+(?:vehicle|car|truck)\b)");
    if (!passive && striker > 0 && struck > 0 && r.vehicles.size() == 2 && std::regex_search(s, am, kOfTheOther)) {
      note(struck, am[1].str());
    }
    if (std::regex_search(s, am, kItsArea)) note(passive ? struck : striker, am[1].str());
    static const regex kFrontToFront(R"(\bfront[- ]to[- ]front\b)");
    static const regex kFrontToRear(R"(\bfront[- ]to[- ](?:rear|back)\b)");
    if (Has(s, HeadOnPhrase()) || Has(s, kFrontToFront)) {
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
    if (Has(s, RearEndPhrase()) || Has(s, kFromBehind)) {
      note(striker, "front");
      note(struck, "rear");
    }
    // The next sentence often names the struck area ("... hit him in the door").
    if (!area_words.count(struck) && struck > 0) {
      for (size_t k = impact + 1; k < std::min(sentences.size(), impact + 3); ++k) {
        const string& t = sentences[k].text;
        if (!Has(t, ContactVerb())) continue;
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
  rd.parked_struck =
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
  rd.from_driveway = std::any_of(segments.begin(), segments.end(), [&](const Segment& seg) {
    return !seg.perceived && seg.sentence <= impact && sentences[seg.sentence].kind == Kind::kNarrative &&
           LeavesDriveway(seg.text);
  });
}

void ClassifyCrash(Reading& rd) {
  AccidentRecord& r = rd.r;
  const std::vector<Sentence>& sentences = rd.sentences;
  const size_t impact = rd.impact;
  const std::vector<Segment>& segments = rd.segments;
  std::vector<MovementEvidence>& narrative = rd.narrative;
  const string& scene = rd.scene;
  const bool case_summary = rd.case_summary;
  std::map<int, AreaWords>& area_words = rd.area_words;
  const int striker = rd.striker;
  const int struck = rd.struck;
  const bool struck_object = rd.struck_object;
  const bool parked_struck = rd.parked_struck;
  const bool from_driveway = rd.from_driveway;
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
  const string impact_text = rd.ImpactText();
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
        R"(\b(?:from|out of|exiting|leaving|pulling out|pulled out|entered the (?:road|roadway|street|highway) from)\b[^.]{0,40}?\b(?:side (?:road|street)|driveway|parking|lot|private|alley|station|stop sign|minor road|intersecting|garage|field|farm|parking (?:deck|structure)))");
    // "turned left onto oak ave" enters a road; when the other vehicle came
    // the opposite way on the road the turner left, the turn crosses its path.
    static const regex kOnto(R"(\bonto\b)");
    static const regex kOncoming(
        R"(\b(?:the other way|the opposite way|oncoming|(?:from|in) the opposite direction|opposing (?:traffic|direction))\b)");
    // A turner held by a stop sign, the other not coming the other way,
    // turns in from the side road ("was stopped at the stop sign on
    // millbrook rd ..., waiting to turn left").
    static const regex kAtStopSign(
        R"(\b(?:stopped|waiting|sitting|stopping)\s+(?:\w+\s+){0,2}?(?:at|for)\s+(?:the|a|its)\s+stop\s+(?:sign|line|bar)\b)");
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
            (Has(seg.text, kFromSide) || (!other_oncoming && !same && (Has(seg.text, kOnto) || Has(seg.text, kAtStopSign))))) {
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
    // (So does a contact told as head-on: "where it struck v2 head-on".)
    // (Or the report names the crash so: "this head-on crash occurred on a
    // rural 2-lane state highway", though a spinning car took it in the side.)
    static const regex kHeadOnCrashTold(
        R"(\b(?:this|the|a)\s+(?:[\w-]+\s+){0,2}?head[- ]on\s+(?:crash|collision)\s+(?:occurred|happened|took place)\b)");
    const bool front_to_front =
        (sa.front && (sb.front || !sb.any())) || Has(impact_text, HeadOnPhrase()) || Has(scene, kHeadOnCrashTold);
    // Paths that cross: a junction, a vehicle running a sign or light, or one
    // pulling out of a drive.
    const bool crossing_paths = r.road.kind.value == RoadKind::kIntersection ||
                                r.road.kind.value == RoadKind::kTJunction || RanTrafficControl(scene) || from_driveway;
    if (const auto from_coding =
            CrashTypeFromCoding(coded, turner != nullptr, turner && turner->movement.value == Movement::kTurnRight,
                                Has(impact_text, kLaneChangeNow), front_to_front,
                                a_turn && b_turn && a->movement.value == b->movement.value && !opposite)) {
      type = *from_coding;
      type_src = Provenance::kStated;
    } else if (Has(impact_text, RearEndPhrase())) {
      type = CrashType::kRearEnd;
    } else if (Has(impact_text, HeadOnPhrase()) || (opposite && Has(scene, kHeadOnCrashTold))) {
      type = CrashType::kHeadOn;
    } else if (struck_plain_rear && sa.front && turner == b && turner_from_side) {
      // Struck in the back just after turning onto the striker's road from
      // a side road or drive: NASS codes the turn into its path (78/79).
      type = CrashType::kTurnIntoPath;
    } else if (struck_plain_rear && (sa.front || !sa.any()) && !opposite && !lane_change_at_impact) {
      // (A striker's part untold: "the car behind it ran into its back end".)
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
    // (Its driver may be the one to tell the turn: "he activated his right
    // turn signal and began to slow ... to turn right into a field driveway".)
    if (!narrative[bi + 1].meant_turn() && !rd.statement[bi + 1].meant_turn()) {
      r.vehicles[bi].pre_event.Set(Movement::kStraight, Provenance::kInferred);
    }
  }
  // A vehicle about to turn that another, going its way, passes or
  // encroaches on from the next lane is coded going straight, whatever it did
  // before its turn (straight/0: "she had stopped prior to turning";
  // crossing/21): the other vehicle's move is the critical event.
  // Not when the other turned the same way beside it (a double turn lane)
  // and no turn is coded as the critical event.
  const bool turn_coded = Has(coded, CodedTurn());
  for (size_t i = 0; i < r.vehicles.size(); ++i) {
    VehicleRecord& v = r.vehicles[i];
    const MovementEvidence& told = narrative[i + 1];
    const bool about_to_turn = Turning(v.movement.value) || told.meant_turn();
    if (!about_to_turn || told.coded_turn_left || told.coded_turn_right || told.coded_straight) continue;
    const bool side_by_side =
        !turn_coded && std::any_of(r.vehicles.begin(), r.vehicles.end(), [&](const VehicleRecord& o) {
          return &o != &v && Turning(o.movement.value) && o.movement.value == v.movement.value;
        });
    if (side_by_side) continue;
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
      // (A turn out of a driveway or lot is from no lane: "exited in one
      // continuous sweeping right turn ..., heading east".)
      const bool out_of_drive = std::any_of(segments.begin(), segments.end(), [&](const Segment& seg) {
        return seg.vehicle == static_cast<int>(i) + 1 && !seg.perceived && seg.sentence <= rd.impact &&
               sentences[seg.sentence].kind == Kind::kNarrative && LeavesDriveway(seg.text);
      });
      const bool wrong_lane = !out_of_drive && std::any_of(r.vehicles.begin(), r.vehicles.end(), [&](const VehicleRecord& o) {
        return &o != &v && o.travel.value && o.travel.value == v.travel.value && !o.parked.value;
      });
      if (road_curves || wrong_lane) v.pre_event.Set(Movement::kStraight, Provenance::kInferred);
    }
  }
}

void SetDamagedPlanes(Reading& rd) {
  AccidentRecord& r = rd.r;
  const CrashType type = r.crash.type.value;
  std::map<int, AreaWords>& area_words = rd.area_words;
  const int striker = rd.striker;
  const int struck = rd.struck;
  const bool struck_object = rd.struck_object;
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
  if (!striker && r.vehicles.size() == 1 && type == CrashType::kSingleVehicle) {
    // "the front struck a 60 cm tree", "it left the road and overturned":
    // the crash's one vehicle did whatever was done.
    r.crash.striking.Set("V1", Provenance::kInferred);
  }
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
}

void LocateCrash(Reading& rd) {
  AccidentRecord& r = rd.r;
  const std::vector<Sentence>& sentences = rd.sentences;
  const size_t impact = rd.impact;
  const bool from_driveway = rd.from_driveway;
  const string impact_text = rd.ImpactText();
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
        R"(\b(?:in|at|within|into|entered|entering|through|crossing|crossed|approaching|near|toward)\s+(?:the|an|a)\s+(?:\w+[- ]?){0,4}?(?:intersection|junction|crossover)\b|\bintersection of\b|)"
        // The ramp's terminal is a junction ("at the terminal of the exit
        // ramp, where the ramp forms a t-intersection with highway 20").
        // (Not a queue's aim: "stopped at the end of the queue, intending to
        // go straight across at the ramp terminal".)
        R"(\b(?:occurred|happened|took place|collided|crashed)\s+(?:[^.;]{0,40}?\s)?at\s+the\s+(?:(?:[\w-]+\s+){0,2}?ramp\s+terminal|(?:terminal|terminus)\s+of\s+(?:the|an?)\s+(?:[\w-]+\s+){0,3}?(?:(?:off|on|exit|entrance)-)?ramp)\b|\bramp\s+(?:forms|creates|makes)\s+(?:a|an)\s+(?:[\w-]+\s+)?(?:intersection|junction)\b)");
    static const regex kAtIntersection(
        R"(\b(?:in|at|within|into|entered|entering|through|crossing|crossed|approaching|near|toward)\s+(?:the|an|a)\s+(?:\w+[- ]?){0,4}?(?:intersection|junction)\b|\bside (?:road|street)|\bcross street|\bintersection of\b|)"
        // A vehicle held by the signal ("stopped at a red arrow in the
        // left-turn lane") is in the junction's queue.
        R"(\b(?:stopped|waiting|stopping|sitting|queued)\s+(?:\w+\s+){0,2}?(?:at|for)\s+(?:a|an|the)\s+(?:steady\s+)?(?:red|yellow|amber)\s+(?:(?:left[- ]turn|right[- ]turn|turn)\s+)?(?:light|signal|arrow|indication|phase)\b|)"
        // ("stopped in a queue about 20 m back from a red signal".)
        R"(\b(?:stopped|waiting|queued)\s+in\s+(?:a|the)\s+queue\s+(?:[\w.]+\s+){0,3}?(?:back\s+from|short\s+of|behind)\s+(?:a|an|the)\s+(?:red\s+)?(?:light|signal|stop line|stop bar)\b|)"
        // So is a turn made at one ("turning left at a green light", "a left
        // turn on the green arrow", "turned right at the stop sign").
        R"(\b(?:turn\w*\s+(?:left|right)|(?:left|right)[- ]turn)\s+(?:at|on)\s+(?:a|an|the)\s+(?:[\w-]+\s+){0,2}?(?:light|signal|arrow|stop sign)\b|)" +
        WhereRoadsMeet());
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
    static const regex kOnTheRamp(R"(\b(?:on|onto|along|of|in|up|down|from|via)\s+(?:the|a|an)\s+(?:[\w-]+\s+){0,2}?ramp\b)");
    // Nor a drive people got off at: "a school bus stopped to let two
    // children off at their driveway".
    static const string kDriveNoun = R"((?:driveways?|(?:farm|field|private|ranch)\s+(?:lane|drive|entrance|access)s?))";
    static const regex kPeoplesDrive(
        R"(\b(?:children|kids|students|pupils|passengers?|child|riders?)\s+(?:\w+\s+){0,3}?(?:at|to|near)\s+(?:their|his|her|a|the)\s+(?:\w+\s+)?)" + kDriveNoun + R"(\b|)"
        // Nor one it drove past: "had passed the entrance to a shopping plaza".
        R"(\b(?:passed|missed|past|overshot)\s+(?:the|a|an)\s+(?:entrance|driveway|drive)\b[^.;,]{0,40})");
    // Nor one named as a landmark: "just north of a farm lane, v1 drifted
    // across the centerline", unless someone turned into or out of it
    // ("waiting ... before turning into the farm lane", told anywhere).
    static const regex kLandmarkDrive(
        R"(\b(?:just\s+|immediately\s+|slightly\s+)?(?:north|south|east|west|short)\s+of\s+(?:a|an|the)\s+(?:[\w-]+\s+){0,2}?)" + kDriveNoun + R"(\b)");
    static const regex kTurnAtDrive(
        R"(\b(?:turn\w*|pull\w*|back\w*|exit\w*|leav\w*|enter\w*)\s+(?:\w+\s+){0,2}?(?:into|out of|from|onto|to)\s+(?:a|an|the|his|her|their)\s+(?:[\w'-]+\s+){0,2}?)" + kDriveNoun + R"(\b)");
    const bool drive_used = Has(rd.norm, kTurnAtDrive);
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
    } else if (Has(std::regex_replace(drive_used ? pre : std::regex_replace(pre, kLandmarkDrive, " "), kPeoplesDrive, " "),
                   DrivewayWord())) {
      r.crash.location.Set(CrashLocation::kDriveway, Provenance::kInferred);
    } else if (Has(pre, kOnTheRamp)) {
      r.crash.location.Set(CrashLocation::kRamp, Provenance::kInferred);
    } else if (r.road.kind.value == RoadKind::kIntersection || r.road.kind.value == RoadKind::kTJunction) {
      r.crash.location.Set(CrashLocation::kJunction, Provenance::kInferred);
    } else if (Has(pre, RampWord())) {
      r.crash.location.Set(CrashLocation::kRamp, Provenance::kInferred);
    } else if (impact < sentences.size()) {
      r.crash.location.Set(CrashLocation::kSegment, Provenance::kInferred);
    }
    if (r.crash.location.value == CrashLocation::kDriveway && r.road.kind.value == RoadKind::kStraight) {
      r.road.kind.Set(RoadKind::kDriveway, Provenance::kInferred);
    }
    // A crash at a junction no sentence names ("ran the red light and struck
    // the left side of vehicle b"): the roads cross there.
    if (r.crash.location.value == CrashLocation::kJunction && r.road.kind.value == RoadKind::kStraight &&
        !r.road.kind.known()) {
      r.road.kind.Set(RoadKind::kIntersection, Provenance::kInferred);
    }
    // "where a one-lane entrance ramp joins the eastbound lanes": the
    // roads meet at the ramp's merge, not at an intersection.
    static const regex kJunctionNoun(R"(\bintersection\b|\bjunction\b)");
    if (r.crash.location.value == CrashLocation::kRamp && r.road.kind.value == RoadKind::kIntersection &&
        !Has(pre, kJunctionNoun)) {
      r.road.kind.Set(RoadKind::kRamp, Provenance::kInferred);
    }
  }
}

}  // namespace accsim::narrative
