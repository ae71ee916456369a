#pragma once
// Runs a pass plan for one model and returns the image. Render thread only.
#include <optional>
#include <string>
#include <vector>

#include "gpu/program_cache.h"
#include "gpu/render_target.h"
#include "gpu/normal_depth_target.h"
#include "gpu/shadow_map.h"
#include "image/image.h"
#include "render/face_culling.h"
#include "render/gpu_model.h"
#include "render/pass_plan.h"
#include "render/pass_timing.h"
#include "render/render_params.h"

namespace toond::render {

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

struct RenderOutput {
  image::Image image;
  std::vector<PassTiming> timings;
  std::string plan;  // PassPlan::describe()
  std::vector<LodUse> lods;  // one per object, in order
  // Samples per pixel the target really has: `msaa` clamped to the
  // driver's GL_MAX_SAMPLES (llvmpipe: 4).
  int samples = 1;
};

// One object of the scene: a model on the GPU and its transform (model
// coordinates → scene coordinates; the identity for a lone model).
struct RenderObject {
  const GpuModel& model;
  glm::dmat4 transform{1.0};
};

class Renderer {
 public:
  explicit Renderer(gpu::ProgramCache& programs) : programs_(programs) {}

  // On by default. Off draws both sides of every face: for tests that show
  // culling changes no pixel.
  void set_face_culling(bool on) { face_culling_ = on; }

  // Every object shares the camera, the lights and the passes; camera fit,
  // shadow fit and floor use the union of their transformed bounds.
  RenderOutput render(const std::vector<RenderObject>& objects, const RenderParams& params);
  RenderOutput render(const GpuModel& model, const RenderParams& params) {
    return render({RenderObject{model, glm::dmat4(1.0)}}, params);
  }

 private:
  gpu::RenderTarget& target_for(int width, int height, int samples);
  gpu::ShadowMap& shadow_map_for(int size);
  gpu::NormalDepthTarget& normal_depth_for(int width, int height, int samples);
  const GpuModel& floor_for(const scene::Bounds& bounds, const FloorParams& floor, bool textured);

  gpu::ProgramCache& programs_;
  bool face_culling_ = true;
  // Asked of the context at the first render: whether it rasterizes on a
  // GPU or on this CPU's threads (gpu::software_rasterizer). That decides
  // whether GPU time is counted and how pixels come back.
  std::optional<bool> real_gpu_;
  std::optional<gpu::RenderTarget> target_;  // reused while the size stays the same
  std::optional<gpu::ShadowMap> shadow_map_;
  std::optional<gpu::NormalDepthTarget> normal_depth_;
  // Core profile draws need a bound VAO even when the vertex shader makes
  // its own positions (the full-screen triangle).
  gpu::VertexArray fullscreen_vao_ = gpu::VertexArray::create();
  std::optional<GpuModel> floor_;             // rebuilt when the scene's bounds change
  scene::Bounds floor_bounds_;
  float floor_size_ = 0;
  float floor_repeat_ = 0;
  std::shared_ptr<const scene::Texture> floor_image_;  // the image floor_ was built with
};

}  // namespace toond::render
