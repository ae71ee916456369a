#include "gpu/uniform_arena.h"

#include <algorithm>

namespace toond::gpu {
namespace {

std::size_t offset_alignment() {
  GLint alignment = 0;
  glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &alignment);
  // std140 blocks start on 16 bytes whatever the driver allows.
  return std::max<std::size_t>(16, static_cast<std::size_t>(alignment));
}

}  // namespace

UniformArena::UniformArena() : alignment_(offset_alignment()) {}

void UniformArena::upload() {
  if (bytes_.empty()) return;
  if (!buffer_ || capacity_ < bytes_.size()) {
    // Room to grow, so a frame with one more object does not reallocate.
    capacity_ = std::max(bytes_.size(), 2 * capacity_);
    buffer_ = Buffer::create();
    glNamedBufferStorage(buffer_.id(), static_cast<GLsizeiptr>(capacity_), nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  glNamedBufferSubData(buffer_.id(), 0, static_cast<GLsizeiptr>(bytes_.size()), bytes_.data());
}

void UniformArena::bind(GLuint binding, std::size_t offset, std::size_t size) const {
  glBindBufferRange(GL_UNIFORM_BUFFER, binding, buffer_.id(), static_cast<GLintptr>(offset),
                    static_cast<GLsizeiptr>(size));
}

}  // namespace toond::gpu
