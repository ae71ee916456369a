#pragma once
// The frame's uniform blocks, written into one buffer before the first pass
// draws: the view, the shading, the outline's style, and the placement of
// each object (bound per object as passes draw it). Materials carry their
// blocks too, made from the frame's materials (FrameContext::materials),
// since a request may change how they are drawn. Render thread only.
#include <cstddef>
#include <vector>

#include "gpu/uniform_arena.h"
#include "render/frame/frame_context.h"

namespace toond::render {

class FrameBlocks {
 public:
  // Fills `arena` (kept from frame to frame) and uploads it, then binds the
  // blocks every program of the frame shares.
  FrameBlocks(const FrameContext& frame, gpu::UniformArena& arena);

  // Object i's ObjectPlacement.
  void bind_object(std::size_t i) const;
  // The placement of geometry made in frame coordinates (the floor).
  void bind_frame_placement() const;
  // Object i's material m (shaders/material.glsl).
  void bind_material(std::size_t i, int m) const;

 private:
  const gpu::UniformArena& arena_;
  std::vector<std::size_t> objects_;
  std::vector<std::vector<std::size_t>> materials_;  // per object, per material
  std::size_t frame_placement_ = 0;
};

}  // namespace toond::render
