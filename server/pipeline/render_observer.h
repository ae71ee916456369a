#pragma once
// What is counted of the renders the entry (render_entry.h) runs, as they
// happen: GET /metrics counts them (server/http/service_metrics.h).
#include <string>
#include <vector>

#include "render/frame/pass_timing.h"

namespace toond::pipeline {

class RenderObserver {
 public:
  virtual ~RenderObserver() = default;

  // One finished render: the whole request (from its arrival to its encoded
  // answer), and the stages of its Server-Timing header: queue wait, each
  // pass, encoding (stage `encode_stage`: "png", or "webp" for an animated
  // sheet).
  virtual void observe_render(double seconds, const std::vector<render::PassTiming>& passes, double queue_ms,
                              double encode_ms, const std::string& encode_stage) = 0;
  // A render request's price (render/plan/render_cost.h) as it was admitted, its
  // lane, and the render threads' time its frames took: the two counters'
  // ratio is the seconds one Msample costs on this machine.
  virtual void observe_cost(double predicted_msamples, bool long_lane, double render_thread_seconds) = 0;
  // A request refused for its predicted cost (--max-render-cost).
  virtual void count_cost_refusal() = 0;
  // A render stopped at its deadline between chunks.
  virtual void count_abort() = 0;

 protected:
  RenderObserver() = default;
  RenderObserver(const RenderObserver&) = default;
  RenderObserver& operator=(const RenderObserver&) = default;
};

}  // namespace toond::pipeline
