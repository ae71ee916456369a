#pragma once
// Everything a frame's passes share, taken from its plan (frame_plan.h:
// everything about the frame was decided there) in the form the passes and
// shaders use: the matrices rounded to float, the lights relative to the
// frame's origin, the ramp's arrays, the faces skipped as this renderer
// draws them. No decision is made here, and no GL call.
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "render/plan/camera.h"
#include "render/plan/drawn_materials.h"
#include "render/plan/face_culling.h"
#include "render/plan/frame_plan.h"
#include "render/plan/lod_choice.h"
#include "render/plan/pass_plan.h"
#include "render/plan/render_params.h"
#include "render/plan/shadow_fit.h"
#include "scene/animation/pose.h"
#include "scene/mesh/model.h"

namespace toond::render {

// One object of the frame as its passes draw it: the model as imported, in
// the pose its GPU copy holds. What the plan decided for it is the plan's
// (FramePlan::objects).
struct FrameObject {
  const scene::Model& model;
  const scene::SkinPose* pose = nullptr;  // null: as imported
  bool skinned = false;                   // posed by the vertex stages (GpuModel::skinned)
};

// The lights in the form toon.frag's arrays take: a direction toward the
// light (directional) or a position in frame coordinates (point). A
// directional light of zero direction lights nothing and is left out.
struct ShadingLights {
  std::vector<glm::vec3> vec;
  std::vector<glm::vec3> color;
  std::vector<int> is_point;
  std::vector<float> radius;
};

// The plan's parts are referred to, not copied: the plan outlives the frame.
struct FrameContext {
  std::vector<FrameObject> objects;
  const RenderParams& params;
  const PassPlan& plan;
  // Everything below is in the frame's coordinates: scene coordinates less
  // a point at the scene's middle (camera.h, frame_scene).
  const SceneFrame& scene;
  const CameraSetup& camera;
  const glm::dmat4& clip;  // projection × view, in double
  const Viewer& viewer;
  const std::optional<ShadowFit>& shadow;
  std::vector<glm::mat4> model_matrices{};   // per object, rounded to float from scene.matrices
  std::vector<glm::mat3> normal_matrices{};  // inverse-transpose of their upper 3×3
  glm::mat4 view_projection{1.0f};           // clip, rounded for the shaders
  // Supersampling draws everything `supersample` times larger, pixel sizes
  // included, then averages back down.
  int supersample = 1;
  int draw_width = 0;
  int draw_height = 0;
  float outline_px = 0;  // every outline method draws this one width, in drawn pixels
  // One per object, the plan's: every pass draws an object at its level;
  // `culled` says which faces the main pass left out as drawn.
  std::vector<LodUse> lods{};
  // Per object, the faces each pass skips: the plan's, or none in a frame
  // that draws both sides of every face.
  std::vector<FaceSkip> main_faces{};  // the main pass, the edge prepass, a data layer
  std::vector<FaceSkip> hull_faces{};  // the outline hull
  std::vector<HiddenFaces> shadow_faces{};
  // The faces that cannot show to the camera whether or not this frame
  // culls faces, which a pass may leave out of what it draws over the
  // surface (crease lines) without changing a pixel either way.
  std::vector<FaceSkip> unseen_faces{};
  // Per object, its materials as this frame draws them (the plan's).
  std::vector<std::vector<DrawnMaterial>> materials{};
  std::vector<double> view_depths{};  // per object, the plan's ObjectPlan::view_depth
  ShadingLights lights{};
  // The colour ramp's stops as toon.frag's arrays take them.
  std::vector<float> ramp_at{};
  std::vector<glm::vec3> ramp_color{};

  std::size_t lod_of(std::size_t i) const { return lods[i].level; }
  const DrawnMaterial& material(std::size_t i, int m) const { return materials[i][static_cast<std::size_t>(m)]; }
  // Whether some material of object i is cut out or blended: what follows
  // its surface must go material by material and test the alpha.
  bool has_cutouts(std::size_t i) const;
  bool orthographic() const { return viewer.orthographic; }
  glm::vec3 eye() const { return glm::vec3(camera.eye); }
  glm::vec3 view_dir() const { return glm::vec3(viewer.forward); }
  // The size of one drawn pixel at clip w = 1 (FramePlan::world_per_px_at_w1).
  double world_per_px_at_w1() const { return 2.0 / (camera.projection[1][1] * draw_height); }
};

// `objects` in the plan's order. `face_culling` off draws both sides of
// every face (tests that show culling changes no pixel).
FrameContext build_frame_context(std::vector<FrameObject> objects, const FramePlan& plan, bool face_culling);

}  // namespace toond::render
