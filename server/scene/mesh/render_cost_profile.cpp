#include "scene/mesh/render_cost_profile.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace toond::scene {
namespace {

constexpr int kSide = RenderCostProfile::kBinsPerSide;

// The bin of an area vector, and the vector turned into its bin's half
// space (the largest component positive) so that a bin's vectors add up.
int bin_of(glm::dvec3& area) {
  const glm::dvec3 a = glm::abs(area);
  const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  if (area[axis] < 0) area = -area;
  const double major = area[axis];
  if (!(major > 0)) return 0;
  const double u = area[(axis + 1) % 3] / major;  // -1..1 across the face
  const double v = area[(axis + 2) % 3] / major;
  const auto cell = [](double t) { return std::clamp(static_cast<int>((t + 1.0) * 0.5 * kSide), 0, kSide - 1); };
  return (axis * kSide + cell(u)) * kSide + cell(v);
}

// Area of the box's shadow along unit direction v.
double box_projected_area(const glm::dvec3& extent, const glm::dvec3& v) {
  return std::abs(v.x) * extent.y * extent.z + std::abs(v.y) * extent.x * extent.z +
         std::abs(v.z) * extent.x * extent.y;
}

// Evenly spread directions on the half sphere z ≥ 0 (a Fibonacci spiral),
// with the axes among them: a flat model lying in a coordinate plane is
// seen face on from one of them, where its layers are densest.
std::array<glm::dvec3, 48> half_sphere_spiral_directions() {
  std::array<glm::dvec3, 48> dirs{};
  const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    const double z = (static_cast<double>(i) + 0.5) / static_cast<double>(dirs.size());
    const double r = std::sqrt(1.0 - z * z);
    const double a = golden_angle * static_cast<double>(i);
    dirs[i] = {r * std::cos(a), r * std::sin(a), z};
  }
  dirs[0] = {0, 0, 1};
  dirs[1] = {1, 0, 0};
  dirs[2] = {0, 1, 0};
  return dirs;
}

}  // namespace

RenderCostProfile::RenderCostProfile(const std::array<glm::dvec3, kBins>& area_bins, const glm::dvec3& extent,
                                     double edge_span)
    : extent_(extent), edge_span_(edge_span) {
  for (std::size_t i = 0; i < area_bins_.size(); ++i) area_bins_[i] = glm::vec3(area_bins[i]);
  static const std::array<glm::dvec3, 48> dirs = half_sphere_spiral_directions();
  for (const glm::dvec3& d : dirs) max_layers_ = std::max(max_layers_, layers_toward(d));
}

double RenderCostProfile::layers_toward(const glm::dvec3& view) const {
  const double length = glm::length(view);
  if (!(length > 0)) return max_layers_;
  const glm::dvec3 v = view / length;
  double projected = 0;
  for (const glm::vec3& bin : area_bins_) projected += std::abs(glm::dot(glm::dvec3(bin), v));
  // A flat or thin model's box has (nearly) no area along some directions;
  // it is read as at least a thousandth of the box's largest face, so that
  // rounding cannot blow the ratio up.
  const double largest_face = std::max({extent_.x * extent_.y, extent_.y * extent_.z, extent_.x * extent_.z});
  const double box = std::max(box_projected_area(extent_, v), largest_face * 1e-3);
  return box > 0 ? projected / box : 0;
}

RenderCostProfile measure_render_cost(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                                      const glm::vec3& extent) {
  std::array<glm::dvec3, RenderCostProfile::kBins> bins{};
  double longest_edges = 0;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const glm::dvec3 a(positions[indices[t]]);
    const glm::dvec3 b(positions[indices[t + 1]]);
    const glm::dvec3 c(positions[indices[t + 2]]);
    glm::dvec3 area = glm::cross(b - a, c - a) * 0.5;
    const int bin = bin_of(area);
    bins[static_cast<std::size_t>(bin)] += area;
    longest_edges += std::sqrt(std::max({glm::dot(b - a, b - a), glm::dot(c - b, c - b), glm::dot(a - c, a - c)}));
  }
  const double diagonal = glm::length(glm::dvec3(extent));
  return RenderCostProfile(bins, glm::dvec3(extent), diagonal > 0 ? longest_edges / diagonal : 0);
}

}  // namespace toond::scene
