#include "image/downsample.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace toond::image {
namespace {

const std::array<float, 256>& srgb_to_linear_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const float c = static_cast<float>(i) / 255.0f;
      t[static_cast<std::size_t>(i)] = c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
    }
    return t;
  }();
  return table;
}

std::uint8_t linear_to_srgb_byte(float linear) {
  const float c = linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
  return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
}

}  // namespace

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
