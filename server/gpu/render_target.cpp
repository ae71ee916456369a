#include "gpu/render_target.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "gpu/gpu_error.h"

namespace toond::gpu {
namespace {

void check_complete(GLuint fbo, const char* what) {
  const GLenum status = glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw GpuError(std::string("RenderTarget: ") + what + " framebuffer incomplete (status 0x" +
                   std::to_string(status) + ")");
  }
}

Renderbuffer make_storage(GLenum format, int width, int height, int samples) {
  Renderbuffer rb = Renderbuffer::create();
  if (samples > 1) {
    glNamedRenderbufferStorageMultisample(rb.id(), samples, format, width, height);
  } else {
    glNamedRenderbufferStorage(rb.id(), format, width, height);
  }
  return rb;
}

}  // namespace

RenderTarget::RenderTarget(int width, int height, int samples, ReadbackPath readback)
    : width_(width),
      height_(height),
      requested_samples_(samples),
      samples_(samples) {
  if (readback == ReadbackPath::PixelBuffer) pixel_buffer_.emplace(width, height);
  GLint max_samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  if (samples_ > max_samples) samples_ = max_samples;

  color_ = make_storage(GL_SRGB8_ALPHA8, width, height, samples_);
  if (samples_ > 1) {
    // A driver may give more samples than asked for (llvmpipe has no 2×
    // mode and gives 4): report, and match, what it gave.
    GLint given = samples_;
    glGetNamedRenderbufferParameteriv(color_.id(), GL_RENDERBUFFER_SAMPLES, &given);
    samples_ = std::max(samples_, static_cast<int>(given));
  }
  depth_stencil_ = make_storage(GL_DEPTH24_STENCIL8, width, height, samples_);
  draw_fbo_ = Framebuffer::create();
  glNamedFramebufferRenderbuffer(draw_fbo_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_.id());
  glNamedFramebufferRenderbuffer(draw_fbo_.id(), GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                 depth_stencil_.id());
  check_complete(draw_fbo_.id(), "draw");

  if (samples_ > 1) {
    resolved_color_ = make_storage(GL_SRGB8_ALPHA8, width, height, 1);
    resolve_fbo_ = Framebuffer::create();
    glNamedFramebufferRenderbuffer(resolve_fbo_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                   resolved_color_.id());
    check_complete(resolve_fbo_.id(), "resolve");
  }
}

void RenderTarget::bind_for_drawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_.id());
  glViewport(0, 0, width_, height_);
}

image::Image RenderTarget::read_back() const {
  GLuint source = draw_fbo_.id();
  if (samples_ > 1) {
    // The resolve averages samples; with an sRGB source and destination and
    // GL_FRAMEBUFFER_SRGB on, the average is taken on linear values.
    glBlitNamedFramebuffer(draw_fbo_.id(), resolve_fbo_.id(), 0, 0, width_, height_, 0, 0, width_,
                           height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    source = resolve_fbo_.id();
  }
  if (pixel_buffer_) return pixel_buffer_->read(source);

  image::Image img;
  img.width = width_;
  img.height = height_;
  img.rgba.resize(static_cast<std::size_t>(width_) * height_ * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, source);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  // GL's rows run bottom to top; images run top to bottom.
  const std::size_t row = static_cast<std::size_t>(width_) * 4;
  std::vector<std::uint8_t> tmp(row);
  for (int y = 0; y < height_ / 2; ++y) {
    auto* a = img.rgba.data() + static_cast<std::size_t>(y) * row;
    auto* b = img.rgba.data() + static_cast<std::size_t>(height_ - 1 - y) * row;
    std::memcpy(tmp.data(), a, row);
    std::memcpy(a, b, row);
    std::memcpy(b, tmp.data(), row);
  }
  return img;
}

}  // namespace toond::gpu
