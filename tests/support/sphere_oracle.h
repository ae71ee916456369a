#pragma once
// Measurements a render of a front-lit sphere (or a flat disk) must meet:
// where its band edges lie against the analytic radii, which pixels inside
// it show something no band would (background or outline through a crack),
// and how wide an outline ring is along every ray. Shared by the accuracy
// tests on the project's own clean meshes and on exporter-style ones.
#include <cstddef>

#include "image/image.h"
#include "support/edge_measure.h"

namespace toond::test {

inline constexpr int kOracleRays = 720;

// Band-edge errors (measured minus analytic radius, in pixels, searched
// within `window` px of it) over every ray and every inner edge of an N-band ceil-rounded render of a white
// sphere under a white light along the view, no ambient: band k has the
// linear level k/N, and the edge between k and k+1 lies at
// R·sqrt(1 − (k/N)²).
ErrorStats band_edge_errors(const image::Image& img, const DiskEstimate& disk, int steps, double window = 1.5);

// Pixels well inside the disk (more than `margin` px from its rim) whose
// colour no band has: not grey, or darker than half the lowest band.
std::size_t speck_pixels(const image::Image& img, const DiskEstimate& disk, int steps, double margin = 3.0);

// A white shape on blue with a red outline: along every ray the line runs
// from where green falls (white → red) to where red falls (red → blue),
// outside the silhouette or across it.
struct RingStats {
  ErrorStats width_error;  // measured width minus the asked width, px
  double min_width = 0;
  double max_width = 0;
  // Pixels farther out than the ring may reach (width + 2 px) that are
  // not background: a hull spike, or stray lines beside it.
  std::size_t stray_pixels = 0;
};
RingStats outline_ring(const image::Image& img, const DiskEstimate& disk, double width);

}  // namespace toond::test
