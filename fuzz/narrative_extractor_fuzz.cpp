// Any bytes in: the extractor must return a record (never crash, hang or
// throw), and the record must serialise.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "accsim/scenarios/narrative_extractor.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const accsim::NarrativeExtractor extractor;
  const accsim::AccidentRecord r =
      extractor.Extract(std::string_view(reinterpret_cast<const char*>(data), size));
  (void)accsim::ToJson(r).dump();
  return 0;
}
