#include "render/plan/render_cost.h"

#include "render/plan/camera.h"
#include "render/plan/line_drawing_cost.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

namespace toond::render {
namespace {

// Passes that rasterise the meshes over the whole drawn frame.
int frame_geometry_passes(const PassPlan& plan) {
  int n = 0;
  for (Pass pass : plan.passes) {
    switch (pass) {
      case Pass::Main:
      case Pass::HullOutline:
      case Pass::Wireframe:
      case Pass::EdgePrepass:
      case Pass::Layer:
        ++n;
        break;
      default:
        break;
    }
  }
  return n;
}

// Passes that touch every sample of the frame once, however much is drawn.
int frame_wide_passes(const PassPlan& plan) {
  int n = 1;  // the clear before the first pass
  for (Pass pass : plan.passes) {
    switch (pass) {
      case Pass::Edges:
      case Pass::Resolve:
      case Pass::Downsample:
      case Pass::Readback:
        ++n;
        break;
      default:
        break;
    }
  }
  return n;
}

// One pass over every mesh at `width` × `height` drawn pixels, seen along
// `view` (none: from their densest direction).
RenderCost pass_cost(std::span<const scene::Mesh* const> meshes, const std::optional<glm::dvec3>& view, double width,
                     double height, double samples) {
  RenderCost cost;
  const double diagonal_tiles = std::hypot(width, height) / kTilePixels;
  for (const scene::Mesh* mesh : meshes) {
    const double layers = view ? mesh->cost.layers_toward(*view) : mesh->cost.layers();
    cost.samples += layers * width * height * samples;
    cost.triangles += static_cast<double>(mesh->triangle_count());
    cost.tiles += mesh->cost.edge_span() * diagonal_tiles * samples;
  }
  return cost;
}

// The crease pass: every edge creased at the request's angle (and every
// segment where parts cross that turns as far, drawn alike), and the
// samples its lines cover (each mesh's creased length at the frame's scale:
// framed, its bounding sphere fills the frame's shorter side). Drawn one
// sample a pixel, the lines' coverage is gathered in a target of its own,
// cleared and laid over the image: two more passes over the frame.
RenderCost crease_cost(const PricedFrame& frame, std::span<const scene::Mesh* const> meshes, double width,
                       double height) {
  RenderCost cost;
  const double angle = frame.params.outline.crease_angle_deg;
  const int samples = frame.passes.samples;
  const auto add = [&](const scene::TurnTally& lines) {
    cost.crease_edges += static_cast<double>(lines.creased_at(angle));
    cost.samples += lines.length_at(angle) * std::min(width, height) * frame.line_px * samples;
  };
  for (const scene::Mesh* mesh : meshes) {
    add(mesh->crease_edges);
    add(mesh->intersections);
  }
  if (samples == 1) cost.framebuffer += 2 * kLineCoveragePassSamples * width * height;
  return cost;
}

}  // namespace

double edge_texels_per_pixel(double line_px, bool creases_only) {
  const double reach = std::ceil((0.5 * line_px + 0.5) * 1.4143);
  return 4.0 * reach + (creases_only ? kCreasePixelTexels : kSilhouettePixelTexels);
}

double RenderCost::units() const {
  return (samples + triangles * kTriangleSamples + tiles * kTileSamples + framebuffer * kFramebufferSamples +
          frames * kFrameSamples + edge_texels * kEdgeTexelSamples + crease_edges * kCreaseEdgeSamples +
          line_triangles * kLineTriangleSamples + line_edges * kLineEdgeSamples) /
         1e6;
}

std::string RenderCost::describe() const {
  std::ostringstream s;
  s.precision(3);
  s << units() << " Msamples (surface samples " << samples / 1e6 << " M, triangles " << triangles / 1e6
    << " M, tile samples crossed " << tiles / 1e6 << " M, frame samples " << framebuffer / 1e6 << " M";
  if (edge_texels > 0) s << ", edge pass texels " << edge_texels / 1e6 << " M";
  if (crease_edges > 0) s << ", crease edges " << crease_edges / 1e6 << " M";
  if (line_triangles > 0) s << ", line drawing's triangles " << line_triangles / 1e6 << " M";
  if (line_edges > 0) s << ", line drawing's edges " << line_edges / 1e6 << " M";
  s << ")";
  return s.str();
}

RenderCost& RenderCost::operator+=(const RenderCost& other) {
  samples += other.samples;
  triangles += other.triangles;
  tiles += other.tiles;
  framebuffer += other.framebuffer;
  frames += other.frames;
  edge_texels += other.edge_texels;
  crease_edges += other.crease_edges;
  line_triangles += other.line_triangles;
  line_edges += other.line_edges;
  return *this;
}

RenderCost predict_frame_cost(const PricedFrame& frame, std::span<const scene::Mesh* const> meshes, ViewKnown view) {
  const RenderParams& params = frame.params;
  const PassPlan& plan = frame.passes;
  if (params.output == Output::Svg) return line_drawing_cost(params, meshes);
  const double width = static_cast<double>(params.width) * plan.supersample;
  const double height = static_cast<double>(params.height) * plan.supersample;
  const bool known = view == ViewKnown::Camera;
  const std::optional<glm::dvec3> eye =
      known ? std::optional(toward_eye(params.camera.yaw_deg, params.camera.pitch_deg)) : std::nullopt;
  RenderCost cost;
  const RenderCost one_pass = pass_cost(meshes, eye, width, height, plan.samples);
  for (int i = frame_geometry_passes(plan); i > 0; --i) cost += one_pass;
  if (plan.has(Pass::Shadow)) {
    const double side = params.shadows.map_size;
    cost += pass_cost(meshes, known ? std::optional(frame.shadow_direction) : std::nullopt, side, side, 1);
    cost.framebuffer += side * side;  // its clear
  }
  cost.framebuffer += width * height * plan.samples * frame_wide_passes(plan);
  if (plan.has(Pass::Edges)) {
    cost.edge_texels = width * height * edge_texels_per_pixel(frame.line_px, plan.creases_only);
  }
  if (plan.has(Pass::Creases)) cost += crease_cost(frame, meshes, width, height);
  cost.frames = 1;
  return cost;
}

}  // namespace toond::render
