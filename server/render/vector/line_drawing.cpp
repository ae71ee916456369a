#include "render/vector/line_drawing.h"

#include <glm/gtc/matrix_transform.hpp>

#include <map>

#include "render/vector/contour_filter.h"
#include "render/vector/line_colours.h"
#include "render/vector/occluder_grid.h"
#include "render/vector/pen_order.h"
#include "render/vector/screen_map.h"
#include "render/vector/segment_visibility.h"

namespace toond::render::vector {
namespace {

// A piece shorter than this on screen, cut short by what hides it, is a
// sliver between two occluders rather than a line anyone could see.
constexpr double kSliverPx = 0.01;

std::uint32_t colour_key(const Srgb& c) { return (std::uint32_t{c[0]} << 16) | (std::uint32_t{c[1]} << 8) | c[2]; }

Srgb colour_of_key(std::uint32_t key) {
  return {static_cast<std::uint8_t>(key >> 16), static_cast<std::uint8_t>(key >> 8), static_cast<std::uint8_t>(key)};
}

// Each piece with the points it joins others at: a segment's own ends
// where it is drawn to them, an id of its own where it is cut; the visible
// ones by kind and colour (ordered by colour, so the file does not depend
// on the order pieces were found in).
struct LayerPieces {
  std::array<std::map<std::uint32_t, std::vector<StrokePiece>>, kLineKinds> visible;
  std::vector<StrokePiece> hidden;
  std::uint32_t node_count = 0;
};

LayerPieces layer_pieces(const Candidates& candidates, const std::vector<Piece>& pieces, const ScreenMap& screen,
                         const LineColours& colours) {
  LayerPieces out;
  out.node_count = candidates.node_count;
  for (const Piece& piece : pieces) {
    const Segment& s = candidates.segments[piece.segment];
    const glm::dvec3 d = s.b - s.a;
    StrokePiece stroke;
    stroke.p0 = screen.to_pixels(s.a + piece.t0 * d);
    stroke.p1 = screen.to_pixels(s.a + piece.t1 * d);
    const bool whole_start = piece.t0 == 0.0, whole_end = piece.t1 == 1.0;
    if (!(whole_start && whole_end) && glm::length(stroke.p1 - stroke.p0) < kSliverPx) continue;
    stroke.node0 = whole_start ? s.node_a : out.node_count++;
    stroke.node1 = whole_end ? s.node_b : out.node_count++;
    if (piece.hidden) {
      out.hidden.push_back(stroke);
    } else {
      out.visible[static_cast<std::size_t>(s.kind)][colour_key(colours.of(s))].push_back(stroke);
    }
  }
  return out;
}

std::vector<Polyline> strokes_of(const std::vector<StrokePiece>& pieces, std::uint32_t node_count, double gap) {
  std::vector<Polyline> strokes = stitch_strokes(chain_strokes(pieces, node_count), gap);
  order_for_pen(strokes);
  return strokes;
}

// The pieces' points numbered from 0 (in the order they come), so that
// chaining one colour of many costs its own pieces, not every point of
// the frame. `scratch`: one entry a point id, each kNoGroup; left so.
std::uint32_t renumber_nodes(std::vector<StrokePiece>& pieces, std::vector<std::uint32_t>& scratch) {
  std::uint32_t next = 0;
  const auto renumber = [&](std::uint32_t& node) {
    if (scratch[node] == kNoGroup) scratch[node] = next++;
    node = scratch[node];
  };
  std::vector<std::uint32_t> used;
  for (StrokePiece& piece : pieces) {
    used.push_back(piece.node0);
    used.push_back(piece.node1);
    renumber(piece.node0);
    renumber(piece.node1);
  }
  for (std::uint32_t node : used) scratch[node] = kNoGroup;
  return next;
}

// One layer's strokes, a set per colour; a layer of one colour chains as
// it is.
std::vector<ColouredStrokes> layer_strokes(std::map<std::uint32_t, std::vector<StrokePiece>>& by_colour,
                                           std::uint32_t node_count, double gap) {
  std::vector<ColouredStrokes> sets;
  std::vector<std::uint32_t> scratch;
  if (by_colour.size() > 1) scratch.assign(node_count, kNoGroup);
  for (auto& [key, pieces] : by_colour) {
    const std::uint32_t nodes = by_colour.size() > 1 ? renumber_nodes(pieces, scratch) : node_count;
    sets.push_back({colour_of_key(key), strokes_of(pieces, nodes, gap)});
  }
  return sets;
}

// The drawing's frame, size, stroke and camera, without its lines.
SvgDrawing blank_drawing(const FramePlan& plan) {
  const RenderParams& p = plan.params;
  SvgDrawing svg;
  svg.width = p.width;
  svg.height = p.height;
  svg.stroke_px = plan.outline_px > 0 ? plan.outline_px / plan.passes.supersample : p.contour.width_px;
  svg.colour = fixed_line_colour(plan);
  // The frame's coordinates are the scene's less its origin.
  svg.view = plan.camera.view * glm::translate(glm::dmat4(1.0), -plan.scene->origin);
  svg.projection = plan.camera.projection;
  if (p.svg.hidden) svg.hidden.emplace();
  return svg;
}

}  // namespace

LineChoice line_choice(const FramePlan& plan) {
  const PassPlan& passes = plan.passes;
  LineChoice choice;
  const bool edge_pass_silhouettes = passes.has(Pass::Edges) && !passes.creases_only;
  choice.silhouettes = passes.has(Pass::HullOutline) || passes.has(Pass::Wireframe) || edge_pass_silhouettes ||
                       plan.params.contour.enabled;
  if (passes.has(Pass::Wireframe) || plan.params.contour.enabled) {
    choice.contours = ContourRule::All;
  } else if (edge_pass_silhouettes) {
    // As the edge pass measures it (edge_pass.cpp): a share of the scene's size.
    choice.contours = ContourRule::DepthJump;
    choice.depth_jump = plan.params.outline.depth_threshold * 2.0 * plan.scene->bounds.radius();
  }
  choice.boundaries = choice.silhouettes;
  choice.creases = passes.has(Pass::Creases) || passes.has(Pass::Edges);
  choice.intersections = choice.creases;
  choice.crease_angle_deg = plan.params.outline.crease_angle_deg;
  choice.keep_hidden = plan.params.svg.hidden;
  return choice;
}

LineDrawing draw_lines(const FramePlan& plan, std::span<const PlannedObject> objects,
                       std::span<const std::shared_ptr<const scene::Model>> models, EdgeCache& edges,
                       std::chrono::steady_clock::time_point deadline) {
  LineDrawing drawing;
  drawing.svg = blank_drawing(plan);
  const LineChoice choice = line_choice(plan);
  if (!choice.silhouettes && !choice.creases) return drawing;  // no line to look for
  LineStats& stats = drawing.stats;
  auto lap = std::chrono::steady_clock::now();
  const auto lap_ms = [&lap] {
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - lap).count();
    lap = now;
    return ms;
  };
  const ViewMesh mesh = view_mesh_of(plan, objects, models, edges);
  const Candidates candidates = line_candidates(mesh, choice);
  const LineColours colours(plan, mesh);
  stats.view_ms = lap_ms();
  const ScreenMap screen = ScreenMap::of(plan.camera.projection, plan.params.width, plan.params.height);
  const double margin = drawing.svg.stroke_px + 1.0;
  const OccluderGrid grid(mesh, screen, margin);
  stats.occluders = grid.size();
  stats.grid_ms = lap_ms();
  const Visibility visibility =
      split_by_visibility(candidates.segments, mesh, grid, screen,
                          {.hidden_pieces = choice.keep_hidden, .margin_px = margin, .deadline = deadline});
  // Judged just past the stroke's edge, where the hull's ring would show.
  const std::vector<Piece> drawn = keep_drawn_contours(visibility.pieces, candidates.segments, grid, screen, choice,
                                                       0.5 * drawing.svg.stroke_px + 1.0);
  stats.visibility_ms = lap_ms();
  LayerPieces pieces = layer_pieces(candidates, drawn, screen, colours);
  // Ends nearer than half the stroke's width are one to the eye and the pen.
  const double stitch_gap = std::min(1.0, 0.5 * drawing.svg.stroke_px);
  for (LineKind kind : kAllLineKinds) {
    const std::size_t k = static_cast<std::size_t>(kind);
    drawing.svg.layers[k] = layer_strokes(pieces.visible[k], pieces.node_count, stitch_gap);
    for (const ColouredStrokes& set : drawing.svg.layers[k]) stats.paths += set.strokes.size();
  }
  if (choice.keep_hidden) {
    drawing.svg.hidden = strokes_of(pieces.hidden, pieces.node_count, stitch_gap);
    stats.paths += drawing.svg.hidden->size();
  }
  stats.strokes_ms = lap_ms();
  stats.candidates = candidates.segments.size();
  stats.occluder_tests = visibility.occluder_tests;
  stats.pieces = visibility.pieces.size();
  return drawing;
}

}  // namespace toond::render::vector
