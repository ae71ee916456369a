#include "scene/mesh/duplicate_triangles.h"

#include <array>
#include <cstdint>
#include <cstring>

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

std::uint64_t hash_of(const TriangleKey& key) {
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (std::uint64_t word : key) {
    h ^= word + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
  }
  return h * 0x9E3779B97F4A7C15ull;  // Fibonacci hashing: the slot is taken from the top bits
}

}  // namespace

std::vector<bool> last_of_each_triangle(std::span<const TriangleCorners> triangles) {
  std::vector<bool> keep(triangles.size(), true);
  // Open addressing over triangle numbers, each slot the last triangle seen
  // with some key and that key's hash. A key (nine words) is made again from
  // the corners only where the hashes match, so the table is a tenth of what
  // it would be with the keys in it, and stays in cache.
  constexpr std::uint32_t kEmpty = ~0u;
  struct Slot {
    std::uint32_t hash = 0;  // the top bits of the key's
    std::uint32_t last = kEmpty;
  };
  int bits = 4;
  while ((std::size_t{1} << bits) < 2 * triangles.size()) ++bits;
  std::vector<Slot> slots(std::size_t{1} << bits);
  const std::size_t mask = slots.size() - 1;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const TriangleKey key = triangle_key(triangles[t]);
    const std::uint64_t h = hash_of(key);
    const auto tag = static_cast<std::uint32_t>(h >> 32);
    std::size_t i = static_cast<std::size_t>(h >> (64 - bits));
    while (slots[i].last != kEmpty && !(slots[i].hash == tag && triangle_key(triangles[slots[i].last]) == key)) {
      i = (i + 1) & mask;
    }
    if (slots[i].last != kEmpty) keep[slots[i].last] = false;
    slots[i] = {tag, static_cast<std::uint32_t>(t)};
  }
  return keep;
}

}  // namespace toond::scene
