#pragma once
// What a frame's plan decides for each of its objects before the frame is
// queued: the level of detail every pass draws it at, and the side of its
// faces each pass may leave out because it cannot show. Pure arithmetic,
// no GL.
#include <span>
#include <vector>

#include "render/plan/drawn_materials.h"
#include "render/plan/face_culling.h"
#include "render/plan/lod_choice.h"
#include "render/plan/planned_object.h"

namespace toond::render {

struct FramePlan;

struct ObjectPlan {
  LodUse lod;
  // Seen by the camera: what the main pass, the edge prepass and a data
  // layer skip, and the side a crease line between two such faces hides on.
  FaceSkip main;
  // The outline hull's own, offset by the outline's width (only where the
  // plan draws a hull).
  FaceSkip hull;
  // Seen from the shadow's light: the far side, whose nearest surface the
  // map holds anyway (only where the plan casts a shadow).
  HiddenFaces shadow = HiddenFaces::None;
  // Its model's materials as this frame draws them.
  std::vector<DrawnMaterial> materials;
  // How far ahead of the camera its bounds' centre lies: blended surfaces
  // are drawn farthest object first.
  double view_depth = 0.0;
};

// Per object of `objects`, as `plan` sees them (its camera, framing,
// outline width, passes, lights and shadow fit decided), drawn with
// `materials` (one list per object).
std::vector<ObjectPlan> plan_objects(const FramePlan& plan, std::span<const PlannedObject> objects,
                                     std::vector<std::vector<DrawnMaterial>> materials);

}  // namespace toond::render
