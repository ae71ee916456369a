#pragma once
// Exact visibility: each candidate segment split where it passes behind a
// surface. A triangle hides one interval of a segment's parameter (four
// half-spaces, each linear along it: occluder_grid.h), found in view space
// so that perspective needs no depth interpolated on screen; the union of
// the intervals its occluders hide is its hidden part, the rest its
// visible part. Segments are first cut to the view (the near and far
// planes, the image and a margin round it).
#include <chrono>
#include <cstdint>
#include <vector>

#include "render/vector/line_candidates.h"
#include "render/vector/occluder_grid.h"
#include "render/vector/screen_map.h"
#include "render/vector/view_mesh.h"

namespace toond::render::vector {

// The stretch [t0, t1] of a segment (0 at its a, 1 at its b).
struct Piece {
  std::uint32_t segment = 0;
  double t0 = 0, t1 = 1;
  bool hidden = false;
};

struct VisibilityOptions {
  bool hidden_pieces = false;  // the hidden stretches too
  double margin_px = 0;        // drawn this far past the image's sides
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
};

// Also counts the triangles tested, for the benchmark.
struct Visibility {
  std::vector<Piece> pieces;  // in the segments' order, each segment's along it
  std::size_t occluder_tests = 0;
};

// Throws render::RenderAborted when the deadline passes.
Visibility split_by_visibility(const std::vector<Segment>& segments, const ViewMesh& mesh, const OccluderGrid& grid,
                               const ScreenMap& screen, const VisibilityOptions& options);

// The part [t0, t1] of the segment from a to b that lies in the view: in
// front of the near plane, short of the far one, within the image and
// `margin_px` round it. t0 >= t1: none of it.
std::pair<double, double> clip_to_view(const glm::dvec3& a, const glm::dvec3& b, const ScreenMap& screen,
                                       double margin_px);

// The interval of the segment from a (a + t d) that the occluder hides,
// within [lo, hi]; empty (first >= second) where it hides none. `tolerance`:
// a point this near the occluder's own plane, or the sides of its cone on
// the rim of what hides, is not hidden by it; one this near a side it
// shares with another that hides is.
std::pair<double, double> hidden_interval(const Occluder& o, const glm::dvec3& a, const glm::dvec3& d, double lo,
                                          double hi, double tolerance);

}  // namespace toond::render::vector
