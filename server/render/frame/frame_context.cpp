#include "render/frame/frame_context.h"

namespace toond::render {
namespace {

// `placed` are in scene coordinates (FramePlan::lights); the render works
// relative to the frame's origin, so point lights move with it.
ShadingLights lights_of(const std::vector<Light>& placed, const glm::dvec3& origin) {
  ShadingLights lights;
  for (const Light& l : placed) {
    if (l.kind == LightKind::Point) {
      lights.vec.push_back(glm::vec3(l.position - origin));
    } else {
      const double len = glm::length(l.direction);
      if (!(len > 0.0)) continue;
      lights.vec.push_back(glm::vec3(-l.direction / len));
    }
    lights.color.push_back(l.color);
    lights.is_point.push_back(l.kind == LightKind::Point ? 1 : 0);
    lights.radius.push_back(static_cast<float>(l.radius));
  }
  return lights;
}

// Each object's level, materials and the faces each pass skips, as the
// plan decided them; no face skipped at all where the frame draws both
// sides of every face.
void take_object_plans(FrameContext& frame, const std::vector<ObjectPlan>& objects, bool face_culling) {
  for (const ObjectPlan& o : objects) {
    frame.lods.push_back(o.lod);
    frame.materials.push_back(o.materials);
    frame.view_depths.push_back(o.view_depth);
    frame.unseen_faces.push_back(o.main);
    frame.main_faces.push_back(face_culling ? o.main : FaceSkip{});
    frame.hull_faces.push_back(face_culling ? o.hull : FaceSkip{});
    frame.shadow_faces.push_back(face_culling ? o.shadow : HiddenFaces::None);
    frame.lods.back().culled = frame.main_faces.back().hidden;
  }
}

}  // namespace

bool FrameContext::has_cutouts(std::size_t i) const {
  for (const DrawnMaterial& m : materials[i]) {
    if (m.cuts || m.blended) return true;
  }
  return false;
}

FrameContext build_frame_context(std::vector<FrameObject> objects, const FramePlan& plan, bool face_culling) {
  const RenderParams& params = plan.params;
  FrameContext frame{.objects = std::move(objects),
                     .params = params,
                     .plan = plan.passes,
                     .scene = *plan.scene,
                     .camera = plan.camera,
                     .clip = plan.clip,
                     .viewer = plan.viewer,
                     .shadow = plan.shadow};
  for (const glm::dmat4& m : frame.scene.matrices) {
    // Composed in double, rounded to float only now. The inverse-transpose
    // keeps normals perpendicular to the surface under non-uniform scale.
    frame.model_matrices.emplace_back(m);
    frame.normal_matrices.emplace_back(glm::transpose(glm::inverse(glm::dmat3(m))));
  }
  frame.view_projection = glm::mat4(frame.clip);
  frame.supersample = frame.plan.supersample;
  frame.draw_width = plan.draw_width();
  frame.draw_height = plan.draw_height();
  frame.outline_px = plan.outline_px;
  take_object_plans(frame, plan.objects, face_culling);
  frame.lights = lights_of(plan.lights, frame.scene.origin);
  for (const RampStop& stop : params.ramp) {
    frame.ramp_at.push_back(stop.at);
    frame.ramp_color.push_back(stop.color);
  }
  return frame;
}

}  // namespace toond::render
