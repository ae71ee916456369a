#include "render/frame/gpu_seams.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "render/frame/vertex_attribute.h"

namespace toond::render {

GpuSeams::GpuSeams(std::span<const scene::IntersectionLines* const> levels) {
  std::vector<glm::vec3> points;
  for (const scene::IntersectionLines* lines : levels) {
    levels_.push_back({points.size(), lines->edges_over});
    points.insert(points.end(), lines->points.begin(), lines->points.end());
  }
  if (points.empty()) return;
  std::vector<std::uint32_t> indices(points.size());
  std::iota(indices.begin(), indices.end(), 0u);
  points_ = gpu::Buffer::create();
  glNamedBufferStorage(points_.id(), static_cast<GLsizeiptr>(points.size() * sizeof(glm::vec3)), points.data(), 0);
  indices_ = gpu::Buffer::create();
  glNamedBufferStorage(indices_.id(), static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data(),
                       0);
  gpu_bytes_ = points.size() * sizeof(glm::vec3) + indices.size() * sizeof(std::uint32_t);
  vao_ = gpu::VertexArray::create();
  glVertexArrayVertexBuffer(vao_.id(), 0, points_.id(), 0, sizeof(glm::vec3));
  glVertexArrayElementBuffer(vao_.id(), indices_.id());
  glEnableVertexArrayAttrib(vao_.id(), kPositionAttribute);
  glVertexArrayAttribFormat(vao_.id(), kPositionAttribute, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao_.id(), kPositionAttribute, 0);
}

std::size_t GpuSeams::segments(std::size_t lod, double degrees) const {
  if (lod >= levels_.size()) return 0;
  const auto whole = static_cast<std::size_t>(std::clamp(std::floor(degrees), 0.0, 180.0));
  return levels_[lod].over[whole];
}

std::size_t GpuSeams::draw(std::size_t lod, double degrees, DrawPacing* pacing) const {
  const std::size_t count = segments(lod, degrees);
  if (count == 0) return 0;
  glBindVertexArray(vao_.id());
  draw_crease_edges(pacing, 4 * count, levels_[lod].first_index);
  return count;
}

}  // namespace toond::render
