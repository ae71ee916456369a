#pragma once
// Where the objects of a scene pass through each other. Import finds the
// seams within a model (scene/mesh/intersection_lines.h); objects placed so
// that their boxes overlap may cross too, where no import looked. Those
// seams are found for the frame, by the same search, on the triangles of
// each pair of overlapping objects that reach into the other's box, in view
// space; each pair's triangles are the two parts the search tells apart.
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "render/vector/view_mesh.h"

namespace toond::render::vector {

// The segments (view space) where objects of `mesh` cross that turn by
// more than `crease_angle_deg` (between the two faces' planes); none where
// a pair's search gives up (too many crossings to look through).
std::vector<std::pair<glm::dvec3, glm::dvec3>> scene_seams(const ViewMesh& mesh, double crease_angle_deg);

}  // namespace toond::render::vector
