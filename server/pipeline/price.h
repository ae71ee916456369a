#pragma once
// The price of a render request, worked out before it is queued
// (render/plan/render_cost.h): a sheet costs all its frames, in every layer
// it draws (sheet_layers.h). Over the daemon's
// --max-render-cost the request is refused with the figures and what would
// bring it under; under it, the price picks the queue lane and whether the
// draws are paced (render/frame/draw_pacing.h).
#include <cstddef>
#include <vector>

#include "limit_error.h"
#include "pipeline/pose.h"
#include "pipeline/render_limits.h"
#include "pipeline/request.h"
#include "render/plan/frame_plan.h"
#include "render/plan/render_cost.h"
#include "render/plan/schedule.h"

namespace toond::pipeline {

struct RenderPrice {
  render::RenderCost total;  // every frame of the request
  std::size_t frames = 1;
  render::RenderCost per_frame() const;
};

// The price of frames planned (plan.h): the sum of their plans' costs.
RenderPrice price_of(const std::vector<render::FramePlan>& plans);

// A request refused for its price: the daemon counts these (/metrics).
class CostRefused : public LimitError {
 public:
  using LimitError::LimitError;
};

// Throws CostRefused (422, limit_exceeded, --max-render-cost) when the price
// is over the limit, naming the figure, the limit, and the changes to the
// request (size, msaa, supersample, outline) that would fit, each priced
// from the plans its frames would have in the same `poses` (pose.h).
void check_render_cost(const Request& request, const std::vector<ObjectPoses>& poses, const RenderPrice& price,
                       const RenderLimits& limits);

// Frames priced at this many Msamples or more (about 0.7 s of llvmpipe) are
// drawn in chunks of about kPacedChunkCost each (about 45 ms), the deadline
// checked between them: such a render stops within about a chunk of it,
// and a short render waits for at most one of its chunks.
inline constexpr double kPacedFrameCost = 400;
inline constexpr double kPacedChunkCost = 25;
// Triangles per chunk for a frame of this price (the edge pass and the
// crease edges left out: they are paced in bands and chunks of their
// own); 0: not paced.
std::size_t paced_chunk_triangles(const render::RenderCost& frame);
// Texels of the edge pass per band for a frame of this price, a chunk's
// worth (render/frame/draw_pacing.h); 0: not paced.
std::size_t paced_band_texels(const render::RenderCost& frame);
// Both, for every frame of a request of this price.
render::Pacing pacing_of(const RenderPrice& price);

}  // namespace toond::pipeline
