#include "pipeline/atlas.h"

#include "render/camera.h"
#include "render/sheet_atlas.h"

namespace toond::pipeline {
namespace {

// The models as the framing sees them, the same as the render thread does.
render::SceneFrame scene_of(const Request& request, const ObjectPoses& poses) {
  std::vector<render::ScenePart> parts;
  for (std::size_t i = 0; i < request.objects.size(); ++i) {
    const render::JobObject& o = request.objects[i];
    const scene::Mesh& mesh = o.model->mesh;
    // A posed object is framed as its pose says (a whole clip's reach).
    if (const scene::SkinPose* pose = poses[i].get()) {
      parts.push_back({pose->bounds, mesh.origin, o.transform, pose->extremes});
    } else {
      parts.push_back({mesh.bounds, mesh.origin, o.transform, mesh.extremes});
    }
  }
  return render::frame_scene(parts);
}

}  // namespace

nlohmann::json atlas_of(const Request& request, const ObjectPoses& poses) {
  const render::RenderParams& params = request.params;
  return render::sheet_atlas(*request.layout, params, scene_of(request, poses),
                             params.sheet->animate ? "sheet.webp" : "sheet.png");
}

}  // namespace toond::pipeline
