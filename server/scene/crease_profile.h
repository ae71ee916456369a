#pragma once
// Hard-edged models (a machined part, a crate, a chair) read by their
// creases, and a silhouette outline alone leaves them out; an organic scan
// has a few sharp folds that crease lines would only litter. Import
// measures how much of a mesh's edge length is creased at each angle, so a
// render can decide, for the crease angle it was asked for, whether the
// model is hard-edged.
#include <array>
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

namespace toond::scene {

// fraction_over[d]: the share of the mesh's total edge length (edges
// between two triangles, split copies of a position counting as one edge)
// where the shading normals on the two sides turn by more than d degrees.
// A crease is what the screen-space edge pass sees: the normals it compares
// are the shading normals, so a smoothed edge is no crease.
struct CreaseProfile {
  std::array<float, 181> fraction_over{};
  double at(double degrees) const;
  // Hard-edged at this crease angle: kHardEdgedShare of the edge length or
  // more is creased. A scan's stray folds stay far below it, a box's or a
  // machined part's edges far above.
  bool hard_edged(double degrees) const;
};
inline constexpr double kHardEdgedShare = 0.05;

// Positions must be welded (equal where the model means one point).
CreaseProfile measure_creases(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                              std::span<const std::uint32_t> indices);

}  // namespace toond::scene
