#include "image_error.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "support/edge_measure.h"

namespace toond::bench {

PixelError compare_images(const image::Image& reference, const image::Image& image) {
  if (reference.width != image.width || reference.height != image.height) {
    throw std::runtime_error("compare_images: sizes differ");
  }
  double sum = 0;
  std::size_t off = 0;
  const std::size_t pixels = reference.rgba.size() / 4;
  for (std::size_t i = 0; i < reference.rgba.size(); i += 4) {
    int worst = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      const int d = std::abs(int{reference.rgba[i + c]} - int{image.rgba[i + c]});
      sum += d;
      worst = std::max(worst, d);
    }
    off += worst > kOffTolerance ? 1 : 0;
  }
  return {sum / static_cast<double>(pixels * 3), 100.0 * static_cast<double>(off) / static_cast<double>(pixels)};
}

BandEdgeError sphere_band_edge_error(const image::Image& silhouette, const image::Image& banded, int steps) {
  constexpr double kPi = 3.14159265358979323846;
  constexpr int kRays = 720;
  const test::DiskEstimate disk = test::estimate_disk(test::LinearChannel(silhouette, 1));
  const test::LinearChannel grey(banded, 1);
  test::ErrorStats stats;
  for (int k = 1; k < steps; ++k) {
    const double expected = disk.radius * std::sqrt(1.0 - double(k * k) / double(steps * steps));
    const double midpoint = (k + 0.5) / steps;  // between the linear levels k/N and (k+1)/N
    for (int i = 0; i < kRays; ++i) {
      const double angle = 2.0 * kPi * (i + 0.5) / kRays;
      const auto found =
          test::ray_crossing(grey, disk.centre_x, disk.centre_y, angle, expected - 3.0, expected + 3.0, midpoint);
      if (found) stats.add(*found - expected);
      else ++stats.missing;
    }
  }
  return {stats.mean_abs, stats.max_abs, stats.missing};
}

}  // namespace toond::bench
