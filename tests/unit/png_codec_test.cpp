#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>

#include "image/png_codec.h"
#include "image/sub_filter.h"

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

// An image whose pixels cycle through `colours` distinct opaque colours
// (or, with `alpha_step`, colours whose alpha varies as well).
Image with_colours(int w, int h, int colours, int alpha_step = 0) {
  Image img{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 4)};
  for (int i = 0; i < w * h; ++i) {
    const int c = i % colours;
    std::uint8_t* p = img.rgba.data() + static_cast<std::size_t>(i) * 4;
    p[0] = static_cast<std::uint8_t>(c * 37);
    p[1] = static_cast<std::uint8_t>(c / 7);
    p[2] = static_cast<std::uint8_t>(c & 3);
    p[3] = static_cast<std::uint8_t>(255 - (alpha_step * c) % 256);
  }
  return img;
}

Image noise(int w, int h, bool opaque, unsigned seed) {
  std::mt19937 random(seed);
  Image img{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 4)};
  for (std::size_t i = 0; i < img.rgba.size(); ++i) {
    img.rgba[i] = (opaque && i % 4 == 3) ? 255 : static_cast<std::uint8_t>(random());
  }
  return img;
}

// IHDR sits right after the 8-byte signature: length, type, width, height,
// bit depth, then the colour type at byte 25.
int colour_type(const std::string& png) { return static_cast<unsigned char>(png.at(25)); }
constexpr int kRgb = 2, kPalette = 3, kRgba = 6;

bool has_chunk(const std::string& png, const std::string& type) {
  for (std::size_t at = 8; at + 8 <= png.size();) {
    const std::uint32_t length = static_cast<std::uint32_t>(
        static_cast<unsigned char>(png[at]) << 24 | static_cast<unsigned char>(png[at + 1]) << 16 |
        static_cast<unsigned char>(png[at + 2]) << 8 | static_cast<unsigned char>(png[at + 3]));
    if (png.compare(at + 4, 4, type) == 0) return true;
    at += 12 + length;
  }
  return false;
}

