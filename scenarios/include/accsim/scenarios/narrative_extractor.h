// Deterministic, offline extraction of an AccidentRecord from a crash
// narrative (NHTSA / police style or a user's short description).
//
// Rules over normalised sentences: vehicle references ("V1", "Vehicle one",
// "vehicle #2", "the Ford" once the Ford was introduced), number words, mph
// and km/h, compass directions, movement verbs (with intentions such as
// "waiting to turn" kept apart from turning), damage-area phrases and
// contact verbs in active and passive voice, road descriptions tied to the
// vehicle that used them, and NHTSA's coded critical-event wording.
// Sentences about people (age, injuries, medication) are not used for
// motion. docs/extraction.md lists the rules.
//
// Thread-safe: Extract is const and the object holds no state. Never
// throws on text: what it cannot read stays defaulted, with a warning.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "accsim/scenarios/accident_record.h"

namespace accsim {

class NarrativeExtractor {
 public:
  // Text beyond this many bytes is ignored (with a warning): real reports
  // are a few kilobytes, and the rules are linear in the text only per
  // sentence.
  static constexpr size_t kMaxBytes = 200000;

  AccidentRecord Extract(std::string_view text) const;
};

}  // namespace accsim
