#pragma once
// Sub-pixel measurements on rendered images, in linear light, for tests that
// compare a render against an analytic answer: where a disk's area puts its
// centre and radius, and where along a ray a channel crosses a level.
#include <optional>
#include <vector>

#include "image/image.h"

namespace toond::test {

// One channel of an image decoded from sRGB to linear light, rows top to
// bottom; pixel (x, y) has its centre at (x + 0.5, y + 0.5).
struct LinearChannel {
  int width = 0;
  int height = 0;
  std::vector<double> values;

  LinearChannel(const image::Image& img, int channel);
  double at(int x, int y) const;
  // Bilinear between pixel centres (edge pixels repeat outward).
  double sample(double x, double y) const;
};

double srgb_byte_to_linear(int byte);

// A disk seen as coverage: value 0 is background, 1 full cover (linear
// light, so a partly covered pixel holds its covered fraction). The area is
// the sum of the values, the centre their weighted mean.
struct DiskEstimate {
  double centre_x = 0;
  double centre_y = 0;
  double radius = 0;  // sqrt(area / π)
  double area = 0;
};
DiskEstimate estimate_disk(const LinearChannel& coverage);

// Walks the ray centre + t·(cos a, sin a) from t = from to t = to and
// returns the first t where the bilinear value crosses `level` (in either
// direction), interpolated linearly between the samples around it.
std::optional<double> ray_crossing(const LinearChannel& channel, double centre_x, double centre_y, double angle,
                                   double from, double to, double level);

struct ErrorStats {
  double mean_abs = 0;
  double max_abs = 0;
  std::size_t count = 0;
  std::size_t missing = 0;  // rays where no crossing was found
  void add(double error);
};

}  // namespace toond::test
