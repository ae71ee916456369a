#include "gpu/normal_depth_target.h"

#include <string>

#include "gpu/gpu_error.h"

namespace toond::gpu {

NormalDepthTarget::NormalDepthTarget(int width, int height) : width_(width), height_(height) {
  normal_depth_ = Texture::create(GL_TEXTURE_2D);
  glTextureStorage2D(normal_depth_.id(), 1, GL_RGBA32F, width, height);
  glTextureParameteri(normal_depth_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(normal_depth_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  depth_ = Renderbuffer::create();
  glNamedRenderbufferStorage(depth_.id(), GL_DEPTH_COMPONENT24, width, height);
  fbo_ = Framebuffer::create();
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, normal_depth_.id(), 0);
  glNamedFramebufferRenderbuffer(fbo_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  const GLenum status = glCheckNamedFramebufferStatus(fbo_.id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw GpuError("NormalDepthTarget: framebuffer incomplete (status " + std::to_string(status) + ")");
  }
}

void NormalDepthTarget::bind_for_drawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width_, height_);
  const float background[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, background);
  glClearNamedFramebufferfi(fbo_.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
}

}  // namespace toond::gpu
