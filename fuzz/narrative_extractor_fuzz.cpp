// Any bytes in: the extractor must return a record (never crash, hang or
// throw), the record must serialise, and its JSON must read back.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "accsim/scenarios/narrative_extractor.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const accsim::NarrativeExtractor extractor;
  const accsim::AccidentRecord r = extractor.Extract(std::string_view(reinterpret_cast<const char*>(data), size));
  const nlohmann::json j = accsim::ToJson(r);
  (void)j.dump();
  const accsim::AccidentRecord back = accsim::AccidentRecordFromJson(j);
  if (back.vehicles.size() != r.vehicles.size()) std::abort();
  return 0;
}
