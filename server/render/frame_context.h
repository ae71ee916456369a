#pragma once
// Everything a frame's passes share, worked out once before the first one
// draws: the plan, the scene's frame and matrices, the camera, the level of
// detail and the faces each object may skip, the outline's width in
// pixels, the shadow's fit and the lights as the shaders take them. Pure
// arithmetic, no GL.
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "render/camera.h"
#include "render/face_culling.h"
#include "render/gpu_model.h"
#include "render/object_draw.h"
#include "render/pass_plan.h"
#include "render/render_params.h"
#include "render/shadow_fit.h"

namespace toond::render {

// One object of the scene: a model on the GPU and its transform (model
// coordinates → scene coordinates; the identity for a lone model).
struct RenderObject {
  const GpuModel& model;
  glm::dmat4 transform{1.0};
};

// The level of detail one object was drawn at (see lod_choice.h).
struct LodUse {
  std::size_t level = 0;      // 0 = full detail
  std::size_t levels = 1;     // how many the model has
  std::size_t triangles = 0;  // drawn per pass
  double error_px = 0;        // the level's error projected to output pixels
  // The side of the faces the main pass skipped (None: both drawn): a
  // closed level seen from outside (face_culling.h), or an open one none
  // of whose holes showed (their caps were checked and hidden).
  HiddenFaces culled = HiddenFaces::None;
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

struct FrameContext {
  const std::vector<RenderObject>& objects;
  const RenderParams& params;
  PassPlan plan;
  // Everything below is in the frame's coordinates: scene coordinates less
  // a point at the scene's middle (camera.h, frame_scene).
  SceneFrame scene;
  std::vector<glm::mat4> model_matrices{};   // per object, rounded to float from scene.matrices
  std::vector<glm::mat3> normal_matrices{};  // inverse-transpose of their upper 3×3
  CameraSetup camera{};
  glm::dmat4 clip{1.0};               // projection × view, in double
  glm::mat4 view_projection{1.0f};    // the same, rounded for the shaders
  Viewer viewer{};
  // Supersampling draws everything `supersample` times larger, pixel sizes
  // included, then averages back down.
  int supersample = 1;
  int draw_width = 0;
  int draw_height = 0;
  float outline_px = 0;  // every outline method draws this one width, in drawn pixels
  std::vector<LodUse> lods{};  // one per object; every pass draws an object at its level
  std::vector<FaceSkip> main_faces{};  // per object: of the main pass and the edge prepass
  std::optional<ShadowFit> shadow{};
  ShadingLights lights{};
  // The colour ramp's stops as toon.frag's arrays take them.
  std::vector<float> ramp_at{};
  std::vector<glm::vec3> ramp_color{};
  bool face_culling = true;

  std::size_t lod_of(std::size_t i) const { return lods[i].level; }
  bool orthographic() const { return viewer.orthographic; }
  glm::vec3 eye() const { return glm::vec3(camera.eye); }
  glm::vec3 view_dir() const { return glm::vec3(viewer.forward); }
  // The size of one drawn pixel at clip w = 1 (a pixel at depth w is w
  // times it): projection[1][1] maps a view-space height at depth w to NDC,
  // and NDC spans `draw_height` pixels over 2 units.
  double world_per_px_at_w1() const { return 2.0 / (camera.projection[1][1] * draw_height); }
  // The faces of object i that cannot show through `view_projection` to
  // `seen_by`. An object with holes whose caps do not all turn away skips
  // them too in a pass that can check its caps (`caps_checked`), else none.
  FaceSkip culling_for(std::size_t i, const glm::dmat4& view_projection, const Viewer& seen_by,
                       bool caps_checked) const;
  // The same whether or not this frame culls faces (`face_culling`): the
  // faces that cannot show, which a pass may leave out of what it draws
  // over the surface (crease lines) without changing a pixel either way.
  FaceSkip hidden_from(std::size_t i, const glm::dmat4& view_projection, const Viewer& seen_by,
                       bool caps_checked) const;
};

// `face_culling` off draws both sides of every face (tests that show
// culling changes no pixel).
FrameContext build_frame_context(const std::vector<RenderObject>& objects, const RenderParams& params,
                                 bool face_culling);

}  // namespace toond::render
