#include "image/downsample.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

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
  // One output row at a time: its sums fill from `factor` source rows read
  // front to back, then are encoded.
  std::vector<float> sums(static_cast<std::size_t>(out.width) * 4);
  for (int y = 0; y < out.height; ++y) {
    std::fill(sums.begin(), sums.end(), 0.0f);
    for (int dy = 0; dy < factor; ++dy) {
      const std::uint8_t* p = source.pixel(0, y * factor + dy);
      for (float* sum = sums.data(); sum != sums.data() + sums.size(); sum += 4) {
        for (int dx = 0; dx < factor; ++dx, p += 4) {
          const float alpha = static_cast<float>(p[3]) / 255.0f;
          sum[0] += to_linear[p[0]] * alpha;
          sum[1] += to_linear[p[1]] * alpha;
          sum[2] += to_linear[p[2]] * alpha;
          sum[3] += alpha;
        }
      }
    }
    std::uint8_t* q = out.pixel(0, y);
    for (const float* sum = sums.data(); sum != sums.data() + sums.size(); sum += 4, q += 4) {
      const float inv = sum[3] > 0 ? 1.0f / sum[3] : 0.0f;
      q[0] = linear_to_srgb_byte(sum[0] * inv);
      q[1] = linear_to_srgb_byte(sum[1] * inv);
      q[2] = linear_to_srgb_byte(sum[2] * inv);
      q[3] = static_cast<std::uint8_t>(std::lround(sum[3] / samples * 255.0f));
    }
  }
  return out;
}

}  // namespace toond::image
