#include <gtest/gtest.h>

#include "image/palette.h"

namespace toond::image {
namespace {

Image from_pixels(int w, int h, const std::vector<Rgba8>& pixels) {
  Image img{w, h, {}};
  for (const Rgba8& p : pixels) img.rgba.insert(img.rgba.end(), {p.r, p.g, p.b, p.a});
  return img;
}

// Every pixel's palette entry must be the pixel itself.
void expect_indices_give_back(const Image& image, const PalettedImage& paletted) {
  const std::size_t stride = static_cast<std::size_t>(image.width) + 1;
  for (int y = 0; y < image.height; ++y) {
    EXPECT_EQ(paletted.scanlines[y * stride], 0) << "filter byte of row " << y;
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      const Rgba8& c = paletted.colours.at(paletted.scanlines[y * stride + 1 + x]);
      EXPECT_EQ(c, (Rgba8{p[0], p[1], p[2], p[3]})) << x << "," << y;
    }
  }
}

TEST(Palette, IndexesEachDistinctColourOnce) {
  const Image img = from_pixels(3, 2, {{1, 2, 3, 255}, {1, 2, 3, 255}, {9, 9, 9, 255},
                                       {9, 9, 9, 255}, {1, 2, 3, 255}, {0, 0, 0, 255}});
  const auto paletted = make_palette(img);
  ASSERT_TRUE(paletted);
  EXPECT_EQ(paletted->colours.size(), 3u);
  EXPECT_EQ(paletted->translucent_count, 0);
  expect_indices_give_back(img, *paletted);
}

TEST(Palette, TranslucentColoursComeFirst) {
  const Image img = from_pixels(4, 1, {{1, 1, 1, 255}, {2, 2, 2, 0}, {3, 3, 3, 255}, {4, 4, 4, 77}});
  const auto paletted = make_palette(img);
  ASSERT_TRUE(paletted);
  ASSERT_EQ(paletted->translucent_count, 2);
  EXPECT_EQ(paletted->colours[0], (Rgba8{2, 2, 2, 0}));
  EXPECT_EQ(paletted->colours[1], (Rgba8{4, 4, 4, 77}));
  expect_indices_give_back(img, *paletted);
}

TEST(Palette, ColoursDifferingOnlyInAlphaStayApart) {
  const Image img = from_pixels(2, 2, {{5, 5, 5, 255}, {5, 5, 5, 254}, {5, 5, 5, 0}, {6, 5, 5, 0}});
  const auto paletted = make_palette(img);
  ASSERT_TRUE(paletted);
  EXPECT_EQ(paletted->colours.size(), 4u);
  expect_indices_give_back(img, *paletted);
}

TEST(Palette, TwoHundredFiftySixFitAndOneMoreDoesNot) {
  std::vector<Rgba8> pixels;
  for (int i = 0; i < 256; ++i) pixels.push_back({static_cast<std::uint8_t>(i), 0, static_cast<std::uint8_t>(i / 3), 255});
  const Image full = from_pixels(16, 16, pixels);
  const auto paletted = make_palette(full);
  ASSERT_TRUE(paletted);
  EXPECT_EQ(paletted->colours.size(), 256u);
  expect_indices_give_back(full, *paletted);

  pixels.push_back({0, 1, 0, 255});
  pixels.resize(17 * 16, {0, 0, 0, 255});
  EXPECT_FALSE(make_palette(from_pixels(17, 16, pixels)));
}

}  // namespace
}  // namespace toond::image
