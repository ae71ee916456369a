#pragma once
#include <cstddef>
#include <vector>

namespace toond::image {

// Four floats a pixel, rows top to bottom: a data layer as the GPU wrote
// it (a depth, a normal or an id), before it is turned into PNG samples.
// The fourth value is the share of the pixel the model covers, 0 for
// background.
struct FloatImage {
  int width = 0;
  int height = 0;
  std::vector<float> values;  // width * height * 4

  float* pixel(int x, int y) { return values.data() + (static_cast<std::size_t>(y) * width + x) * 4; }
  const float* pixel(int x, int y) const { return values.data() + (static_cast<std::size_t>(y) * width + x) * 4; }
  bool covered(int x, int y) const { return pixel(x, y)[3] > 0.0f; }
};

}  // namespace toond::image
