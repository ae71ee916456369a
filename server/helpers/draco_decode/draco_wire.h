#pragma once
// What toond-draco-decode answers on its standard output: a decoded Draco
// mesh in a plain little-endian layout. The daemon reads it trusting
// nothing, since the helper may have been fed a hostile file: every size
// must add up to the bytes given, and every index must name a point.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace toond::draco_wire {

// glTF's component types, which the wire uses for attribute values.
inline constexpr int kByte = 5120;
inline constexpr int kUnsignedByte = 5121;
inline constexpr int kShort = 5122;
inline constexpr int kUnsignedShort = 5123;
inline constexpr int kUnsignedInt = 5125;
inline constexpr int kFloat = 5126;

// Bytes per component of one of the types above, 0 for any other.
std::size_t component_size(int component_type);

struct Attribute {
  std::uint32_t unique_id = 0;  // the Draco attribute's id, as the glTF extension names it
  int component_type = kFloat;
  std::uint32_t components = 0;      // 1 to 4
  std::vector<std::uint8_t> values;  // per point, `components` values of `component_type`
};

struct Mesh {
  std::uint32_t points = 0;
  std::vector<std::uint32_t> indices;  // three per triangle, each below `points`
  std::vector<Attribute> attributes;
};

class WireError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

std::string write_mesh(const Mesh& mesh);

// The mesh in `bytes`; WireError saying what does not fit (magic,
// truncation, sizes, an index past the points, an unknown type).
Mesh read_mesh(std::string_view bytes);

}  // namespace toond::draco_wire
