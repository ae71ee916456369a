#pragma once
// Waiting on a queued render no longer than the request may wait.
#include <chrono>
#include <future>

#include "render/run/render_service.h"
#include "render/run/renderer.h"

namespace toond::pipeline {

// How long a request waits for `job`: a paced job stops itself at its
// deadline and says so (503 render_aborted) within about a chunk, so it is
// given kAbortGrace more to do that; any other job is waited for until its
// deadline (which the pipeline always sets).
inline constexpr std::chrono::milliseconds kAbortGrace{2000};
std::chrono::steady_clock::time_point wait_limit(const render::RenderJob& job);

// The render's output, or RequestError 503 "deadline_exceeded" (naming
// --render-timeout, `limit` long) when it is not done by `deadline`.
render::RenderOutput await_render(std::future<render::RenderOutput>& future,
                                  std::chrono::steady_clock::time_point deadline, std::chrono::milliseconds limit);

}  // namespace toond::pipeline
