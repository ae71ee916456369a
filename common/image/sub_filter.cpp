#include "image/sub_filter.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstring>

#include "parallel/parallel_tasks.h"

namespace toond::image {
namespace {

constexpr std::uint8_t kSubFilter = 1;

void sub_filter_rgba_row(const std::uint8_t* __restrict in, std::uint8_t* __restrict out, int width) {
  std::memcpy(out, in, 4);
  const std::size_t bytes = static_cast<std::size_t>(width) * 4;
  for (std::size_t i = 4; i < bytes; ++i) out[i] = static_cast<std::uint8_t>(in[i] - in[i - 4]);
}

// Each byte less the same byte of the pixel before, for two RGBA pixels at
// once: a borrow never crosses into the next byte because every byte of the
// minuend has its top bit set and every byte of the subtrahend has it clear
// first, the top bits being put right afterwards.
std::uint64_t subtract_bytes(std::uint64_t a, std::uint64_t b) {
  constexpr std::uint64_t kTopBits = 0x8080808080808080ull;
  return ((a | kTopBits) - (b & ~kTopBits)) ^ ((a ^ ~b) & kTopBits);
}

// RGB out of RGBA in: each pixel's difference is stored as four bytes, the
// fourth overwritten by the next pixel's, so a pixel is one store; the last
// pixel, whose fourth byte would fall past the row, is stored as three.
void sub_filter_rgb_row(const std::uint8_t* __restrict in, std::uint8_t* __restrict out, int width) {
  std::memcpy(out, in, 3);
  int x = 1;
  if constexpr (std::endian::native == std::endian::little) {
    for (; x + 2 < width; x += 2) {
      std::uint64_t now;
      std::uint64_t before;
      std::memcpy(&now, in + 4 * x, 8);
      std::memcpy(&before, in + 4 * x - 4, 8);
      const std::uint64_t diff = subtract_bytes(now, before);
      const auto first = static_cast<std::uint32_t>(diff);
      const auto second = static_cast<std::uint32_t>(diff >> 32);
      std::memcpy(out + 3 * x, &first, 4);
      std::memcpy(out + 3 * x + 3, &second, 4);
    }
  }
  for (; x < width; ++x) {
    const std::uint8_t* p = in + static_cast<std::size_t>(x) * 4;
    std::uint8_t* o = out + static_cast<std::size_t>(x) * 3;
    o[0] = static_cast<std::uint8_t>(p[0] - p[-4]);
    o[1] = static_cast<std::uint8_t>(p[1] - p[-3]);
    o[2] = static_cast<std::uint8_t>(p[2] - p[-2]);
  }
}

}  // namespace

std::span<const std::uint8_t> sub_filtered_rows(const Image& image, TruecolourLayout layout, int first_row,
                                                int row_count, std::vector<std::uint8_t>& scratch) {
  const std::size_t stride = static_cast<std::size_t>(image.width) * bytes_per_pixel(layout) + 1;
  scratch.resize(stride * static_cast<std::size_t>(row_count));
  for (int r = 0; r < row_count; ++r) {
    std::uint8_t* out = scratch.data() + static_cast<std::size_t>(r) * stride;
    const std::uint8_t* in = image.pixel(0, first_row + r);
    out[0] = kSubFilter;
    if (layout == TruecolourLayout::Rgba) {
      sub_filter_rgba_row(in, out + 1, image.width);
    } else {
      sub_filter_rgb_row(in, out + 1, image.width);
    }
  }
  return scratch;
}

namespace {

// Whether pixels [first, end) all have alpha 255. Two pixels a word, ANDed
// together without branching, so the compiler can vectorise it; only the
// alpha bytes of the result are looked at.
bool span_opaque(const std::uint8_t* rgba, std::size_t first, std::size_t end) {
  constexpr std::uint64_t kAlphaBytes = 0xff000000ff000000ull;
  std::uint64_t all = ~0ull;
  std::size_t i = first;
  for (; i + 2 <= end; i += 2) {
    std::uint64_t two;
    std::memcpy(&two, rgba + i * 4, 8);
    all &= two;
  }
  if (i < end && rgba[i * 4 + 3] != 0xff) return false;
  return (all & kAlphaBytes) == kAlphaBytes;
}

}  // namespace

bool is_opaque(const Image& image, int parts, int threads) {
  // In parts on the encode's helpers: between the palette's scan and the
  // deflate, a pass on the caller alone outlasts the time a helper watches
  // for its next job, and waking it again cost the deflate most of its
  // second core (toond_png_bench).
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  const auto count = static_cast<std::size_t>(std::max(parts, 1));
  std::atomic<bool> opaque{true};
  parallel::run_tasks(static_cast<int>(count), threads, [&](int part) {
    const std::size_t first = pixels * static_cast<std::size_t>(part) / count;
    const std::size_t end = pixels * static_cast<std::size_t>(part + 1) / count;
    if (opaque.load(std::memory_order_relaxed) && !span_opaque(image.rgba.data(), first, end)) opaque = false;
  });
  return opaque;
}

}  // namespace toond::image
