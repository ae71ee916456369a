#include "render/plan/planned_object.h"

namespace toond::render {

const scene::Bounds& PlannedObject::bounds() const { return pose ? pose->bounds : model.mesh.bounds; }

std::vector<double> PlannedObject::lod_errors() const {
  std::vector<double> errors{0.0};
  for (const scene::MeshLod& lod : model.mesh.lods) errors.push_back(lod.error);
  return errors;
}

std::size_t PlannedObject::triangles(std::size_t lod) const {
  return (lod == 0 ? model.mesh.indices.size() : model.mesh.lods[lod - 1].indices.size()) / 3;
}

scene::Enclosure PlannedObject::enclosure(std::size_t lod) const {
  return lod == 0 ? model.mesh.enclosure : model.mesh.lods[lod - 1].enclosure;
}

const std::vector<glm::vec3>& PlannedObject::caps(std::size_t lod) const {
  if (pose) return pose->caps[lod];
  return lod == 0 ? model.mesh.caps : model.mesh.lods[lod - 1].caps;
}

}  // namespace toond::render