void expect_round_trip(const Image& original, const std::string& png) {
  const Image decoded = decode_png(png);
  EXPECT_EQ(decoded.width, original.width);
  EXPECT_EQ(decoded.height, original.height);
  EXPECT_TRUE(decoded.rgba == original.rgba) << original.width << "x" << original.height;
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

TEST(PngCodec, FewOpaqueColoursAreWrittenAsAPalette) {
  const Image original = with_colours(61, 47, 200);
  const std::string png = encode_png(original);
  EXPECT_EQ(colour_type(png), kPalette);
  EXPECT_FALSE(has_chunk(png, "tRNS"));
  expect_round_trip(original, png);
}

TEST(PngCodec, TranslucentPaletteColoursGetATransparencyChunk) {
  const Image original = with_colours(64, 40, 150, 3);
  const std::string png = encode_png(original);
  EXPECT_EQ(colour_type(png), kPalette);
  EXPECT_TRUE(has_chunk(png, "tRNS"));
  expect_round_trip(original, png);
}

TEST(PngCodec, InvisiblePixelsKeepTheirColour) {
  // Alpha 0 with different RGB values: still different pixels, exactly kept.
  Image original = with_colours(16, 16, 100);
  for (std::size_t i = 3; i < original.rgba.size(); i += 8) original.rgba[i] = 0;
  const std::string png = encode_png(original);
  EXPECT_EQ(colour_type(png), kPalette);
  expect_round_trip(original, png);
}

TEST(PngCodec, ExactlyTwoHundredFiftySixColoursFitAPalette) {
  const Image original = with_colours(256, 3, 256);
  const std::string png = encode_png(original);
  EXPECT_EQ(colour_type(png), kPalette);
  expect_round_trip(original, png);
}

TEST(PngCodec, TwoHundredFiftySevenColoursDoNot) {
  const Image opaque = with_colours(257, 3, 257);
  const std::string rgb = encode_png(opaque);
  EXPECT_EQ(colour_type(rgb), kRgb);
  expect_round_trip(opaque, rgb);

  const Image translucent = with_colours(257, 3, 257, 1);
  const std::string rgba = encode_png(translucent);
  EXPECT_EQ(colour_type(rgba), kRgba);
  expect_round_trip(translucent, rgba);
}

TEST(PngCodec, OnePixel) {
  for (const std::uint8_t alpha : {255, 128, 0}) {
    const Image original{1, 1, {10, 20, 30, alpha}};
    const std::string png = encode_png(original);
    EXPECT_EQ(colour_type(png), kPalette);
    expect_round_trip(original, png);
  }
}

TEST(PngCodec, OddTallAndWideSizes) {
  for (const auto& [w, h] : {std::pair{1, 1001}, {1001, 1}, {3, 5}, {513, 257}, {257, 513}}) {
    const Image few = with_colours(w, h, 70);
    expect_round_trip(few, encode_png(few));
    const Image many = noise(w, h, false, static_cast<unsigned>(w * 7 + h));
    expect_round_trip(many, encode_png(many));
    const Image opaque = noise(w, h, true, static_cast<unsigned>(w + h * 7));
    expect_round_trip(opaque, encode_png(opaque));
  }
}

TEST(PngCodec, NoiseFallsBackToTruecolour) {
  const Image translucent = noise(300, 200, false, 1);
  const std::string rgba = encode_png(translucent);
  EXPECT_EQ(colour_type(rgba), kRgba);
  expect_round_trip(translucent, rgba);

  const Image opaque = noise(300, 200, true, 2);
  const std::string rgb = encode_png(opaque);
  EXPECT_EQ(colour_type(rgb), kRgb);
  expect_round_trip(opaque, rgb);
}

// The opacity check runs in parts on the helpers (as many as the deflate's
// strips: eight for a large image, one for a small one): one translucent
// pixel anywhere, at a part's first or last pixel, or the odd last pixel,
// is found whatever the parts and threads, and makes the frame RGBA.
TEST(PngCodec, OneTranslucentPixelAnywhereIsFoundOnEveryThreadCount) {
  // Odd sizes: the last pixel has no partner in the two-pixel words.
  for (const Image& opaque : {noise(601, 301, true, 6), noise(31, 17, true, 7)}) {
    const std::size_t pixels = static_cast<std::size_t>(opaque.width) * opaque.height;
    for (const int threads : {1, 2, 3, 8}) {
      for (const int parts : {1, 3, 8}) {
        EXPECT_TRUE(is_opaque(opaque, parts, threads)) << parts << " parts, " << threads << " threads";
      }
      for (std::size_t at : {std::size_t{0}, pixels / 8 - 1, pixels / 8, pixels / 3, pixels / 2 + 1, 7 * pixels / 8,
                             pixels - 2, pixels - 1}) {
        Image one = opaque;
        one.rgba[at * 4 + 3] = 254;
        for (const int parts : {1, 3, 8}) {
          EXPECT_FALSE(is_opaque(one, parts, threads))
              << "pixel " << at << " of " << pixels << ", " << parts << " parts, " << threads << " threads";
        }
        EXPECT_EQ(colour_type(encode_png(one, {1, threads})), kRgba) << "pixel " << at << ", threads " << threads;
      }
    }
  }
}

TEST(PngCodec, EveryLevelAndThreadCountRoundTripsEveryKind) {
  // Large enough to be cut into strips when more than one thread may run.
  const Image kinds[] = {with_colours(700, 500, 90), with_colours(700, 500, 90, 5), noise(700, 500, true, 3),
                         noise(700, 500, false, 4)};
  for (const Image& original : kinds) {
    for (const int threads : {1, 2, 0}) {
      for (const int level : {0, 1, 3, 6, 9}) {
        SCOPED_TRACE("level " + std::to_string(level) + ", threads " + std::to_string(threads));
        expect_round_trip(original, encode_png(original, {level, threads}));
      }
    }
  }
}

TEST(PngCodec, BytesDoNotDependOnTheThreadCount) {
  // The same render must give the same PNG (and ETag) on every machine.
  const Image kinds[] = {with_colours(900, 700, 120), noise(900, 700, true, 5)};
  for (const Image& original : kinds) {
    const std::string one_thread = encode_png(original, {3, 1});
    EXPECT_EQ(encode_png(original, {3, 2}), one_thread);
    EXPECT_EQ(encode_png(original, {3, 0}), one_thread);
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
