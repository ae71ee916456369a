#pragma once
// Uniform blocks packed into one buffer, each at an offset a uniform-buffer
// binding accepts, then uploaded in one call: a frame's per-object blocks
// or a model's per-material ones, bound range by range as draws need them.
// Render thread only.
#include <cstddef>
#include <cstring>
#include <vector>

#include "gpu/gl_object.h"

namespace toond::gpu {

class UniformArena {
 public:
  UniformArena();

  // Appends a block (a std140 mirror struct); returns where it lies.
  template <class Block>
  std::size_t add(const Block& block) {
    const std::size_t at = (bytes_.size() + alignment_ - 1) / alignment_ * alignment_;
    bytes_.resize(at + sizeof(Block));
    std::memcpy(bytes_.data() + at, &block, sizeof(Block));
    return at;
  }
  // Drops the blocks added; the buffer stays for the next upload.
  void clear() { bytes_.clear(); }
  // Copies every block added so far to the GPU, growing the buffer if it
  // must.
  void upload();
  // Binds `size` bytes at `offset` (as add() returned) to a block binding.
  void bind(GLuint binding, std::size_t offset, std::size_t size) const;

 private:
  std::size_t alignment_;
  std::vector<std::byte> bytes_;
  Buffer buffer_;
  std::size_t capacity_ = 0;
};

}  // namespace toond::gpu
