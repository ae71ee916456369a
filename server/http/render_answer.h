#pragma once
// How a finished render goes back to the client: the PNG with its ETag, or
// 304 Not Modified when the client's If-None-Match already names it; and the
// result cache in front of the render thread.
#include <memory>
#include <string>

#include <httplib.h>

#include "http/result_cache.h"

namespace toond::http {

// Sets ETag, X-Toond-Passes and X-Toond-Lod, then the body, or status 304
// with no body when If-None-Match matches.
void answer_render(const httplib::Request& req, httplib::Response& res, const CachedRender& render);

// A cached render for `key`, answered (with `Server-Timing: cache`), or
// false when the cache is off or does not hold it.
bool answer_from_cache(ResultCache* cache, const std::string& key, const httplib::Request& req, httplib::Response& res);

}  // namespace toond::http
