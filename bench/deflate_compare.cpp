#include "deflate_compare.h"

#include <libdeflate.h>
#include <zlib.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <vector>

#include "image/sub_filter.h"
#include "stats.h"

namespace toond::bench {
namespace {

using Clock = std::chrono::steady_clock;

// The median time of `compress`, and the size it gives.
std::pair<double, std::size_t> timed(const std::function<std::size_t()>& compress, int repeats) {
  std::vector<double> ms;
  std::size_t size = 0;
  for (int i = 0; i < repeats; ++i) {
    const auto start = Clock::now();
    size = compress();
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  return {median(ms), size};
}

}  // namespace

void compare_deflaters(const char* name, const image::Image& frame, int level, int repeats) {
  std::vector<std::uint8_t> scratch;
  // The layout the PNG encoder picks: RGB when every pixel is opaque.
  const auto layout = image::is_opaque(frame) ? image::TruecolourLayout::Rgb : image::TruecolourLayout::Rgba;
  const auto rows = image::sub_filtered_rows(frame, layout, 0, frame.height, scratch);
  std::vector<std::uint8_t> out(compressBound(static_cast<uLong>(rows.size())) + 1024);
  const auto [zlib_ms, zlib_bytes] = timed(
      [&] {
        uLongf length = static_cast<uLongf>(out.size());
        if (compress2(out.data(), &length, rows.data(), static_cast<uLong>(rows.size()), level) != Z_OK) {
          throw std::runtime_error("zlib failed");
        }
        return static_cast<std::size_t>(length);
      },
      repeats);
  libdeflate_compressor* compressor = libdeflate_alloc_compressor(level);
  if (!compressor) throw std::runtime_error("libdeflate has no level " + std::to_string(level));
  const auto [libdeflate_ms, libdeflate_bytes] = timed(
      [&] { return libdeflate_zlib_compress(compressor, rows.data(), rows.size(), out.data(), out.size()); }, repeats);
  libdeflate_free_compressor(compressor);
  std::printf("%-30s level %d, one thread, whole frame: zlib %6.3f ms %8zu bytes | libdeflate %6.3f ms %8zu bytes\n",
              name, level, zlib_ms, zlib_bytes, libdeflate_ms, libdeflate_bytes);
}

}  // namespace toond::bench
