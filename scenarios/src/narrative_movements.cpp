#include "narrative_reading.h"

#include <algorithm>
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
using regex_text::ReplaceWith;

namespace {

// Reads one piece of text about a vehicle for movement statements.
void ReadMovement(const string& text, MovementEvidence& e) {
  // What a driver saw another vehicle do is that vehicle's movement: "she
  // stated ... the car turned right in front of her".
  static const regex kOtherInFront(
      R"(\b(?:the|a|an|another|some)\s+(?:other\s+)?[a-z-]+\s+(?:[\w-]+\s+){0,5}?in front of (?:him|her|me|them|us)\b)");
  // Nor is what the driver believed another vehicle would do: "she thought
  // v1 was going to turn onto carver road and she began a left turn".
  static const regex kBeliefOfOther(
      R"(\b(?:thought|believed|assumed|expected|figured)\s+(?:that\s+)?(?:v[1-9]|the\s+other\s+(?:car|vehicle|driver|truck|van)|)"
      // "saw v2's brake lights but thought it was only slowing a little".
      R"(it\s+(?=(?:was|would)\s+(?:only\s+|just\s+)?(?:slowing|stopping|stopped|turning|waiting|going to|about to)\b)))"
      R"(\b[^,.;]*?(?=,|\b(?:and|but|so)\s+(?:then\s+)?(?:he|she|i)\b|$))");
  // Nor what a driver quoted the other doing to him: "she just turned right
  // in front of me".
  static const regex kQuotedOther(
      R"("[^"]{0,40}?\b(?:she|he|they|it|the other (?:car|vehicle|driver|truck))\b[^"]{0,60}?\b(?:me|my|us)\b[^"]{0,40}")");
  // Nor what the other did to the speaker: "was still stopped ... when it
  // backed into her".
  static const regex kDoneToSpeaker(
      R"(\b(?:it|he|she|they)\s+(?:\w+\s+)?(?:backed|pulled|turned|cut|swerved|swung|came)\s+(?:\w+\s+){0,3}?(?:into|in front of|toward|towards|across)\s+(?:her|him|me|them|us)\b)");
  // Nor what the driver saw or missed the other doing: "didn't notice she
  // was slowing".
  static const regex kPerceivedOther(
      R"(\b(?:notic\w*|see|saw|seen|seeing|realiz\w*|realis\w*|observ\w*)\s+(?:that\s+)?(?:she|he|it|they)\s+(?:was|were|had)\s+[^,.;"]{0,40})");
  // Nor what the other did that the driver reacted to: "when it stopped he
  // braked hard".
  static const regex kOtherWhenDriver(
      R"(\b(?:when|as|after|once)\s+(?:it|the other (?:car|vehicle|truck|van))\s+(?:\w+\s+)?(?:stopped|slowed|braked|turned|pulled out)\b(?=\s*,?\s*(?:he|she|i)\s))");
  // Nor a sign's words: "lane ends merge left" signs are posted.
  static const regex kSignWords(
      R"("[^"]{1,40}"\s+(?:warning\s+)?signs?\b|\bsigns?\s+(?:reading|that read|which read|saying|stating)\s+"[^"]{1,40}")");
  // A habit given up is no stop: "he had recently stopped taking his
  // medication".
  static const regex kCeased(
      R"(\b(?:stopped|stop|stopping|quit)\s+(?:taking|using|drinking|smoking|wearing|attending|seeing|working|sleeping|eating)\b)");
  string t = std::regex_replace(text, kOtherInFront, " ");
  for (const regex* not_its_own : {&kBeliefOfOther, &kQuotedOther, &kDoneToSpeaker, &kPerceivedOther, &kOtherWhenDriver,
                                   &kSignWords, &kCeased}) {
    t = std::regex_replace(t, *not_its_own, " ");
  }
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
      R"(\b(?:coming|pull|pulling|pulled|leaving|left|exiting)\s+(?:out\s+)?(?:of|from)\s+(?:a|the|his|her)?\s*(?:(?:parallel|diagonal|angled?|curbside|metered)\s+)?(?:parking (?:spot|space|position|place)|parked position)|)"
      // "came out from the curb", "pulled away from the curb".
      R"(\b(?:came|come|coming|pull|pulling|pulled|eased|easing|started|starting|moved|moving)\s+(?:out\s+|away\s+)(?:from\s+)?(?:the|a)\s+curb\b(?!\s+lane)|\bfrom (?:a|the) parked position|\bwas parked\b.{0,80}\b(?:entered|pulled|began|attempt))");
  // Crossing the road into a drive on its far side is a left turn (traffic keeps right).
  static const regex kLeft(
      R"(\bturn(?:ed|ing|s)?\s+(?:to\s+(?:the\s+)?)?left\b|\bleft[- ]hand turn|\bleft turn\b|\bturn(?:ed|ing)? left|\b(?:made|make|making)\s+a\s+left\s+(?:onto|into)\b|\bu-?\s?turn|\bcross\w*\s+(?:over\s+)?(?:into|to)\s+(?:a|the)\s+(?:\w+\s+){0,2}?(?:driveway|parking lot|lot|alley)\b)");
  static const regex kRight(R"(\bturn(?:ed|ing|s)?\s+(?:to\s+(?:the\s+)?)?right\b|\bright[- ]hand turn|\bright turn\b|\b(?:made|make|making)\s+a\s+right\s+(?:onto|into)\b)");
  // An intention is not the movement: "waiting to turn left", "intending to turn".
  static const regex kIntention(
      R"(\b(?:intend\w*|intention|plann\w*|prepar\w*|wait\w*|await\w*|signal\w*|going to|about to|wanted to|wanting to|would)\b[^,.]{0,30}?\b(?:turn|left|right)|\bin order to\s+(?:turn|make\s+(?:a|the)\s+(?:left|right))\b|\bintended\s+(?:left|right)|\bintended\s+(?:path|turn)|)"
      // "to get into position for a right turn into a plaza".
      R"(\bfor (?:a|an|the|his|her|its) (?:[\w-]+ )?(?:left|right) turn\b)");
  static const regex kLaneChange(
      R"(\bchang\w*\s+lanes?\b|\blane change|\b(?:moved|moving|steered|pulled|cut|swung)\s+(?:over\s+)?to the (?:left|right)\s+to (?:reach|take|get to|get into|make|enter|exit|pass|go around|prepare for|set up for|line up for)\b|\b(?:(?:began|started|tried|attempted) to move|moved|moving|steered|steering|swerved|veered|drifted|drifting|merged|pulled|pulling|crossed)\s+(?:from\s+the\s+\w+\s+lane\s+|(?:\w+\s+){0,3}?)into\s+(?:(?:the\s+)?(?:left|right|adjacent|other|next|inside|outside|center|middle|median|curb|offside|nearside|fast|slow|passing|overtaking|1st|2nd|3rd)\s+(?:travel\s+)?lane|lane\s+[1-9]\b)|\bre-?entered the roadway from the shoulder|)"
      // "moved right toward lane one in order to turn right".
      R"(\b(?:moved|moving|steered|pulled|cut|swung|eased)\s+(?:over\s+)?(?:to\s+the\s+)?(?:left|right)\s+(?:toward|towards)\s+(?:the\s+)?(?:lane\s+\d|(?:left|right|curb|adjacent|next|outside|inside|center|middle)\s+lane)\b|)"
      // "wanted to exit at an off-ramp 0.8 km ahead and moved right".
      // (Not "saw the car come over and moved right": an avoidance.)
      R"(\b(?:wanted|intended|planned|needed|decided|was going|was trying|tried|attempting)\s+to\s+(?:exit|get off|take|reach|enter|turn|make|pass)\b(?:[^.;]|\.\d){0,60}?\band\s+(?:then\s+)?(?:moved|cut|swung|eased)\s+(?:over\s+)?(?:to\s+the\s+)?(?:left|right)\b)");
  static const regex kMerge(
      R"(\bmerg(?:e|ed|es|ing)\b|\bentering the (?:freeway|interstate|highway) from|\b(?:on|from|along) (?:a|an|the) (?:[\w-]+[ ,]+){0,3}?(?:entrance|on-?) ramp\b|)"
      // "came down the ramp and reached the end of the acceleration lane".
      R"(\b(?:in|into|along|from|reached|used|using) (?:the|an|its) (?:end of (?:the|an) )?(?:short |long |1-lane |brief )?acceleration lane\b)");
  // "traffic was backed up" is a queue, not a vehicle reversing.
  static const regex kBack(
      R"(\bbacking\s+(?:up|out|in|into|from|toward|across)\b|\b(?:began|started|attempted|tried)\s+to\s+back\s+(?:up|out|in|into)\b|(?:^|\b(?!(?:was|were|is|are|been)\s)\w+\s+)backed\s+(?:up|out|into|from|toward|across)|\breversing\b|\bin reverse\b)");
  static const regex kPass(
      R"(\b(?:was|were)\s+(?:\w+\s+)?(?:passing|overtaking)\b|\bin the process of passing\b|\b(?:attempt\w*|began|started|trying|tried) to (?:pass|overtake)\b|\b(?:began|started)\s+(?:passing|overtaking)\b|\bto (?:pass|overtake)\s+(?:a|an)\s+(?:slower|slow|slow-moving)\b|\b(?:pulled|moved|swung|steered|went|crossed|entered)\s+(?:\w+\s+){0,7}?to (?:pass|overtake)\b)");
  static const regex kSlow(
      R"(\b(?:was|were)\s+(?!not\b|never\b)(?:\w+\s+)?(?:and\s+)?(?:slowing|decelerating|braking)\b|)"
      // "v4, v3 and v2 were eastbound in the left lane in that order, all braking".
      R"(,\s*all\s+(?:3\s+|4\s+|of them\s+)?(?:slowing|decelerating|braking)\b|)"
      // "was westbound in lane two, slowing from about 50 mph".
      R"((?:,|\band)\s+(?:slowing|decelerating)\s+(?:down\s+)?(?:from|for|to|because|due)\b|\bhad\s+(?:\w+\s+)?(?:slowed|decelerated)\b|\bslowed\s+(?:down\s+)?(?:for|because|due|to\s+(?:about\s+|approximately\s+|around\s+)?\d|to\s+(?:turn|make)\b)|\b(?:began|started)\s+(?:slowing|to slow|decelerating|braking)\b|\bslowed\s+(?:down\s+)?(?:and|,)\s+(?:then\s+)?(?:turned|(?:began|started)\s+(?:to\s+)?(?:(?:a|an|its|his|her)\s+(?:\w+\s+)?)?(?:turn|make|pull|enter|cross|mov|stop|brak)\w*|made|moved)\b)");
  static const regex kStraight(
      R"(\b(?:going|went|travel\w*|continu\w*|proceed\w*|drove|driving)\s+straight\b|\bpass(?:ing|ed)? through the intersection|\bcross(?:ing|ed)? (?:the|through the) intersection)");
  // "... impacted the left side of a legally parked and unoccupied van": the
  // parked thing is what the vehicle struck, not the vehicle itself; nor is
  // one it saw ("could see past the parked truck").
  static const regex kParkedObject(
      R"(\b(?:struck|hit|impacted|contacted|collided with|ran into|crashed into|sideswiped|rear[- ]ended|into)\s+(?:the\s+[\w -]{1,20}?\s+of\s+)?(?:a|an|another)\s+(?:\w+\s+){0,3}?(?:parked|unoccupied)(?:\s*,?\s*(?:and\s+)?(?:parked|unoccupied))?\b[^,.;]*|\b(?:the|a|an|another|several|other|many|\d)\s+(?:\w+[\s-])?parked\s+(?:[\w-]+\s+)?(?:cars?|trucks?|vans?|vehicles?|suvs?|pickups?|bus|buses|trailers?)\b|\bparked\s+(?:cars|trucks|vans|vehicles)\b|\b(?:cars|trucks|vans|vehicles|suvs|pickups|buses|trailers)\s+(?:were\s+|are\s+|often\s+|usually\s+)?parked\b|)"
      // "thought it was parked, or going normal speed": the other's state as
      // the driver took it.
      R"(\b(?:thought|believed|assumed|figured|guessed)\s+(?:that\s+)?(?:it|the\s+\w+|v[1-9]|she|he|they)\s+(?:was|were|had been)\s+(?:\w+\s+)?parked\b|)"
      // "a landscaping trailer parked at the south curb limited the v2 driver's view".
      R"(\b(?:a|an|another|the)\s+(?:[\w'-]+\s+){0,2}?(?:cars?|trucks?|vans?|vehicles?|suvs?|pickups?|bus|trailers?|sedans?)\s+(?:was\s+)?(?:double-)?parked\b|)"
      // "was passing the parked v2": the state of the vehicle named next.
      R"(\b(?:the|a)\s+(?:legally\s+|illegally\s+)?parked\s+(?=v[1-9]\b))");
  const bool parked = Has(std::regex_replace(t, kParkedObject, " "), kParked);
  if (parked && !Has(t, kLeavingParking)) e.parked = true;
  if (Has(t, kLeavingParking)) e.leaving_parking = true;
  // Into a space: "pulled up beside an open space, stopped, shifted into
  // reverse and began backing in", "was backing into a parking space".
  static const regex kEnteringParking(
      R"(\b(?:back\w*|pull\w*|turn\w*|steer\w*)\s+(?:\w+\s+){0,2}?into\s+(?:a|an|the|his|her|their)\s+(?:[\w-]+\s+){0,2}?(?:parking\s+)?(?:space|spot|stall|parking position)\b|)"
      R"(\b(?:was|were|began|started|attempting|attempted|tried|trying)\s+(?:to\s+)?parallel[- ]park|\b(?:began|started)\s+(?:backing|to back)\s+in\b(?!to))");
  if (Has(t, kEnteringParking)) e.entering_parking = true;
  if (Has(t, kRolledStop)) e.rolled_stop = true;
  static const regex kSlowedWord(
      R"(\b(?:slowed|slowing|slows|decelerat\w+|reduced\s+(?:\w+\s+)?speed|rolled|rolling|coasted|coasting)\b)");
  if (Has(t, kSlowedWord)) e.slowed_word = true;
  // On a green nothing asks for a stop: "had a green ball and, without
  // stopping, continued into its left turn" turned; it did not roll a stop
  // unless it slowed ("slowed ... and began the left turn on a circular
  // green without stopping").
  static const regex kHadGreen(
      R"(\b(?:had|with|on)\s+(?:a|the|its|his|her)\s+(?:steady\s+|circular\s+)?green\b|\b(?:signal|light)\s+(?:was|showed|displayed)\s+(?:a\s+)?green\b)");
  if (Has(t, kNoStop) && (e.slowed_word || !Has(t, kHadGreen))) e.no_stop = true;
  static const regex kSkippedStop(
      R"(\b(?:did not|didn't|failed to|never|without)\s+(?:\w+\s+){0,3}?stop(?:ping)?\s+(?:at|for)\s+(?:the|a|its|his|her)\s+(?:[\w-]+\s+){0,2}?(?:stop sign|sign|stop line|red|signal|light|end|edge|mouth|exit|apron)\b)");
  if (Has(t, kSkippedStop)) e.skipped_stop = true;
  // A stop made on seeing the other vehicle is the avoidance, after the
  // critical event: "when he saw the other car coming, he stopped".
  static const regex kAvoidanceStop(R"(\b(?:saw|seeing|noticed|observed|spotted)\b[^.]{0,80}?\b(?:stopped|braked to a stop)\b)");
  // "was almost stopped when he was hit" is no stop.
  static const regex kAlmostStopped(
      // ("had 'almost stopped' waiting to make her turn": the wait too.)
      R"(\b(?:almost|nearly|virtually|practically)\s+(?:stopped|at a stop|to a stop|come to a stop|came to a stop)\b(?:"?,?\s+waiting\b)?)");
  // Nor is "to go around the stopped vehicle": a stopped thing it passed.
  static const regex kStoppedObject(
      R"(\b(?:the|a|an|another|other|several)\s+(?:[\w-]+\s+)?stopped\s+(?:[\w-]+\s+)?(?:vehicles?|cars?|trucks?|vans?|minivans?|suvs?|pickups?|sedans?|bus|buses|traffic)\b)");
  // Nor is the queue's stop: "did not recognize that the queue had stopped".
  static const regex kQueueStopped(
      R"(\b(?:the|that)\s+(?:queue|traffic|line of (?:traffic|vehicles|cars))\s+(?:ahead\s+)?(?:had|was|were)\s+(?:already\s+|just\s+)?(?:stopped|come to a stop|at a stop)\b)");
  // Nor a stop made earlier and elsewhere: "had stopped at the previous
  // light a block back and was speeding back up".
  static const regex kEarlierStop(
      R"(\b(?:stopped|come to a stop|came to a stop)\s+(?:at|for)\s+(?:the|a)\s+(?:previous|prior|last|earlier)\s+(?:\w+\s+){0,2}?(?:light|signal|sign|intersection|stop sign|traffic light)s?\b)");
  // ... or an errand on the way: "had stopped at a convenience store about
  // 20 minutes before the crash to buy coffee".
  static const regex kErrandStop(
      R"(\b(?:stopped|come to a stop|came to a stop)\s+(?:at|by|for)\s+(?:a|an|the|his|her|their)\s+(?:[\w'-]+\s+){0,2}?(?:store|station|restaurant|tavern|house|home|shop|market|mall|office|school|church|bank|pharmacy|diner|motel|hotel|coffee|lunch|dinner|breakfast|gas|fuel)\b(?!'?s?\s+(?:exit|driveway|drive|entrance|apron|lot|parking|pumps?|station)\b)|\b(?:stopped|come to a stop|came to a stop)\b[^.;]{0,60}?\b\d+\s+(?:minutes?|hours?|miles?|kilometers?|km)\s+(?:before|earlier|prior)\b)");
  string stops = t;
  for (const regex* not_its_stop : {&kAlmostStopped, &kStoppedObject, &kQueueStopped, &kEarlierStop, &kErrandStop}) {
    stops = std::regex_replace(stops, *not_its_stop, " ");
  }
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
      R"(\b(?:entered|began to enter|started to enter|pulled (?:out|into|onto|away|forward|past|across)|(?:inched|crept|nosed|edged) (?:out|forward|into|onto)|went for it|proceeded (?:into|onto|to)|drove (?:into|onto|out)|accelerated (?:into|onto|across) (?:the|a) (?:intersection|junction|road|roadway|street|highway))\b(?!\s+(?:the|a|an)\s+(?:[\w-]+\s+){0,2}?(?:center|centre|middle|turn|turning|left-turn|right-turn)\s+lane\b)|)"
      R"(\b(?:began|started|initiated|commenced) (?:the|its|his|her|a) (?:left |right )?turn\b|)"
      // "she accelerated into the turn".
      R"(\b(?:accelerated|moved|went|eased|pulled|proceeded|started|began|drove|swung|swept|rolled)\s+(?:forward\s+|ahead\s+|out\s+)?into\s+(?:the|its|his|her|a)\s+(?:left\s+|right\s+)?turn\b(?![- ](?:lanes?|bays?|pocket|only)\b))");
  // A lane's name is not a manoeuvre: "in the two-way left turn lane".
  static const regex kTurnLane(
      R"(\b(?:(?:2[- ]way\s+)?(?:left|right)[- ]turn(?:[- ]only)?|turning)\s+(?:only\s+)?lanes?\b|\b(?:left|right)[- ]turn\s+(?:signal|blinker|indicator)s?\b)");
  const string turns = std::regex_replace(t, kTurnLane, " lane ");
  const bool intention = Has(turns, kIntention);
  // "slowing with its right turn signal on to turn into the driveway".
  static const regex kTurnMeant(R"(\bto (?:(?:make|begin|start) (?:a|the|his|her|its) )?turn\b|\bturn signal\b)");
  if (Has(t, kTurnMeant)) e.turn_meant = true;
  // "slowed with its left turn signal on": the signal tells the intent.
  static const regex kOwnSignal(
      R"(\b(?:with|had|activated|turned on|put on|using)\s+(?:its|his|her|their)\s+(left|right)(?:[- ]turn)?\s+(?:signal|blinker|indicator)s?\b|\bsignal(?:ed|led|ing)\s+(?:for\s+)?a\s+(left|right)\s+turn\b)");
  if (smatch sm; std::regex_search(t, sm, kOwnSignal)) {
    ((sm[1].matched ? sm[1].str() : sm[2].str()) == "left" ? e.intent_left : e.intent_right) = true;
  }
  // A vehicle in a turn lane ("was northbound in the left-turn lane") meant
  // that turn (not in the centre lane both ways use).
  static const regex kInTurnLane(
      R"(\b(?:in|into|from|entered)\s+(?:the|a|an|its|his|her)\s+(?:(?:exclusive|dedicated|protected|\w+bound)\s+)?(left|right)[- ]turn(?:[- ]only)?\s+(?:lane|bay|pocket)\b)");
  if (smatch tl; std::regex_search(t, tl, kInTurnLane)) (tl[1].str() == "left" ? e.intent_left : e.intent_right) = true;
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
      R"(\b(?:moving|moved|changing|changed|merging|merged)\s+(?:over\s+)?(?:into|to)\s+(?:the\s+)?\w+\s+lane\s+(?:a\s+(?:block|mile|while|few\s+\w+)|(?:\w+\s+)?(?:blocks|miles|minutes))\s+(?:earlier|before|back|ago)\b|)"
      // Told in the past perfect it is background ("had entered the highway
      // ... and had moved over into the middle lane"), unless it was "just".
      // "left his signal on from an earlier lane change".
      R"(\b(?:an?|the|his|her|its)\s+(?:earlier|previous|prior)\s+lane change\b|)"
      R"(\bhad\s+(?!just\b|only\b)(?:\w+\s+)?(?:moved|changed|merged|pulled)\s+(?:over\s+)?(?:into|to)\s+(?:the\s+)?(?:[\w-]+\s+){0,3}?lane\b|\bhad\s+(?!just\b|only\b)(?:\w+\s+)?changed\s+lanes\b)");
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
  // A merge still to come is no merge: "looking at traffic to judge his own merge".
  static const regex kOwnMergeAhead(R"(\b(?:his|her|its|their|own)\s+merge\b)");
  if (Has(std::regex_replace(t, kOwnMergeAhead, " "), kMerge)) e.merge = true;
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
      R"(\b(?:began|started)\s+(?:moving|to move|rolling|to roll|forward|to go|to proceed|proceeding|to accelerate|accelerating|across|through|off)\b|\bpulled away\b|\bmoved (?:forward|off)\b|\baccelerated\b|)"
      // "both vehicles started from their stop signs".
      R"(\b(?:started|moved off|took off|set off|pulled out)\s+from\s+(?:a|the|their|its|his|her)\s+(?:complete\s+|full\s+)?(?:stop|stops|stop signs?|stop lines?|stopped positions?)\b)");
  if (Has(t, kStarted)) e.started = true;
  static const regex kOnGreen(
      R"(\b(?:when|once|after|as soon as|as)\s+(?:the\s+)?(?:traffic\s+)?(?:light|signal)\s+(?:for\s+[\w ]{1,30}?\s+)?(?:turned|changed|went|cycled)\s+(?:to\s+)?green\b|)"
      // "v2's signal turned green and v2 proceeded into the intersection".
      R"(\b(?:light|signal)\s+(?:turned|changed|went|cycled)\s+(?:to\s+)?green\s*,?\s*(?:and|then|and then)\s+(?:[\w']+\s+){0,2}?(?:proceeded|pulled|started|began|moved|accelerated|entered|went|drove)\b)");
  if (Has(t, kOnGreen)) e.green_start = true;
  static const regex kUTurn(R"(\bu-?\s?turn)");
  if (!intention && Has(t, kUTurn)) e.u_turn = true;
}

