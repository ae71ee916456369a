#include "support/image_checks.h"

#include <cmath>

namespace toond::test {

Rgb rgb_at(const Image& img, int x, int y) {
  const auto* p = img.pixel(x, y);
  return {p[0], p[1], p[2]};
}

double luminance(Rgb c) { return (0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b) / 255.0; }

std::vector<bool> foreground_mask(const Image& img) {
  const Rgb bg = rgb_at(img, 0, 0);
  std::vector<bool> mask(static_cast<std::size_t>(img.width) * img.height);
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      mask[static_cast<std::size_t>(y) * img.width + x] = rgb_at(img, x, y) != bg;
    }
  }
  return mask;
}

std::size_t count(const std::vector<bool>& mask) {
  std::size_t n = 0;
  for (bool b : mask) n += b ? 1 : 0;
  return n;
}

double coverage(const std::vector<bool>& mask) {
  return mask.empty() ? 0.0 : static_cast<double>(count(mask)) / static_cast<double>(mask.size());
}

std::map<Rgb, std::size_t> colour_histogram(const Image& img, const std::vector<bool>& mask) {
  std::map<Rgb, std::size_t> hist;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      if (mask[static_cast<std::size_t>(y) * img.width + x]) ++hist[rgb_at(img, x, y)];
    }
  }
  return hist;
}

std::size_t dominant_colours(const Image& img, const std::vector<bool>& mask, double min_fraction) {
  const auto hist = colour_histogram(img, mask);
  const double total = static_cast<double>(count(mask));
  std::size_t n = 0;
  for (const auto& [colour, pixels] : hist) {
    if (static_cast<double>(pixels) >= min_fraction * total) ++n;
  }
  return n;
}

std::vector<bool> boundary(const std::vector<bool>& mask, int width, int height) {
  std::vector<bool> out(mask.size());
  auto at = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < width && y < height && mask[static_cast<std::size_t>(y) * width + x];
  };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (at(x, y) && (!at(x - 1, y) || !at(x + 1, y) || !at(x, y - 1) || !at(x, y + 1))) {
        out[static_cast<std::size_t>(y) * width + x] = true;
      }
    }
  }
  return out;
}

}  // namespace toond::test
