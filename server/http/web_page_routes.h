#pragma once
// Serves the web page (client/web/, embedded at build time): GET / is
// index.html, and every other embedded file is served at its own path
// (/app.js, /style.css, /lib/controls.js) with a content type from its
// extension, so the page can be split into plain ES modules with no build step.
#include <string_view>

#include <httplib.h>

namespace toond::http {

void register_web_page_routes(httplib::Server& server);

// The Content-Type for an embedded file's name; empty for an extension the
// page does not use, which is then not served.
std::string_view web_content_type(std::string_view name);

}  // namespace toond::http
