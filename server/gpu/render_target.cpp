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

// Depth and stencil a pass may read (texelFetch) while it draws into a
// framebuffer without them: every sample of it when multisampled.
Texture make_depth_texture(int width, int height, int samples) {
  if (samples > 1) {
    Texture texture = Texture::create(GL_TEXTURE_2D_MULTISAMPLE);
    glTextureStorage2DMultisample(texture.id(), samples, GL_DEPTH24_STENCIL8, width, height, GL_TRUE);
    return texture;
  }
  Texture texture = Texture::create(GL_TEXTURE_2D);
  glTextureStorage2D(texture.id(), 1, GL_DEPTH24_STENCIL8, width, height);
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return texture;
}

Texture single_sample_texture(int width, int height) {
  Texture texture = Texture::create(GL_TEXTURE_2D);
  glTextureStorage2D(texture.id(), 1, GL_SRGB8_ALPHA8, width, height);
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return texture;
}

}  // namespace

RenderTarget::RenderTarget(int width, int height, int samples, ReadbackPath readback, int shrink)
    : width_(width), height_(height), requested_samples_(samples), samples_(samples), shrink_(shrink) {
  if (shrink_ < 1 || width % shrink_ != 0 || height % shrink_ != 0) {
    throw GpuError("RenderTarget: " + std::to_string(width) + "x" + std::to_string(height) +
                   " is not a multiple of the shrink factor " + std::to_string(shrink_));
  }
  if (readback == ReadbackPath::PixelBuffer) pixel_buffer_.emplace(width / shrink_, height / shrink_);
  GLint max_samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples_ = std::clamp(samples_, 1, static_cast<int>(max_samples));

  make_drawing_framebuffer();
  if (samples_ > 1) make_resolve_framebuffer();
  if (shrink_ > 1) make_shrunk_framebuffer();
}

void RenderTarget::make_drawing_framebuffer() {
  draw_fbo_ = Framebuffer::create();
  if (shrink_ > 1) single_color_ = single_sample_texture(width_, height_);
  if (samples_ > 1 || shrink_ == 1) {
    color_ = make_storage(GL_SRGB8_ALPHA8, width_, height_, samples_);
    glNamedFramebufferRenderbuffer(draw_fbo_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_.id());
  } else {
    // One sample and shrinking: the drawing goes straight into the texture
    // the downsample pass reads.
    glNamedFramebufferTexture(draw_fbo_.id(), GL_COLOR_ATTACHMENT0, single_color_.id(), 0);
  }
  if (samples_ > 1) {
    // A driver may give more samples than asked for (llvmpipe has no 2×
    // mode and gives 4): report, and match, what it gave.
    GLint given = samples_;
    glGetNamedRenderbufferParameteriv(color_.id(), GL_RENDERBUFFER_SAMPLES, &given);
    samples_ = std::max(samples_, static_cast<int>(given));
  }
  depth_stencil_ = make_depth_texture(width_, height_, samples_);
  glNamedFramebufferTexture(draw_fbo_.id(), GL_DEPTH_STENCIL_ATTACHMENT, depth_stencil_.id(), 0);
  check_complete(draw_fbo_.id(), "draw");
  find_sample_positions();
}

void RenderTarget::find_sample_positions() {
  if (samples_ == 1) {
    sample_positions_ = {glm::vec2(0.5f)};
    return;
  }
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, draw_fbo_.id());
  sample_positions_.resize(static_cast<std::size_t>(samples_));
  for (std::size_t k = 0; k < sample_positions_.size(); ++k)
    glGetMultisamplefv(GL_SAMPLE_POSITION, static_cast<GLuint>(k), &sample_positions_[k].x);
}

