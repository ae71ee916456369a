#pragma once
// A depth texture to render the shadow-casting light's view into, sampled
// with hardware depth comparison (sampler2DShadow) in the main pass.
#include "gpu/gl_object.h"

namespace toond::gpu {

class ShadowMap {
 public:
  explicit ShadowMap(int size);

  int size() const { return size_; }
  GLuint texture() const { return depth_.id(); }
  // Binds the depth-only framebuffer, sets the viewport, clears to far.
  void bind_for_drawing() const;

 private:
  int size_;
  Texture depth_;
  Framebuffer fbo_;
};

}  // namespace toond::gpu
