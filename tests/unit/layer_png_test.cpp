// The data layers' PNG samples, read back through libpng's simplified API
// (16-bit grey as it is stored, palette indices as colour-mapped bytes);
// the integration tests read the same files with PIL.
#include <gtest/gtest.h>

#include <png.h>

#include <cstdint>
#include <string>
#include <vector>

#include "image/layer_png.h"

namespace toond::image {
namespace {

// A layer of one row: `values[i]` at pixel i, covered where `covered[i]`.
FloatImage row_of(const std::vector<float>& values, const std::vector<bool>& covered) {
  FloatImage layer{static_cast<int>(values.size()), 1, std::vector<float>(values.size() * 4, 0.0f)};
  for (std::size_t i = 0; i < values.size(); ++i) {
    layer.values[i * 4] = values[i];
    layer.values[i * 4 + 3] = covered[i] ? 1.0f : 0.0f;
  }
  return layer;
}

// The PNG read as `format` (a PNG_FORMAT_*), one sample per channel.
template <class Sample>
std::vector<Sample> read_as(const std::string& png, png_uint_32 format, png_uint_32* colour_map_entries = nullptr) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  EXPECT_TRUE(png_image_begin_read_from_memory(&image, png.data(), png.size())) << image.message;
  if (colour_map_entries) *colour_map_entries = image.colormap_entries;
  image.format = format;
  std::vector<Sample> samples(PNG_IMAGE_SIZE(image) / sizeof(Sample));
  std::vector<png_byte> colour_map(PNG_IMAGE_COLORMAP_SIZE(image));
  EXPECT_TRUE(
      png_image_finish_read(&image, nullptr, samples.data(), 0, colour_map.empty() ? nullptr : colour_map.data()))
      << image.message;
  return samples;
}

TEST(LayerPng, DepthRunsFromZeroAtTheNearestToTheFarthestAndTheBackgroundIsAbove) {
  const FloatImage layer = row_of({2.0f, 3.0f, 4.5f, 99.0f, 2.5f}, {true, true, true, false, true});
  const DepthRange range = visible_depth_range(layer);
  EXPECT_EQ(range.near_depth, 2.0f);
  EXPECT_EQ(range.far_depth, 4.5f) << "the background's value is no depth";
  const std::string png = encode_depth_png(layer, range, 6, {{"toond:depth", "{}"}});
  const std::vector<std::uint16_t> depth = read_as<std::uint16_t>(png, PNG_FORMAT_LINEAR_Y);
  ASSERT_EQ(depth.size(), 5u);
  EXPECT_EQ(depth[0], 0);
  EXPECT_EQ(depth[1], 26214);  // 1.0 / 2.5 of 65534
  EXPECT_EQ(depth[2], 65534);
  EXPECT_EQ(depth[3], 65535);
  EXPECT_EQ(depth[4], 13107);
}

TEST(LayerPng, AFlatDepthIsAllNearAndNothingCoveredHasNoRange) {
  const FloatImage flat = row_of({5.0f, 5.0f}, {true, true});
  const std::vector<std::uint16_t> depth =
      read_as<std::uint16_t>(encode_depth_png(flat, visible_depth_range(flat), 6, {}), PNG_FORMAT_LINEAR_Y);
  EXPECT_EQ(depth, (std::vector<std::uint16_t>{0, 0}));
  const DepthRange none = visible_depth_range(row_of({1.0f}, {false}));
  EXPECT_EQ(none.near_depth, 0.0f);
  EXPECT_EQ(none.far_depth, 0.0f);
}

TEST(LayerPng, NormalsAreHalfPlusHalfTheirValueAndTheBackgroundIsClear) {
  FloatImage layer{2, 1, {0.0f, 0.0f, 1.0f, 1.0f, /* background */ 0.3f, 0.3f, 0.3f, 0.0f}};
  const std::vector<std::uint8_t> rgba = read_as<std::uint8_t>(encode_normal_png(layer, 6, {}), PNG_FORMAT_RGBA);
  EXPECT_EQ(rgba, (std::vector<std::uint8_t>{128, 128, 255, 255, 0, 0, 0, 0}));
}

TEST(LayerPng, IdsAreThePaletteIndicesWithTheBackgroundTransparent) {
  const FloatImage layer = row_of({1.0f, 2.0f, 0.0f, 3.0f}, {true, true, false, true});
  png_uint_32 entries = 0;
  const std::string png = encode_id_png(layer, 3, 6, {});
  const std::vector<std::uint8_t> index =
      read_as<std::uint8_t>(png, PNG_FORMAT_RGBA | PNG_FORMAT_FLAG_COLORMAP, &entries);
  EXPECT_EQ(entries, 4u) << "the background and three ids";
  EXPECT_EQ(index, (std::vector<std::uint8_t>{1, 2, 0, 3}));
  EXPECT_THROW(encode_id_png(layer, kMaxLayerIds + 1, 6, {}), std::runtime_error);
}

}  // namespace
}  // namespace toond::image
