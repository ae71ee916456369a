#include "http/access_control.h"

#include <algorithm>

#include "http/error_response.h"

namespace toond::http {
namespace {

constexpr const char* kAllowedHeaders = "Authorization, Content-Type";
constexpr const char* kExposedHeaders =
    "Server-Timing, X-Toond-Passes, X-Toond-Lod, X-Toond-Samples, X-Toond-Cost, Retry-After, ETag";

bool is_preflight(const httplib::Request& req) {
  return req.method == "OPTIONS" && req.has_header("Access-Control-Request-Method");
}

// The Access-Control-Allow-Origin value for this request's Origin, or empty.
std::string allowed_origin(const httplib::Request& req, const std::vector<std::string>& origins) {
  if (origins.empty() || !req.has_header("Origin")) return {};
  if (std::find(origins.begin(), origins.end(), "*") != origins.end()) return "*";
  const std::string origin = req.get_header_value("Origin");
  return std::find(origins.begin(), origins.end(), origin) != origins.end() ? origin : std::string{};
}

}  // namespace

bool bearer_token_matches(const std::string& header, const std::string& token) {
  static constexpr std::string_view kScheme = "Bearer ";
  if (header.size() < kScheme.size()) return false;
  for (std::size_t i = 0; i < kScheme.size(); ++i) {
    // The scheme is case-insensitive (RFC 7235).
    if (std::tolower(static_cast<unsigned char>(header[i])) != std::tolower(static_cast<unsigned char>(kScheme[i]))) {
      return false;
    }
  }
  const std::string_view given = std::string_view(header).substr(kScheme.size());
  // Every byte of the longer string is visited, so the time taken tells
  // nothing about how much of a guess was right.
  const std::size_t n = std::max(given.size(), token.size());
  unsigned diff = given.size() == token.size() ? 0u : 1u;
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char a = i < given.size() ? static_cast<unsigned char>(given[i]) : 0;
    const unsigned char b = i < token.size() ? static_cast<unsigned char>(token[i]) : 0;
    diff |= static_cast<unsigned>(a ^ b);
  }
  return diff == 0 && !token.empty();
}

void install_access_control(httplib::Server& server, const AccessOptions& access) {
  if (!access.cors_origins.empty()) {
    // Preflights carry no credentials; they are answered before the token
    // check and never reach a route.
    server.Options(R"(/.*)", [](const httplib::Request&, httplib::Response& res) { res.status = 204; });
  }
  server.set_pre_routing_handler([access](const httplib::Request& req, httplib::Response& res) {
    if (access.token.empty() || req.path == "/healthz" || (is_preflight(req) && !access.cors_origins.empty())) {
      return httplib::Server::HandlerResponse::Unhandled;
    }
    if (bearer_token_matches(req.get_header_value("Authorization"), access.token)) {
      return httplib::Server::HandlerResponse::Unhandled;
    }
    res.set_header("WWW-Authenticate", "Bearer realm=\"toond\"");
    write_error(res, 401, "unauthorized",
                req.has_header("Authorization") ? "the bearer token is not the daemon's (--token / TOOND_TOKEN)"
                                                : "this daemon needs \"Authorization: Bearer <token>\" "
                                                  "(--token / TOOND_TOKEN) on every route but /healthz");
    return httplib::Server::HandlerResponse::Handled;
  });
  if (access.cors_origins.empty()) return;
  server.set_post_routing_handler([origins = access.cors_origins](const httplib::Request& req, httplib::Response& res) {
    const std::string origin = allowed_origin(req, origins);
    if (origins.size() > 1 || origin != "*") res.set_header("Vary", "Origin");
    if (origin.empty()) return;
    res.set_header("Access-Control-Allow-Origin", origin);
    res.set_header("Access-Control-Expose-Headers", kExposedHeaders);
    if (is_preflight(req)) {
      res.set_header("Access-Control-Allow-Methods", "GET, POST, DELETE, OPTIONS");
      res.set_header("Access-Control-Allow-Headers", kAllowedHeaders);
      res.set_header("Access-Control-Max-Age", "600");
    }
  });
}

}  // namespace toond::http
