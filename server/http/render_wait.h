#pragma once
// Waiting on a queued render no longer than the request may wait.
#include <chrono>
#include <future>

#include "render/renderer.h"

namespace toond::http {

// The render's output, or RequestError 503 "deadline_exceeded" (naming
// --render-timeout, `limit` long) when it is not done by `deadline`.
render::RenderOutput await_render(std::future<render::RenderOutput>& future,
                                  std::chrono::steady_clock::time_point deadline, std::chrono::milliseconds limit);

}  // namespace toond::http
