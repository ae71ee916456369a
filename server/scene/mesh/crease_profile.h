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
// lines_area_over[d]: the share of the mesh's surface in triangles beside
// a crease line: a connected run of such edges at least kCreaseLineLength
// of the mesh's bounding-box diagonal long. A CAD part's curved patches are
// tessellated densely, so its sharp edges are a small share of its edge
// length, but they join into long lines that the thin triangles of its
// patches run up to: that is what a viewer sees as hard-edged. A scan's
// creases are short scattered folds, however many.
struct CreaseProfile {
  std::array<float, 181> fraction_over{};
  std::array<float, 181> lines_area_over{};
  double at(double degrees) const;
  double lines_area(double degrees) const;
  // Hard-edged at this crease angle: kHardEdgedShare of the edge length or
  // more is creased (a box, a crate), or kHardEdgedShare of the surface
  // lies beside crease lines (a CAD part of curved patches meeting at sharp
  // edges: CGAL's fandisk 0.107). Shared scans stay below both (the
  // bunny's surface beside lines 0.003, the armadillo's 0.027).
  bool hard_edged(double degrees) const;
};
inline constexpr double kHardEdgedShare = 0.05;
inline constexpr double kCreaseLineLength = 0.25;

// Positions must be welded (equal where the model means one point).
CreaseProfile measure_creases(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                              std::span<const std::uint32_t> indices);
// The same for a caller that has group_by_position(positions) already.
CreaseProfile measure_creases(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                              std::span<const std::uint32_t> indices, std::span<const std::uint32_t> group);

}  // namespace toond::scene
