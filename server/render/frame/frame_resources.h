#pragma once
// The GL objects frames draw into and with, kept from one render to the next
// while their size stays the same: the target, the shadow map, the edge
// prepass, the floor's mesh, the full-screen triangle's vertex array and
// the buffer of the frame's uniform blocks.
// Render thread only.
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "gpu/normal_depth_target.h"
#include "gpu/render_target.h"
#include "gpu/shadow_map.h"
#include "gpu/uniform_arena.h"
#include "render/frame/gpu_model.h"
#include "render/plan/render_params.h"

namespace toond::render {

class FrameResources {
 public:
  // The target drawn at width × height and read back shrunk by `shrink`
  // (supersampling). `real_gpu`: read back through a pixel buffer (on a CPU
  // rasterizer the pack happens inside glReadPixels whatever the
  // destination, and straight into memory measured faster there).
  gpu::RenderTarget& target_for(int width, int height, int samples, int shrink, bool real_gpu);
  gpu::ShadowMap& shadow_map_for(int size);
  gpu::NormalDepthTarget& normal_depth_for(int width, int height, int samples);
  // A pixel buffer for a frame kept in flight, which holds it until its
  // pixels are copied out and then hands it back: buffers of the size in
  // use are kept (mapping a new one costs more than a frame's readback).
  std::unique_ptr<gpu::ReadbackBuffer> readback_buffer(int width, int height);
  void give_back(std::unique_ptr<gpu::ReadbackBuffer> buffer);
  // A square ground plane under `bounds`, rebuilt when they or the floor's
  // parameters change.
  const GpuModel& floor_for(const scene::Bounds& bounds, const FloorParams& floor, bool textured);
  // The shadow map and the edge prepass the last shadow pass and prepass
  // drew.
  const gpu::ShadowMap& shadow_map() const { return *shadow_map_; }
  const gpu::NormalDepthTarget& normal_depth() const { return *normal_depth_; }
  // Where the frame's uniform blocks are written (render/frame/frame_blocks.h),
  // the same buffer from frame to frame.
  gpu::UniformArena& frame_uniforms() { return frame_uniforms_; }
  // Binds the vertex array a full-screen triangle is drawn with (core
  // profile draws need one even when the vertex shader makes its own
  // positions) and draws it.
  void draw_fullscreen_triangle() const;
  // The widest line, in pixels, the driver draws whether or not it is
  // multisampled (the narrower of GL_ALIASED_LINE_WIDTH_RANGE's and
  // GL_SMOOTH_LINE_WIDTH_RANGE's largest), asked once.
  float widest_line();
  // Where the hull's faces that may show are written each frame
  // (render/cull/hull_cull.h), the parts one after the other, given fresh
  // storage every time so a frame still in flight keeps the last one's.
  const gpu::Buffer& hull_indices(const std::vector<std::span<const std::uint32_t>>& parts);

 private:
  std::optional<gpu::RenderTarget> target_;
  std::optional<gpu::ShadowMap> shadow_map_;
  std::optional<gpu::NormalDepthTarget> normal_depth_;
  std::vector<std::unique_ptr<gpu::ReadbackBuffer>> spare_readback_buffers_;
  gpu::VertexArray fullscreen_vao_ = gpu::VertexArray::create();
  gpu::Buffer hull_indices_ = gpu::Buffer::create();
  gpu::UniformArena frame_uniforms_;
  std::optional<GpuModel> floor_;
  scene::Bounds floor_bounds_;
  float floor_size_ = 0;
  std::optional<float> widest_line_;
  float floor_repeat_ = 0;
  glm::vec3 floor_color_{0.0f};
  std::shared_ptr<const scene::Texture> floor_image_;  // the image floor_ was built with
};

}  // namespace toond::render
