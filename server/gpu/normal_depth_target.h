#pragma once
// Single-sample framebuffer holding each pixel's normal and distance from the
// eye (RGBA32F) with its own depth buffer: the input of the screen-space
// edge pass.
#include "gpu/gl_object.h"

namespace toond::gpu {

class NormalDepthTarget {
 public:
  NormalDepthTarget(int width, int height);

  bool matches(int width, int height) const { return width == width_ && height == height_; }
  GLuint texture() const { return normal_depth_.id(); }
  // Binds, sets the viewport and clears to "background" (w = 0).
  void bind_for_drawing() const;

 private:
  int width_;
  int height_;
  Texture normal_depth_;
  Renderbuffer depth_;
  Framebuffer fbo_;
};

}  // namespace toond::gpu
