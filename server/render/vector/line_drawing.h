#pragma once
// A frame's lines as vectors (`output: "svg"`): the lines the same
// request's PNG draws, found exactly on the triangles drawn (the level of
// detail and pose the plan chose), each cut where it passes behind a
// surface, chained into strokes and ordered for a pen. Pure CPU work on
// the frame's plan (frame_plan.h, no GL): the
// pipeline runs it on the request's thread, its runs spread over the cores.
//   view_mesh          the triangles in view space, which way each faces
//   line_candidates    silhouettes, creases, seams, open edges (scene_seams:
//                      where a scene's objects cross)
//   occluder_grid      what may hide each, binned on screen
//   segment_visibility each cut into visible and hidden pieces
//   contour_filter     the silhouettes the outline methods draw
//   line_colours       the colour of each, as the PNG draws it
//   stroke_chains      pieces joined into strokes, one layer a kind
//   pen_order          the strokes ordered for a plotter
//   svg_document       the SVG text
#include <chrono>
#include <memory>
#include <span>

#include "render/plan/frame_plan.h"
#include "render/vector/line_candidates.h"
#include "render/vector/mesh_edges.h"
#include "render/vector/svg_document.h"

namespace toond::render::vector {

// What a drawing held and took, for its answer's headers and the benchmark.
struct LineStats {
  std::size_t candidates = 0;      // segments before visibility
  std::size_t occluder_tests = 0;  // triangles a segment was tested against
  std::size_t pieces = 0;          // visible and hidden pieces
  std::size_t paths = 0;           // strokes written, every layer
  std::size_t occluders = 0;       // triangles that may hide something, binned
  // Milliseconds: the triangles placed and the candidates found; the
  // occluders made and binned; visibility and the silhouettes kept; strokes.
  double view_ms = 0, grid_ms = 0, visibility_ms = 0, strokes_ms = 0;
};

struct LineDrawing {
  SvgDrawing svg;
  LineStats stats;
};

// The kinds of line the plan's PNG draws: silhouettes and open edges with
// any outline method (or contour lines), creases and seams where crease
// lines are drawn along edges or found in screen space.
LineChoice line_choice(const FramePlan& plan);

// The frame's lines. `objects`: the plan's, in their poses; `models`: their
// models as shared (the
// edge cache keys on them); posed objects must carry their CPU sums
// (scene::SkinPose::cpu_sums). Throws RenderAborted past `deadline`.
LineDrawing draw_lines(const FramePlan& plan, std::span<const PlannedObject> objects,
                       std::span<const std::shared_ptr<const scene::Model>> models, EdgeCache& edges,
                       std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max());

}  // namespace toond::render::vector
