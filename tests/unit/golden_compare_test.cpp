// The golden comparison passes rounding and catches a change.
#include <gtest/gtest.h>

#include "support/golden_compare.h"

namespace toond::test {
namespace {

image::Image grey(int width, int height, std::uint8_t level) {
  image::Image img;
  img.width = width;
  img.height = height;
  img.rgba.assign(static_cast<std::size_t>(width) * height * 4, level);
  return img;
}

TEST(GoldenCompare, RoundingPassesAndAChangeFails) {
  const image::Image reference = grey(16, 16, 100);
  EXPECT_TRUE(compare_golden(reference, reference).passes());

  image::Image rounded = reference;
  for (std::size_t i = 0; i < rounded.rgba.size(); i += 7) rounded.rgba[i] += kGoldenLevels;
  EXPECT_TRUE(compare_golden(reference, rounded).passes());

  image::Image changed = reference;
  for (std::size_t p = 0; p <= kGoldenPixels; ++p) changed.rgba[p * 4 + 1] = 140;  // one more than allowed
  const GoldenDiff diff = compare_golden(reference, changed);
  EXPECT_FALSE(diff.passes());
  EXPECT_EQ(diff.pixels_over, kGoldenPixels + 1);
  EXPECT_EQ(diff.largest, 40);

  EXPECT_FALSE(compare_golden(reference, grey(16, 15, 100)).passes());
}

TEST(GoldenCompare, TheDiffImageShowsBothAndTheirDifference) {
  const image::Image reference = grey(4, 2, 100);
  image::Image changed = reference;
  changed.rgba[0] = 110;
  const image::Image diff = side_by_side_diff(reference, changed);
  EXPECT_EQ(diff.width, 12);
  EXPECT_EQ(diff.height, 2);
  EXPECT_EQ(diff.rgba[0], 100);      // reference
  EXPECT_EQ(diff.rgba[4 * 4], 110);  // render
  EXPECT_EQ(diff.rgba[8 * 4], 80);   // 8 × the difference of 10
  EXPECT_EQ(diff.rgba[8 * 4 + 1], 0);
  EXPECT_EQ(diff.rgba[3], 255);
}

}  // namespace
}  // namespace toond::test
