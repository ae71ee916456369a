#include "image/unpremultiply.h"

#include "image/srgb.h"

namespace toond::image {

void unpremultiply_linear(Image& image) {
  const auto& to_linear = srgb_to_linear_table();
  for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
    std::uint8_t* p = image.rgba.data() + i;
    if (p[3] == 255) continue;
    if (p[3] == 0) {
      p[0] = p[1] = p[2] = 0;
      continue;
    }
    const float inv_alpha = 255.0f / static_cast<float>(p[3]);
    for (int c = 0; c < 3; ++c) p[c] = linear_to_srgb_byte(to_linear[p[c]] * inv_alpha);
  }
}

}  // namespace toond::image
