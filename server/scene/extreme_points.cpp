#include "scene/extreme_points.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace toond::scene {
namespace {

// Points of a golden-angle spiral: nearly even spacing for any count.
std::array<glm::dvec3, kExtremeDirections> sphere_spiral_directions() {
  std::array<glm::dvec3, kExtremeDirections> dirs{};
  const double golden_angle = std::acos(-1.0) * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < kExtremeDirections; ++i) {
    const double y = 1.0 - (i + 0.5) * 2.0 / kExtremeDirections;
    const double r = std::sqrt(1.0 - y * y);
    const double a = golden_angle * i;
    dirs[static_cast<std::size_t>(i)] = {r * std::cos(a), y, r * std::sin(a)};
  }
  return dirs;
}

}  // namespace

std::vector<glm::vec3> extreme_points(std::span<const glm::vec3> positions) {
  if (positions.empty()) return {};
  static const std::array<glm::dvec3, kExtremeDirections> dirs = sphere_spiral_directions();
  std::array<double, kExtremeDirections> best;
  best.fill(-std::numeric_limits<double>::infinity());
  std::array<std::size_t, kExtremeDirections> best_index{};
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const glm::dvec3 p(positions[v]);
    for (std::size_t d = 0; d < dirs.size(); ++d) {
      const double reach = glm::dot(p, dirs[d]);
      if (reach > best[d]) {
        best[d] = reach;
        best_index[d] = v;
      }
    }
  }
  std::sort(best_index.begin(), best_index.end());
  std::vector<glm::vec3> points;
  for (std::size_t i = 0; i < best_index.size(); ++i) {
    if (i == 0 || best_index[i] != best_index[i - 1]) points.push_back(positions[best_index[i]]);
  }
  return points;
}

}  // namespace toond::scene
