#include "pipeline/render_wait.h"

#include <string>

#include "request_error.h"

namespace toond::pipeline {

std::chrono::steady_clock::time_point wait_limit(const render::RenderJob& job) {
  const std::chrono::steady_clock::time_point deadline = *job.schedule.deadline;
  return job.schedule.pacing.paced() ? deadline + kAbortGrace : deadline;
}

render::RenderOutput await_render(std::future<render::RenderOutput>& future,
                                  std::chrono::steady_clock::time_point deadline, std::chrono::milliseconds limit) {
  if (future.wait_until(deadline) != std::future_status::ready) {
    throw RequestError(
        503, "deadline_exceeded",
        "the render did not finish within the limit --render-timeout = " + std::to_string(limit.count()) + " ms");
  }
  return future.get();
}

}  // namespace toond::pipeline
