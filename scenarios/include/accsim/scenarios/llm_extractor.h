// Optional second extraction back end for users who run a local LLM: any
// OpenAI-compatible chat endpoint (llama.cpp server, Ollama, vLLM).
//
// The rule extractor runs first; the model is then asked, with a few-shot
// prompt, for a compact JSON answer (schema in BuildLlmMessages). Every
// field of the answer is validated on its own and merged into the record:
// a valid model value replaces a rule value that was only inferred or
// defaulted, never one the rules read as stated (a disagreement becomes a
// warning). Invalid fields are dropped with a warning naming the field, so
// a wrong or half-broken answer never breaks the record.
//
// Plain HTTP only (the model runs locally). Thread-safe: Extract is const
// and opens its own connection per call.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "accsim/scenarios/accident_record.h"
#include "accsim/scenarios/narrative_extractor.h"

namespace accsim {

struct LlmConfig {
  std::string url = "http://127.0.0.1:8080";  // server base URL; "/v1/chat/completions" is appended
  std::string model = "local";                // model name the server expects (Ollama: e.g. "llama3.1")
  double timeout_s = 120.0;                   // [s] per request, connect and read
  int max_tokens = 1024;
  std::string api_key;                        // sent as "Authorization: Bearer" when not empty
};

// Throws std::invalid_argument naming the field (llm.url, llm.timeout_s, ...).
void Validate(const LlmConfig& c);

// The chat messages sent for one narrative: system instructions with the
// answer schema, two worked examples, then the narrative.
nlohmann::json BuildLlmMessages(std::string_view narrative);

// Merges a model answer into r, field by field (see above). Returns the
// number of fields taken from the answer.
int MergeLlmAnswer(const nlohmann::json& answer, AccidentRecord& r);

class LlmExtractor {
 public:
  explicit LlmExtractor(LlmConfig config);  // validates the config

  // Rules, then the model. A transport or protocol failure leaves the rule
  // record with a warning saying why (the caller still gets a record).
  AccidentRecord Extract(std::string_view text) const;

  // One chat completion; returns the parsed JSON object the model wrote.
  // Throws std::runtime_error on connection, HTTP or protocol errors.
  nlohmann::json Ask(std::string_view narrative) const;

 private:
  LlmConfig config_;
  NarrativeExtractor rules_;
};

}  // namespace accsim
