#include "http/render_price.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "limit_error.h"
#include "render/pass_plan.h"
#include "render/pixel_art_frame.h"
#include "render/sheet_layout.h"

namespace toond::http {
namespace {

using render::RenderCost;
using render::RenderParams;

// The parameters each frame is drawn with, as the sheet renderer draws
// them (http/sheet_render.cpp): its yaw and pitch, a pixel-art frame at its
// reduced size, one sample a pixel.
std::vector<RenderParams> drawn_frames(const RenderParams& params) {
  if (!params.sheet) return {params};
  const render::SheetLayout layout = render::layout_sheet(*params.sheet, params.width, params.height);
  std::vector<RenderParams> frames;
  for (const render::SheetFrame& frame : layout.frames) {
    RenderParams one = render::frame_params(params, layout, frame);
    if (params.sheet->pixel_art) one = render::pixel_art_frame_params(std::move(one), *params.sheet->pixel_art);
    frames.push_back(std::move(one));
  }
  return frames;
}

// Only what changes the passes drawn: a hard-edged model adds crease lines,
// drawn along its crease edges (or found in screen space on masked
// materials).
render::ModelTraits traits_of(const render::RenderJob& job) {
  render::ModelTraits traits;
  const double crease_angle = job.params.outline.crease_angle_deg;
  for (const render::JobObject& o : job.objects) {
    traits.hard_edged |= o.model->mesh.creases.hard_edged(crease_angle);
    traits.has_crease_edges |= o.model->mesh.crease_edges.creased_at(crease_angle) > 0;
    for (const scene::Material& m : o.model->materials) traits.has_masked_materials |= m.alpha_cutoff >= 0.0f;
  }
  return traits;
}

RenderPrice price(const render::RenderJob& job, const RenderParams& params) {
  std::vector<const scene::Mesh*> meshes;
  for (const render::JobObject& o : job.objects) meshes.push_back(&o.model->mesh);
  // A scene's objects are turned by their transforms: priced from their
  // densest direction, not the camera's.
  const render::ViewKnown view = params.objects.empty() ? render::ViewKnown::Camera : render::ViewKnown::Any;
  const render::ModelTraits traits = traits_of(job);
  RenderPrice p;
  p.frames = 0;
  for (const RenderParams& frame : drawn_frames(params)) {
    p.total += render::predict_frame_cost(frame, render::plan_passes(frame, traits), meshes, view);
    ++p.frames;
  }
  return p;
}

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(v < 10 ? 2 : 0);
  s << std::fixed << v;
  return s.str();
}

// The changes to the request, each alone, that would bring it under the
// limit; the size is halved (aspect kept) until it fits or reaches 16.
std::vector<std::string> ways_under(const render::RenderJob& job, double limit) {
  std::vector<std::string> ways;
  const RenderParams& p = job.params;
  const auto fits = [&](const RenderParams& changed) { return price(job, changed).total.units() <= limit; };
  RenderParams smaller = p;
  while (smaller.width > 16 && smaller.height > 16) {
    smaller.width = std::max(16, smaller.width / 2);
    smaller.height = std::max(16, smaller.height / 2);
    if (fits(smaller)) {
      ways.push_back("width and height " + std::to_string(smaller.width) + " × " + std::to_string(smaller.height));
      break;
    }
  }
  if (p.msaa > 1) {
    RenderParams one_sample = p;
    one_sample.msaa = 1;
    if (fits(one_sample)) ways.push_back("msaa 1");
  }
  if (p.supersample > 1) {
    RenderParams no_supersample = p;
    no_supersample.supersample = 1;
    if (fits(no_supersample)) ways.push_back("supersample 1");
  }
  if (p.outline.any()) {
    RenderParams no_outline = p;
    no_outline.outline.enabled = false;
    if (fits(no_outline)) ways.push_back("outline.enabled false");
  }
  return ways;
}

double deepest_layers(const render::RenderJob& job) {
  double layers = 0;
  for (const render::JobObject& o : job.objects) layers = std::max(layers, o.model->mesh.cost.layers());
  return layers;
}

}  // namespace

RenderCost RenderPrice::per_frame() const {
  RenderCost one = total;
  const double n = static_cast<double>(std::max<std::size_t>(frames, 1));
  one.samples /= n;
  one.triangles /= n;
  one.tiles /= n;
  one.framebuffer /= n;
  one.frames /= n;
  one.edge_texels /= n;
  one.crease_edges /= n;
  return one;
}

RenderPrice price_render(const render::RenderJob& job) { return price(job, job.params); }

void check_render_cost(const render::RenderJob& job, const RenderPrice& p, const RenderLimits& limits) {
  const double limit = limits.max_render_cost;
  if (limit <= 0 || p.total.units() <= limit) return;
  std::string message = "the render is predicted to cost " + p.total.describe();
  if (p.frames > 1) message += " for its " + std::to_string(p.frames) + " frames";
  message += ", more than the limit --max-render-cost = " + fmt(limit) + " Msamples; the model's surface lies up to " +
             fmt(deepest_layers(job)) + " layers deep";
  const std::vector<std::string> ways = ways_under(job, limit);
  if (ways.empty()) {
    message += "; no single change of size, msaa, supersample or outline brings it under: the model itself is too "
               "costly to draw (upload it with fewer overlapping faces)";
  } else {
    message += "; any of these would bring it under: ";
    for (std::size_t i = 0; i < ways.size(); ++i) message += (i ? ", " : "") + ways[i];
  }
  throw LimitError(422, "--max-render-cost", message, job.params.sheet ? "/sheet" : "/width");
}

std::size_t paced_chunk_triangles(const RenderCost& frame) {
  if (frame.units() < kPacedFrameCost || frame.triangles <= 0) return 0;
  RenderCost drawing = frame;
  drawing.edge_texels = 0;
  drawing.crease_edges = 0;
  const double per_triangle = drawing.units() / frame.triangles;
  return static_cast<std::size_t>(std::max(16.0, std::floor(kPacedChunkCost / per_triangle)));
}

std::size_t paced_band_texels(const RenderCost& frame) {
  if (frame.units() < kPacedFrameCost || frame.triangles <= 0) return 0;
  return static_cast<std::size_t>(kPacedChunkCost * 1e6 / render::kEdgeTexelSamples);
}

}  // namespace toond::http
