#include "image/downsample.h"

#include <cmath>
#include <stdexcept>

#include "image/srgb.h"

namespace toond::image {

Image downsample_box(const Image& source, int factor) {
  if (factor == 1) return source;
  if (factor < 1 || source.width % factor != 0 || source.height % factor != 0) {
    throw std::invalid_argument("downsample_box: size is not a multiple of the factor");
  }
  const auto& to_linear = srgb_to_linear_table();
  Image out;
  out.width = source.width / factor;
  out.height = source.height / factor;
  out.rgba.resize(static_cast<std::size_t>(out.width) * out.height * 4);
  const float samples = static_cast<float>(factor * factor);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      float r = 0, g = 0, b = 0, a = 0;
      for (int dy = 0; dy < factor; ++dy) {
        for (int dx = 0; dx < factor; ++dx) {
          const std::uint8_t* p = source.pixel(x * factor + dx, y * factor + dy);
          const float alpha = static_cast<float>(p[3]) / 255.0f;
          r += to_linear[p[0]] * alpha;
          g += to_linear[p[1]] * alpha;
          b += to_linear[p[2]] * alpha;
          a += alpha;
        }
      }
      std::uint8_t* q = out.pixel(x, y);
      const float inv = a > 0 ? 1.0f / a : 0.0f;
      q[0] = linear_to_srgb_byte(r * inv);
      q[1] = linear_to_srgb_byte(g * inv);
      q[2] = linear_to_srgb_byte(b * inv);
      q[3] = static_cast<std::uint8_t>(std::lround(a / samples * 255.0f));
    }
  }
  return out;
}

}  // namespace toond::image
