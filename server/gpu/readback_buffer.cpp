#include "gpu/readback_buffer.h"

#include <cstdint>
#include <cstring>
#include <string>

#include "gpu/gpu_error.h"

namespace toond::gpu {
namespace {

// Blocks until every command before `fence` has finished. The first wait
// flushes, so the fence cannot sit unsubmitted in this context.
void wait_for(const Fence& fence) {
  if (fence.get() == nullptr) throw GpuError("glFenceSync failed while reading pixels back");
  GLbitfield flags = GL_SYNC_FLUSH_COMMANDS_BIT;
  for (;;) {
    const GLenum state = glClientWaitSync(fence.get(), flags, std::uint64_t{1'000'000'000});
    if (state == GL_ALREADY_SIGNALED || state == GL_CONDITION_SATISFIED) return;
    if (state == GL_WAIT_FAILED) throw GpuError("glClientWaitSync failed while reading pixels back");
    flags = 0;  // GL_TIMEOUT_EXPIRED: a slow frame; a lost context is the caller's to find
  }
}

}  // namespace

ReadbackBuffer::ReadbackBuffer(int width, int height)
    : width_(width),
      height_(height),
      bytes_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4),
      buffer_(Buffer::create()) {
  const GLbitfield access = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT;
  const auto size = static_cast<GLsizeiptr>(bytes_);
  glNamedBufferStorage(buffer_.id(), size, nullptr, access | GL_CLIENT_STORAGE_BIT);
  mapped_ = static_cast<const std::uint8_t*>(glMapNamedBufferRange(buffer_.id(), 0, size, access));
  if (mapped_ == nullptr) {
    throw GpuError("ReadbackBuffer: could not map a pixel buffer of " + std::to_string(bytes_) + " bytes");
  }
}

void ReadbackBuffer::start(GLuint framebuffer) {
  if (packed_) throw GpuError("ReadbackBuffer: a second pack started before the first one was finished");
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer_.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  // Without GL_MAP_COHERENT_BIT the pack must be made visible to the
  // mapping before the fence that says it is done.
  glMemoryBarrier(GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
  packed_.emplace();
}

image::Image ReadbackBuffer::finish() {
  if (!packed_) throw GpuError("ReadbackBuffer: finish() without a pack started");
  wait_for(*packed_);
  packed_.reset();

  image::Image img;
  img.width = width_;
  img.height = height_;
  img.rgba.resize(bytes_);
  // GL's rows run bottom to top; images run top to bottom.
  const std::size_t row = static_cast<std::size_t>(width_) * 4;
  for (int y = 0; y < height_; ++y) {
    std::memcpy(img.rgba.data() + static_cast<std::size_t>(y) * row,
                mapped_ + static_cast<std::size_t>(height_ - 1 - y) * row, row);
  }
  return img;
}

}  // namespace toond::gpu
