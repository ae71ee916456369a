#include "image/palette.h"

#include <algorithm>
#include <atomic>
#include <utility>

#include "parallel/parallel_tasks.h"

namespace toond::image {
namespace {

Rgba8 unpack(std::uint32_t packed) {
  std::uint8_t bytes[4];
  std::memcpy(bytes, &packed, 4);
  return {bytes[0], bytes[1], bytes[2], bytes[3]};
}

// Whether the kBlockPixels pixels at `in` are all `colour`: one test for a
// stretch of a flat band, which the compiler turns into a few vector compares.
constexpr int kBlockPixels = 8;
bool block_is(const std::uint8_t* in, std::uint32_t colour) {
  std::uint32_t differ = 0;
  for (int k = 0; k < kBlockPixels; ++k) differ |= load_rgba(in + 4 * k) ^ colour;
  return differ == 0;
}

// Adds the colours of rows [first_row, end_row) to the band's table. Toon
// frames are long runs of one colour, so a pixel equal to its left neighbour
// costs one compare. Gives up, setting `too_many`, once the band alone has
// too many colours, and as soon as another band has set it.
void collect_colours(const Image& image, int first_row, int end_row, ColourTable& table, std::atomic<bool>& too_many) {
  std::uint32_t previous = load_rgba(image.pixel(0, first_row));
  if (table.index_of(previous) < 0) return;
  for (int y = first_row; y < end_row; ++y) {
    if (too_many.load(std::memory_order_relaxed)) return;
    const std::uint8_t* in = image.pixel(0, y);
    for (int x = 0; x < image.width;) {
      if (x + kBlockPixels <= image.width && block_is(in, previous)) {
        x += kBlockPixels;
        in += 4 * kBlockPixels;
        continue;
      }
      for (const int end = std::min(image.width, x + kBlockPixels); x < end; ++x, in += 4) {
        const std::uint32_t colour = load_rgba(in);
        if (colour == previous) continue;
        previous = colour;
        if (table.index_of(colour) < 0) {
          too_many.store(true, std::memory_order_relaxed);
          return;
        }
      }
    }
  }
}

// Every band's colours in one table; nullopt past 256.
std::optional<ColourTable> merge(const std::vector<ColourTable>& bands) {
  ColourTable merged;
  for (const ColourTable& band : bands) {
    for (const std::uint32_t colour : band.colours()) {
      if (merged.index_of(colour) < 0) return std::nullopt;
    }
  }
  return merged;
}

// Below this many pixels a band is scanned faster than a helper thread wakes.
constexpr std::size_t kMinBandPixels = 32 * 1024;

}  // namespace

std::optional<Palette> find_palette(const Image& image, int threads) {
  if (image.width <= 0 || image.height <= 0) return std::nullopt;
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  const int bands = std::clamp(static_cast<int>(pixels / kMinBandPixels), 1, std::clamp(threads, 1, image.height));
  std::vector<ColourTable> tables(static_cast<std::size_t>(bands));
  std::atomic<bool> too_many{false};
  parallel::run_tasks(bands, threads, [&](int b) {
    collect_colours(image, image.height * b / bands, image.height * (b + 1) / bands,
                    tables[static_cast<std::size_t>(b)], too_many);
  });
  if (too_many) return std::nullopt;
  const std::optional<ColourTable> merged = merge(tables);
  if (!merged) return std::nullopt;

  // Translucent colours first, keeping first-seen order within each group.
  Palette palette;
  for (const bool translucent : {true, false}) {
    for (const std::uint32_t packed : merged->colours()) {
      const Rgba8 colour = unpack(packed);
      if ((colour.a < 255) != translucent) continue;
      palette.lookup_.index_of(packed);
      palette.colours_.push_back(colour);
      palette.translucent_count_ += translucent;
    }
  }
  return palette;
}

std::span<const std::uint8_t> Palette::index_rows(const Image& image, int first_row, int row_count,
                                                  std::vector<std::uint8_t>& scratch) const {
  const std::size_t stride = static_cast<std::size_t>(image.width) + 1;
  scratch.resize(stride * static_cast<std::size_t>(row_count));
  std::uint32_t previous = load_rgba(image.pixel(0, first_row));
  std::uint8_t previous_index = static_cast<std::uint8_t>(lookup_.find(previous));
  for (int r = 0; r < row_count; ++r) {
    const std::uint8_t* in = image.pixel(0, first_row + r);
    std::uint8_t* out = scratch.data() + static_cast<std::size_t>(r) * stride;
    *out++ = 0;
    for (int x = 0; x < image.width;) {
      if (x + kBlockPixels <= image.width && block_is(in, previous)) {
        std::memset(out + x, previous_index, kBlockPixels);
        x += kBlockPixels;
        in += 4 * kBlockPixels;
        continue;
      }
      for (const int end = std::min(image.width, x + kBlockPixels); x < end; ++x, in += 4) {
        const std::uint32_t colour = load_rgba(in);
        if (colour != previous) {
          previous = colour;
          previous_index = static_cast<std::uint8_t>(lookup_.find(colour));
        }
        out[x] = previous_index;
      }
    }
  }
  return scratch;
}

}  // namespace toond::image
