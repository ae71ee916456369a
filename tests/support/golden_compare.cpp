#include "support/golden_compare.h"

#include <algorithm>
#include <cstdlib>

namespace toond::test {

GoldenDiff compare_golden(const image::Image& reference, const image::Image& actual) {
  GoldenDiff diff;
  if (reference.width != actual.width || reference.height != actual.height ||
      reference.rgba.size() != actual.rgba.size()) {
    diff.same_size = false;
    return diff;
  }
  for (std::size_t i = 0; i < reference.rgba.size(); i += 4) {
    int worst = 0;
    for (std::size_t c = 0; c < 4; ++c) worst = std::max(worst, std::abs(reference.rgba[i + c] - actual.rgba[i + c]));
    diff.pixels_over += worst > kGoldenLevels ? 1 : 0;
    diff.largest = std::max(diff.largest, worst);
  }
  return diff;
}

image::Image side_by_side_diff(const image::Image& reference, const image::Image& actual) {
  const int w = std::max(reference.width, actual.width), h = std::max(reference.height, actual.height);
  image::Image out;
  out.width = 3 * w;
  out.height = h;
  out.rgba.assign(static_cast<std::size_t>(out.width) * h * 4, 0);
  auto pixel = [](const image::Image& img, int x, int y, std::size_t c) -> int {
    if (x >= img.width || y >= img.height) return 0;
    return img.rgba[(static_cast<std::size_t>(y) * img.width + x) * 4 + c];
  };
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (std::size_t c = 0; c < 3; ++c) {
        const int a = pixel(reference, x, y, c), b = pixel(actual, x, y, c);
        const std::size_t row = static_cast<std::size_t>(y) * out.width;
        out.rgba[(row + x) * 4 + c] = static_cast<std::uint8_t>(a);
        out.rgba[(row + w + x) * 4 + c] = static_cast<std::uint8_t>(b);
        out.rgba[(row + 2 * w + x) * 4 + c] = static_cast<std::uint8_t>(std::min(255, 8 * std::abs(a - b)));
      }
      for (int panel = 0; panel < 3; ++panel) {
        out.rgba[((static_cast<std::size_t>(y) * out.width) + panel * w + x) * 4 + 3] = 255;
      }
    }
  }
  return out;
}

}  // namespace toond::test
