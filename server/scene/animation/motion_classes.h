#pragma once
// Which vertices of a rigged model move alike in every pose. A level of
// detail is simplified at rest (scene/mesh/mesh_lod.h): merging two vertices that
// a pose moves apart (a ring at an elbow into the rings beside it) gives a
// level that looks right at rest and wrong once bent. Vertices of one class
// are moved by one and the same matrix in every pose, so a surface made of
// them alone, simplified at rest, is posed by that matrix as a whole, and
// its distance from the full surface grows at most with the matrix's
// scale.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh/model.h"
#include "scene/mesh/rig.h"

namespace toond::scene {

// Per vertex of `mesh` (whose Mesh::motion indexes rig.motions), a class
// id: equal ids move alike. Vertices with the same binding and the same
// joints at the same weights share a class; a vertex that a morph target
// moves has a class of its own (with the other copies of its position).
std::vector<std::uint32_t> motion_classes(const Mesh& mesh, const Rig& rig);

// How much a pose may lengthen any distance on the mesh: the largest
// spectral norm of the joint matrices' linear parts. A vertex's matrix is a
// weighted mean of its joints', so no class's matrix stretches more.
double largest_joint_stretch(const std::vector<glm::mat4>& joint_matrices);

}  // namespace toond::scene
