#include "gpu/normal_depth_target.h"

#include <algorithm>
#include <string>

#include "gpu/gpu_error.h"

namespace toond::gpu {
namespace {

int float_texture_samples(int wanted) {
  if (wanted <= 1) return 1;
  GLint max_color = 1;
  GLint max_depth = 1;
  glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &max_color);
  glGetIntegerv(GL_MAX_SAMPLES, &max_depth);
  return std::max(1, std::min({wanted, static_cast<int>(max_color), static_cast<int>(max_depth)}));
}

Texture pixel_texture(GLenum format, int width, int height) {
  Texture texture = Texture::create(GL_TEXTURE_2D);
  glTextureStorage2D(texture.id(), 1, format, width, height);
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return texture;
}

void check_complete(const Framebuffer& fbo, const char* which, int samples) {
  const GLenum status = glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw GpuError(std::string("NormalDepthTarget: ") + which + " framebuffer incomplete (status " +
                   std::to_string(status) + ", " + std::to_string(samples) + " samples)");
  }
}

}  // namespace

NormalDepthTarget::NormalDepthTarget(int width, int height, int samples)
    : width_(width), height_(height), requested_samples_(samples), samples_(float_texture_samples(samples)) {
  pixel_texture_ = pixel_texture(GL_RGBA32F, width, height);
  coverage_texture_ = pixel_texture(GL_R8, width, height);
  // The prepass (one sample) or the resolve (several) writes both.
  const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  depth_ = Renderbuffer::create();
  draw_fbo_ = Framebuffer::create();
  if (samples_ > 1) {
    sample_texture_ = Texture::create(GL_TEXTURE_2D_MULTISAMPLE);
    // Fixed sample locations: every pixel's samples cover it alike, so a
    // count of covered samples is the same share of area everywhere.
    glTextureStorage2DMultisample(sample_texture_.id(), samples_, GL_RGBA32F, width, height, GL_TRUE);
    glNamedRenderbufferStorageMultisample(depth_.id(), samples_, GL_DEPTH_COMPONENT24, width, height);
    glNamedFramebufferTexture(draw_fbo_.id(), GL_COLOR_ATTACHMENT0, sample_texture_.id(), 0);
    resolve_fbo_ = Framebuffer::create();
    glNamedFramebufferTexture(resolve_fbo_.id(), GL_COLOR_ATTACHMENT0, pixel_texture_.id(), 0);
    glNamedFramebufferTexture(resolve_fbo_.id(), GL_COLOR_ATTACHMENT1, coverage_texture_.id(), 0);
    glNamedFramebufferDrawBuffers(resolve_fbo_.id(), 2, both);
    check_complete(resolve_fbo_, "resolve", 1);
  } else {
    glNamedRenderbufferStorage(depth_.id(), GL_DEPTH_COMPONENT24, width, height);
    glNamedFramebufferTexture(draw_fbo_.id(), GL_COLOR_ATTACHMENT0, pixel_texture_.id(), 0);
    glNamedFramebufferTexture(draw_fbo_.id(), GL_COLOR_ATTACHMENT1, coverage_texture_.id(), 0);
    glNamedFramebufferDrawBuffers(draw_fbo_.id(), 2, both);
  }
  glNamedFramebufferRenderbuffer(draw_fbo_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  check_complete(draw_fbo_, "prepass", samples_);
}

void NormalDepthTarget::bind_for_drawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_.id());
  glViewport(0, 0, width_, height_);
  const float background[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(draw_fbo_.id(), GL_COLOR, 0, background);
  if (samples_ == 1) glClearNamedFramebufferfv(draw_fbo_.id(), GL_COLOR, 1, background);
  glClearNamedFramebufferfi(draw_fbo_.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
}

image::FloatImage NormalDepthTarget::read_pixels() const {
  image::FloatImage out;
  out.width = width_;
  out.height = height_;
  const std::size_t row = static_cast<std::size_t>(width_) * 4;
  std::vector<float> gl_rows(row * height_);
  glGetTextureImage(pixel_texture_.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(gl_rows.size() * sizeof(float)),
                    gl_rows.data());
  out.values.resize(gl_rows.size());
  // GL's rows run bottom to top; images run top to bottom.
  for (int y = 0; y < height_; ++y) {
    std::copy_n(gl_rows.data() + static_cast<std::size_t>(height_ - 1 - y) * row, row,
                out.values.data() + static_cast<std::size_t>(y) * row);
  }
  return out;
}

void NormalDepthTarget::bind_for_resolve() const {
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_.id());
  glViewport(0, 0, width_, height_);
}

}  // namespace toond::gpu