GLuint RenderTarget::bind_line_coverage() {
  if (samples_ > 1) throw GpuError("RenderTarget: a line coverage channel is for one sample a pixel");
  if (!line_coverage_fbo_) {
    line_coverage_ = Texture::create(GL_TEXTURE_2D);
    glTextureStorage2D(line_coverage_.id(), 1, GL_R8, width_, height_);
    line_coverage_fbo_ = Framebuffer::create();
    glNamedFramebufferTexture(line_coverage_fbo_.id(), GL_COLOR_ATTACHMENT0, line_coverage_.id(), 0);
    check_complete(line_coverage_fbo_.id(), "line coverage");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, line_coverage_fbo_.id());
  glViewport(0, 0, width_, height_);
  const float none[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(line_coverage_fbo_.id(), GL_COLOR, 0, none);
  return line_coverage_.id();
}

void RenderTarget::bind_colour_alone() {
  if (samples_ == 1) throw GpuError("RenderTarget: drawing the colour alone is for several samples a pixel");
  if (!colour_alone_fbo_) {
    colour_alone_fbo_ = Framebuffer::create();
    glNamedFramebufferRenderbuffer(colour_alone_fbo_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_.id());
    check_complete(colour_alone_fbo_.id(), "colour alone");
  }
  glBindFramebuffer(GL_FRAMEBUFFER, colour_alone_fbo_.id());
  glViewport(0, 0, width_, height_);
}

// The samples resolve into what is read next: the texture the downsample
// pass reads when shrinking, else a renderbuffer read back as it is.
void RenderTarget::make_resolve_framebuffer() {
  resolve_fbo_ = Framebuffer::create();
  if (shrink_ > 1) {
    glNamedFramebufferTexture(resolve_fbo_.id(), GL_COLOR_ATTACHMENT0, single_color_.id(), 0);
  } else {
    resolved_color_ = make_storage(GL_SRGB8_ALPHA8, width_, height_, 1);
    glNamedFramebufferRenderbuffer(resolve_fbo_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolved_color_.id());
  }
  check_complete(resolve_fbo_.id(), "resolve");
}

void RenderTarget::make_shrunk_framebuffer() {
  shrunk_color_ = make_storage(GL_SRGB8_ALPHA8, width_ / shrink_, height_ / shrink_, 1);
  shrunk_fbo_ = Framebuffer::create();
  glNamedFramebufferRenderbuffer(shrunk_fbo_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, shrunk_color_.id());
  check_complete(shrunk_fbo_.id(), "shrunk");
}

void RenderTarget::bind_for_drawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_.id());
  glViewport(0, 0, width_, height_);
}

GLuint RenderTarget::resolve() const {
  if (samples_ == 1) return draw_fbo_.id();
  // The resolve averages samples; with an sRGB source and destination and
  // GL_FRAMEBUFFER_SRGB on, the average is taken on linear values.
  glBlitNamedFramebuffer(draw_fbo_.id(), resolve_fbo_.id(), 0, 0, width_, height_, 0, 0, width_, height_,
                         GL_COLOR_BUFFER_BIT, GL_NEAREST);
  return resolve_fbo_.id();
}

GLuint RenderTarget::resolve_for_shrinking() const {
  if (shrink_ == 1) throw GpuError("RenderTarget: resolve_for_shrinking on a target that does not shrink");
  resolve();
  return single_color_.id();
}

void RenderTarget::bind_for_shrinking() const {
  glBindFramebuffer(GL_FRAMEBUFFER, shrunk_fbo_.id());
  glViewport(0, 0, width_ / shrink_, height_ / shrink_);
}

GLuint RenderTarget::read_source() const { return shrink_ > 1 ? shrunk_fbo_.id() : resolve(); }

void RenderTarget::start_read_back(ReadbackBuffer& into) const {
  if (into.width() != read_width() || into.height() != read_height()) {
    throw GpuError("RenderTarget: a readback buffer of " + std::to_string(into.width()) + "x" +
                   std::to_string(into.height()) + " for an image of " + std::to_string(read_width()) + "x" +
                   std::to_string(read_height()));
  }
  into.start(read_source());
}

image::Image RenderTarget::read_back() {
  const GLuint source = read_source();
  if (pixel_buffer_) return pixel_buffer_->read(source);

  image::Image img;
  img.width = read_width();
  img.height = read_height();
  img.rgba.resize(static_cast<std::size_t>(img.width) * img.height * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, source);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  // GL's rows run bottom to top; images run top to bottom.
  const std::size_t row = static_cast<std::size_t>(img.width) * 4;
  std::vector<std::uint8_t> tmp(row);
  for (int y = 0; y < img.height / 2; ++y) {
    auto* a = img.rgba.data() + static_cast<std::size_t>(y) * row;
    auto* b = img.rgba.data() + static_cast<std::size_t>(img.height - 1 - y) * row;
    std::memcpy(tmp.data(), a, row);
    std::memcpy(a, b, row);
    std::memcpy(b, tmp.data(), row);
  }
  return img;
}

}  // namespace toond::gpu
