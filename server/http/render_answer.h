#pragma once
// How a render's answer goes back to the client: a sheet's file as it is;
// a render with its ETag, or 304 Not Modified when the client's
// If-None-Match already names it; a result cache hit marked as one.
#include <chrono>
#include <string>

#include <httplib.h>

#include "pipeline/render_entry.h"

namespace toond::http {

// The entry's answer (pipeline/render_entry.h) as the response; `asked`:
// when the entry was asked, which a cache hit's Server-Timing counts from.
void write_answer(const httplib::Request& req, httplib::Response& res, const pipeline::Answer& answer,
                  std::chrono::steady_clock::time_point asked);

// Whether an If-None-Match header value matches `etag` ("*", or one of a
// comma-separated list; weak tags compare by their opaque part).
bool etag_matches(const std::string& if_none_match, const std::string& etag);

}  // namespace toond::http
