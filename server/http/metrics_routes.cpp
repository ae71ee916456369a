// GET /metrics: Prometheus text format. Requests are counted by the server's
// logger hook (it runs once per answered request, after the error handler
// has settled the status), so no route has to count itself.
#include "http/routes.h"

namespace toond::http {

void register_metrics_routes(httplib::Server& server, ServiceContext& context) {
  MetricsRegistry& registry = context.metrics.registry();
  registry.gauge("toond_render_queue_depth", "Render jobs waiting for the render thread.",
                 [&context] { return static_cast<double>(context.renders.queue_depth()); });
  registry.gauge("toond_models_stored", "Models in the data directory (shared by every replica that mounts it).",
                 [&context] { return static_cast<double>(context.store.usage().models); });
  registry.gauge("toond_store_bytes",
                 "Bytes of the stored models' files, every replica's (what --max-store-mb bounds).",
                 [&context] { return static_cast<double>(context.store.usage().bytes); });
  registry.gauge("toond_store_max_bytes", "The bound --max-store-mb puts on toond_store_bytes, in bytes; 0: none.",
                 [&context] { return static_cast<double>(context.store.max_bytes()); });
  registry.gauge("toond_store_volume_free_bytes",
                 "Bytes still free on the file system of the data directory (to the daemon's user).", [&context] {
                   const auto volume = context.store.volume();
                   return volume ? static_cast<double>(volume->free_bytes) : 0.0;
                 });
  registry.counter_from("toond_store_evictions_total",
                        "Models this replica let go to keep the store under --max-store-mb, least recently used first.",
                        [&context] { return static_cast<double>(context.store.evictions()); });
  registry.counter_from("toond_gpu_context_resets_total",
                        "Lost GL contexts (GPU resets) replaced by a new one since start.",
                        [&context] { return static_cast<double>(context.renders.gpu_resets()); });
  registry.counter_from("toond_frames_overlapped_total",
                        "Frames recorded while the same render thread's previous frame was still being read back "
                        "(--frames-in-flight 2).",
                        [&context] { return static_cast<double>(context.renders.overlapped_frames()); });
  registry.gauge("toond_gpu_models_loaded", "Models whose GPU copy this replica holds (its GPU LRU).",
                 [&context] { return static_cast<double>(context.renders.gpu_models_loaded()); });
  registry.gauge("toond_gpu_model_bytes",
                 "GPU memory held by the loaded models: vertex and index buffers and textures with mipmaps.",
                 [&context] { return static_cast<double>(context.renders.gpu_model_bytes()); });
  // The result cache counts its own lookups; without a cache both stay 0.
  const pipeline::ResultCache* results = context.renders.result_cache();
  registry.counter_from("toond_result_cache_hits_total", "Render requests answered from the result cache.",
                        [results] { return results ? static_cast<double>(results->hits()) : 0.0; });
  registry.counter_from("toond_result_cache_misses_total", "Render requests the result cache could not answer.",
                        [results] { return results ? static_cast<double>(results->misses()) : 0.0; });
  registry.gauge("toond_result_cache_bytes", "Bytes of PNGs the result cache holds.",
                 [results] { return results ? static_cast<double>(results->bytes()) : 0.0; });

  server.set_logger([&context](const httplib::Request& req, const httplib::Response& res) {
    context.metrics.count_request(req.method, route_label(req.path), res.status);
  });

  server.Get("/metrics", [&context](const httplib::Request&, httplib::Response& res) {
    res.set_content(context.metrics.registry().exposition(), "text/plain; version=0.0.4; charset=utf-8");
  });
}

}  // namespace toond::http
