#include "accsim/env/json_fields.h"

#include <cmath>
#include <sstream>

namespace accsim {
namespace {

std::string TypeName(const nlohmann::json& j) { return j.type_name(); }

std::string Fmt(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

}  // namespace

JsonFields::JsonFields(const nlohmann::json& object, std::string path)
    : object_(object), path_(std::move(path)) {
  if (!object_.is_object()) {
    throw FieldError(path_.empty() ? "(document)" : path_,
                     "expected an object, got " + TypeName(object_));
  }
}

std::string JsonFields::PathOf(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

bool JsonFields::Has(const std::string& key) const { return object_.contains(key); }

const nlohmann::json& JsonFields::Get(const std::string& key) {
  read_.insert(key);
  auto it = object_.find(key);
  if (it == object_.end()) throw FieldError(PathOf(key), "missing required field");
  return *it;
}

const nlohmann::json* JsonFields::Raw(const std::string& key) {
  read_.insert(key);
  auto it = object_.find(key);
  return it == object_.end() ? nullptr : &*it;
}

double JsonFields::Number(const std::string& key, double lo, double hi) {
  const auto& j = Get(key);
  if (!j.is_number()) throw FieldError(PathOf(key), "expected a number, got " + TypeName(j));
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw FieldError(PathOf(key), "not a finite number");
  if (v < lo || v > hi) {
    throw FieldError(PathOf(key), "must be in [" + Fmt(lo) + ", " + Fmt(hi) + "], got " + Fmt(v));
  }
  return v;
}

double JsonFields::Number(const std::string& key, double lo, double hi, double fallback) {
  if (!Has(key)) {
    read_.insert(key);
    return fallback;
  }
  return Number(key, lo, hi);
}

long long JsonFields::Integer(const std::string& key, long long lo, long long hi) {
  const auto& j = Get(key);
  if (!j.is_number_integer()) {
    throw FieldError(PathOf(key), "expected an integer, got " +
                                      (j.is_number() ? std::string("a fractional number")
                                                     : TypeName(j)));
  }
  long long v = 0;
  if (j.is_number_unsigned()) {
    const auto u = j.get<unsigned long long>();
    if (u > static_cast<unsigned long long>(hi)) {
      throw FieldError(PathOf(key), "must be in [" + std::to_string(lo) + ", " +
                                        std::to_string(hi) + "], got " + std::to_string(u));
    }
    v = static_cast<long long>(u);
  } else {
    v = j.get<long long>();
  }
  if (v < lo || v > hi) {
    throw FieldError(PathOf(key), "must be in [" + std::to_string(lo) + ", " +
                                      std::to_string(hi) + "], got " + std::to_string(v));
  }
  return v;
}

long long JsonFields::Integer(const std::string& key, long long lo, long long hi,
                              long long fallback) {
  if (!Has(key)) {
    read_.insert(key);
    return fallback;
  }
  return Integer(key, lo, hi);
}

bool JsonFields::Bool(const std::string& key) {
  const auto& j = Get(key);
  if (!j.is_boolean()) throw FieldError(PathOf(key), "expected true or false, got " + TypeName(j));
  return j.get<bool>();
}

bool JsonFields::Bool(const std::string& key, bool fallback) {
  if (!Has(key)) {
    read_.insert(key);
    return fallback;
  }
  return Bool(key);
}

std::string JsonFields::String(const std::string& key) {
  const auto& j = Get(key);
  if (!j.is_string()) throw FieldError(PathOf(key), "expected a string, got " + TypeName(j));
  return j.get<std::string>();
}

std::string JsonFields::String(const std::string& key, const std::string& fallback) {
  if (!Has(key)) {
    read_.insert(key);
    return fallback;
  }
  return String(key);
}

const nlohmann::json& JsonFields::Array(const std::string& key, size_t min_size) {
  const auto& j = Get(key);
  if (!j.is_array()) throw FieldError(PathOf(key), "expected an array, got " + TypeName(j));
  if (j.size() < min_size) {
    throw FieldError(PathOf(key), "needs at least " + std::to_string(min_size) +
                                      " entries, got " + std::to_string(j.size()));
  }
  return j;
}

JsonFields JsonFields::Object(const std::string& key) { return JsonFields(Get(key), PathOf(key)); }

void JsonFields::RejectUnknown() const {
  for (auto it = object_.begin(); it != object_.end(); ++it) {
    if (!read_.count(it.key())) {
      std::string known;
      for (const auto& k : read_) known += (known.empty() ? "" : ", ") + k;
      throw FieldError(PathOf(it.key()), "unknown field (known fields: " + known + ")");
    }
  }
}

std::pair<double, double> ReadPoint(const nlohmann::json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number()) {
    throw FieldError(path, "expected [x, y] with two numbers");
  }
  const double x = j[0].get<double>(), y = j[1].get<double>();
  if (!std::isfinite(x) || !std::isfinite(y)) throw FieldError(path, "not a finite number");
  constexpr double kLimit = 1e5;  // [m] the same bound as every other coordinate
  if (std::abs(x) > kLimit || std::abs(y) > kLimit) {
    throw FieldError(path, "coordinates must be within +-100 km of the origin");
  }
  return {x, y};
}

}  // namespace accsim
