#pragma once
// Comparing a render with its golden reference: a few levels of per-channel
// difference are rounding (another Mesa build may round a blend the other
// way), more than that on more than a few pixels is a change.
#include <cstddef>

#include "image/image.h"

namespace toond::test {

inline constexpr int kGoldenLevels = 3;          // per channel, of 255
inline constexpr std::size_t kGoldenPixels = 8;  // pixels allowed over it

struct GoldenDiff {
  bool same_size = true;
  std::size_t pixels_over = 0;  // pixels with a channel more than kGoldenLevels off
  int largest = 0;              // the largest channel difference
  bool passes() const { return same_size && pixels_over <= kGoldenPixels; }
};

GoldenDiff compare_golden(const image::Image& reference, const image::Image& actual);

// Reference | actual | the difference ×8 on black, side by side (RGBA, the
// alpha made opaque so a viewer shows what transparent pixels held).
image::Image side_by_side_diff(const image::Image& reference, const image::Image& actual);

}  // namespace toond::test
