#pragma once
// "data:" URIs, which glTF files use to carry buffers and images inline.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace toond::scene {

// Whether `uri` is a data URI (scheme "data:", ASCII case-insensitive).
bool is_data_uri(std::string_view uri);

// The bytes of a base64 data URI ("data:<type>[;...];base64,<payload>") and
// its media type. nullopt when `uri` is not one (no "base64" marker, a
// payload that is not base64): glTF writes no other kind.
struct DataUri {
  std::string media_type;
  std::vector<std::uint8_t> bytes;
};
std::optional<DataUri> decode_data_uri(std::string_view uri);

}  // namespace toond::scene
