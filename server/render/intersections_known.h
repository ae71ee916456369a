#pragma once
// Whether the segments where parts cross, found at import
// (scene/intersection_lines.h), are every intersection line a frame can
// show. They are not where parts can meet in ways import did not see:
// - a posed model of several parts (its parts move apart from one
//   another; the segments hold the rest pose, and the crease pass draws
//   none while posed),
// - a model whose search gave up (IntersectionLines::complete),
// - two objects of a scene whose boxes overlap (import sees one model at a
//   time).
// Where they are not, the pass plan has the edge pass find crease and
// intersection lines in screen space, as it did before the crease pass
// (render/pass_plan.cpp).
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "scene/model.h"

namespace toond::render {

struct JobObject;

// One object of a frame, as far as this rule asks.
struct ObjectParts {
  std::uint32_t parts = 1;       // scene::Mesh::parts
  bool searched_through = true;  // IntersectionLines::complete, every level
  bool posed = false;
  scene::Bounds bounds;          // relative to `origin`; posed: the pose's
  glm::dvec3 origin{0.0};        // scene::Mesh::origin
  glm::dmat4 transform{1.0};     // model to scene coordinates
};

bool intersections_known(std::span<const ObjectParts> objects);
// The same for a job's objects, as the price sees them before the render.
bool intersections_known(std::span<const JobObject> objects);

}  // namespace toond::render
