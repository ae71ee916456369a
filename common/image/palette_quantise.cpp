#include "image/palette_quantise.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace toond::image {
namespace {

// A colour as one number whose order is (r, g, b): sorting these sorts
// colours the same way on every machine.
std::uint32_t pack(Rgb8 c) { return (std::uint32_t{c.r} << 16) | (std::uint32_t{c.g} << 8) | c.b; }
Rgb8 unpack(std::uint32_t p) {
  return {static_cast<std::uint8_t>(p >> 16), static_cast<std::uint8_t>(p >> 8), static_cast<std::uint8_t>(p)};
}
int channel(std::uint32_t p, int which) { return static_cast<int>((p >> (16 - 8 * which)) & 0xff); }

struct ColourCount {
  std::uint32_t colour;
  std::uint64_t pixels;
};

// Every visible colour of the images with how many pixels have it, in
// colour order.
std::vector<ColourCount> histogram(std::span<const Image* const> images) {
  std::vector<std::uint32_t> visible;
  for (const Image* image : images) {
    const std::size_t n = static_cast<std::size_t>(image->width) * image->height;
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint8_t* p = image->rgba.data() + i * 4;
      if (p[3] != 0) visible.push_back(pack({p[0], p[1], p[2]}));
    }
  }
  std::sort(visible.begin(), visible.end());
  std::vector<ColourCount> counts;
  for (std::uint32_t c : visible) {
    if (counts.empty() || counts.back().colour != c) counts.push_back({c, 0});
    ++counts.back().pixels;
  }
  return counts;
}

// A run [begin, end) of the histogram: the colours one palette entry stands for.
struct Box {
  std::size_t begin, end;
  std::uint64_t pixels = 0;
  int widest_channel = 0;
  int range = 0;  // of the widest channel
};

Box measure(const std::vector<ColourCount>& counts, std::size_t begin, std::size_t end) {
  Box box{begin, end};
  std::array<int, 3> lo{255, 255, 255}, hi{0, 0, 0};
  for (std::size_t i = begin; i < end; ++i) {
    box.pixels += counts[i].pixels;
    for (int ch = 0; ch < 3; ++ch) {
      lo[ch] = std::min(lo[ch], channel(counts[i].colour, ch));
      hi[ch] = std::max(hi[ch], channel(counts[i].colour, ch));
    }
  }
  for (int ch = 0; ch < 3; ++ch) {
    if (hi[ch] - lo[ch] > box.range) {
      box.range = hi[ch] - lo[ch];
      box.widest_channel = ch;
    }
  }
  return box;
}

Rgb8 mean_colour(const std::vector<ColourCount>& counts, const Box& box) {
  std::array<std::uint64_t, 3> sum{};
  for (std::size_t i = box.begin; i < box.end; ++i) {
    for (int ch = 0; ch < 3; ++ch)
      sum[ch] += static_cast<std::uint64_t>(channel(counts[i].colour, ch)) * counts[i].pixels;
  }
  auto mean = [&](int ch) { return static_cast<std::uint8_t>((sum[ch] + box.pixels / 2) / box.pixels); };
  return {mean(0), mean(1), mean(2)};
}

// 4×4 Bayer matrix: thresholds 0..15 spread so that any 2×2, and any
// run along a row, mixes high and low.
constexpr std::array<std::array<int, 4>, 4> kBayer4 = {{{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}}};

// How far apart the palette's colours lie per channel: the mean distance
// from an entry to its nearest other entry, divided by √3 since an offset
// added to all three channels moves √3 times as far. Dithering by this
// much mixes neighbouring entries in proportion to where a colour lies
// between them, and never reaches entries further off.
double dither_amplitude(std::span<const Rgb8> palette) {
  if (palette.size() < 2) return 0;
  double total = 0;
  for (std::size_t i = 0; i < palette.size(); ++i) {
    int nearest = std::numeric_limits<int>::max();
    for (std::size_t j = 0; j < palette.size(); ++j) {
      if (i == j) continue;
      const int dr = palette[i].r - palette[j].r, dg = palette[i].g - palette[j].g, db = palette[i].b - palette[j].b;
      nearest = std::min(nearest, dr * dr + dg * dg + db * db);
    }
    total += std::sqrt(static_cast<double>(nearest));
  }
  return total / static_cast<double>(palette.size()) / std::sqrt(3.0);
}

