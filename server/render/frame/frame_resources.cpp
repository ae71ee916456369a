#include "render/frame/frame_resources.h"

#include <algorithm>

namespace toond::render {
namespace {

// A square ground plane just under the model's lowest point (a hair lower,
// so a flat-bottomed model does not z-fight with it), facing up; its texture
// coordinates run over `repeat` tiles per side.
scene::Model make_floor(const scene::Bounds& bounds, const FloorParams& params,
                        const std::shared_ptr<const scene::Texture>& image) {
  const float size = params.size;
  const float repeat = params.texture_repeat;
  const float half = bounds.radius() * size;
  const glm::vec3 c = bounds.centre();
  const float y = bounds.min.y - bounds.radius() * 1e-3f;
  scene::Model floor;
  scene::Mesh& m = floor.mesh;
  m.positions = {{c.x - half, y, c.z - half},
                 {c.x + half, y, c.z - half},
                 {c.x + half, y, c.z + half},
                 {c.x - half, y, c.z + half}};
  m.normals.assign(4, glm::vec3(0, 1, 0));
  m.outline_normals.assign(4, glm::vec3(0, 1, 0));
  m.texcoords = {{0, 0}, {repeat, 0}, {repeat, repeat}, {0, repeat}};
  m.indices = {0, 2, 1, 0, 3, 2};
  m.submeshes = {{0, 6, 0}};
  m.bounds = {m.positions[0], m.positions[2]};
  floor.materials.push_back({});
  floor.materials[0].diffuse = params.color;
  if (image) {
    floor.textures.push_back(*image);
    floor.materials[0].diffuse_texture = 0;
  }
  return floor;
}

}  // namespace

gpu::RenderTarget& FrameResources::target_for(int width, int height, int samples, int shrink, bool real_gpu) {
  if (!target_ || !target_->matches(width, height, samples, shrink)) {
    target_.reset();  // free the old storage before allocating the new
    target_.emplace(width, height, samples, real_gpu ? gpu::ReadbackPath::PixelBuffer : gpu::ReadbackPath::ClientMemory,
                    shrink);
  }
  return *target_;
}

gpu::ShadowMap& FrameResources::shadow_map_for(int size) {
  if (!shadow_map_ || shadow_map_->size() != size) {
    shadow_map_.reset();
    shadow_map_.emplace(size);
  }
  return *shadow_map_;
}

gpu::NormalDepthTarget& FrameResources::normal_depth_for(int width, int height, int samples) {
  if (!normal_depth_ || !normal_depth_->matches(width, height, samples)) {
    normal_depth_.reset();
    normal_depth_.emplace(width, height, samples);
  }
  return *normal_depth_;
}

std::unique_ptr<gpu::ReadbackBuffer> FrameResources::readback_buffer(int width, int height) {
  // Buffers of another size will not be asked for again soon.
  std::erase_if(spare_readback_buffers_, [&](const auto& b) { return b->width() != width || b->height() != height; });
  if (spare_readback_buffers_.empty()) return std::make_unique<gpu::ReadbackBuffer>(width, height);
  std::unique_ptr<gpu::ReadbackBuffer> buffer = std::move(spare_readback_buffers_.back());
  spare_readback_buffers_.pop_back();
  return buffer;
}

void FrameResources::give_back(std::unique_ptr<gpu::ReadbackBuffer> buffer) {
  // Two frames are in flight at most: a third spare would never be used.
  if (spare_readback_buffers_.size() < 2) spare_readback_buffers_.push_back(std::move(buffer));
}

const GpuModel& FrameResources::floor_for(const scene::Bounds& b, const FloorParams& params, bool textured) {
  const std::shared_ptr<const scene::Texture> image = textured ? params.image : nullptr;
  if (!floor_ || floor_size_ != params.size || floor_repeat_ != params.texture_repeat || floor_image_ != image ||
      floor_color_ != params.color || floor_bounds_.min != b.min || floor_bounds_.max != b.max) {
    floor_.reset();
    floor_.emplace(make_floor(b, params, image));
    floor_bounds_ = b;
    floor_size_ = params.size;
    floor_repeat_ = params.texture_repeat;
    floor_image_ = image;
    floor_color_ = params.color;
  }
  return *floor_;
}

void FrameResources::draw_fullscreen_triangle() const {
  glBindVertexArray(fullscreen_vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

float FrameResources::widest_line() {
  if (!widest_line_) {
    GLfloat aliased[2] = {1.0f, 1.0f};
    GLfloat smooth[2] = {1.0f, 1.0f};
    glGetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, aliased);
    glGetFloatv(GL_SMOOTH_LINE_WIDTH_RANGE, smooth);
    widest_line_ = std::min(aliased[1], smooth[1]);
  }
  return *widest_line_;
}

const gpu::Buffer& FrameResources::hull_indices(const std::vector<std::span<const std::uint32_t>>& parts) {
  std::size_t bytes = 0;
  for (const auto& part : parts) bytes += part.size_bytes();
  glNamedBufferData(hull_indices_.id(), static_cast<GLsizeiptr>(bytes), nullptr, GL_STREAM_DRAW);
  std::size_t at = 0;
  for (const auto& part : parts) {
    glNamedBufferSubData(hull_indices_.id(), static_cast<GLintptr>(at), static_cast<GLsizeiptr>(part.size_bytes()),
                         part.data());
    at += part.size_bytes();
  }
  return hull_indices_;
}

}  // namespace toond::render
