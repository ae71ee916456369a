#include "render/plan/object_plan.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "render/plan/frame_plan.h"

namespace toond::render {
namespace {

// The coarsest level whose error, at the object's nearest distance from
// the camera, stays within the pixel budget. Scale in the object's
// transform scales its error along, and so does a pose's stretch.
LodUse choose_level(const FramePlan& plan, const PlannedObject& object, const glm::dmat4& placement) {
  const RenderParams& params = plan.params;
  const double scale = std::max({glm::length(glm::dvec3(placement[0])), glm::length(glm::dvec3(placement[1])),
                                 glm::length(glm::dvec3(placement[2]))});
  const glm::dvec3 centre = glm::dvec3(placement * glm::dvec4(glm::dvec3(object.bounds().centre()), 1.0));
  const double px_per_unit =
      object.pose_stretch() * scale *
      pixels_per_unit(plan.camera, plan.viewer.orthographic, centre, object.bounds().radius() * scale, params.height);
  const std::vector<double> errors = object.lod_errors();
  LodUse use;
  use.levels = object.lod_count();
  if (params.lod_auto) use.level = choose_lod(errors, px_per_unit, params.lod_error_px);
  use.triangles = object.triangles(use.level);
  use.error_px = errors[use.level] * px_per_unit;
  return use;
}

// The faces of an object at `lod` that cannot show through
// `view_projection` to `seen_by`. An object with holes whose caps do not
// all turn away skips them too where the pass checks its caps
// (`caps_checked`), else none.
FaceSkip faces_hidden(const PlannedObject& object, std::size_t lod, const glm::dmat4& placement,
                      const glm::dmat4& view_projection, const Viewer& seen_by, bool caps_checked) {
  FaceSkip skip;
  const scene::Enclosure enclosure = object.enclosure(lod);
  const bool caps_away = caps_face_away(object.caps(lod), enclosure, placement, seen_by);
  if (!caps_away && !caps_checked) return skip;
  skip.hidden = hidden_faces(enclosure, placement, view_projection, object.bounds());
  skip.unless_caps_show = !caps_away && skip.hidden != HiddenFaces::None;
  return skip;
}

// How far the hull may stand out of the model's box: up to 3 widths
// (mitred corners), where a pixel's size grows with the depth w, which the
// offset itself adds to.
double hull_reach(const FramePlan& plan) {
  const double k = 3.0 * plan.outline_px * plan.world_per_px_at_w1();
  if (plan.viewer.orthographic) return k;
  if (k >= 0.5) return std::numeric_limits<double>::infinity();
  double w_max = 1.0;
  for (int corner = 0; corner < 8; ++corner) {
    w_max = std::max(w_max, (plan.clip * glm::dvec4(plan.scene->bounds.corner(corner), 1.0)).w);
  }
  return k * w_max / (1.0 - k);
}

// Which side of the object's hull its draw skips. The stencil keeps the
// hull off the model, so its faces toward the camera may draw the ring:
// where a closed model's back faces may be skipped, the hull's may too.
// Its front faces lie nearer than its back ones, so they pass every depth
// test (a floor's) the back ones would. The hull must not be cut by the
// near or far plane either: where it is, its back faces show through the
// cut.
FaceSkip hull_faces_hidden(const FramePlan& plan, const PlannedObject& object, const ObjectPlan& decided,
                           const glm::dmat4& placement) {
  FaceSkip hull;
  if (decided.main.hidden == HiddenFaces::None) return hull;
  const std::size_t lod = decided.lod.level;
  hull.hidden = hidden_faces(object.enclosure(lod), placement, plan.clip, object.bounds(), hull_reach(plan));
  // The hull's holes move with its offset and may turn toward the camera
  // where the model's do not: its own caps, offset like it (they share
  // its vertices), are checked.
  hull.unless_caps_show = hull.hidden != HiddenFaces::None && !object.caps(lod).empty();
  return hull;
}

}  // namespace

std::vector<ObjectPlan> plan_objects(const FramePlan& plan, std::span<const PlannedObject> objects,
                                     std::vector<std::vector<DrawnMaterial>> materials) {
  std::vector<ObjectPlan> decided;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const PlannedObject& object = objects[i];
    const glm::dmat4& placement = plan.scene->matrices[i];
    ObjectPlan o;
    o.lod = choose_level(plan, object, placement);
    o.main = faces_hidden(object, o.lod.level, placement, plan.clip, plan.viewer, true);
    o.lod.culled = o.main.hidden;
    if (plan.passes.has(Pass::HullOutline)) o.hull = hull_faces_hidden(plan, object, o, placement);
    if (plan.shadow) {
      // The nearest surface seen from the light is the same with the far
      // side skipped, so the map is too.
      const glm::dvec3 direction = plan.lights[static_cast<std::size_t>(plan.passes.shadow_light)].direction;
      const Viewer light{glm::dvec3(0.0), glm::normalize(direction), true};
      o.shadow = faces_hidden(object, o.lod.level, placement, plan.shadow->view_projection, light, false).hidden;
    }
    o.materials = std::move(materials[i]);
    const glm::dvec3 centre(placement * glm::dvec4(glm::dvec3(object.bounds().centre()), 1.0));
    o.view_depth = glm::dot(centre - plan.camera.eye, glm::dvec3(plan.viewer.forward));
    decided.push_back(std::move(o));
  }
  return decided;
}

}  // namespace toond::render
