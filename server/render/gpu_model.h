#pragma once
// A model's GPU copy: one interleaved vertex buffer, one index buffer, its
// textures (sRGB, mipmapped, repeating) and per-material draw ranges.
// Created and destroyed on the render thread only.
#include <vector>

#include "gpu/gl_object.h"
#include "scene/model.h"

namespace toond::render {

struct GpuMaterial {
  std::string name;  // as in the MTL, for per-material request parameters
  glm::vec3 diffuse{0.8f};
  int texture = -1;         // index into GpuModel::textures()
  int normal_texture = -1;  // tangent-space normal map, linear
};

class GpuModel {
 public:
  explicit GpuModel(const scene::Model& model);

  void bind() const { glBindVertexArray(vao_.id()); }
  // Draws one submesh (the VAO must be bound).
  void draw(const scene::Submesh& submesh) const;
  void draw_all() const;

  const std::vector<scene::Submesh>& submeshes() const { return submeshes_; }
  const std::vector<GpuMaterial>& materials() const { return materials_; }
  GLuint texture(int index) const { return textures_[static_cast<std::size_t>(index)].id(); }
  bool has_textures() const { return !textures_.empty(); }
  bool has_vertex_colors() const { return has_vertex_colors_; }
  bool has_normal_maps() const {
    for (const GpuMaterial& m : materials_)
      if (m.normal_texture >= 0) return true;
    return false;
  }
  const scene::Bounds& bounds() const { return bounds_; }
  // The model-space point the vertex positions are relative to.
  const glm::dvec3& origin() const { return origin_; }
  std::size_t gpu_bytes() const { return gpu_bytes_; }

 private:
  gpu::VertexArray vao_;
  gpu::Buffer vertices_;
  gpu::Buffer indices_;
  std::vector<gpu::Texture> textures_;
  std::vector<GpuMaterial> materials_;
  std::vector<scene::Submesh> submeshes_;
  scene::Bounds bounds_;
  glm::dvec3 origin_{0.0};
  std::size_t index_count_ = 0;
  bool has_vertex_colors_ = false;
  std::size_t gpu_bytes_ = 0;
};

}  // namespace toond::render
