// Meaning-preserving rewrites of a crash narrative: the same facts in
// another writer's wording ("V1" -> "Vehicle one", "48 km/h (30 mph)" ->
// "30 mph", "two-lane" -> "2-lane", past -> present tense, ALL CAPS ...).
// An extractor that reads the facts and not one writer's habits gives the
// same record for each; `accsim eval-extraction --rewrite NAME` scores a
// labelled folder through one of them.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace accsim {

struct NarrativeRewrite {
  std::string name;
  std::string description;
};

// Every rewrite, in a fixed order.
const std::vector<NarrativeRewrite>& NarrativeRewrites();

// `text` rewritten by the rewrite called `name`; std::invalid_argument
// naming the known rewrites when there is none of that name.
std::string RewriteNarrative(std::string_view text, std::string_view name);

}  // namespace accsim
