#pragma once
// Error figures for the benchmark: an image against a reference render, and
// the band edges of the analytic sphere against their exact radii.
#include "image/image.h"

namespace toond::bench {

// A pixel is "off" when a channel differs by more than this many levels of
// 255: an antialiased edge that moved by a sliver of a pixel is not off, a
// band edge or a silhouette that moved by a pixel is. The LOD integration
// test uses the same rule.
inline constexpr int kOffTolerance = 8;

struct PixelError {
  double mean_abs = 0;  // over every RGB channel of every pixel, in levels of 255
  double pct_off = 0;   // percent of pixels "off" (see kOffTolerance)
  // Pixels in the largest 4-connected group of off pixels: scattered
  // slivers along edges stay small, a crack or a missing part does not.
  std::size_t largest_blob = 0;
};

// Both images must have the same size.
PixelError compare_images(const image::Image& reference, const image::Image& image);

// The sphere oracle (the same measurement as tests/integration/
// analytic_oracle_test.cpp, through tests/support/edge_measure.h): an
// orthographic, front-lit sphere with `steps` ceil-rounded bands on a black
// background, white base, no ambient, has its band edges at
// R·sqrt(1 − (k/N)²). `silhouette` is a flat white render of the same
// sphere at the highest quality, which gives the centre and R.
struct BandEdgeError {
  double mean_px = 0;
  double max_px = 0;
  std::size_t missing = 0;  // rays along which an edge was not found
};
BandEdgeError sphere_band_edge_error(const image::Image& silhouette, const image::Image& banded, int steps);

}  // namespace toond::bench
