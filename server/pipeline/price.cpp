#include "pipeline/price.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "pipeline/frames.h"
#include "pipeline/plan.h"
#include "pipeline/sheet_layers.h"

namespace toond::pipeline {
namespace {

using render::RenderCost;
using render::RenderParams;

// What the request would cost drawn with `params` instead of its own, in
// the same poses: its frames planned as they would be.
RenderPrice price_with(const Request& request, const std::vector<ObjectPoses>& poses, const RenderParams& params) {
  return price_of(plan_frames(request, poses, params, layout_of(params)));
}

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(v < 10 ? 2 : 0);
  s << std::fixed << v;
  return s.str();
}

// The changes to the request, each alone, that would bring it under the
// limit; the size is halved (aspect kept) until it fits or reaches 16.
std::vector<std::string> ways_under(const Request& request, const std::vector<ObjectPoses>& poses, double limit) {
  std::vector<std::string> ways;
  const RenderParams& p = request.params;
  const auto fits = [&](const RenderParams& changed) {
    return price_with(request, poses, changed).total.units() <= limit;
  };
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

double deepest_layers(const Request& request) {
  double layers = 0;
  for (const render::JobObject& o : request.objects) layers = std::max(layers, o.model->mesh.cost.layers());
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
  one.line_triangles /= n;
  one.line_edges /= n;
  return one;
}

RenderPrice price_of(const std::vector<render::FramePlan>& plans) {
  RenderPrice p;
  p.frames = plans.size();
  for (const render::FramePlan& plan : plans) p.total += plan.cost;
  return p;
}

void check_render_cost(const Request& request, const std::vector<ObjectPoses>& poses, const RenderPrice& p,
                       const RenderLimits& limits) {
  const double limit = limits.max_render_cost;
  if (limit <= 0 || p.total.units() <= limit) return;
  std::string message = "the render is predicted to cost " + p.total.describe();
  const std::size_t layers = drawn_layers(request.params, request.answer.file).size();
  if (layers > 1) {
    message += " for its " + std::to_string(p.frames / layers) + " frames × " + std::to_string(layers) + " layers";
  } else if (p.frames > 1) {
    message += " for its " + std::to_string(p.frames) + " frames";
  }
  message += ", more than the limit --max-render-cost = " + fmt(limit) + " Msamples; the model's surface lies up to " +
             fmt(deepest_layers(request)) + " layers deep";
  const std::vector<std::string> ways = ways_under(request, poses, limit);
  if (ways.empty()) {
    message +=
        "; no single change of size, msaa, supersample or outline brings it under: the model itself is too "
        "costly to draw (upload it with fewer overlapping faces)";
  } else {
    message += "; any of these would bring it under: ";
    for (std::size_t i = 0; i < ways.size(); ++i) message += (i ? ", " : "") + ways[i];
  }
  throw CostRefused(422, "--max-render-cost", message, request.params.sheet ? "/sheet" : "/width");
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

render::Pacing pacing_of(const RenderPrice& price) {
  return {paced_chunk_triangles(price.per_frame()), paced_band_texels(price.per_frame())};
}

}  // namespace toond::pipeline