// NHTSA critical-event wording ("this vehicle traveling, turning left at
// intersection", "other motor vehicle in lane, other vehicle stopped").
void ReadCoding(const string& t, MovementEvidence& self, MovementEvidence* other) {
  // (The coding may leave "this vehicle" out: "v1's critical precrash
  // event was turning left at the intersection".)
  static const string kSelf =
      R"((?:\bthis vehicle\b[^.]{0,40}?|\bcritical (?:pre-?crash |precrash )?event\b[^.]{0,30}?\b(?:was|as)\s+(?:coded\s+)?(?:as\s+)?))";
  static const regex kSelfLeft(kSelf + R"(\bturning left)");
  static const regex kSelfRight(kSelf + R"(\bturning right)");
  static const regex kSelfStraight(
      R"(\bthis vehicle\b[^.]{0,40}?\b(?:crossing over|passing through|going straight|over the (?:left |right )?lane line|off the edge|control loss|traveling too fast|over the line)|)"
      // "... was when she began to travel over the lane line".
      R"(\bwhen (?:he|she|it|the (?:driver|vehicle)|v[1-9])\s+(?:(?:began|started) to (?:travel|drift|move|cross)|travell?ed|drifted|moved|crossed)\s+over the (?:left |right )?(?:lane|center|centre) ?line)");
  static const regex kSelfBack(kSelf + R"(\bbacking)");
  static const regex kSelfLane(kSelf + R"(\bchanging lanes)");
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
  // Entering a parking position: grouped with leaving one, as a move into or
  // out of the traffic lane.
  if (n.entering_parking) {
    const Movement path = n.back ? Movement::kBacking : n.turn_left ? Movement::kTurnLeft : n.turn_right ? Movement::kTurnRight : Movement::kStraight;
    return MovementDecision{path, Movement::kMerging, Provenance::kStated};
  }
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
    // (One that did not stop where it should have, "did not stop at the end
    // of the driveway and began a left turn", is slowing only when the text
    // slows it: "slowed at the stop sign without coming to a complete stop".)
    const bool skipped = n.skipped_stop || st.skipped_stop;
    const bool rolled = n.rolled_stop || st.rolled_stop ||
                        ((n.no_stop || st.no_stop) && (!skipped || n.slowed_word || st.slowed_word));
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
  // (Its driver may be the one to tell the turn it slowed for.)
  const bool meant_turn = n.meant_turn() || st.meant_turn();
  if (n.other_says_decelerating && !meant_turn) return both(Movement::kStraight, Provenance::kStated);
  // (A stop told by the driver that the narrative has him move off from,
  // "he then accelerated from the stop", is NASS "starting in traffic lane".)
  if (e.stopped && (!(e.started || n.started || n.green_start) || e.stopped_again)) {
    return both(Movement::kStopped, Provenance::kStated);
  }
  // A lane change that is itself the vehicle's coded critical event ("this
  // vehicle traveling over the lane line") was preceded by driving on:
  // NASS codes that as the pre-event movement, as for turns.
  // (A move from the ramp's lane into lane 1 is the merge.)
  if ((e.lane_change || n.coded_lane_change) && !e.merge) {
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

}  // namespace

// A vehicle described parked that then enters the road, turns or pulls
// out was leaving its parking position, not a parked object.
// So is one that backed out of its space (NASS "leaving a parking position":
// its backing is "other than for parking" only off a parking space).
bool LeftParking(const MovementEvidence& n) {
  return n.parked && (n.entered || n.turn_left || n.turn_right || n.merge || n.lane_change || n.back || n.leaving_parking);
}

bool Turning(Movement m) { return m == Movement::kTurnLeft || m == Movement::kTurnRight; }

void ReadVehicles(Reading& rd) {
  AccidentRecord& r = rd.r;
  const std::vector<Sentence>& sentences = rd.sentences;
  const size_t impact = rd.impact;
  const std::vector<Segment>& segments = rd.segments;
  static const regex kLaneNo(
      R"(\b(?:in|within|using|from|occupying)\s+(?:the\s+)?(?:lane\s+([1-9])\b|([1-9])(?:st|nd|rd|th)\s+(?:\w+\s+){0,2}?lane))");
  static const regex kSpeed(
      R"(\b(?:travel\w*|going|speed\w*|estimated|at|approximately|about|between|around|driving|doing|less than|no more than)\s+(?:\w+\s+){0,4}?(\d{1,3})(?:\s*(?:-|to)\s*(\d{1,3}))?\s*(kmh|mph)\b)");
  static const regex kLimitWords(R"(limit|posted|advisory|suggested|recommended|speed zone)");
  static const regex kSameDir(R"(\b(?:same direction|also (?:travel\w*|heading|going) (?:north|south|east|west)|behind v[1-9]|followed|following)\b)");
  static const regex kOppositeDir(R"(\b(?:opposite direction|proceeding opposite|oncoming|opposing direction)\b)");
  rd.narrative.assign(r.vehicles.size() + 1, MovementEvidence{});
  rd.statement.assign(r.vehicles.size() + 1, MovementEvidence{});
  std::vector<MovementEvidence>& narrative = rd.narrative;
  std::vector<MovementEvidence>& statement = rd.statement;
  std::vector<int> relation(r.vehicles.size() + 1, 0);  // +1 same direction as the other, -1 opposite
  std::vector<int> relation_to(r.vehicles.size() + 1, 0);  // the vehicle it is relative to, when named
  std::vector<std::optional<Compass>> late_travel(r.vehicles.size() + 1);
  // A turn told by the compass ("intending to turn west", "turned north
  // onto elm"): left or right once the vehicle's own course is known.
  struct CompassTurn {
    size_t vehicle;
    bool statement;  // evidence of the driver's account, not the narrative's
    Compass to;
    bool intended;
  };
  std::vector<CompassTurn> compass_turns;
  // The other vehicle a coded event speaks of ("other vehicle stopped"): of
  // two, the other; of more, its partner in the first contact when the
  // contact names just the two (0: none).
  std::set<int> first_pair;
  if (r.vehicles.size() > 2 && rd.impact < sentences.size()) {
    for (const Ref& ref : sentences[rd.impact].refs) {
      if (ref.vehicle >= 1 && ref.vehicle < static_cast<int>(narrative.size())) first_pair.insert(ref.vehicle);
    }
  }
  auto coded_partner = [&](size_t vi) -> size_t {
    if (r.vehicles.size() == 2) return vi == 1 ? 2 : 1;
    const int v = static_cast<int>(vi);
    if (first_pair.size() != 2 || !first_pair.count(v)) return 0;
    return static_cast<size_t>(*first_pair.begin() == v ? *first_pair.rbegin() : *first_pair.begin());
  };
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
        R"(^v[1-9]\s*(?:,\s*(?:an?\s+)?[^,]{0,50}?(?:,|(?=\s+(?:which|that)\b)))?\s*(?:(?:which|that|who)\s+(?:was|were|had been)\s+(?:\w+\s+)?(?:stopped|parked|stationary|waiting|sitting|standing|slowing)|(?:was|were|had been)\s+(?:legally\s+|lawfully\s+)?(?:parked|unoccupied))\b)");
    // (Also without the comma: "v3, a 2004 ford escape that was stopped".)
    // A vehicle introduced after the impact ("v2 was a 1997 dodge pickup that
    // was stopped to make a left turn"): the introduction is background.
    static const regex kIntroduction(R"(^v[1-9]\s+(?:was|is)\s+an?\s+(?:(?:19|20)\d\d|[a-z]+\s+(?:19|20)\d\d)\b)");
    // Several vehicles' state told together after the impact ("vehicles 3
    // and 4 were stopped and had no part in the first collision"): being
    // pushed does not leave two vehicles "stopped"; the state is before it.
    static const regex kStateTogether(R"(^v[1-9]\s+were\s+(?:both\s+|all\s+)?(?:stopped|stationary|waiting|queued|parked)\b(?!\s+by\b))");
    const bool state_in_relative =
        !pre_impact && (Has(seg.text, kRelativeState) || Has(seg.text, kIntroduction) || Has(seg.text, kStateTogether));
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
        // "had been behind v3": relative to the vehicle it names.
        static const regex kBehindWhom(R"(\b(?:behind|following|followed)\s+v([1-9])\b)");
        if (smatch bw; relation[vi] > 0 && std::regex_search(seg.text, bw, kBehindWhom)) relation_to[vi] = std::stoi(bw[1].str());
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
    static const regex kTurnTo(
        R"(\bturn(?:ed|ing|s)?\s+(?:(?:on)?to\s+(?:the\s+)?)?(north|south|east|west)(?:bound|ward)?\b)");
    static const regex kMeantBefore(
        R"(\b(?:intend\w*|intention|plann\w*|prepar\w*|wait\w*|await\w*|signal\w*|going to|about to|wanted to|wanting to|would|in order to)\b[^,.]{0,20}$)");
    auto note_compass_turns = [&](bool statement_evidence) {
      for (auto it = std::sregex_iterator(seg.text.begin(), seg.text.end(), kTurnTo); it != std::sregex_iterator(); ++it) {
        const auto to = CompassWord((*it)[1].str());
        const bool meant = Has(Before(seg.text, static_cast<size_t>(it->position()), 40), kMeantBefore);
        if (to) compass_turns.push_back({vi, statement_evidence, *to, meant});
      }
    };
    if (kind == Kind::kNarrative && pre_impact && !seg.perceived) {
      ReadMovement(seg.text, narrative[vi]);
      note_compass_turns(false);
    } else if (kind == Kind::kStatement || seg.perceived || (kind == Kind::kPeople && Has(seg.text, kParkedOnly)) ||
               (kind == Kind::kNarrative && (told_of_before || state_in_relative))) {
      ReadMovement(seg.text, statement[vi]);
      note_compass_turns(true);
    } else if (kind == Kind::kCoding) {
      const size_t partner = coded_partner(vi);
      ReadCoding(seg.text, narrative[vi], partner > 0 ? &narrative[partner] : nullptr);
    }
  }
  // "4 passenger vehicles were stopped in the right lane: v5, ..., then v4,
  // ...": every vehicle listed after the colon is in that state.
  {
    static const regex kListState(
        R"(\b(?:\d|all|the|several)\s+(?:\w+\s+)?(?:vehicles|cars)\s+were\s+(?:\w+\s+)?(stopped|stationary|waiting|queued|slowing)\b[^:]*:)");
    // The list may run on over ";"-separated items ("; then v4, a sienna").
    static const regex kListItem(R"(^(?:then|and|followed by)?\s*v[1-9]\b)");
    // Every vehicle named in [from, until) of a sentence is in the state.
    auto mark = [&](const Sentence& t, size_t from, size_t until, const string& state) {
      const bool slowing = state == "slowing";
      for (const Ref& ref : t.refs) {
        if (ref.pos < from || ref.pos >= until || ref.vehicle < 1 || ref.vehicle >= static_cast<int>(statement.size())) continue;
        MovementEvidence& e = statement[static_cast<size_t>(ref.vehicle)];
        (slowing ? e.slowing : e.stopped) = true;
      }
    };
    constexpr size_t kAll = string::npos;
    for (size_t i = 0; i < sentences.size(); ++i) {
      const Sentence& s = sentences[i];
      smatch m;
      if ((s.kind != Kind::kNarrative && s.kind != Kind::kStatement) || !std::regex_search(s.text, m, kListState)) continue;
      mark(s, static_cast<size_t>(m.position() + m.length()), kAll, m[1].str());
      for (size_t j = i + 1; j < sentences.size() && Has(sentences[j].text, kListItem); ++j) mark(sentences[j], 0, kAll, m[1].str());
    }
    // ... and with the state after the list ("from front to back: v4, a
    // honda; v3, a malibu; and v2, a camry, were all stopped"): the list's
    // items run back over the ";"-separated pieces without a verb.
    static const regex kStateAfterList(
        R"(^(?:and\s+)?v[1-9]\b[^;]*?\bwere\s+(?:all\s+|both\s+)?(?:\w+\s+)?(stopped|stationary|waiting|queued|slowing)\b)");
    static const regex kBareItem(R"(^(?:[\w ]{0,30}:\s*)?v[1-9]\s*,)");
    static const regex kVerb(R"(\b(?:was|were|is|are|had|has|stopped|slowed|traveled|travelled|struck|turned)\b)");
    for (size_t i = 1; i < sentences.size(); ++i) {
      const Sentence& s = sentences[i];
      smatch m;
      if ((s.kind != Kind::kNarrative && s.kind != Kind::kStatement) || !std::regex_search(s.text, m, kStateAfterList)) continue;
      size_t j = i;
      while (j > 0 && !sentences[j - 1].refs.empty() && Has(sentences[j - 1].text, kBareItem) &&
             !Has(sentences[j - 1].text, kVerb)) {
        --j;
      }
      if (j == i) continue;  // one vehicle: its own sentence says it
      for (size_t k = j; k < i; ++k) mark(sentences[k], 0, kAll, m[1].str());
      mark(s, 0, static_cast<size_t>(m.position(1)), m[1].str());
    }
  }
  // "When the signal turned green, both vehicles began to move forward":
  // what the vehicles did together before the impact is each one's.
  {
    static const regex kAllSubject(
        R"((?:^|[,;:]\s*|\b(?:and|then|when|as)\s+)(?:both|all|all 3|all 4|the 2|the 3) (?:vehicles|cars|units)\b(?!\s+(?:came|were (?:towed|driven|removed)|rested)\b)|)"
        // Or a bare "both" doing something ("both stopped at their signs
        // ... and both started off"), and "both vehicles" moving off after
        // an unpunctuated clause ("when the green arrow came on both
        // vehicles started to move").
        R"((?:^|[,;:]\s*|\b(?:and|then|when|as)\s+)both\s+(?=(?:then\s+)?(?:stopped|started|began|moved|pulled|proceeded|entered|slowed|braked|accelerated)\b)|)"
        // (Not what others did: "traffic ahead of both vehicles began to slow".)
        R"((?:^|\b(?!of\b)\w+\s+)both (?:vehicles|cars|units)\s+(?=(?:then\s+)?(?:(?:started|began)\s+(?:to\s+)?(?:move|moving|go|going|proceed\w*|accelerat\w*|forward|off)|moved|pulled|proceeded|accelerated)\b))");
    // "the light turned green and the queue began to move": every vehicle
    // stopped in it moved off.
    static const regex kQueueMoved(
        R"(\b(?:the\s+)?(?:queue|traffic|line of (?:traffic|vehicles|cars))\s+(?:\w+\s+){0,3}?(?:began|started)\s+(?:to\s+)?(?:move|moving|go|going|proceed\w*|pull\w*|roll\w*)\b)");
    for (size_t i = 0; i < sentences.size() && i < impact; ++i) {
      const Sentence& s = sentences[i];
      if (s.kind != Kind::kNarrative || !s.refs.empty() || !Has(s.text, kQueueMoved)) continue;
      for (size_t k = 1; k < narrative.size(); ++k) {
        if (narrative[k].stopped) narrative[k].started = true;
      }
    }
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
    for (size_t i = 1; i < relation.size(); ++i) {
      const size_t other = relation_to[i] > 0 ? static_cast<size_t>(relation_to[i]) : (i <= 2 ? 3 - i : 0);
      if (other == 0 || other == i || other > r.vehicles.size()) continue;
      VehicleRecord& v = r.vehicles[i - 1];
      const VehicleRecord& o = r.vehicles[other - 1];
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
  for (const CompassTurn& ct : compass_turns) {
    const auto& course = r.vehicles[ct.vehicle - 1].travel;
    if (!course.known() || !course.value) continue;
    const int from = static_cast<int>(*course.value), to = static_cast<int>(ct.to);
    const bool left = to == (from + 1) % 4, right = to == (from + 3) % 4;  // Compass runs anticlockwise
    if (!left && !right) continue;
    MovementEvidence& e = ct.statement ? statement[ct.vehicle] : narrative[ct.vehicle];
    if (ct.intended) (left ? e.intent_left : e.intent_right) = true;
    else (left ? e.turn_left : e.turn_right) = true;
  }
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
  // "struck the back of the parked v2", "v2 was not in transport": how v2
  // stood, wherever the report tells it.
  {
    static const regex kParkedRef(
        R"(\b(?:the|a)\s+(?:legally\s+|illegally\s+)?(?:parked|unoccupied|abandoned)\s+v([1-9])\b|\bv([1-9])\s+(?:was|had been)\s+(?:\w+\s+)?not in transport\b)");
    for (const Sentence& s : sentences) {
      if (s.kind == Kind::kPeople) continue;
      for (auto it = std::sregex_iterator(s.text.begin(), s.text.end(), kParkedRef); it != std::sregex_iterator(); ++it) {
        const size_t k = static_cast<size_t>(std::stoi((*it)[1].matched ? (*it)[1].str() : (*it)[2].str()));
        if (k < narrative.size()) narrative[k].parked = true;
      }
    }
  }
  // CIREN case summaries code a vehicle that stopped and then turned by its
  // turn (the development set's one such case, a car stopped in the mouth of
  // a driveway waiting to turn left, is coded turning left); NMVCCS reports,
  // which quote the coded critical events, code the stop.
  // (Read in the text as given: normalising names the case vehicle v1.)
  static const regex kCaseSummary(R"(\bcase\s+(?:vehicle|occupant)\b)", std::regex::icase);
  rd.case_summary = std::regex_search(rd.text.begin(), rd.text.end(), kCaseSummary) && !rd.quotes_coding;
  const bool case_summary = rd.case_summary;
  for (size_t i = 0; i < r.vehicles.size(); ++i) {
    VehicleRecord& v = r.vehicles[i];
    // A parked car that someone's account has pull out ("the car 'just came
    // out from the curb'", the other driver said) was leaving its position.
    if ((narrative[i + 1].parked || statement[i + 1].parked) && statement[i + 1].leaving_parking) {
      narrative[i + 1].parked = narrative[i + 1].leaving_parking = true;
    }
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
}

}  // namespace accsim::narrative
