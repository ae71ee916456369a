#pragma once
// Who may call the API: an optional bearer token on every route but
// /healthz, and which browser origins may call it from another site (CORS).
#include <string>
#include <vector>

#include <httplib.h>

namespace toond::http {

struct AccessOptions {
  // Empty: no token needed. Otherwise every request but GET /healthz and
  // CORS preflights must carry "Authorization: Bearer <token>" (401 JSON
  // error "unauthorized" otherwise).
  std::string token;
  // Origins answered with Access-Control-Allow-Origin; "*" allows any.
  // Empty: no CORS headers (the daemon's own page is same-origin).
  std::vector<std::string> cors_origins;
};

// Installs the token check (before the body is read) and the CORS headers.
void install_access_control(httplib::Server& server, const AccessOptions& access);

// Whether `header` (an Authorization value) carries `token`; compared in
// time independent of where the first difference lies.
bool bearer_token_matches(const std::string& header, const std::string& token);

}  // namespace toond::http
