#include "scene/mesh/duplicate_triangles.h"

#include <array>
#include <cstdint>
#include <cstring>

#include "scene/mesh/flat_map.h"

namespace toond::scene {
namespace {

// One coordinate's bits, with -0 read as +0 so the two zeros are one point.
std::uint64_t coordinate_bits(double v) {
  if (v == 0.0) v = 0.0;
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  return bits;
}

using PointKey = std::array<std::uint64_t, 3>;
using TriangleKey = std::array<std::uint64_t, 9>;

PointKey point_key(const glm::dvec3& p) { return {coordinate_bits(p.x), coordinate_bits(p.y), coordinate_bits(p.z)}; }

// The rotation that starts at the smallest corner names every rotation of
// the triangle alike; the reversed triangle gets another key.
TriangleKey triangle_key(const TriangleCorners& t) {
  const PointKey p[3] = {point_key(t.corner[0]), point_key(t.corner[1]), point_key(t.corner[2])};
  int first = 0;
  for (int i = 1; i < 3; ++i) {
    if (p[i] < p[first]) first = i;
  }
  TriangleKey key{};
  for (int i = 0; i < 3; ++i) {
    const PointKey& q = p[(first + i) % 3];
    for (int k = 0; k < 3; ++k) key[static_cast<std::size_t>(i * 3 + k)] = q[static_cast<std::size_t>(k)];
  }
  return key;
}

struct TriangleKeyHash {
  std::size_t operator()(const TriangleKey& key) const noexcept {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (std::uint64_t word : key) {
      h ^= word + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    }
    return static_cast<std::size_t>(h);
  }
};

}  // namespace

std::vector<bool> last_of_each_triangle(std::span<const TriangleCorners> triangles) {
  std::vector<bool> keep(triangles.size(), true);
  FlatMap<TriangleKey, std::size_t, TriangleKeyHash> last_seen(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    auto [last, inserted] = last_seen.try_emplace(triangle_key(triangles[t]), t);
    if (!inserted) {
      keep[last] = false;
      last = t;
    }
  }
  return keep;
}

}  // namespace toond::scene
