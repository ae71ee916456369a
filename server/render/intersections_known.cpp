#include "render/intersections_known.h"

#include <algorithm>
#include <vector>

#include "render/render_service.h"

namespace toond::render {
namespace {

struct SceneBox {
  glm::dvec3 min{0.0};
  glm::dvec3 max{0.0};
};

SceneBox scene_box(const ObjectParts& o) {
  SceneBox box{glm::dvec3(std::numeric_limits<double>::max()), glm::dvec3(std::numeric_limits<double>::lowest())};
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 p = glm::dvec3(o.transform * glm::dvec4(o.origin + o.bounds.corner(i), 1.0));
    box.min = glm::min(box.min, p);
    box.max = glm::max(box.max, p);
  }
  return box;
}

bool overlap(const SceneBox& a, const SceneBox& b) {
  return glm::all(glm::lessThanEqual(a.min, b.max)) && glm::all(glm::lessThanEqual(b.min, a.max));
}

}  // namespace

bool intersections_known(std::span<const ObjectParts> objects) {
  for (const ObjectParts& o : objects) {
    if (o.parts > 1 && (o.posed || !o.searched_through)) return false;
  }
  std::vector<SceneBox> boxes;
  for (const ObjectParts& o : objects) boxes.push_back(scene_box(o));
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      if (overlap(boxes[i], boxes[j])) return false;
    }
  }
  return true;
}

bool intersections_known(std::span<const JobObject> objects) {
  std::vector<ObjectParts> parts;
  for (const JobObject& o : objects) {
    const scene::Mesh& mesh = o.model->mesh;
    bool searched_through = mesh.intersections.complete;
    for (const scene::MeshLod& lod : mesh.lods) searched_through = searched_through && lod.intersections.complete;
    const bool posed = o.pose != nullptr && o.model->rig != nullptr;
    parts.push_back({mesh.parts, searched_through, posed, posed ? o.pose->bounds : mesh.bounds, mesh.origin,
                     o.transform});
  }
  return intersections_known(parts);
}

}  // namespace toond::render
