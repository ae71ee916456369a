#pragma once
// One object as a frame's plan sees it: the model as imported (its levels
// of detail, closed or open, their hole caps), placed by its transform
// (model → scene coordinates), in its pose when posed. Pure arithmetic, no
// GL: the plan is made before the frame is queued.
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "scene/animation/pose.h"
#include "scene/mesh/model.h"

namespace toond::render {

struct PlannedObject {
  const scene::Model& model;
  glm::dmat4 transform{1.0};
  const scene::SkinPose* pose = nullptr;  // null: as imported

  // The pose's when posed (which may be a whole clip's reach).
  const scene::Bounds& bounds() const;
  // How much the pose may lengthen a level's error (SkinPose::stretch); 1 as imported.
  double pose_stretch() const { return pose ? pose->stretch : 1.0; }
  // Level 0 is the full mesh; the rest come from scene::Mesh::lods.
  std::size_t lod_count() const { return 1 + model.mesh.lods.size(); }
  // Per level, in the mesh's units: how far its surface may stray (0 at level 0).
  std::vector<double> lod_errors() const;
  std::size_t triangles(std::size_t lod) const;
  // Whether a level's triangles close around a volume (scene/mesh/enclosure.h);
  // a pose keeps the topology.
  scene::Enclosure enclosure(std::size_t lod) const;
  // Triangles closing the level's holes; posed, they moved with the pose.
  const std::vector<glm::vec3>& caps(std::size_t lod) const;
};

}  // namespace toond::render
