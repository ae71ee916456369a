#pragma once
// A finished render (pipeline.h's Rendered) as its answer says it: the
// bytes with their ETag and what the X-Toond- headers report, the form the
// result cache keeps; and the Server-Timing of its stages.
#include <memory>
#include <string>

#include "pipeline/pipeline.h"
#include "pipeline/result_cache.h"

namespace toond::pipeline {

// Moves the encoded bytes out of `rendered`.
std::shared_ptr<CachedRender> cached_render_of(Rendered& rendered);

// "pose;dur=…, queue;dur=…, <pass>;dur=…, …, png;dur=…, total;dur=…".
std::string server_timing(const Rendered& rendered);

}  // namespace toond::pipeline
