#include "http/render_answer.h"

#include <sstream>
#include <string_view>

#include "text/trim.h"

namespace toond::http {
namespace {

// A body written as it goes out, in chunks (Transfer-Encoding: chunked):
// the whole text is never held. The provider runs after the route has
// returned, so it keeps the body alive itself.
void answer_streamed(httplib::Response& res, const pipeline::CachedRender& render) {
  res.set_chunked_content_provider(render.content_type, [stream = render.stream](std::size_t, httplib::DataSink& sink) {
    stream->write([&sink](std::string_view piece) { return sink.write(piece.data(), piece.size()); });
    sink.done();
    return true;
  });
}

// Sets ETag, X-Toond-Passes, -Lod, -Samples and the render's own headers,
// then the body, or status 304 with no body when If-None-Match matches.
// A streamed body has no ETag, so it is always sent.
void answer_render(const httplib::Request& req, httplib::Response& res, const pipeline::CachedRender& render) {
  if (!render.etag.empty()) res.set_header("ETag", render.etag);
  res.set_header("X-Toond-Passes", render.passes);
  if (!render.lod.empty()) res.set_header("X-Toond-Lod", render.lod);
  res.set_header("X-Toond-Samples", std::to_string(render.samples));
  for (const auto& [name, value] : render.headers) res.set_header(name, value);
  // The same parameters always give the same bytes, so a client may reuse
  // its copy, but should ask again (the model may have been replaced).
  res.set_header("Cache-Control", "no-cache");
  if (render.stream) {
    answer_streamed(res, render);
    return;
  }
  if (req.has_header("If-None-Match") && etag_matches(req.get_header_value("If-None-Match"), render.etag)) {
    res.status = 304;
    return;
  }
  res.set_content(render.body, render.content_type);
}

}  // namespace

void write_answer(const httplib::Request& req, httplib::Response& res, const pipeline::Answer& answer,
                  std::chrono::steady_clock::time_point asked) {
  const pipeline::CachedRender& render = *answer.render;
  switch (answer.from) {
    case pipeline::Answer::From::File:
      for (const auto& [name, value] : render.headers) res.set_header(name, value);
      res.set_content(render.body, render.content_type);
      return;
    case pipeline::Answer::From::Render:
      res.set_header("Server-Timing", answer.server_timing);
      answer_render(req, res, render);
      return;
    case pipeline::Answer::From::Cache: {
      answer_render(req, res, render);
      std::ostringstream timing;
      timing.precision(3);
      timing << std::fixed << "cache;desc=hit;dur="
             << std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - asked).count();
      res.set_header("Server-Timing", timing.str());
      res.set_header("X-Toond-Cache", "hit");
      return;
    }
  }
}

bool etag_matches(const std::string& if_none_match, const std::string& etag) {
  auto strong_tag = [](std::string_view s) {
    s = text::trim(s);
    // If-None-Match compares weakly: W/"x" matches "x".
    if (s.rfind("W/", 0) == 0) s.remove_prefix(2);
    return std::string(s);
  };
  std::size_t pos = 0;
  while (pos <= if_none_match.size()) {
    const std::size_t comma = if_none_match.find(',', pos);
    const std::string tag = strong_tag(
        std::string_view(if_none_match).substr(pos, comma == std::string::npos ? std::string::npos : comma - pos));
    if (tag == "*" || (!tag.empty() && tag == strong_tag(etag))) return true;
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  return false;
}

}  // namespace toond::http
