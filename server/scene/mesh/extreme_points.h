#pragma once
// Framing fits the camera to what the model covers in the image, not to a
// sphere around its box (which leaves a sphere filling half the frame). The
// outline of a projection is made of points extreme in some direction, so a
// render projects these few instead of every vertex.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace toond::scene {

// How many directions, spread evenly over the sphere, are searched. Any
// other direction is within about 8.5° of one of them, so a projected
// extent is missed by at most 1 − cos 8.5° ≈ 1 % of the model's radius.
inline constexpr int kExtremeDirections = 256;

// The distinct vertices that lie farthest along each direction: at most
// kExtremeDirections of them, in no particular order. Linear in the number
// of positions.
std::vector<glm::vec3> extreme_points(std::span<const glm::vec3> positions);
// The same, searching only the first vertex at each point: `position_group`
// is group_by_position(positions) (scene/mesh/mesh_processing.h), which an
// import has at hand. A copy of a point (split for shading or a seam) is
// never farther than the point itself.
std::vector<glm::vec3> extreme_points(std::span<const glm::vec3> positions,
                                      std::span<const std::uint32_t> position_group);

}  // namespace toond::scene
