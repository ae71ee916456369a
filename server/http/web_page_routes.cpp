#include "http/web_page_routes.h"

#include <array>
#include <string>
#include <utility>

#include "http/error_response.h"
#include "toond_web_files.h"

namespace toond::http {

std::string_view web_content_type(std::string_view name) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 7> kTypes{{
      {".html", "text/html; charset=utf-8"},
      // Module scripts are refused by browsers unless served as JavaScript.
      {".js", "text/javascript; charset=utf-8"},
      {".css", "text/css; charset=utf-8"},
      {".svg", "image/svg+xml"},
      {".png", "image/png"},
      {".ico", "image/x-icon"},
      {".json", "application/json"},
  }};
  for (const auto& [extension, type] : kTypes) {
    if (name.size() > extension.size() && name.ends_with(extension)) return type;
  }
  return {};
}

namespace {
void serve_embedded(std::string_view name, httplib::Response& res) {
  const std::string_view type = web_content_type(name);
  const std::string_view content = toond::web_files::find(name);
  if (type.empty() || content.data() == nullptr) {
    write_error(res, 404, "not_found", "no such page file: /" + std::string(name), "/" + std::string(name));
    return;
  }
  // The files change only with the binary; revalidating each load keeps a
  // browser from mixing modules of two daemon versions.
  res.set_header("Cache-Control", "no-cache");
  res.set_content(std::string(content), std::string(type));
}
}  // namespace

void register_web_page_routes(httplib::Server& server) {
  server.Get("/", [](const httplib::Request&, httplib::Response& res) { serve_embedded("index.html", res); });
  // Only names with a known extension, so this never shadows an API route
  // (/models, /schema, /presets, /healthz have none).
  server.Get(
      R"(/((?:[A-Za-z0-9_-]+/)*[A-Za-z0-9_.-]+\.(?:html|js|css|svg|png|ico|json)))",
      [](const httplib::Request& req, httplib::Response& res) { serve_embedded(std::string(req.matches[1]), res); });
}

}  // namespace toond::http
