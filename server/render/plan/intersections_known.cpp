#include "render/plan/intersections_known.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace toond::render {
namespace {

struct SceneBox {
  glm::dvec3 min{std::numeric_limits<double>::max()};
  glm::dvec3 max{std::numeric_limits<double>::lowest()};
};

// The box round an object's bounds (its pose's when posed) in scene
// coordinates.
SceneBox scene_box(const PlannedObject& o) {
  const scene::Mesh& mesh = o.model.mesh;
  const scene::Bounds& bounds = o.pose ? o.pose->bounds : mesh.bounds;
  SceneBox box;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 p = glm::dvec3(o.transform * glm::dvec4(mesh.origin + bounds.corner(i), 1.0));
    box.min = glm::min(box.min, p);
    box.max = glm::max(box.max, p);
  }
  return box;
}

bool overlap(const SceneBox& a, const SceneBox& b) {
  return glm::all(glm::lessThanEqual(a.min, b.max)) && glm::all(glm::lessThanEqual(b.min, a.max));
}

bool known_alone(const PlannedObject& o) {
  const scene::Mesh& mesh = o.model.mesh;
  if (mesh.parts < 2) return true;
  if (o.pose == nullptr || o.model.rig == nullptr) return searched_through(mesh);
  const std::vector<scene::IntersectionLines>& posed = o.pose->intersections;
  return !posed.empty() && std::all_of(posed.begin(), posed.end(), [](const auto& l) { return l.complete; });
}

}  // namespace

bool searched_through(const scene::Mesh& mesh) {
  bool through = mesh.intersections.complete;
  for (const scene::MeshLod& lod : mesh.lods) through = through && lod.intersections.complete;
  return through;
}

bool intersections_known(std::span<const PlannedObject> objects) {
  for (const PlannedObject& o : objects) {
    if (!known_alone(o)) return false;
  }
  std::vector<SceneBox> boxes;
  for (const PlannedObject& o : objects) boxes.push_back(scene_box(o));
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      if (overlap(boxes[i], boxes[j])) return false;
    }
  }
  return true;
}

}  // namespace toond::render
