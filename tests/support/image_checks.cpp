#include "support/image_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

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

double differing_share(const Image& a, const Image& b, int levels) {
  std::size_t differing = 0;
  for (std::size_t i = 0; i + 3 < a.rgba.size() && i + 3 < b.rgba.size(); i += 4) {
    for (std::size_t c = 0; c < 3; ++c) {
      if (std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])) > levels) {
        ++differing;
        break;
      }
    }
  }
  return a.rgba.empty() ? 0.0 : static_cast<double>(differing) / static_cast<double>(a.rgba.size() / 4);
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

namespace {

// Distances from every pixel on the ring's outer edge to the nearest model
// pixel, ascending.
std::vector<double> outline_distances(const Image& bare, const Image& outlined) {
  const int w = bare.width, h = bare.height;
  const auto model = foreground_mask(bare);
  std::vector<bool> ring(model.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      ring[static_cast<std::size_t>(y) * w + x] =
          !model[static_cast<std::size_t>(y) * w + x] && rgb_at(bare, x, y) != rgb_at(outlined, x, y);
  std::vector<bool> covered(model.size());
  for (std::size_t i = 0; i < covered.size(); ++i) covered[i] = model[i] || ring[i];
  const auto outer = boundary(covered, w, h);
  constexpr int kReach = 40;
  std::vector<double> distances;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      if (!ring[i] || !outer[i]) continue;
      double best = 1e9;
      for (int dy = -kReach; dy <= kReach; ++dy) {
        for (int dx = -kReach; dx <= kReach; ++dx) {
          const int xx = x + dx, yy = y + dy;
          if (xx < 0 || yy < 0 || xx >= w || yy >= h || !model[static_cast<std::size_t>(yy) * w + xx]) continue;
          best = std::min(best, std::hypot(dx, dy));
        }
      }
      if (best < 1e9) distances.push_back(best);
    }
  }
  std::sort(distances.begin(), distances.end());
  return distances;
}

}  // namespace

double outline_width_px(const Image& bare, const Image& outlined) {
  const std::vector<double> distances = outline_distances(bare, outlined);
  return distances.empty() ? 0.0 : distances[distances.size() / 2];
}

double outline_reach_px(const Image& bare, const Image& outlined) {
  const std::vector<double> distances = outline_distances(bare, outlined);
  return distances.empty() ? 0.0 : distances.back();
}

}  // namespace toond::test
