#include "scene/crease_profile.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "scene/mesh_processing.h"

namespace toond::scene {
namespace {

// The first triangle side seen on an edge, waiting for its neighbour.
struct OpenSide {
  glm::vec3 normal_at_low;   // shading normal at the edge's lower position group
  glm::vec3 normal_at_high;  // and at its higher one
  bool matched = false;
};

double angle_deg(const glm::vec3& a, const glm::vec3& b) {
  const double c = std::clamp(static_cast<double>(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0);
  return std::acos(c) * 180.0 / std::acos(-1.0);
}

}  // namespace

double CreaseProfile::at(double degrees) const {
  const auto d = static_cast<std::size_t>(std::clamp(std::floor(degrees), 0.0, 180.0));
  return fraction_over[d];
}

bool CreaseProfile::hard_edged(double degrees) const { return at(degrees) >= kHardEdgedShare; }

CreaseProfile measure_creases(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                              std::span<const std::uint32_t> indices) {
  CreaseProfile profile;
  const std::vector<std::uint32_t> group = group_by_position(positions);
  std::unordered_map<std::uint64_t, OpenSide> sides;
  sides.reserve(indices.size());
  std::array<double, 181> length_over{};
  double total_length = 0.0;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    for (std::size_t k = 0; k < 3; ++k) {
      std::uint32_t a = indices[t + k], b = indices[t + (k + 1) % 3];
      if (group[a] == group[b]) continue;
      if (group[a] > group[b]) std::swap(a, b);
      const std::uint64_t key = static_cast<std::uint64_t>(group[a]) << 32 | group[b];
      const auto [it, first] = sides.try_emplace(key, OpenSide{normals[a], normals[b]});
      // An edge counts once, with the first two sides met; further sides of
      // a non-manifold edge add nothing.
      if (first || it->second.matched) continue;
      it->second.matched = true;
      const double turn = std::max(angle_deg(it->second.normal_at_low, normals[a]),
                                   angle_deg(it->second.normal_at_high, normals[b]));
      const double length = glm::length(glm::dvec3(positions[a]) - glm::dvec3(positions[b]));
      total_length += length;
      // Counted at the largest whole degree it exceeds; summed down below.
      if (turn > 0.0) length_over[static_cast<std::size_t>(std::min(std::ceil(turn) - 1.0, 180.0))] += length;
    }
  }
  if (total_length > 0.0) {
    double over = 0.0;
    for (std::size_t d = length_over.size(); d-- > 0;) {
      over += length_over[d];
      profile.fraction_over[d] = static_cast<float>(over / total_length);
    }
  }
  return profile;
}

}  // namespace toond::scene
