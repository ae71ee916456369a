#pragma once
// Everything a frame's passes share, worked out once before the first one
// draws: from its plan (frame_plan.h: the passes, the scene's frame, the
// camera, the outline's width in pixels) the matrices, the level of detail
// and the faces each object may skip, the shadow's fit and the lights as
// the shaders take them. Pure arithmetic, no GL: it sees the models as
// imported, not their GPU copies.
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "render/plan/camera.h"
#include "render/plan/drawn_materials.h"
#include "render/plan/face_culling.h"
#include "render/plan/frame_plan.h"
#include "render/plan/pass_plan.h"
#include "render/plan/render_params.h"
#include "render/plan/shadow_fit.h"
#include "scene/animation/pose.h"
#include "scene/mesh/model.h"

namespace toond::render {

// One object of the frame as its arithmetic sees it: the model as imported
// (its levels of detail, closed or open, their hole caps) in its pose.
// Where it stands is the plan's (FramePlan::scene).
struct FrameObject {
  const scene::Model& model;
  const scene::SkinPose* pose = nullptr;  // null: as imported
  bool skinned = false;                   // posed by the vertex stages (GpuModel::skinned)

  // The pose's when posed (which may be a whole clip's reach).
  const scene::Bounds& bounds() const;
  // How much the pose may lengthen a level's error (SkinPose::stretch); 1 as imported.
  double pose_stretch() const { return pose ? pose->stretch : 1.0; }
  // Level 0 is the full mesh; the rest come from scene::Mesh::lods.
  std::size_t lod_count() const { return 1 + model.mesh.lods.size(); }
  // Per level, in the mesh's units: how far its surface may stray (0 at level 0).
  std::vector<double> lod_errors() const;
  std::size_t triangles(std::size_t lod) const;
  // Whether a level's triangles close around a volume (scene/mesh/enclosure.h);
  // a pose keeps the topology.
  scene::Enclosure enclosure(std::size_t lod) const;
  // Triangles closing the level's holes; posed, they moved with the pose.
  const std::vector<glm::vec3>& caps(std::size_t lod) const;
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

// The plan's parts are referred to, not copied: the plan outlives the frame.
struct FrameContext {
  std::vector<FrameObject> objects;
  const RenderParams& params;
  const PassPlan& plan;
  // Everything below is in the frame's coordinates: scene coordinates less
  // a point at the scene's middle (camera.h, frame_scene).
  const SceneFrame& scene;
  const CameraSetup& camera;
  std::vector<glm::mat4> model_matrices{};   // per object, rounded to float from scene.matrices
  std::vector<glm::mat3> normal_matrices{};  // inverse-transpose of their upper 3×3
  glm::dmat4 clip{1.0};                      // projection × view, in double
  glm::mat4 view_projection{1.0f};           // the same, rounded for the shaders
  Viewer viewer{};
  // Supersampling draws everything `supersample` times larger, pixel sizes
  // included, then averages back down.
  int supersample = 1;
  int draw_width = 0;
  int draw_height = 0;
  float outline_px = 0;                // every outline method draws this one width, in drawn pixels
  std::vector<LodUse> lods{};          // one per object; every pass draws an object at its level
  std::vector<FaceSkip> main_faces{};  // per object: of the main pass and the edge prepass
  // Per object, its materials as this frame draws them (drawn_materials.h).
  std::vector<std::vector<DrawnMaterial>> materials{};
  std::optional<ShadowFit> shadow{};
  ShadingLights lights{};
  // The colour ramp's stops as toon.frag's arrays take them.
  std::vector<float> ramp_at{};
  std::vector<glm::vec3> ramp_color{};
  bool face_culling = true;

  std::size_t lod_of(std::size_t i) const { return lods[i].level; }
  const DrawnMaterial& material(std::size_t i, int m) const { return materials[i][static_cast<std::size_t>(m)]; }
  // Whether some material of object i is cut out or blended: what follows
  // its surface must go material by material and test the alpha.
  bool has_cutouts(std::size_t i) const;
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

// `objects` in the plan's order. `face_culling` off draws both sides of
// every face (tests that show culling changes no pixel).
FrameContext build_frame_context(std::vector<FrameObject> objects, const FramePlan& plan, bool face_culling);

}  // namespace toond::render
