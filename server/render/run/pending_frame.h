#pragma once
// A frame whose passes are recorded and whose pixels are on their way back:
// what Renderer::start() hands over and Renderer::finish() completes. With
// frames in flight the render thread records the next frame before it
// waits for this one's pixels, so a GPU draws one frame while the last one
// is packed and copied out. Render thread only.
#include <memory>
#include <vector>

#include "gpu/gl_object.h"
#include "gpu/readback_buffer.h"
#include "render/frame/pass_timer.h"
#include "render/frame/render_output.h"

namespace toond::render {

struct PendingFrame {
  RenderOutput out;  // everything but the pixels, when they are in flight
  PassTimer timer;   // writes out.timings
  // The main pass's cap checks (object_draw.h), read once the pixels are
  // back, when their answers are ready anyway.
  std::vector<gpu::Query> cap_checks;
  // Set while the pixels are in flight: the buffer they are packed into.
  std::unique_ptr<gpu::ReadbackBuffer> readback;
  bool unpremultiply = false;  // the plan's CPU step after the readback

  explicit PendingFrame(bool gpu_timers) : timer(out.timings, gpu_timers) {}
  PendingFrame(const PendingFrame&) = delete;
  PendingFrame& operator=(const PendingFrame&) = delete;
};

}  // namespace toond::render
