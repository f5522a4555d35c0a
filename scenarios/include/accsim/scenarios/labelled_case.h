// Investigators' coded attributes (labels.jsonl rows of the NMVCCS and
// CIREN folders, docs/reconstruction.md "Label mapping") as a
// CrashDescription, so the planner's reconstruction rate can be measured
// apart from narrative extraction.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "accsim/scenarios/crash_description.h"

namespace accsim {

// The road type of a labelled case: NMVCCS from its folder (crossing/, t/,
// straight/), CIREN from the relation to junction (intersection-related ->
// intersection, driveway -> T-junction, otherwise straight).
RoadType LabelledRoadType(const nlohmann::json& row);

// Every attribute the codes carry is kStated; what they lack is defaulted
// and left for the planner to fill. The reconstructed impact is the first
// vehicle-to-vehicle event by event number. Throws std::invalid_argument
// naming the field when the row is not a labelled case.
CrashDescription DescriptionFromLabels(const nlohmann::json& row);

}  // namespace accsim
