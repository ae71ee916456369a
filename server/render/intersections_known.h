#pragma once
// Whether the segments where parts cross, found at import
// (scene/intersection_lines.h), are every intersection line a frame can
// show. They are not where parts can meet in ways import did not see:
// - a posed model whose parts cross at rest (the segments hold the rest
//   pose; the pose moves the parts, and with them where they cross),
// - a model of several parts whose search gave up
//   (IntersectionLines::complete),
// - two objects of a scene whose boxes overlap (import sees one model at a
//   time).
// Where they are not, the pass plan has the edge pass find crease and
// intersection lines in screen space for the whole frame, as it did before
// the crease pass (render/pass_plan.cpp). Pure arithmetic, no GL.
#include <span>

#include "render/frame_plan.h"

namespace toond::render {

bool intersections_known(std::span<const PlannedObject> objects);

// Whether a mesh's search for where its parts cross saw every level
// through (trivially so for a mesh of one part).
bool searched_through(const scene::Mesh& mesh);

// Whether any level of a mesh has a segment where its parts cross, at any
// angle.
bool parts_cross(const scene::Mesh& mesh);

}  // namespace toond::render