std::uint8_t clamp_byte(double v) { return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L)); }

}  // namespace

std::vector<Rgb8> median_cut_palette(std::span<const Image* const> images, int colours) {
  std::vector<ColourCount> counts = histogram(images);
  std::vector<Rgb8> palette;
  if (counts.empty()) return palette;
  if (counts.size() <= static_cast<std::size_t>(std::max(colours, 1))) {
    for (const ColourCount& c : counts) palette.push_back(unpack(c.colour));
    return palette;
  }

  std::vector<Box> boxes{measure(counts, 0, counts.size())};
  while (boxes.size() < static_cast<std::size_t>(colours)) {
    // The box that most needs splitting: many pixels over a wide range of
    // colour. Ties go to the earlier box, so the result is reproducible.
    auto score = [](const Box& b) { return b.end - b.begin < 2 ? 0.0 : static_cast<double>(b.pixels) * b.range; };
    const auto target =
        std::max_element(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) { return score(a) < score(b); });
    if (score(*target) == 0) break;  // every box is one colour
    const Box box = *target;
    const int ch = box.widest_channel;
    // Order the box's colours along its widest channel (colour order
    // breaks ties) and cut where half its pixels lie on either side.
    std::sort(counts.begin() + static_cast<std::ptrdiff_t>(box.begin),
              counts.begin() + static_cast<std::ptrdiff_t>(box.end), [ch](const ColourCount& a, const ColourCount& b) {
                const int ca = channel(a.colour, ch), cb = channel(b.colour, ch);
                return ca != cb ? ca < cb : a.colour < b.colour;
              });
    std::uint64_t below = 0;
    std::size_t cut = box.begin + 1;
    for (std::size_t i = box.begin; i < box.end - 1; ++i) {
      below += counts[i].pixels;
      cut = i + 1;
      if (2 * below >= box.pixels) break;
    }
    *target = measure(counts, box.begin, cut);
    boxes.push_back(measure(counts, cut, box.end));
  }
  std::vector<std::uint32_t> packed;
  for (const Box& box : boxes) packed.push_back(pack(mean_colour(counts, box)));
  std::sort(packed.begin(), packed.end());
  packed.erase(std::unique(packed.begin(), packed.end()), packed.end());
  for (std::uint32_t p : packed) palette.push_back(unpack(p));
  return palette;
}

int nearest_entry(std::span<const Rgb8> palette, Rgb8 c) {
  int best = 0;
  int best_distance = std::numeric_limits<int>::max();
  for (std::size_t i = 0; i < palette.size(); ++i) {
    const int dr = c.r - palette[i].r, dg = c.g - palette[i].g, db = c.b - palette[i].b;
    const int d = dr * dr + dg * dg + db * db;
    if (d < best_distance) {
      best_distance = d;
      best = static_cast<int>(i);
    }
  }
  return best;
}

void quantise_to_palette(Image& image, std::span<const Rgb8> palette, bool dither) {
  const double amplitude = dither ? dither_amplitude(palette) : 0.0;
  // Toon frames hold few distinct colours (and dithering adds only 16
  // thresholds to each): remembering each answer saves the search over
  // the palette for almost every pixel.
  std::unordered_map<std::uint32_t, std::uint8_t> answered;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      if (p[3] == 0) continue;
      const int threshold = dither ? kBayer4[y & 3][x & 3] : 0;
      const std::uint32_t key = pack({p[0], p[1], p[2]}) | (static_cast<std::uint32_t>(threshold) << 24);
      auto known = answered.find(key);
      if (known == answered.end()) {
        Rgb8 c{p[0], p[1], p[2]};
        if (dither) {
          // Thresholds centred on zero: (t + 0.5) / 16 − 0.5 in (−0.5, 0.5).
          const double offset = ((threshold + 0.5) / 16.0 - 0.5) * amplitude;
          c = {clamp_byte(c.r + offset), clamp_byte(c.g + offset), clamp_byte(c.b + offset)};
        }
        known = answered.emplace(key, static_cast<std::uint8_t>(nearest_entry(palette, c))).first;
      }
      const Rgb8 entry = palette[known->second];
      p[0] = entry.r;
      p[1] = entry.g;
      p[2] = entry.b;
    }
  }
}

}  // namespace toond::image
