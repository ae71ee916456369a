#include "support/sphere_oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace toond::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

double ray_angle(int i) { return 2.0 * kPi * (i + 0.5) / kOracleRays; }

double distance_from_centre(const DiskEstimate& disk, int x, int y) {
  return std::hypot(x + 0.5 - disk.centre_x, y + 0.5 - disk.centre_y);
}

}  // namespace

ErrorStats band_edge_errors(const image::Image& img, const DiskEstimate& disk, int steps, double window) {
  const LinearChannel grey(img, 1);
  ErrorStats stats;
  for (int k = 1; k < steps; ++k) {
    const double expected = disk.radius * std::sqrt(1.0 - double(k * k) / double(steps * steps));
    const double midpoint = (k + 0.5) / steps;
    for (int i = 0; i < kOracleRays; ++i) {
      const auto found = ray_crossing(grey, disk.centre_x, disk.centre_y, ray_angle(i), expected - window,
                                      expected + window, midpoint);
      if (found)
        stats.add(*found - expected);
      else
        ++stats.missing;
    }
  }
  return stats;
}

std::size_t speck_pixels(const image::Image& img, const DiskEstimate& disk, int steps, double margin) {
  const LinearChannel r(img, 0), g(img, 1), b(img, 2);
  const double darkest = 0.5 / steps;
  std::size_t specks = 0;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      if (distance_from_centre(disk, x, y) > disk.radius - margin) continue;
      const double red = r.at(x, y), green = g.at(x, y), blue = b.at(x, y);
      const bool grey = std::abs(red - green) < 0.02 && std::abs(green - blue) < 0.02;
      if (!grey || green < darkest) ++specks;
    }
  }
  return specks;
}

RingStats outline_ring(const image::Image& img, const DiskEstimate& disk, double width) {
  const LinearChannel red(img, 0), green(img, 1), blue(img, 2);
  RingStats ring;
  ring.min_width = std::numeric_limits<double>::infinity();
  for (int i = 0; i < kOracleRays; ++i) {
    const double angle = ray_angle(i);
    // A line may lie outside the silhouette (hull, wireframe) or straddle
    // it (edges): both crossings are searched from a width inside it.
    const double from = disk.radius - width - 2;
    const auto inner = ray_crossing(green, disk.centre_x, disk.centre_y, angle, from, disk.radius + 2, 0.5);
    const auto outer = ray_crossing(red, disk.centre_x, disk.centre_y, angle, from, disk.radius + width + 2, 0.5);
    if (!inner || !outer) {
      ++ring.width_error.missing;
      continue;
    }
    const double measured = *outer - *inner;
    ring.width_error.add(measured - width);
    ring.min_width = std::min(ring.min_width, measured);
    ring.max_width = std::max(ring.max_width, measured);
  }
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      if (distance_from_centre(disk, x, y) < disk.radius + width + 2.0) continue;
      if (red.at(x, y) > 0.02 || green.at(x, y) > 0.02 || blue.at(x, y) < 0.98) ++ring.stray_pixels;
    }
  }
  return ring;
}

}  // namespace toond::test
