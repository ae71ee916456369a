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
#include "render/gpu_model.h"
#include "render/pass_plan.h"
#include "render/render_params.h"

namespace toond::render {

struct PassTiming {
  std::string pass;
  double ms = 0;  // CPU wall time for issuing + (for readback) waiting
};

struct RenderOutput {
  image::Image image;
  std::vector<PassTiming> timings;
  std::string plan;  // PassPlan::describe()
};

class Renderer {
 public:
  explicit Renderer(gpu::ProgramCache& programs) : programs_(programs) {}

  RenderOutput render(const GpuModel& model, const RenderParams& params);

 private:
  gpu::RenderTarget& target_for(int width, int height, int samples);
  gpu::ShadowMap& shadow_map_for(int size);
  gpu::NormalDepthTarget& normal_depth_for(int width, int height);
  const GpuModel& floor_for(const GpuModel& model, float size);

  gpu::ProgramCache& programs_;
  std::optional<gpu::RenderTarget> target_;  // reused while the size stays the same
  std::optional<gpu::ShadowMap> shadow_map_;
  std::optional<gpu::NormalDepthTarget> normal_depth_;
  // Core profile draws need a bound VAO even when the vertex shader makes
  // its own positions (the full-screen triangle).
  gpu::VertexArray fullscreen_vao_ = gpu::VertexArray::create();
  std::optional<GpuModel> floor_;             // rebuilt when the model's bounds change
  scene::Bounds floor_bounds_;
  float floor_size_ = 0;
};

}  // namespace toond::render
