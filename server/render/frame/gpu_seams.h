#pragma once
// The segments where a model's parts cross (scene/mesh/intersection_lines.h),
// every level of detail's, on the GPU: their points (p1, a, b, p2 a
// segment) in a buffer of their own and indices counting through them, in
// a vertex array of their own, which the crease pass draws as
// GL_LINES_ADJACENCY beside the crease edges. A model's GPU copy keeps the
// rest pose's and the applied pose's (GpuModel::apply_pose), whose points
// are posed already. Render thread only.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "gpu/gl_object.h"
#include "render/frame/draw_pacing.h"
#include "scene/mesh/intersection_lines.h"

namespace toond::render {

class GpuSeams {
 public:
  GpuSeams() = default;
  // Every level's segments, full detail first; no GL object is made where
  // there are none.
  explicit GpuSeams(std::span<const scene::IntersectionLines* const> levels);

  // How many of a level's segments turn by more than `degrees` (none for
  // a level it was not given).
  std::size_t segments(std::size_t lod, double degrees) const;
  // Those segments, from its vertex array, left bound. Returns how many.
  std::size_t draw(std::size_t lod, double degrees, DrawPacing* pacing) const;
  std::size_t gpu_bytes() const { return gpu_bytes_; }

 private:
  struct Level {
    std::size_t first_index = 0;            // four a segment
    std::array<std::uint32_t, 181> over{};  // scene::IntersectionLines::edges_over
  };
  std::vector<Level> levels_;
  gpu::VertexArray vao_;
  gpu::Buffer points_;
  gpu::Buffer indices_;
  std::size_t gpu_bytes_ = 0;
};

}  // namespace toond::render
