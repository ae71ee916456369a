#include "gpu/shadow_map.h"

#include <string>

#include "gpu/gpu_error.h"

namespace toond::gpu {

ShadowMap::ShadowMap(int size) : size_(size) {
  depth_ = Texture::create(GL_TEXTURE_2D);
  glTextureStorage2D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, size, size);
  glTextureParameteri(depth_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(depth_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // Outside the map nothing casts: sample as fully lit.
  glTextureParameteri(depth_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTextureParameteri(depth_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float far_depth[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glTextureParameterfv(depth_.id(), GL_TEXTURE_BORDER_COLOR, far_depth);
  glTextureParameteri(depth_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTextureParameteri(depth_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  fbo_ = Framebuffer::create();
  glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  glNamedFramebufferDrawBuffer(fbo_.id(), GL_NONE);
  glNamedFramebufferReadBuffer(fbo_.id(), GL_NONE);
  const GLenum status = glCheckNamedFramebufferStatus(fbo_.id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw GpuError("ShadowMap: framebuffer incomplete (status " + std::to_string(status) + ")");
  }
}

void ShadowMap::bind_for_drawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, size_, size_);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
}

}  // namespace toond::gpu
