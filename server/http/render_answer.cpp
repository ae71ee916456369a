#include "http/render_answer.h"

#include <chrono>
#include <sstream>

namespace toond::http {

void answer_render(const httplib::Request& req, httplib::Response& res, const CachedRender& render) {
  res.set_header("ETag", render.etag);
  res.set_header("X-Toond-Passes", render.passes);
  if (!render.lod.empty()) res.set_header("X-Toond-Lod", render.lod);
  res.set_header("X-Toond-Samples", std::to_string(render.samples));
  for (const auto& [name, value] : render.headers) res.set_header(name, value);
  // The same parameters always give the same bytes, so a client may reuse
  // its copy, but should ask again (the model may have been replaced).
  res.set_header("Cache-Control", "no-cache");
  if (req.has_header("If-None-Match") && etag_matches(req.get_header_value("If-None-Match"), render.etag)) {
    res.status = 304;
    return;
  }
  res.set_content(render.body, render.content_type);
}

bool answer_from_cache(ResultCache* cache, const std::string& key, const httplib::Request& req,
                       httplib::Response& res) {
  if (!cache) return false;
  const auto start = std::chrono::steady_clock::now();
  const auto hit = cache->find(key);
  if (!hit) return false;
  answer_render(req, res, *hit);
  std::ostringstream timing;
  timing.precision(3);
  timing << std::fixed << "cache;desc=hit;dur="
         << std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  res.set_header("Server-Timing", timing.str());
  res.set_header("X-Toond-Cache", "hit");
  return true;
}

}  // namespace toond::http
