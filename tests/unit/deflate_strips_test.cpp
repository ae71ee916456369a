#include <gtest/gtest.h>
#include <zlib.h>

#include <random>
#include <tuple>

#include "image/deflate_strips.h"

namespace toond::image {
namespace {

// Rows of `width` bytes: a filter byte, then runs and noise, like filtered
// toon scanlines.
std::vector<std::uint8_t> scanlines(int rows, int width) {
  std::mt19937 random(7);
  std::vector<std::uint8_t> bytes;
  for (int y = 0; y < rows; ++y) {
    bytes.push_back(static_cast<std::uint8_t>(y % 5));
    for (int x = 1; x < width; ++x) bytes.push_back(x % 50 < 40 ? 0 : static_cast<std::uint8_t>(random()));
  }
  return bytes;
}

std::vector<std::uint8_t> inflate_zlib(const std::string& stream, std::size_t expected_size) {
  std::vector<std::uint8_t> out(expected_size + 1);
  uLongf size = static_cast<uLongf>(out.size());
  const int rc =
      uncompress(out.data(), &size, reinterpret_cast<const Bytef*>(stream.data()), static_cast<uLong>(stream.size()));
  EXPECT_EQ(rc, Z_OK);
  out.resize(size);
  return out;
}

TEST(DeflateStrips, StripsJoinIntoOneZlibStream) {
  const int rows = 97, width = 301;
  const std::vector<std::uint8_t> input = scanlines(rows, width);
  const ScanlineSource source = [&](int first, int count, std::vector<std::uint8_t>&) {
    return std::span<const std::uint8_t>(input).subspan(static_cast<std::size_t>(first) * width,
                                                        static_cast<std::size_t>(count) * width);
  };
  for (const int strips : {1, 2, 3, 7, 97, 500}) {
    for (const int threads : {1, 2, 4}) {
      for (const auto& [method, level, strategy] : {std::tuple{DeflateMethod::Runs, 1, Z_DEFAULT_STRATEGY},
                                                    {DeflateMethod::Zlib, 0, Z_DEFAULT_STRATEGY},
                                                    {DeflateMethod::Zlib, 1, Z_RLE},
                                                    {DeflateMethod::Zlib, 1, Z_DEFAULT_STRATEGY},
                                                    {DeflateMethod::Zlib, 9, Z_DEFAULT_STRATEGY}}) {
        SCOPED_TRACE(testing::Message() << strips << " strips, " << threads << " threads, "
                                        << (method == DeflateMethod::Runs ? "runs" : "zlib level ") << level);
        const std::string stream = deflate_scanlines(rows, width, source, {method, level, strategy, strips, threads});
        EXPECT_TRUE(inflate_zlib(stream, input.size()) == input);
      }
    }
  }
}

TEST(DeflateStrips, LongRowsAreAskedForAFewAtATime) {
  // Rows of 40000 bytes: the source is asked for one or two at a time.
  const std::size_t width = 40000;
  const ScanlineSource source = [&](int first, int count, std::vector<std::uint8_t>& scratch) {
    EXPECT_LE(count, 2);
    scratch.assign(width * static_cast<std::size_t>(count), 0);
    for (int r = 0; r < count; ++r) scratch[width * static_cast<std::size_t>(r)] = static_cast<std::uint8_t>(first + r);
    return std::span<const std::uint8_t>(scratch);
  };
  for (const DeflateMethod method : {DeflateMethod::Runs, DeflateMethod::Zlib}) {
    const std::string stream = deflate_scanlines(200, width, source, {method, 1, Z_RLE, 4, 2});
    const std::vector<std::uint8_t> out = inflate_zlib(stream, 200 * width);
    ASSERT_EQ(out.size(), 200 * width);
    for (int i = 0; i < 200; ++i) EXPECT_EQ(out[width * static_cast<std::size_t>(i)], i);
  }
}

TEST(DeflateStrips, SourceFailureIsReported) {
  const ScanlineSource source = [](int, int, std::vector<std::uint8_t>&) -> std::span<const std::uint8_t> {
    throw std::runtime_error("no rows");
  };
  EXPECT_THROW(deflate_scanlines(10, 10, source, {DeflateMethod::Runs, 1, Z_RLE, 2, 2}), std::runtime_error);
  EXPECT_THROW(deflate_scanlines(10, 10, source, {DeflateMethod::Zlib, 1, Z_RLE, 2, 2}), std::runtime_error);
}

}  // namespace
}  // namespace toond::image
