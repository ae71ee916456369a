#include <gtest/gtest.h>

#include <stdexcept>

#include "image/downsample.h"

namespace toond::image {
namespace {

Image filled(int w, int h, std::uint8_t v, std::uint8_t a = 255) {
  Image img{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 4)};
  for (std::size_t i = 0; i < img.rgba.size(); i += 4) {
    img.rgba[i] = img.rgba[i + 1] = img.rgba[i + 2] = v;
    img.rgba[i + 3] = a;
  }
  return img;
}

TEST(DownsampleBox, AveragesInLinearLight) {
  Image img = filled(2, 2, 0);
  img.pixel(0, 0)[0] = img.pixel(0, 0)[1] = img.pixel(0, 0)[2] = 255;
  img.pixel(1, 1)[0] = img.pixel(1, 1)[1] = img.pixel(1, 1)[2] = 255;
  const Image out = downsample_box(img, 2);
  ASSERT_EQ(out.width, 1);
  // Half white, half black is linear 0.5, which sRGB-encodes to 188, not 128.
  EXPECT_EQ(out.pixel(0, 0)[0], 188);
  EXPECT_EQ(out.pixel(0, 0)[3], 255);
}

TEST(DownsampleBox, UniformBlocksKeepTheirValue) {
  for (int v : {0, 1, 77, 128, 200, 254, 255}) {
    const Image out = downsample_box(filled(6, 3, static_cast<std::uint8_t>(v)), 3);
    ASSERT_EQ(out.width, 2);
    ASSERT_EQ(out.height, 1);
    EXPECT_EQ(out.pixel(1, 0)[1], v);
  }
}

TEST(DownsampleBox, TransparentSamplesDoNotDarkenColour) {
  Image img = filled(2, 1, 200, 255);
  img.pixel(1, 0)[0] = img.pixel(1, 0)[1] = img.pixel(1, 0)[2] = 0;
  img.pixel(1, 0)[3] = 0;  // transparent background sample
  Image wide{2, 2, {}};
  wide.rgba.resize(16);
  std::copy(img.rgba.begin(), img.rgba.end(), wide.rgba.begin());
  std::copy(img.rgba.begin(), img.rgba.end(), wide.rgba.begin() + 8);
  const Image out = downsample_box(wide, 2);
  EXPECT_EQ(out.pixel(0, 0)[0], 200);
  EXPECT_EQ(out.pixel(0, 0)[3], 128);
}

TEST(DownsampleBox, FactorOneIsIdentityAndBadSizesThrow) {
  const Image img = filled(3, 3, 9);
  EXPECT_EQ(downsample_box(img, 1).rgba, img.rgba);
  EXPECT_THROW(downsample_box(img, 2), std::invalid_argument);
}

}  // namespace
}  // namespace toond::image
