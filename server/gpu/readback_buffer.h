#pragma once
// Reads a framebuffer's pixels back through a pixel buffer object that stays
// mapped for its whole life (GL_MAP_PERSISTENT_BIT). glReadPixels packs into
// the buffer, a fence says when the pack is done, and the rows are copied
// out of the mapping bottom row last, so the image comes out top row first
// in one pass over the pixels. The wait follows the pack at once: frames
// are not pipelined on one context. Used where a GPU packs (render_target.h
// says when).
#include <cstddef>

#include "gpu/gl_object.h"
#include "image/image.h"

namespace toond::gpu {

class ReadbackBuffer {
 public:
  // Room for an RGBA8 image of width × height.
  ReadbackBuffer(int width, int height);

  // The colour attachment of `framebuffer` (single-sampled), top row first.
  image::Image read(GLuint framebuffer) const;

 private:
  int width_;
  int height_;
  std::size_t bytes_;
  Buffer buffer_;
  const std::uint8_t* mapped_ = nullptr;  // valid while buffer_ lives
};

}  // namespace toond::gpu
