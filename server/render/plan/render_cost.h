#pragma once
// The price of a render, worked out before it is queued from the pass plan,
// the drawn size and each mesh's cost profile (scene/mesh/render_cost_profile.h).
// It decides three things: whether a request is refused outright
// (--max-render-cost), which queue lane it waits in (a long render must not
// hold up short ones), and whether its draws are paced in chunks that check
// the deadline between them. Pure arithmetic, no GL.
#include <span>
#include <string>

#include <glm/glm.hpp>

#include "render/plan/pass_plan.h"
#include "render/plan/render_params.h"
#include "scene/mesh/model.h"

namespace toond::render {

// The three things a rasteriser spends its time on, added up over every pass
// that draws the meshes (main, floor excluded, hull, wireframe, edge
// prepass, layer; the shadow pass at the shadow map's size).
struct RenderCost {
  double samples = 0;    // samples covered: layers × drawn pixels × MSAA samples
  double triangles = 0;  // triangles set up
  // Screen tiles crossed by triangles (their longest edges), times the
  // samples a pixel has: a multisampled tile costs a rasteriser that much more.
  double tiles = 0;
  // The frame's own samples once per pass that touches them all (the
  // clear, the resolve, full-screen passes, the readback), whatever is drawn.
  double framebuffer = 0;
  double frames = 0;  // frames drawn: each has a fixed cost of its own
  // Texels the screen-space edge pass reads: drawn pixels × what one
  // pixel's walks toward the nearest edge read (edges.frag), which grows
  // with the line's width. At 2048² that pass alone costs llvmpipe more
  // than drawing the meshes.
  double edge_texels = 0;
  // Crease edges the crease pass draws (every edge creased at the
  // request's angle, of every mesh): each is four vertices posed, a
  // geometry stage and a line set up, whatever its length. The samples
  // its lines cover are counted with the others.
  double crease_edges = 0;
  // A vector line drawing (output svg, render/vector/line_drawing.h) draws
  // nothing on the GPU: it places, faces and bins every triangle on the
  // CPU, then tests each edge that may be a line against the triangles
  // near it on screen (render/plan/line_drawing_cost.h).
  double line_triangles = 0;
  double line_edges = 0;

  // One figure, in millions of sample-equivalents ("Msamples"): a triangle
  // set up counts as kTriangleSamples samples, a tile sample crossed as
  // kTileSamples, a frame sample as kFramebufferSamples, a frame as
  // kFrameSamples, a texel the edge pass reads as kEdgeTexelSamples, a
  // crease edge drawn as kCreaseEdgeSamples, a line drawing's triangle as
  // kLineTriangleSamples and its edge as kLineEdgeSamples. The
  // weights were fitted to llvmpipe's render times (bench/render_cost.py:
  // 1.0–1.8 ms per Msample on a 2-core machine, from day to day); on a GPU
  // the figure is still proportional to the work.
  double units() const;
  // "12.3 Msamples (layers × pixels: …, triangles: …, tiles: …)" for messages.
  std::string describe() const;
  RenderCost& operator+=(const RenderCost& other);
};

inline constexpr double kTriangleSamples = 40;
inline constexpr double kTileSamples = 320;
inline constexpr double kFramebufferSamples = 1;
inline constexpr double kFrameSamples = 1.3e6;
inline constexpr double kEdgeTexelSamples = 4.5;
// The crease pass's weights were fitted to its own time (a frame with it
// less the same with `creases: never`; bench/render_cost.py --crease-pass)
// on the shared windmill, the Kenney dog and 3,375 separate cubes at 256²
// to 2048², MSAA 1 and 4, line widths 2 and 8, three runs: 203-335 samples
// an edge, a sample its lines cover at 0.4-1.3 of a surface's (kept at 1:
// counted with the surface's), and 1.25-2.5 framebuffer samples a pixel
// for each of the two passes over the frame that gather and lay the lines'
// coverage when there is one sample a pixel; the medians kept.
inline constexpr double kCreaseEdgeSamples = 275;
inline constexpr double kLineCoveragePassSamples = 1.6;
// A line drawing's weights (render/plan/line_drawing_cost.h), fitted by
// bench/line_drawing.py --fit to its own time (Server-Timing `lines`) on
// the shared models and fandisk, two views each, at 1.4 ms a Msample: 497
// and 2416 (2026-12-07, a 2-core machine shared with other builds). They
// over-price the small closed models (2 ms drawn, 6-15 ms priced) and
// under-price the windmill's many crease edges by up to half; the price
// only refuses (--max-render-cost), so erring high is the safe side.
inline constexpr double kLineTriangleSamples = 500;
inline constexpr double kLineEdgeSamples = 2400;
inline constexpr double kSilhouetteEdgesPerRootTriangle = 8;
// The screen tile a rasteriser bins triangles into (llvmpipe's is 64 pixels).
inline constexpr double kTilePixels = 64;

// What one pixel of the edge pass costs, in texels it reads (edges.frag),
// for a line this many drawn pixels wide: four walks along the axes, each
// as far as an edge that could still touch the pixel, and a fixed part
// counted as so many texels more. The fixed parts were measured
// (bench/render_cost.py: the pass's time at line widths 2 and 8): crease
// lines alone cost about 9 texels' worth besides the walks; silhouettes
// about 33 (the multisampled prepass resolved first, the texel behind each
// walk, the covered shares, and the walks across near an edge).
inline constexpr double kCreasePixelTexels = 9;
inline constexpr double kSilhouettePixelTexels = 33;
double edge_texels_per_pixel(double line_px, bool creases_only);

// How the meshes of a frame are seen: from the camera's own direction (a
// lone model drawn as it is), or from any (the objects of a scene, each
// turned by its transform: priced at their densest direction).
enum class ViewKnown { Camera, Any };

// What a frame's price reads of its plan (frame_plan.h): the parameters it
// is drawn with (a pixel-art frame's reduced size, a sheet frame's yaw and
// pitch), its passes, the width its lines are drawn at and, where it casts
// a shadow, the way the shadow's light travels (scene coordinates, a
// view-space light already turned with the camera).
struct PricedFrame {
  const RenderParams& params;
  const PassPlan& passes;
  double line_px = 0;
  glm::dvec3 shadow_direction{0.0, 0.0, -1.0};
};

// The cost of one frame. Every mesh is assumed to fill the frame, at full
// detail; the shadow pass sees them from its light's direction.
RenderCost predict_frame_cost(const PricedFrame& frame, std::span<const scene::Mesh* const> meshes,
                              ViewKnown view = ViewKnown::Camera);

}  // namespace toond::render
