// An image ramp becomes the same stops a JSON ramp would give.
#include "render/frame/ramp_image.h"

#include <gtest/gtest.h>

namespace toond::render {
namespace {

scene::Texture row_of(const std::vector<std::uint8_t>& greys, int height = 1) {
  scene::Texture t;
  t.width = static_cast<int>(greys.size());
  t.height = height;
  for (int y = 0; y < height; ++y) {
    for (std::uint8_t g : greys) {
      // Rows other than the middle one are red, so reading the wrong row shows.
      const bool middle = y == height / 2;
      t.rgba.insert(t.rgba.end(),
                    {middle ? g : std::uint8_t{255}, middle ? g : std::uint8_t{0}, middle ? g : std::uint8_t{0}, 255});
    }
  }
  return t;
}

TEST(RampImage, SixteenTexelsThreeShadesGiveThreeStops) {
  std::vector<std::uint8_t> texels(16, 255);
  for (int i = 0; i < 6; ++i) texels[static_cast<std::size_t>(i)] = 0;
  for (int i = 6; i < 12; ++i) texels[static_cast<std::size_t>(i)] = 188;
  const std::vector<RampStop> stops = ramp_from_image(row_of(texels));
  ASSERT_EQ(stops.size(), 3u);
  // Texel 0 covers everything facing away from the light too.
  EXPECT_EQ(stops[0].at, -1.0f);
  EXPECT_FLOAT_EQ(stops[1].at, 6.0f / 16.0f);
  EXPECT_FLOAT_EQ(stops[2].at, 12.0f / 16.0f);
  EXPECT_EQ(stops[0].color, glm::vec3(0.0f));
  // sRGB 188 is about half the light.
  EXPECT_NEAR(stops[1].color.g, 0.5f, 0.01f);
  EXPECT_EQ(stops[2].color, glm::vec3(1.0f));
}

TEST(RampImage, ReadsTheMiddleRow) {
  const std::vector<RampStop> stops = ramp_from_image(row_of({40, 40, 200, 200}, 5));
  ASSERT_EQ(stops.size(), 2u);
  EXPECT_EQ(stops[0].color.r, stops[0].color.g);  // grey, not the red rows
  EXPECT_FLOAT_EQ(stops[1].at, 0.5f);
}

TEST(RampImage, AGradientIsNotACelRamp) {
  std::vector<std::uint8_t> gradient;
  for (int i = 0; i < 64; ++i) gradient.push_back(static_cast<std::uint8_t>(i * 4));
  try {
    ramp_from_image(row_of(gradient));
    FAIL() << "a 64-shade gradient was accepted";
  } catch (const RampImageError& e) {
    EXPECT_NE(std::string(e.what()).find("64 runs"), std::string::npos) << e.what();
  }
  // Sixteen shades still fit.
  gradient.resize(16);
  EXPECT_EQ(ramp_from_image(row_of(gradient)).size(), 16u);
}

TEST(RampImage, EmptyImageIsAnError) { EXPECT_THROW(ramp_from_image(scene::Texture{}), RampImageError); }

}  // namespace
}  // namespace toond::render
