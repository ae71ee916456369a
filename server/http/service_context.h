#pragma once
// What the routes share: the model store, the in-memory model library, the
// render thread and the daemon's limits.
#include <chrono>
#include <memory>

#include "http/request_limits.h"
#include "http/result_cache.h"
#include "http/service_metrics.h"
#include "pipeline/pose.h"
#include "pipeline/svg_render.h"
#include "render/run/render_service.h"
#include "scene/store/model_library.h"
#include "scene/store/model_store.h"

namespace toond::http {

struct ServiceContext {
  scene::ModelStore& store;
  scene::ModelLibrary& library;
  render::RenderService& renderer;
  std::chrono::milliseconds render_deadline{60000};
  RequestLimits limits{};
  // Default-constructed with the context: GET /metrics and the hooks that feed it.
  ServiceMetrics metrics{};
  // Finished renders by canonical parameters; null: every request renders.
  std::unique_ptr<ResultCache> results{};
  // Recently used clips' framings (a request with `animation`).
  pipeline::ClipFramings clip_framings{};
  // Output svg's models' edges and the lane its drawings wait in.
  pipeline::LineDrawings line_drawings{};
};

}  // namespace toond::http
