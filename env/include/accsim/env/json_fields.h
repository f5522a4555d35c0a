// Validated reading of JSON objects (scenario files, and YAML configs after
// conversion): every error names the full field path and the reason, and
// unknown fields are rejected so a misspelt option never passes silently.
#pragma once

#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <string>

namespace accsim {

// An input error; what() is "<field path>: <reason>".
class FieldError : public std::invalid_argument {
 public:
  FieldError(const std::string& path, const std::string& reason)
      : std::invalid_argument(path + ": " + reason), path_(path) {}
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

class JsonFields {
 public:
  // `path` names the object itself ("" for the document root).
  JsonFields(const nlohmann::json& object, std::string path);

  std::string PathOf(const std::string& key) const;
  bool Has(const std::string& key) const;

  // Required number within [lo, hi]; finite.
  double Number(const std::string& key, double lo, double hi);
  // Optional number; `fallback` when absent.
  double Number(const std::string& key, double lo, double hi, double fallback);
  long long Integer(const std::string& key, long long lo, long long hi);
  long long Integer(const std::string& key, long long lo, long long hi, long long fallback);
  bool Bool(const std::string& key);
  bool Bool(const std::string& key, bool fallback);
  std::string String(const std::string& key);
  std::string String(const std::string& key, const std::string& fallback);
  // Required array (possibly empty when min_size == 0).
  const nlohmann::json& Array(const std::string& key, size_t min_size = 0);
  // Required / optional nested object.
  JsonFields Object(const std::string& key);
  // Raw access, marks the key as read.
  const nlohmann::json* Raw(const std::string& key);

  // Throws FieldError for any key that was never read.
  void RejectUnknown() const;

 private:
  const nlohmann::json& Get(const std::string& key);
  const nlohmann::json& object_;
  std::string path_;
  std::set<std::string> read_;
};

// [x, y] pair with finite numbers.
std::pair<double, double> ReadPoint(const nlohmann::json& j, const std::string& path);

}  // namespace accsim
