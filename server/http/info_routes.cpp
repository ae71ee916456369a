// GET /healthz, GET /schema, GET /presets, and the web page (web_page_routes).
#include <nlohmann/json.hpp>

#include "http/request_limits.h"
#include "http/routes.h"
#include "http/web_page_routes.h"
#include "param_schema.h"
#include "presets.h"

namespace toond::http {
namespace {

// How full the model store is: its models and bytes against the bound
// (`used`, a fraction, only with one), and the volume it is on.
nlohmann::json store_document(const scene::ModelStore& store) {
  const scene::StoreUsage usage = store.usage();
  nlohmann::json doc = {{"models", usage.models}, {"bytes", usage.bytes}, {"max_bytes", store.max_bytes()}};
  if (store.max_bytes() > 0) {
    doc["used"] = static_cast<double>(usage.bytes) / static_cast<double>(store.max_bytes());
  }
  if (const auto volume = store.volume()) {
    doc["volume"] = {{"bytes", volume->bytes}, {"free_bytes", volume->free_bytes}};
  }
  return doc;
}

}  // namespace

void register_info_routes(httplib::Server& server, ServiceContext& context) {
  server.Get("/healthz", [&context](const httplib::Request&, httplib::Response& res) {
    nlohmann::json body = {
        {"status", "ok"},
        {"gl", context.renders.gl_document()},
        {"queue_depth", context.renders.queue_depth()},
        {"limits", limits_document(context.limits)},
        {"store", store_document(context.store)},
    };
    res.set_content(body.dump(), "application/json");
  });

  server.Get("/schema", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(proto::ParamSchema::render_params().document().dump(2), "application/schema+json");
  });

  server.Get("/presets", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(proto::Presets::builtin().document().dump(2), "application/json");
  });

  register_web_page_routes(server);
}

}  // namespace toond::http
