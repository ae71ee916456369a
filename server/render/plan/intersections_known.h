#pragma once
// Whether the segments where parts cross, found at import
// (scene/mesh/intersection_lines.h) or for the pose (scene::SkinPose::
// intersections), are every intersection line a frame can show. They are
// not where parts can meet in ways no search saw:
// - a model of several parts whose search gave up
//   (IntersectionLines::complete), at rest or in its pose, or a pose
//   whose parts were not searched (one made without skin_pose),
// - two objects of a scene whose boxes overlap (import sees one model at a
//   time).
// Where they are not, the pass plan has the edge pass find crease and
// intersection lines in screen space for the whole frame, as it did before
// the crease pass (render/plan/pass_plan.cpp). Pure arithmetic, no GL.
#include <span>

#include "render/plan/frame_plan.h"

namespace toond::render {

bool intersections_known(std::span<const PlannedObject> objects);

// Whether a mesh's search for where its parts cross saw every level
// through (trivially so for a mesh of one part).
bool searched_through(const scene::Mesh& mesh);

}  // namespace toond::render
