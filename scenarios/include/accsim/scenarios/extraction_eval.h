// Scores an extractor on a labelled folder (DIR/labels.jsonl) on the
// AccidentSim paper's six attributes. Two label layouts are read: NMVCCS
// (SoVAR's set: vehcount, per-vehicle num_travel_lanes_code,
// speed_limit_kmph, relation_to_junction, pre_event_movement,
// crash_type_code; events with striker/hit areas) and CIREN (CRISCE's set:
// travel_lanes, posted_speed_limit_kmph, crash_type "87 87 ...", events
// with area_of_damage). The input text is each row's `narrative`. How each
// coded label maps to the record is documented in docs/extraction.md.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "accsim/scenarios/narrative_extractor.h"

namespace accsim {

// The six attributes, in the paper's order.
const std::vector<std::string>& ExtractionAttributes();

struct ExtractionScore {
  int n = 0;                                                       // cases read
  std::map<std::string, double> attributes;                        // accuracy in [0, 1] over scored cases
  std::map<std::string, int> scored;                               // cases with a usable label, per attribute
  std::map<std::string, double> extra;                             // impact_areas (damaged planes per vehicle)
  std::map<std::string, std::map<std::string, double>> by_group;   // folder -> attribute -> accuracy
  std::map<std::string, int> group_sizes;
  std::vector<std::string> mismatches;                             // "case: attribute: want X, got Y"
  std::vector<std::string> pairings;  // "case: coded V1 is the narrative's V2 (year, make, model)"
};

using ExtractFn = std::function<AccidentRecord(std::string_view)>;

// Reads DIR/labels.jsonl; errors (std::invalid_argument) name the file and line.
ExtractionScore EvaluateExtraction(const std::string& dir, const ExtractFn& extract);
ExtractionScore EvaluateExtraction(const std::string& dir, const NarrativeExtractor& extractor);
nlohmann::json ToJson(const ExtractionScore& s);

}  // namespace accsim
