#pragma once
// The offscreen framebuffer a render draws into: sRGB colour plus
// depth/stencil, multisampled when asked, resolved into a single-sample
// framebuffer for readback. Blending and the MSAA resolve happen on linear
// values because the colour format is sRGB and GL_FRAMEBUFFER_SRGB is on.
#include <optional>

#include "gpu/gl_object.h"
#include "gpu/readback_buffer.h"
#include "image/image.h"

namespace toond::gpu {

// How pixels come back to the CPU. A GPU packs into a pixel buffer object by
// DMA (readback_buffer.h); a CPU rasterizer packs on the CPU inside
// glReadPixels whatever the destination, and there reading straight into
// the image and flipping it in place measured faster (Server-Timing's
// `readback`, README "Performance").
enum class ReadbackPath { PixelBuffer, ClientMemory };

class RenderTarget {
 public:
  RenderTarget(int width, int height, int samples, ReadbackPath readback = ReadbackPath::PixelBuffer);

  int width() const { return width_; }
  int height() const { return height_; }
  // The samples per pixel the driver gave: the request clamped to its
  // GL_MAX_SAMPLES, or rounded up to a count it has.
  int samples() const { return samples_; }
  // Whether this target is what a request for these would get.
  bool matches(int width, int height, int samples) const {
    return width == width_ && height == height_ && samples == requested_samples_;
  }

  // Binds the drawing framebuffer and sets the viewport.
  void bind_for_drawing() const;

  // Resolves (when multisampled) and reads the pixels back, top row first,
  // the way the target was made with.
  image::Image read_back() const;

 private:
  int width_;
  int height_;
  int requested_samples_;
  int samples_;
  Renderbuffer color_;
  Renderbuffer depth_stencil_;
  Framebuffer draw_fbo_;
  Renderbuffer resolved_color_;   // only with samples > 1
  Framebuffer resolve_fbo_;       // only with samples > 1
  std::optional<ReadbackBuffer> pixel_buffer_;  // only for ReadbackPath::PixelBuffer
};

}  // namespace toond::gpu
