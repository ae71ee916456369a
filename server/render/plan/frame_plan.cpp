#include "render/plan/frame_plan.h"

#include <vector>

#include "render/plan/drawn_materials.h"
#include "render/plan/intersections_known.h"
#include "render/plan/light_space.h"
#include "render/plan/outline_width.h"

namespace toond::render {
namespace {

// What the pass plan needs to know about the objects' models.
ModelTraits traits_of(const RenderParams& params, std::span<const PlannedObject> objects,
                      const std::vector<std::vector<DrawnMaterial>>& materials) {
  ModelTraits traits;
  bool any_specular = false;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const PlannedObject& o = objects[i];
    const scene::Model& model = o.model;
    traits.has_textures |= !model.textures.empty();
    traits.has_vertex_colors |= !model.mesh.colors.empty();
    traits.hard_edged |= model.mesh.creases.hard_edged(params.outline.crease_angle_deg);
    traits.has_crease_edges |= model.mesh.crease_edges.creased_at(params.outline.crease_angle_deg) > 0;
    const scene::IntersectionLines& seams =
        o.pose && model.rig && !o.pose->intersections.empty() ? o.pose->intersections[0] : model.mesh.intersections;
    traits.has_intersection_lines |= seams.creased_at(params.outline.crease_angle_deg) > 0;
    for (const scene::Material& m : model.materials) traits.has_normal_maps |= m.normal_texture >= 0;
    for (const DrawnMaterial& m : materials[i]) {
      traits.has_textures |= m.has_texture();
      traits.has_masked_materials |= m.cuts || m.blended;
      any_specular |= m.specular;
    }
  }
  traits.intersections_unknown = !intersections_known(objects);
  traits.has_specular_materials = any_specular;
  return traits;
}

// The frame's price, from what the plan decided: its passes, the width its
// lines are drawn at and the way its shadow's light travels.
RenderCost cost_of(const FramePlan& plan, std::span<const PlannedObject> objects) {
  std::vector<const scene::Mesh*> meshes;
  for (const PlannedObject& o : objects) meshes.push_back(&o.model.mesh);
  const PricedFrame priced{
      .params = plan.params,
      .passes = plan.passes,
      .line_px = plan.outline_px,
      .shadow_direction =
          plan.shadow ? plan.lights[static_cast<std::size_t>(plan.passes.shadow_light)].direction : glm::dvec3(0.0)};
  // A scene's objects are turned by their transforms: priced from their
  // densest direction, not the camera's.
  const ViewKnown view = plan.params.objects.empty() ? ViewKnown::Camera : ViewKnown::Any;
  return predict_frame_cost(priced, meshes, view);
}

// The camera and what follows from it: where it looks from, the clip
// matrix and the outline's width in drawn pixels.
void place_camera(FramePlan& plan) {
  const RenderParams& p = plan.params;
  const bool orthographic = p.camera.projection == Projection::Orthographic;
  plan.camera = fit_camera(p.camera, plan.scene->bounds, static_cast<double>(p.width) / p.height, plan.scene->outline);
  plan.clip = plan.camera.projection * plan.camera.view;
  plan.viewer = Viewer{plan.camera.eye, glm::normalize(plan.camera.target - plan.camera.eye), orthographic};
  plan.outline_px = static_cast<float>(outline_width_px(p.outline, plan.camera, orthographic, p.height)) *
                    static_cast<float>(plan.passes.supersample);
}

// View-space lights turn with the camera about the point it orbits; the
// shadow's map is fitted to the scene along its light.
void place_lights(FramePlan& plan) {
  const SceneFrame& scene = *plan.scene;
  plan.lights =
      lights_in_scene(plan.params.lights, plan.params.camera, scene.origin + glm::dvec3(scene.bounds.centre()));
  if (!plan.passes.has(Pass::Shadow)) return;
  const Light& caster = plan.lights[static_cast<std::size_t>(plan.passes.shadow_light)];
  plan.shadow = fit_shadow(caster.direction, scene.bounds, plan.params.shadows.map_size);
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

// Every frame's passes are planned here, and only here; so are its camera
// and its lights.
FramePlan plan_frame(RenderParams params, std::span<const PlannedObject> objects,
                     std::shared_ptr<const SceneFrame> scene) {
  FramePlan plan{.params = std::move(params), .scene = std::move(scene)};
  std::vector<std::vector<DrawnMaterial>> materials;
  for (const PlannedObject& o : objects) materials.push_back(drawn_materials(o.model, plan.params));
  plan.passes = plan_passes(plan.params, traits_of(plan.params, objects, materials));
  place_camera(plan);
  place_lights(plan);
  plan.objects = plan_objects(plan, objects, std::move(materials));
  plan.cost = cost_of(plan, objects);
  return plan;
}

FramePlan plan_frame(RenderParams params, std::span<const PlannedObject> objects) {
  return plan_frame(std::move(params), objects, frame_scene_of(objects));
}

}  // namespace toond::render
