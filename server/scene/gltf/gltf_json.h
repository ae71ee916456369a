#pragma once
// Reading members of an untrusted glTF JSON document without throwing:
// a member of the wrong kind reads as absent, and the caller decides
// whether absent is an error.
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace toond::scene::gltf_json {

using nlohmann::json;

inline std::string in_quotes(std::string_view s) { return "'" + std::string(s) + "'"; }

// A member of a JSON object, or null when `object` is not one or lacks it.
inline const json& member(const json& object, std::string_view key) {
  static const json kNull;
  if (!object.is_object()) return kNull;
  const auto it = object.find(key);
  return it == object.end() ? kNull : *it;
}

inline const json& element(const json& array, std::size_t index) {
  static const json kNull;
  return array.is_array() && index < array.size() ? array[index] : kNull;
}

inline double number_or(const json& value, double fallback) {
  return value.is_number() && std::isfinite(value.get<double>()) ? value.get<double>() : fallback;
}

// A non-negative integer that fits an int, or `fallback`.
inline int index_or(const json& value, int fallback) {
  if (!value.is_number_integer() && !value.is_number_unsigned()) return fallback;
  const auto v = value.get<std::int64_t>();
  return v >= 0 && v <= INT32_MAX ? static_cast<int>(v) : fallback;
}

// A non-negative integer, or nullopt.
inline std::optional<std::uint64_t> unsigned_of(const json& value) {
  if (value.is_number_unsigned()) return value.get<std::uint64_t>();
  if (value.is_number_integer() && value.get<std::int64_t>() >= 0) return value.get<std::uint64_t>();
  return std::nullopt;
}

}  // namespace toond::scene::gltf_json
