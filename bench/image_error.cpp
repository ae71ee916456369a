#include "image_error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "support/edge_measure.h"
#include "support/sphere_oracle.h"

namespace toond::bench {

namespace {

// Pixels in the largest 4-connected group of `off` ones.
std::size_t largest_blob(std::vector<std::uint8_t> off, int width, int height) {
  std::size_t largest = 0;
  std::vector<int> stack;
  for (int start = 0; start < width * height; ++start) {
    if (!off[static_cast<std::size_t>(start)]) continue;
    std::size_t size = 0;
    off[static_cast<std::size_t>(start)] = 0;
    stack.push_back(start);
    while (!stack.empty()) {
      const int p = stack.back();
      stack.pop_back();
      ++size;
      const int x = p % width, y = p / width;
      for (const int q :
           {x > 0 ? p - 1 : -1, x + 1 < width ? p + 1 : -1, y > 0 ? p - width : -1, y + 1 < height ? p + width : -1}) {
        if (q < 0 || !off[static_cast<std::size_t>(q)]) continue;
        off[static_cast<std::size_t>(q)] = 0;
        stack.push_back(q);
      }
    }
    largest = std::max(largest, size);
  }
  return largest;
}

}  // namespace

PixelError compare_images(const image::Image& reference, const image::Image& image) {
  if (reference.width != image.width || reference.height != image.height) {
    throw std::runtime_error("compare_images: sizes differ");
  }
  double sum = 0;
  const std::size_t pixels = reference.rgba.size() / 4;
  std::vector<std::uint8_t> off(pixels, 0);
  std::size_t off_count = 0;
  for (std::size_t i = 0; i < reference.rgba.size(); i += 4) {
    int worst = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      const int d = std::abs(int{reference.rgba[i + c]} - int{image.rgba[i + c]});
      sum += d;
      worst = std::max(worst, d);
    }
    off[i / 4] = worst > kOffTolerance ? 1 : 0;
    off_count += off[i / 4];
  }
  return {sum / static_cast<double>(pixels * 3), 100.0 * static_cast<double>(off_count) / static_cast<double>(pixels),
          largest_blob(std::move(off), reference.width, reference.height)};
}

BandEdgeError sphere_band_edge_error(const image::Image& silhouette, const image::Image& banded, int steps) {
  const test::DiskEstimate disk = test::estimate_disk(test::LinearChannel(silhouette, 1));
  const test::ErrorStats stats = test::band_edge_errors(banded, disk, steps, 3.0);
  return {stats.mean_abs, stats.max_abs, stats.missing};
}

}  // namespace toond::bench
