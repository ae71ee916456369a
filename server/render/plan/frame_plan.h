#pragma once
// A frame's plan, made once before it is queued: everything decided about
// the frame. The parameters it is drawn with, its passes (pass_plan.h), the
// scene's framing, the camera, the outline's width in pixels, the lights
// placed in the scene, the shadow's fit, each object's level of detail and
// the faces each pass may skip (object_plan.h), and the predicted cost,
// which is worked out from the plan itself. The render thread only turns
// it into GL state and draws (frame_context.h, renderer.h). Pure
// arithmetic, no GL.
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/plan/camera.h"
#include "render/plan/face_culling.h"
#include "render/plan/object_plan.h"
#include "render/plan/pass_plan.h"
#include "render/plan/planned_object.h"
#include "render/plan/render_cost.h"
#include "render/plan/render_params.h"
#include "render/plan/shadow_fit.h"

namespace toond::render {

struct FramePlan {
  RenderParams params{};  // as drawn: a sheet frame's view, a pixel-art frame's reduced size
  PassPlan passes{};
  // The frame's coordinates and the objects' matrices into them; shared by
  // every frame of a request, whose poses are framed alike.
  std::shared_ptr<const SceneFrame> scene{};
  CameraSetup camera{};
  glm::dmat4 clip{1.0};  // camera.projection × camera.view, frame coordinates to clip space
  Viewer viewer{};       // where the camera is and which way it looks, frame coordinates
  float outline_px = 0;  // every outline method's width, in drawn pixels (supersampling included)
  // The request's lights in scene coordinates, view-space ones turned with
  // the camera (light_space.h); same order and count.
  std::vector<Light> lights{};
  std::optional<ShadowFit> shadow{};  // where the plan casts a shadow
  std::vector<ObjectPlan> objects{};  // per object, in the request's order
  RenderCost cost{};                  // predicted (render_cost.h)

  int draw_width() const { return params.width * passes.supersample; }
  int draw_height() const { return params.height * passes.supersample; }
  // The size of one drawn pixel at clip w = 1 (a pixel at depth w is w
  // times it): projection[1][1] maps a view-space height at depth w to NDC,
  // and NDC spans the drawn height over 2 units.
  double world_per_px_at_w1() const { return 2.0 / (camera.projection[1][1] * draw_height()); }
};

// The framing of the objects: each by its pose's bounds and extreme points
// when posed (a whole clip's reach), else by its mesh's.
std::shared_ptr<const SceneFrame> frame_scene_of(std::span<const PlannedObject> objects);

// The plan of one frame of `objects` drawn with `params`, in `scene`
// (frame_scene_of the same objects, or of another frame's, which poses
// framed alike share).
FramePlan plan_frame(RenderParams params, std::span<const PlannedObject> objects,
                     std::shared_ptr<const SceneFrame> scene);
FramePlan plan_frame(RenderParams params, std::span<const PlannedObject> objects);

}  // namespace toond::render
