#pragma once
// A frame's plan, made once before it is queued: the parameters it is drawn
// with, its passes (pass_plan.h), the scene's framing, the camera, the
// outline's width in pixels and the predicted cost. The render thread only
// executes it (frame_context.h, renderer.h). Pure arithmetic, no GL.
#include <memory>
#include <span>

#include <glm/glm.hpp>

#include "render/plan/camera.h"
#include "render/plan/pass_plan.h"
#include "render/plan/render_cost.h"
#include "render/plan/render_params.h"
#include "scene/animation/pose.h"
#include "scene/mesh/model.h"

namespace toond::render {

// One object as the plan sees it: the model as imported, placed by its
// transform (model → scene coordinates), framed by its pose when posed.
struct PlannedObject {
  const scene::Model& model;
  glm::dmat4 transform{1.0};
  const scene::SkinPose* pose = nullptr;  // null: as imported
};

struct FramePlan {
  RenderParams params{};  // as drawn: a sheet frame's view, a pixel-art frame's reduced size
  PassPlan passes{};
  // The frame's coordinates and the objects' matrices into them; shared by
  // every frame of a request, whose poses are framed alike.
  std::shared_ptr<const SceneFrame> scene{};
  CameraSetup camera{};
  float outline_px = 0;  // every outline method's width, in drawn pixels (supersampling included)
  RenderCost cost{};     // predicted (render_cost.h)
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

// What a frame drawn with `params` would cost, its passes planned as
// plan_frame plans them: for pricing changes to a request (a smaller size,
// fewer samples) without framing them.
RenderCost predict_cost(const RenderParams& params, std::span<const PlannedObject> objects);

}  // namespace toond::render
