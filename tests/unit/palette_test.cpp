#include <gtest/gtest.h>

#include "image/palette.h"

namespace toond::image {
namespace {

Image from_pixels(int w, int h, const std::vector<Rgba8>& pixels) {
  Image img{w, h, {}};
  for (const Rgba8& p : pixels) img.rgba.insert(img.rgba.end(), {p.r, p.g, p.b, p.a});
  return img;
}

// Every pixel's palette entry must be the pixel itself, whichever rows are
// asked for together.
void expect_indices_give_back(const Image& image, const Palette& palette) {
  const std::size_t stride = static_cast<std::size_t>(image.width) + 1;
  for (int rows_at_once : {1, 2, image.height}) {
    std::vector<std::uint8_t> scratch;
    for (int first = 0; first < image.height; first += rows_at_once) {
      const int count = std::min(rows_at_once, image.height - first);
      const auto scanlines = palette.index_rows(image, first, count, scratch);
      ASSERT_EQ(scanlines.size(), stride * count);
      for (int r = 0; r < count; ++r) {
        EXPECT_EQ(scanlines[r * stride], 0) << "filter byte of row " << first + r;
        for (int x = 0; x < image.width; ++x) {
          const std::uint8_t* p = image.pixel(x, first + r);
          const Rgba8& c = palette.colours().at(scanlines[r * stride + 1 + x]);
          EXPECT_EQ(c, (Rgba8{p[0], p[1], p[2], p[3]})) << x << "," << first + r;
        }
      }
    }
  }
}

TEST(Palette, IndexesEachDistinctColourOnce) {
  const Image img = from_pixels(
      3, 2, {{1, 2, 3, 255}, {1, 2, 3, 255}, {9, 9, 9, 255}, {9, 9, 9, 255}, {1, 2, 3, 255}, {0, 0, 0, 255}});
  const auto palette = find_palette(img);
  ASSERT_TRUE(palette);
  EXPECT_EQ(palette->colours().size(), 3u);
  EXPECT_EQ(palette->translucent_count(), 0);
  expect_indices_give_back(img, *palette);
}

TEST(Palette, TranslucentColoursComeFirst) {
  const Image img = from_pixels(4, 1, {{1, 1, 1, 255}, {2, 2, 2, 0}, {3, 3, 3, 255}, {4, 4, 4, 77}});
  const auto palette = find_palette(img);
  ASSERT_TRUE(palette);
  ASSERT_EQ(palette->translucent_count(), 2);
  EXPECT_EQ(palette->colours()[0], (Rgba8{2, 2, 2, 0}));
  EXPECT_EQ(palette->colours()[1], (Rgba8{4, 4, 4, 77}));
  expect_indices_give_back(img, *palette);
}

TEST(Palette, ColoursDifferingOnlyInAlphaStayApart) {
  const Image img = from_pixels(2, 2, {{5, 5, 5, 255}, {5, 5, 5, 254}, {5, 5, 5, 0}, {6, 5, 5, 0}});
  const auto palette = find_palette(img);
  ASSERT_TRUE(palette);
  EXPECT_EQ(palette->colours().size(), 4u);
  expect_indices_give_back(img, *palette);
}

std::vector<Rgba8> distinct_colours(int count) {
  std::vector<Rgba8> colours;
  for (int i = 0; i < count; ++i) {
    colours.push_back(
        {static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(i / 256), static_cast<std::uint8_t>(i / 3), 255});
  }
  return colours;
}

TEST(Palette, TwoHundredFiftySixFitAndOneMoreDoesNot) {
  const Image full = from_pixels(16, 16, distinct_colours(256));
  const auto palette = find_palette(full);
  ASSERT_TRUE(palette);
  EXPECT_EQ(palette->colours().size(), 256u);
  expect_indices_give_back(full, *palette);

  std::vector<Rgba8> pixels = distinct_colours(257);
  pixels.resize(17 * 16, pixels[0]);
  EXPECT_FALSE(find_palette(from_pixels(17, 16, pixels)));
}

// Bands scanned on their own threads: each band fits, together they do not;
// and bands sharing colours merge them.
TEST(Palette, BandsAreMergedExactly) {
  const int w = 256, h = 512;  // enough pixels for several bands
  std::vector<Rgba8> pixels(static_cast<std::size_t>(w) * h);
  const std::vector<Rgba8> colours = distinct_colours(300);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) pixels[static_cast<std::size_t>(y) * w + x] = colours[(y < h / 2 ? 0 : 150) + x % 150];
  }
  for (int threads : {1, 2, 4}) EXPECT_FALSE(find_palette(from_pixels(w, h, pixels), threads)) << threads;

  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) pixels[static_cast<std::size_t>(y) * w + x] = colours[(y * 7 + x) % 200];
  }
  const Image shared = from_pixels(w, h, pixels);
  const auto one_band = find_palette(shared, 1);
  ASSERT_TRUE(one_band);
  EXPECT_EQ(one_band->colours().size(), 200u);
  expect_indices_give_back(shared, *one_band);
  for (int threads : {2, 4}) {
    const auto palette = find_palette(shared, threads);
    ASSERT_TRUE(palette) << threads;
    // First-seen order whatever the bands, so the PNG is the same bytes.
    EXPECT_EQ(palette->colours(), one_band->colours()) << threads;
  }
}

}  // namespace
}  // namespace toond::image
