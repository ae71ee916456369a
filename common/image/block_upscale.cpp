#include "image/block_upscale.h"

#include <cstring>

namespace toond::image {

void blit_upscaled(const Image& source, int factor, Image& target, int x, int y) {
  const std::size_t row_bytes = static_cast<std::size_t>(source.width) * factor * 4;
  for (int sy = 0; sy < source.height; ++sy) {
    // One row widened, then copied to the other rows of its blocks.
    std::uint8_t* first = target.pixel(x, y + sy * factor);
    for (int sx = 0; sx < source.width; ++sx) {
      const std::uint8_t* p = source.pixel(sx, sy);
      for (int i = 0; i < factor; ++i) std::memcpy(first + (static_cast<std::size_t>(sx) * factor + i) * 4, p, 4);
    }
    for (int i = 1; i < factor; ++i) std::memcpy(target.pixel(x, y + sy * factor + i), first, row_bytes);
  }
}

}  // namespace toond::image
