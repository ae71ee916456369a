#pragma once
// Reads a framebuffer's pixels back through a pixel buffer object that stays
// mapped for its whole life (GL_MAP_PERSISTENT_BIT). glReadPixels packs into
// the buffer, a fence says when the pack is done, and the rows are copied
// out of the mapping bottom row last, so the image comes out top row first
// in one pass over the pixels. read() waits for the pack at once; start()
// and finish() let the render thread record the next frame in between
// (frames in flight, render/run/pending_frame.h). Used where a GPU packs
// (render_target.h says when), and for every frame kept in flight.
#include <cstddef>
#include <optional>

#include "gpu/gl_object.h"
#include "image/image.h"

namespace toond::gpu {

class ReadbackBuffer {
 public:
  // Room for an RGBA8 image of width × height.
  ReadbackBuffer(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }

  // The colour attachment of `framebuffer` (single-sampled), top row first.
  image::Image read(GLuint framebuffer) {
    start(framebuffer);
    return finish();
  }
  // Queues the pack of `framebuffer`'s colour into this buffer, behind every
  // command recorded so far, and returns without waiting.
  void start(GLuint framebuffer);
  // Waits for the pack start() queued and copies the image out.
  image::Image finish();

 private:
  int width_;
  int height_;
  std::size_t bytes_;
  Buffer buffer_;
  const std::uint8_t* mapped_ = nullptr;  // valid while buffer_ lives
  std::optional<Fence> packed_;           // set by start(), cleared by finish()
};

}  // namespace toond::gpu
