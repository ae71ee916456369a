#pragma once
// What the routes share: the model store, the render pipeline's entry (it
// owns the result cache and keeps the render threads behind it, so nothing
// the routes include reaches the GPU), the daemon's limits and its metrics.
#include "http/request_limits.h"
#include "http/service_metrics.h"
#include "pipeline/render_entry.h"
#include "scene/store/model_store.h"

namespace toond::http {

struct ServiceContext {
  scene::ModelStore& store;
  pipeline::RenderEntry& renders;
  RequestLimits limits{};
  // Default-constructed with the context: GET /metrics and the hooks that feed it.
  ServiceMetrics metrics{};
};

}  // namespace toond::http
