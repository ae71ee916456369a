#pragma once
// The pipeline's way for output svg: a vector line drawing
// (render/vector/line_drawing.h) instead of a rasterised frame. The same
// stages as a render (pipeline.h): posed (on the CPU, where the drawing
// reads the vertices), planned as the lines layer would be drawn (its
// passes say which lines; the camera and the outline's width are the
// plan's), priced (render/plan/line_drawing_cost.h: over --max-render-cost
// it is refused with what would fit), then drawn when its turn in the
// line lane comes (line_lane.h: not on a render thread) and written as SVG:
// whole, or for a drawing larger than kStreamedSvgBytes as the answer goes
// out, a piece at a time (streamed_body.h), never held whole as text.
#include <cstddef>
#include <string>

#include "pipeline/line_lane.h"
#include "render/vector/mesh_edges.h"

namespace toond::pipeline {

struct Rendered;
struct Request;
struct Services;

inline constexpr std::size_t kStreamedSvgBytes = std::size_t{1} << 20;
inline constexpr std::size_t kStreamedPieceBytes = std::size_t{64} << 10;

// What line drawings keep between requests: the models' edges, the lane.
struct LineDrawings {
  render::vector::EdgeCache edges;
  LineLane lane;
};

// As render() (pipeline.h), for a request whose output is svg.
Rendered render_svg(Request request, const std::string& client, Services& services);

}  // namespace toond::pipeline
