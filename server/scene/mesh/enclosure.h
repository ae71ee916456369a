#pragma once
// Whether a mesh's triangles close around a volume, and which way they face.
// A closed surface seen from outside shows only the faces turned toward the
// camera: the others lie behind them, so a render may skip (cull) them and
// halve the triangles it sets up and rasterises (render/plan/face_culling.h).
#include <cstdint>
#include <span>
#include <vector>

#include "scene/mesh/model.h"

namespace toond::scene {

// See Enclosure in scene/mesh/model.h. `position_group` labels vertices at the
// same position with one id (see group_by_position in mesh_processing.h).
// With `caps`, holes are closed by the least-area triangulation of each
// rim, whose triangles land there (see Mesh::caps) and, with `cap_indices`,
// the same triangles as indices of `positions`; without `caps`, any hole
// makes it Open.
Enclosure classify_enclosure(std::span<const glm::vec3> positions, std::span<const std::uint32_t> position_group,
                             std::span<const std::uint32_t> indices, std::vector<glm::vec3>* caps = nullptr,
                             std::vector<std::uint32_t>* cap_indices = nullptr);

// Sets Mesh::enclosure, Mesh::caps and Mesh::cap_indices for the full mesh
// and every level of detail.
void classify_enclosures(Mesh& mesh);
// The same for a caller that has group_by_position(mesh.positions) already.
void classify_enclosures(Mesh& mesh, std::span<const std::uint32_t> position_group);

}  // namespace toond::scene
