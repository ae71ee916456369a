#pragma once
// The offscreen framebuffer a render draws into: sRGB colour plus
// depth/stencil, multisampled when asked, resolved into a single-sample
// framebuffer for readback. Blending and the MSAA resolve happen on linear
// values because the colour format is sRGB and GL_FRAMEBUFFER_SRGB is on.
// A supersampled target (`shrink` > 1) also holds the image shrunk by that
// factor: its single-sample colour is a texture the downsample pass reads,
// and only the shrunk image comes back.
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "gpu/gl_object.h"
#include "gpu/readback_buffer.h"
#include "image/image.h"

namespace toond::gpu {

// How pixels come back to the CPU. A GPU packs into a pixel buffer object by
// DMA (readback_buffer.h); a CPU rasterizer packs on the CPU inside
// glReadPixels whatever the destination, and there reading straight into
// the image and flipping it in place measured faster (Server-Timing's
// `readback`, docs/performance.md).
enum class ReadbackPath { PixelBuffer, ClientMemory };

class RenderTarget {
 public:
  RenderTarget(int width, int height, int samples, ReadbackPath readback = ReadbackPath::PixelBuffer, int shrink = 1);

  int width() const { return width_; }
  int height() const { return height_; }
  // The samples per pixel the driver gave: the request clamped to its
  // GL_MAX_SAMPLES, or rounded up to a count it has.
  int samples() const { return samples_; }
  // Where each sample lies in its pixel (0..1 from the pixel's lower left
  // corner), as the driver places them: a shader that tests the samples of
  // a pixel itself, rather than by interpolation, reads them here.
  const std::vector<glm::vec2>& sample_positions() const { return sample_positions_; }
  // Whether this target is what a request for these would get.
  bool matches(int width, int height, int samples, int shrink = 1) const {
    return width == width_ && height == height_ && samples == requested_samples_ && shrink == shrink_;
  }

  // Binds the drawing framebuffer and sets the viewport.
  void bind_for_drawing() const;
  // The depth and stencil drawn so far, every sample of it (a multisample
  // texture when the target has several): a pass that tests depth itself
  // reads it while it draws through bind_line_coverage or
  // bind_colour_alone, which leave it out (reading an attached buffer
  // would be a feedback loop).
  GLuint depth_texture() const { return depth_stencil_.id(); }
  // One sample a pixel only: binds a framebuffer of one channel (R8, made
  // on first use) without depth or stencil, sets the viewport and clears
  // it to 0; returns its texture. Where lines overlapping must darken a
  // pixel once (render/passes/crease_pass.cpp), their coverage gathers here
  // before it is laid over the image.
  GLuint bind_line_coverage();
  // Several samples a pixel only: binds a framebuffer of this target's
  // colour alone, without depth or stencil, and sets the viewport.
  void bind_colour_alone();

  // Shrinking targets only. Resolves the samples (when multisampled) into
  // the single-sample colour texture and returns that texture.
  GLuint resolve_for_shrinking() const;
  // Binds the framebuffer of the shrunk image and sets its viewport.
  void bind_for_shrinking() const;

  // Reads the pixels back, top row first, the way the target was made
  // with: the shrunk image of a shrinking target (the downsample pass has
  // drawn it), else the drawn one, resolved when multisampled.
  image::Image read_back();
  // The same image, packed into `into` (sized read_width() × read_height())
  // without waiting: `into.finish()` returns it. The target may be drawn
  // into again meanwhile; GL packs before it runs what comes after.
  void start_read_back(ReadbackBuffer& into) const;
  // The size of the image read back (the shrunk one when shrinking).
  int read_width() const { return width_ / shrink_; }
  int read_height() const { return height_ / shrink_; }

 private:
  void make_drawing_framebuffer();
  void find_sample_positions();
  void make_resolve_framebuffer();
  void make_shrunk_framebuffer();
  // The framebuffer holding one sample a pixel: the multisampled drawing
  // resolved into it, or the drawing itself.
  GLuint resolve() const;
  // The single-sample framebuffer the image is read from, resolved.
  GLuint read_source() const;

  int width_;
  int height_;
  int requested_samples_;
  int samples_;
  std::vector<glm::vec2> sample_positions_;
  int shrink_;
  Renderbuffer color_;     // multisampled, or without shrinking
  Texture depth_stencil_;  // a texture, for depth_texture()
  Framebuffer draw_fbo_;
  Renderbuffer resolved_color_;  // only with samples > 1, without shrinking
  Framebuffer resolve_fbo_;      // only with samples > 1
  Texture line_coverage_;        // bind_line_coverage's, made on first use
  Framebuffer line_coverage_fbo_;
  Framebuffer colour_alone_fbo_;                // bind_colour_alone's, made on first use
  Texture single_color_;                        // shrinking only: the resolve's target, or the drawn colour
  Renderbuffer shrunk_color_;                   // shrinking only
  Framebuffer shrunk_fbo_;                      // shrinking only
  std::optional<ReadbackBuffer> pixel_buffer_;  // only for ReadbackPath::PixelBuffer
};

}  // namespace toond::gpu
