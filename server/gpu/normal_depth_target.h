#pragma once
// The prepass of the screen-space edge pass: each pixel's normal and
// distance from the eye (RGBA32F; distance 0: background) and, apart, the
// share of it the model covers (R8). With several samples the prepass
// draws into a multisampled texture and a resolve pass
// (normal_depth_resolve.frag) turns the samples into those two values per
// pixel; the coverage then places a silhouette to a fraction of a pixel.
#include "gpu/gl_object.h"
#include "image/float_image.h"

namespace toond::gpu {

class NormalDepthTarget {
 public:
  // `samples` > 1 asks for a multisampled prepass: as many as asked, or as
  // many as the driver has for float textures.
  NormalDepthTarget(int width, int height, int samples);

  bool matches(int width, int height, int samples) const {
    return width == width_ && height == height_ && samples == requested_samples_;
  }
  int samples() const { return samples_; }
  bool needs_resolve() const { return samples_ > 1; }
  // The per-sample prepass, for the resolve pass (needs_resolve() only).
  GLuint sample_texture() const { return sample_texture_.id(); }
  // One value per pixel: what the edge pass reads.
  GLuint texture() const { return pixel_texture_.id(); }
  GLuint coverage_texture() const { return coverage_texture_.id(); }
  // Binds, sets the viewport and clears to "background" (all zero).
  void bind_for_drawing() const;
  // Binds the per-pixel texture for the resolve pass to write.
  void bind_for_resolve() const;
  // The per-pixel values, rows top to bottom, with the coverage as the
  // fourth value (the data layers' readback: they draw one sample a pixel
  // and keep their own fourth channel 0 or 1, the same as the coverage).
  image::FloatImage read_pixels() const;

 private:
  int width_;
  int height_;
  int requested_samples_;
  int samples_;
  Texture sample_texture_;  // multisampled only
  Texture pixel_texture_;
  Texture coverage_texture_;
  Renderbuffer depth_;
  Framebuffer draw_fbo_;
  Framebuffer resolve_fbo_;  // multisampled only
};

}  // namespace toond::gpu
