#pragma once
// Every limit the daemon puts on one request, each set by a --max-* flag
// (server/app/limit_options.cpp lists them with their defaults). Over a
// limit the answer is 413 (sizes in bytes) or 422 (counts) with code
// "limit_exceeded" and "limit" naming the flag.
#include <cstddef>
#include <string_view>

#include <nlohmann/json.hpp>

#include "pipeline/render_limits.h"
#include "scene/reading/import_limits.h"

namespace toond::http {

struct RequestLimits {
  std::size_t max_upload_bytes = 256u << 20;  // whole request body (httplib answers 413 beyond)
  std::size_t max_bundle_files = 256;
  std::size_t max_json_bytes = 1u << 20;  // a JSON body or `params` part
  std::size_t max_json_depth = 32;        // nested arrays/objects
  scene::ImportLimits import{10'000'000, 10'000'000, 8192ull * 8192ull, 30.0};
  pipeline::RenderLimits render;
};

// Every limit by the flag that sets it ({"--max-vertices": 10000000, ...}),
// as GET /healthz reports them.
nlohmann::json limits_document(const RequestLimits& limits);

// Parses render parameters sent as JSON text (`where` names it in messages:
// "the request body"). Checks size and nesting depth on the raw text first,
// so a hostile document is refused before the parser builds anything.
// Empty text is an empty object. Throws LimitError or RequestError (400
// "malformed_json").
nlohmann::json parse_limited_json(std::string_view text, const RequestLimits& limits, std::string_view where);

// Counts in the request as sent, before the schema sees it, so a thousand
// lights get the limit's answer (422 naming --max-lights) rather than a
// schema message; lights a preset adds are counted by check_render_budget.
void check_request_counts(const nlohmann::json& request, const RequestLimits& limits);

// The nesting depth of arrays and objects in JSON text, counted outside
// strings; stops counting once past `stop_at`.
std::size_t json_nesting_depth(std::string_view text, std::size_t stop_at);

}  // namespace toond::http
