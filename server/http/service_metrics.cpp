#include "http/service_metrics.h"

#include <regex>

namespace toond::http {
namespace {

// Renders take milliseconds on a GPU and up to seconds on llvmpipe at large
// sizes; passes are a fraction of that.
const std::vector<double> kRenderBounds = {0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1, 2.5, 5, 10, 30};
const std::vector<double> kPassBounds = {0.0005, 0.001, 0.0025, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1, 5};
// Imports run from a cube's milliseconds to tens of seconds for the largest
// uploads; bundles from a few kilobytes to the upload limit.
const std::vector<double> kImportBounds = {0.01, 0.05, 0.1, 0.25, 0.5, 1, 2.5, 5, 10, 30, 60};
const std::vector<double> kImportByteBounds = {1e4, 1e5, 1e6, 1e7, 3e7, 1e8, 3e8};
// A thumbnail costs a few Msamples, a default 512² render tens, a large
// sheet thousands; the default refusal is at 20000.
const std::vector<double> kCostBounds = {1, 3, 10, 30, 100, 300, 1000, 3000, 10000, 30000};

}  // namespace

ServiceMetrics::ServiceMetrics()
    : requests_(registry_.counter("toond_http_requests_total", "HTTP requests answered, by method, route and status.",
                                  {"method", "route", "status"})),
      render_seconds_(registry_.histogram(
          "toond_render_seconds", "Render requests from parsing to the encoded PNG, in seconds.", {}, kRenderBounds)),
      pass_seconds_(
          registry_.histogram("toond_render_pass_seconds",
                              "Time of each render stage as in Server-Timing (queue wait, each GPU pass, png), "
                              "in seconds.",
                              {"pass"}, kPassBounds)),
      predicted_cost_(registry_.histogram("toond_render_predicted_cost_msamples",
                                          "Predicted cost of each admitted render request (all its frames), in "
                                          "Msamples, by queue lane.",
                                          {"lane"}, kCostBounds)),
      predicted_total_(registry_.counter("toond_render_predicted_msamples_total",
                                         "Predicted cost of the renders that finished, in Msamples.")),
      render_thread_seconds_(registry_.counter("toond_render_thread_seconds_total",
                                               "Render threads' measured time for the same renders, in seconds.")),
      cost_refusals_(registry_.counter("toond_render_cost_refusals_total",
                                       "Render requests refused for their predicted cost (--max-render-cost).")),
      aborts_(registry_.counter("toond_render_aborts_total",
                                "Renders stopped at their deadline between chunks of triangles (503 "
                                "render_aborted).")),
      import_seconds_(registry_.histogram("toond_import_seconds",
                                          "Uploads imported as new models, from the bundle to the stored model, in "
                                          "seconds.",
                                          {}, kImportBounds)),
      import_bytes_(registry_.histogram("toond_import_bytes", "Sizes of the bundles imported as new models, in bytes.",
                                        {}, kImportByteBounds)),
      store_refusals_(registry_.counter("toond_store_refusals_total",
                                        "Uploads the model store refused (507 storage_full, or 413 for a model larger "
                                        "than --max-store-mb), by reason.",
                                        {"reason"})) {
  // Each reason is there from the first scrape, at 0.
  for (const char* reason : {"volume_full", "models_in_use", "larger_than_store"}) store_refusals_.add({reason}, 0);
}

void ServiceMetrics::count_request(const std::string& method, const std::string& route, int status) {
  requests_.add({method, route, std::to_string(status)});
}

void ServiceMetrics::observe_render(double seconds, const std::vector<render::PassTiming>& passes, double queue_ms,
                                    double encode_ms, const std::string& encode_stage) {
  render_seconds_.observe({}, seconds);
  pass_seconds_.observe({"queue"}, queue_ms / 1000.0);
  for (const render::PassTiming& p : passes) pass_seconds_.observe({p.pass}, p.ms / 1000.0);
  pass_seconds_.observe({encode_stage}, encode_ms / 1000.0);
}

void ServiceMetrics::observe_cost(double predicted_msamples, bool long_lane, double render_thread_seconds) {
  predicted_cost_.observe({long_lane ? "long" : "short"}, predicted_msamples);
  predicted_total_.add({}, predicted_msamples);
  render_thread_seconds_.add({}, render_thread_seconds);
}

void ServiceMetrics::count_cost_refusal() { cost_refusals_.add({}); }

void ServiceMetrics::count_abort() { aborts_.add({}); }

void ServiceMetrics::observe_import(double seconds, std::size_t bytes) {
  import_seconds_.observe({}, seconds);
  import_bytes_.observe({}, static_cast<double>(bytes));
}

void ServiceMetrics::count_store_refusal(const std::string& reason) { store_refusals_.add({reason}); }

std::string route_label(const std::string& path) {
  static const std::regex model_path("/models/[0-9a-f]{16,64}");
  static const std::regex model_render_path("/models/[0-9a-f]{16,64}/render");
  // The web page's embedded files (web_page_routes.cpp).
  static const std::regex page_file(R"(/(?:[A-Za-z0-9_-]+/)*[A-Za-z0-9_.-]+\.(?:html|js|css|svg|png|ico|json))");
  static const std::vector<std::string> fixed = {"/",       "/healthz", "/schema", "/presets",
                                                 "/models", "/render",  "/metrics"};
  for (const std::string& f : fixed) {
    if (path == f) return f;
  }
  if (std::regex_match(path, model_render_path)) return "/models/{id}/render";
  if (std::regex_match(path, model_path)) return "/models/{id}";
  if (std::regex_match(path, page_file)) return "/{file}";
  return "other";
}

}  // namespace toond::http
