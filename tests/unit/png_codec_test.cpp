#include <gtest/gtest.h>

#include <stdexcept>

#include "image/png_codec.h"

namespace toond::image {
namespace {

Image gradient(int w, int h) {
  Image img{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 4)};
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      auto* p = img.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x * 255 / (w - 1));
      p[1] = static_cast<std::uint8_t>(y * 255 / (h - 1));
      p[2] = static_cast<std::uint8_t>((x ^ y) & 0xff);
      p[3] = static_cast<std::uint8_t>(255 - x % 7);
    }
  }
  return img;
}

TEST(PngCodec, RoundTripIsLossless) {
  const Image original = gradient(37, 23);
  const Image decoded = decode_png(encode_png(original));
  EXPECT_EQ(decoded.width, 37);
  EXPECT_EQ(decoded.height, 23);
  EXPECT_EQ(decoded.rgba, original.rgba);
}

TEST(PngCodec, EveryCompressionLevelRoundTrips) {
  const Image original = gradient(16, 16);
  for (int level = 0; level <= 9; ++level) {
    EXPECT_EQ(decode_png(encode_png(original, {level})).rgba, original.rgba) << "level " << level;
  }
}

TEST(PngCodec, RejectsNonPng) {
  EXPECT_THROW(decode_png("not a png at all"), std::runtime_error);
  EXPECT_THROW(decode_png(""), std::runtime_error);
}

TEST(PngCodec, RejectsTruncatedPng) {
  const std::string bytes = encode_png(gradient(32, 32));
  EXPECT_THROW(decode_png(std::string_view(bytes).substr(0, bytes.size() / 2)), std::runtime_error);
}

TEST(PngCodec, RejectsMismatchedBuffer) {
  Image bad{4, 4, std::vector<std::uint8_t>(10)};
  EXPECT_THROW(encode_png(bad), std::runtime_error);
}

}  // namespace
}  // namespace toond::image
