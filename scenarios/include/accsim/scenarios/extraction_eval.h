// Scores the extractor on a labelled folder (labels.jsonl in the layout of
// the NMVCCS development set) on the paper's six attributes. The mapping
// from investigators' codes to record fields is documented in
// docs/extraction.md and in extraction_eval.cpp.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accsim/scenarios/narrative_extractor.h"

namespace accsim {

inline const std::vector<std::string>& ExtractionAttributes() {
  static const std::vector<std::string> kNames = {"lane_count",      "speed_limit", "collision_location",
                                                  "driving_actions", "crash_type",  "participant_count"};
  return kNames;
}

struct ExtractionScore {
  int n = 0;
  std::map<std::string, double> attributes;                          // accuracy in [0, 1]
  std::map<std::string, std::map<std::string, double>> by_group;     // folder -> attribute -> accuracy
  std::map<std::string, int> group_sizes;
  std::vector<std::string> mismatches;                               // "case: attribute: want X, got Y"
};

// Reads DIR/labels.jsonl; errors name the file and line.
ExtractionScore EvaluateExtraction(const std::string& dir, const NarrativeExtractor& extractor);
nlohmann::json ToJson(const ExtractionScore& s);

}  // namespace accsim
