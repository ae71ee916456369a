#pragma once
#include <httplib.h>

#include "http/service_context.h"

namespace toond::http {

// Installs every route of the HTTP API (proto/openapi.yaml) plus the error
// and exception hooks that make each failure a JSON error body.
void register_routes(httplib::Server& server, ServiceContext& context);

void register_info_routes(httplib::Server& server, ServiceContext& context);
void register_model_routes(httplib::Server& server, ServiceContext& context);
void register_render_routes(httplib::Server& server, ServiceContext& context);
// GET /metrics, and the logger hook that counts every answered request.
void register_metrics_routes(httplib::Server& server, ServiceContext& context);

}  // namespace toond::http
