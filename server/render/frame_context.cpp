#include "render/frame_context.h"

#include <algorithm>

#include "render/light_space.h"
#include "render/lod_choice.h"
#include "render/outline_width.h"

namespace toond::render {
namespace {

PassPlan plan_for(const std::vector<RenderObject>& objects, const RenderParams& params) {
  ModelTraits traits;
  for (const RenderObject& o : objects) {
    traits.has_textures |= o.model.has_textures();
    traits.has_normal_maps |= o.model.has_normal_maps();
    traits.has_vertex_colors |= o.model.has_vertex_colors();
    traits.hard_edged |= o.model.creases().hard_edged(params.outline.crease_angle_deg);
    traits.has_crease_edges |= o.model.creased_edges(0, params.outline.crease_angle_deg) > 0;
    traits.has_masked_materials |= o.model.has_masked_materials();
  }
  return plan_passes(params, traits);
}

SceneFrame scene_of(const std::vector<RenderObject>& objects) {
  std::vector<ScenePart> parts;
  for (const RenderObject& o : objects) {
    parts.push_back({o.model.bounds(), o.model.origin(), o.transform, o.model.extremes()});
  }
  return frame_scene(parts);
}

// Per object, the coarsest level whose error, at the object's nearest
// distance from the camera, stays within the pixel budget. Scale in the
// object's transform scales its error along, and so does a pose's stretch.
std::vector<LodUse> choose_levels(const FrameContext& frame) {
  const RenderParams& params = frame.params;
  std::vector<LodUse> uses;
  for (std::size_t i = 0; i < frame.objects.size(); ++i) {
    const GpuModel& model = frame.objects[i].model;
    const glm::dmat4& m = frame.scene.matrices[i];
    const double scale =
        std::max({glm::length(glm::dvec3(m[0])), glm::length(glm::dvec3(m[1])), glm::length(glm::dvec3(m[2]))});
    const glm::dvec3 centre = glm::dvec3(m * glm::dvec4(glm::dvec3(model.bounds().centre()), 1.0));
    const double px_per_unit = model.pose_stretch() * scale *
                               pixels_per_unit(frame.camera, frame.orthographic(), centre,
                                               model.bounds().radius() * scale, params.height);
    LodUse use;
    use.levels = model.lod_count();
    if (params.lod_auto) use.level = choose_lod(model.lod_errors(), px_per_unit, params.lod_error_px);
    use.triangles = model.triangles(use.level);
    use.error_px = model.lod_errors()[use.level] * px_per_unit;
    uses.push_back(use);
  }
  return uses;
}

// `placed` are in scene coordinates (a lone model's own); the render works
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

}  // namespace

FaceSkip FrameContext::culling_for(std::size_t i, const glm::dmat4& view_to_clip, const Viewer& seen_by,
                                   bool caps_checked) const {
  if (!face_culling) return {};
  return hidden_from(i, view_to_clip, seen_by, caps_checked);
}

FaceSkip FrameContext::hidden_from(std::size_t i, const glm::dmat4& view_to_clip, const Viewer& seen_by,
                                   bool caps_checked) const {
  FaceSkip skip;
  const GpuModel& model = objects[i].model;
  const scene::Enclosure enclosure = model.enclosure(lod_of(i));
  const bool caps_away = caps_face_away(model.caps(lod_of(i)), enclosure, scene.matrices[i], seen_by);
  if (!caps_away && !caps_checked) return skip;
  skip.hidden = hidden_faces(enclosure, scene.matrices[i], view_to_clip, model.bounds());
  skip.unless_caps_show = !caps_away && skip.hidden != HiddenFaces::None;
  return skip;
}

FrameContext build_frame_context(const std::vector<RenderObject>& objects, const RenderParams& params,
                                 bool face_culling) {
  FrameContext frame{.objects = objects, .params = params, .plan = plan_for(objects, params), .scene = scene_of(objects)};
  frame.face_culling = face_culling;
  for (const glm::dmat4& m : frame.scene.matrices) {
    // Composed in double, rounded to float only now. The inverse-transpose
    // keeps normals perpendicular to the surface under non-uniform scale.
    frame.model_matrices.emplace_back(m);
    frame.normal_matrices.emplace_back(glm::transpose(glm::inverse(glm::dmat3(m))));
  }
  frame.camera = fit_camera(params.camera, frame.scene.bounds, static_cast<double>(params.width) / params.height,
                            frame.scene.outline);
  frame.clip = frame.camera.projection * frame.camera.view;
  frame.view_projection = glm::mat4(frame.clip);
  frame.viewer = Viewer{frame.camera.eye, glm::normalize(frame.camera.target - frame.camera.eye),
                        params.camera.projection == Projection::Orthographic};
  frame.supersample = frame.plan.supersample;
  frame.draw_width = params.width * frame.supersample;
  frame.draw_height = params.height * frame.supersample;
  frame.outline_px = static_cast<float>(outline_width_px(params.outline, frame.camera, frame.orthographic(),
                                                         params.height)) *
                     static_cast<float>(frame.supersample);
  frame.lods = choose_levels(frame);
  for (std::size_t i = 0; i < objects.size(); ++i) {
    frame.main_faces.push_back(frame.culling_for(i, frame.clip, frame.viewer, true));
    frame.lods[i].culled = frame.main_faces[i].hidden;
  }
  // View-space lights turn with the camera about the point it orbits.
  const std::vector<Light> placed =
      lights_in_scene(params.lights, params.camera, frame.scene.origin + glm::dvec3(frame.scene.bounds.centre()));
  if (frame.plan.has(Pass::Shadow)) {
    const Light& caster = placed[static_cast<std::size_t>(frame.plan.shadow_light)];
    frame.shadow = fit_shadow(caster.direction, frame.scene.bounds, params.shadows.map_size);
  }
  frame.lights = lights_of(placed, frame.scene.origin);
  for (const RampStop& stop : params.ramp) {
    frame.ramp_at.push_back(stop.at);
    frame.ramp_color.push_back(stop.color);
  }
  return frame;
}

}  // namespace toond::render
