#pragma once
// toond's own metrics, served by GET /metrics (server/http/metrics_routes.cpp).
// Events are counted where they happen (requests by the server's logger
// hook, renders by the pipeline's entry, which reports them to this); what
// other parts count already (result-cache hits) and levels (queue depth,
// models stored and on the GPU, GPU bytes) are read at scrape time
// (metrics_routes.cpp).
#include <cstddef>
#include <string>
#include <vector>

#include "http/metrics.h"
#include "pipeline/render_observer.h"

namespace toond::http {

class ServiceMetrics : public pipeline::RenderObserver {
 public:
  ServiceMetrics();

  // One answered HTTP request; `route` is the route's template
  // (route_label), never the raw path, so ids do not multiply series.
  void count_request(const std::string& method, const std::string& route, int status);
  // What the pipeline's entry reports of each render (pipeline/render_observer.h).
  void observe_render(double seconds, const std::vector<render::PassTiming>& passes, double queue_ms, double encode_ms,
                      const std::string& encode_stage) override;
  void observe_cost(double predicted_msamples, bool long_lane, double render_thread_seconds) override;
  void count_cost_refusal() override;
  void count_abort() override;
  // One upload imported as a new model: how long the import took (parse,
  // mesh processing, levels of detail, storing) and the bundle's bytes.
  void observe_import(double seconds, std::size_t bytes);
  // An upload the model store refused: "volume_full", "models_in_use"
  // (at --max-store-mb, every model that could go held by a render) or
  // "larger_than_store".
  void count_store_refusal(const std::string& reason);

  MetricsRegistry& registry() { return registry_; }
  const CounterFamily& requests() const { return requests_; }

 private:
  MetricsRegistry registry_;
  CounterFamily& requests_;
  HistogramFamily& render_seconds_;
  HistogramFamily& pass_seconds_;
  HistogramFamily& predicted_cost_;
  CounterFamily& predicted_total_;
  CounterFamily& render_thread_seconds_;
  CounterFamily& cost_refusals_;
  CounterFamily& aborts_;
  HistogramFamily& import_seconds_;
  HistogramFamily& import_bytes_;
  CounterFamily& store_refusals_;
};

// The route template a request path belongs to ("/models/{id}/render",
// "/{file}" for the web page's files), or "other" for paths no route serves.
std::string route_label(const std::string& path);

}  // namespace toond::http
