#include "support/edge_measure.h"

#include <algorithm>
#include <cmath>

namespace toond::test {

double srgb_byte_to_linear(int byte) {
  const double c = byte / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

LinearChannel::LinearChannel(const image::Image& img, int channel) : width(img.width), height(img.height) {
  values.reserve(static_cast<std::size_t>(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) values.push_back(srgb_byte_to_linear(img.pixel(x, y)[channel]));
}

double LinearChannel::at(int x, int y) const {
  x = std::clamp(x, 0, width - 1);
  y = std::clamp(y, 0, height - 1);
  return values[static_cast<std::size_t>(y) * width + x];
}

double LinearChannel::sample(double x, double y) const {
  // Pixel centres sit at half-integers.
  const double fx = x - 0.5, fy = y - 0.5;
  const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
  const double tx = fx - x0, ty = fy - y0;
  const double top = at(x0, y0) * (1 - tx) + at(x0 + 1, y0) * tx;
  const double bottom = at(x0, y0 + 1) * (1 - tx) + at(x0 + 1, y0 + 1) * tx;
  return top * (1 - ty) + bottom * ty;
}

DiskEstimate estimate_disk(const LinearChannel& coverage) {
  double sum = 0, sx = 0, sy = 0;
  for (int y = 0; y < coverage.height; ++y)
    for (int x = 0; x < coverage.width; ++x) {
      const double v = coverage.at(x, y);
      sum += v;
      sx += v * (x + 0.5);
      sy += v * (y + 0.5);
    }
  DiskEstimate d;
  d.area = sum;
  if (sum > 0) {
    d.centre_x = sx / sum;
    d.centre_y = sy / sum;
    d.radius = std::sqrt(sum / std::acos(-1.0));
  }
  return d;
}

std::optional<double> ray_crossing(const LinearChannel& channel, double cx, double cy, double angle, double from,
                                   double to, double level) {
  // A fiftieth of a pixel per step: the bilinear profile is piecewise
  // smooth, so linear interpolation between steps is far below the
  // tolerances measured with it.
  constexpr double step = 0.02;
  const double dx = std::cos(angle), dy = std::sin(angle);
  double prev_t = from;
  double prev = channel.sample(cx + dx * from, cy + dy * from) - level;
  for (double t = from + step; t <= to + 1e-9; t += step) {
    const double v = channel.sample(cx + dx * t, cy + dy * t) - level;
    if ((prev < 0) != (v < 0)) return prev_t + (t - prev_t) * prev / (prev - v);
    prev = v;
    prev_t = t;
  }
  return std::nullopt;
}

void ErrorStats::add(double error) {
  const double a = std::abs(error);
  mean_abs = (mean_abs * static_cast<double>(count) + a) / static_cast<double>(count + 1);
  max_abs = std::max(max_abs, a);
  ++count;
}

}  // namespace toond::test
