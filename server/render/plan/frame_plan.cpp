#include "render/plan/frame_plan.h"

#include <vector>

#include "render/plan/drawn_materials.h"
#include "render/plan/intersections_known.h"
#include "render/plan/outline_width.h"

namespace toond::render {
namespace {

// What the pass plan needs to know about the objects' models.
ModelTraits traits_of(const RenderParams& params, std::span<const PlannedObject> objects) {
  ModelTraits traits;
  bool any_specular = false;
  for (const PlannedObject& o : objects) {
    const scene::Model& model = o.model;
    traits.has_textures |= !model.textures.empty();
    traits.has_vertex_colors |= !model.mesh.colors.empty();
    traits.hard_edged |= model.mesh.creases.hard_edged(params.outline.crease_angle_deg);
    traits.has_crease_edges |= model.mesh.crease_edges.creased_at(params.outline.crease_angle_deg) > 0;
    const scene::IntersectionLines& seams =
        o.pose && model.rig && !o.pose->intersections.empty() ? o.pose->intersections[0] : model.mesh.intersections;
    traits.has_intersection_lines |= seams.creased_at(params.outline.crease_angle_deg) > 0;
    for (const scene::Material& m : model.materials) traits.has_normal_maps |= m.normal_texture >= 0;
    for (const DrawnMaterial& m : drawn_materials(model, params)) {
      traits.has_textures |= m.has_texture();
      traits.has_masked_materials |= m.cuts || m.blended;
      any_specular |= m.specular;
    }
  }
  traits.intersections_unknown = !intersections_known(objects);
  traits.has_specular_materials = any_specular;
  return traits;
}

// Every frame's passes are planned here, and only here.
PassPlan passes_of(const RenderParams& params, std::span<const PlannedObject> objects) {
  return plan_passes(params, traits_of(params, objects));
}

RenderCost cost_of(const RenderParams& params, const PassPlan& passes, std::span<const PlannedObject> objects) {
  std::vector<const scene::Mesh*> meshes;
  for (const PlannedObject& o : objects) meshes.push_back(&o.model.mesh);
  // A scene's objects are turned by their transforms: priced from their
  // densest direction, not the camera's.
  const ViewKnown view = params.objects.empty() ? ViewKnown::Camera : ViewKnown::Any;
  return predict_frame_cost(params, passes, meshes, view);
}

}  // namespace

std::shared_ptr<const SceneFrame> frame_scene_of(std::span<const PlannedObject> objects) {
  std::vector<ScenePart> parts;
  for (const PlannedObject& o : objects) {
    const scene::Mesh& mesh = o.model.mesh;
    if (o.pose) {
      parts.push_back({o.pose->bounds, mesh.origin, o.transform, o.pose->extremes});
    } else {
      parts.push_back({mesh.bounds, mesh.origin, o.transform, mesh.extremes});
    }
  }
  return std::make_shared<const SceneFrame>(frame_scene(parts));
}

FramePlan plan_frame(RenderParams params, std::span<const PlannedObject> objects,
                     std::shared_ptr<const SceneFrame> scene) {
  FramePlan plan{.params = std::move(params), .scene = std::move(scene)};
  const RenderParams& p = plan.params;
  plan.passes = passes_of(p, objects);
  plan.camera = fit_camera(p.camera, plan.scene->bounds, static_cast<double>(p.width) / p.height, plan.scene->outline);
  const bool orthographic = p.camera.projection == Projection::Orthographic;
  plan.outline_px = static_cast<float>(outline_width_px(p.outline, plan.camera, orthographic, p.height)) *
                    static_cast<float>(plan.passes.supersample);
  plan.cost = cost_of(p, plan.passes, objects);
  return plan;
}

FramePlan plan_frame(RenderParams params, std::span<const PlannedObject> objects) {
  return plan_frame(std::move(params), objects, frame_scene_of(objects));
}

RenderCost predict_cost(const RenderParams& params, std::span<const PlannedObject> objects) {
  return cost_of(params, passes_of(params, objects), objects);
}

}  // namespace toond::render
