#pragma once
// The offscreen framebuffer a render draws into: sRGB colour plus
// depth/stencil, multisampled when asked, resolved into a single-sample
// framebuffer for readback. Blending and the MSAA resolve happen on linear
// values because the colour format is sRGB and GL_FRAMEBUFFER_SRGB is on.
#include "gpu/gl_object.h"
#include "gpu/readback_buffer.h"
#include "image/image.h"

namespace toond::gpu {

class RenderTarget {
 public:
  RenderTarget(int width, int height, int samples);

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
  // through a pixel buffer object (readback_buffer.h).
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
  ReadbackBuffer readback_;
};

}  // namespace toond::gpu
