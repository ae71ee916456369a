#include "http/routes.h"

#include "http/error_response.h"

namespace toond::http {

void register_routes(httplib::Server& server, ServiceContext& context) {
  register_info_routes(server, context);
  register_model_routes(server, context);
  register_render_routes(server, context);
  register_metrics_routes(server, context);

  server.set_exception_handler(
      [](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) { write_exception(res, ep); });
  // Errors httplib produces itself (unknown route, payload too large, bad
  // request line) get the same JSON shape as ours.
  server.set_error_handler([&context](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return;
    switch (res.status) {
      case 404:
        write_error(res, 404, "not_found", "no route " + req.method + " " + req.path);
        break;
      case 405:
        write_error(res, 405, "method_not_allowed", req.method + " not allowed on " + req.path);
        break;
      case 413:
        write_limit_error(res, 413, "payload_too_large", "--max-upload-bytes",
                          "the request body is larger than the limit --max-upload-bytes = " +
                              std::to_string(context.limits.max_upload_bytes) + " bytes");
        break;
      case 400:
        write_error(res, 400, "bad_request",
                    "the request cannot be read: malformed HTTP, a malformed multipart body, or more than 1024 parts");
        break;
      default:
        write_error(res, res.status, "http_error", "HTTP error " + std::to_string(res.status));
        break;
    }
  });
}

}  // namespace toond::http
