#pragma once
// The pipeline's queueing stage: a request's frames queued together
// (RenderService::submit_all: admitted as one request, drawn back to back),
// then waited for one by one, each handed to the assembly as it comes.
#include <chrono>
#include <vector>

#include "pipeline/assemble.h"
#include "render/run/render_service.h"

namespace toond::pipeline {

// `frames` in layout order; they are queued so that frames sharing a pose
// (an animated sheet's directions of one time) follow each other, and the
// GPU copy poses once for all of them (GpuModel::apply_pose). Each is
// waited for until its schedule's deadline (render_wait.h); `limit` is
// --render-timeout.
void queue_frames(render::RenderService& renderer, std::vector<render::RenderJob> frames,
                  std::chrono::milliseconds limit, Assembly& assembly);

}  // namespace toond::pipeline
