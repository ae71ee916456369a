#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "image/srgb.h"

namespace toond::image {
namespace {

// The defining formula, the yardstick: the byte nearest the encoded value.
std::uint8_t linear_to_srgb_byte_by_formula(float linear) {
  const float c = linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
  return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
}

// The table encoder must give the formula's byte for every input. Every
// float in 0..1 is a billion cases, so these walk a dense comb of them, and
// every float within 512 steps of each place where the byte changes.
TEST(SrgbEncode, TheThresholdsGiveTheFormulasByteEverywhere) {
  const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
  int checked = 0, changes = 0;
  std::uint8_t previous = 0;
  for (std::uint32_t bits = 0; bits <= one; bits += 997) {
    const float x = std::bit_cast<float>(bits);
    const std::uint8_t expected = linear_to_srgb_byte_by_formula(x);
    ASSERT_EQ(linear_to_srgb_byte(x), expected) << "at " << x;
    if (expected != previous) {
      ++changes;
      for (std::uint32_t near = bits > 997 + 512 ? bits - 997 - 512 : 0; near <= bits + 512; ++near) {
        const float y = std::bit_cast<float>(near);
        ASSERT_EQ(linear_to_srgb_byte(y), linear_to_srgb_byte_by_formula(y)) << "at " << y;
        ++checked;
      }
    }
    previous = expected;
    ++checked;
  }
  EXPECT_EQ(changes, 255);  // every byte was reached, so every threshold was walked
  EXPECT_GT(checked, 1'000'000);
}

TEST(SrgbEncode, OutOfRangeAndNanAreClamped) {
  EXPECT_EQ(linear_to_srgb_byte(-1.0f), 0);
  EXPECT_EQ(linear_to_srgb_byte(-0.0f), 0);
  EXPECT_EQ(linear_to_srgb_byte(std::numeric_limits<float>::denorm_min()), 0);
  EXPECT_EQ(linear_to_srgb_byte(std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(linear_to_srgb_byte(1.0f), 255);
  EXPECT_EQ(linear_to_srgb_byte(7.5f), 255);
  EXPECT_EQ(linear_to_srgb_byte(std::numeric_limits<float>::infinity()), 255);
}

TEST(SrgbEncode, DecodingThenEncodingGivesEachByteBack) {
  const auto& to_linear = srgb_to_linear_table();
  for (int b = 0; b < 256; ++b) EXPECT_EQ(linear_to_srgb_byte(to_linear[static_cast<std::size_t>(b)]), b);
}

}  // namespace
}  // namespace toond::image
