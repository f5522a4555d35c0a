// Deterministic, offline extraction of an AccidentRecord from a crash
// narrative (NHTSA / police style or a user's short description). Rules
// over normalised sentences: vehicle references ("V1", "Vehicle one",
// "vehicle #2"), number words, mph and km/h, directions, movements, damage
// areas and contact verbs; injury and driver-history sentences are ignored
// for movements. Thread-safe (no state); never throws on text: what it
// cannot read it leaves defaulted, with a warning.
#pragma once

#include <string>
#include <string_view>

#include "accsim/scenarios/accident_record.h"

namespace accsim {

class NarrativeExtractor {
 public:
  // Text beyond this many bytes is ignored (with a warning): real reports
  // are a few kilobytes.
  static constexpr size_t kMaxBytes = 200000;

  AccidentRecord Extract(std::string_view text) const;
};

}  // namespace accsim
