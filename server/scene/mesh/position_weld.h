#pragma once
// Exporters compute vertices with sin and cos, so points that are one point
// in the model (a sphere's pole, both sides of a UV seam) arrive a rounding
// error apart. Everything that derives topology from positions (shared hull
// normals, smoothing, hole caps, the level-of-detail simplifier, culling)
// compares positions for equality, and would split such a point. Welding
// moves every near-duplicate onto one representative, so equality holds
// where the model means it; shading attributes (normals, texture
// coordinates, materials) stay split.
#include <cstddef>
#include <span>

#include <glm/glm.hpp>

namespace toond::scene {

// Positions closer than this fraction of the bounding box's diagonal are
// one point. Far below anything an image shows (a 512 px frame of the model
// puts it at 5e-4 px), far above double rounding.
inline constexpr double kWeldRelativeTolerance = 1e-6;

struct WeldReport {
  double tolerance = 0;   // absolute, in the mesh's units
  std::size_t moved = 0;  // positions moved onto another one
};

// Moves each position that lies within the tolerance of a kept position
// onto the nearest such one; a position with none near is kept. Positions
// are taken in order, so the result does not depend on hashing. Distances
// in double; a spatial hash with cells of the tolerance's size keeps it
// linear in the number of positions.
WeldReport weld_positions(std::span<glm::vec3> positions);

}  // namespace toond::scene
