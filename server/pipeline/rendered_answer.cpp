#include "pipeline/rendered_answer.h"

#include <sstream>
#include <utility>
#include <vector>

namespace toond::pipeline {
namespace {

// Per object, the level of detail drawn and the faces it drew: "level=2/7;
// triangles=17362; error_px=0.412; faces=front", objects separated by ", ".
std::string lod_header(const std::vector<render::LodUse>& lods) {
  std::ostringstream s;
  s.precision(3);
  for (std::size_t i = 0; i < lods.size(); ++i) {
    const render::LodUse& l = lods[i];
    s << (i ? ", " : "") << "level=" << l.level << "/" << l.levels << "; triangles=" << l.triangles
      << "; error_px=" << std::fixed << l.error_px << std::defaultfloat
      << "; faces=" << (l.culled == render::HiddenFaces::None ? "both" : "front");
  }
  return s.str();
}

// "cost=12.3; frames=1; samples=…; triangles=…; tiles=…; framebuffer=…;
// edge_texels=…; crease_edges=…" (and a line drawing's "line_triangles=…;
// line_edges=…"):
// the predicted Msamples and what they are made of, for clients that size
// their requests and for the cost benchmark, which fits the weights.
std::string cost_header(const RenderPrice& price) {
  std::ostringstream s;
  s.precision(4);
  const render::RenderCost& c = price.total;
  s << "cost=" << c.units() << "; frames=" << price.frames << "; samples=" << c.samples << "; triangles=" << c.triangles
    << "; tiles=" << c.tiles << "; framebuffer=" << c.framebuffer << "; edge_texels=" << c.edge_texels
    << "; crease_edges=" << c.crease_edges;
  if (c.line_triangles > 0) s << "; line_triangles=" << c.line_triangles << "; line_edges=" << c.line_edges;
  return s.str();
}

}  // namespace

std::shared_ptr<CachedRender> cached_render_of(Rendered& rendered) {
  auto answer = std::make_shared<CachedRender>();
  answer->body = std::move(rendered.encoded.body);
  answer->content_type = rendered.encoded.content_type;
  answer->headers = std::move(rendered.encoded.headers);
  answer->stream = std::move(rendered.encoded.stream);
  if (!answer->stream) answer->etag = etag_of(answer->body);
  answer->passes = rendered.plan;
  answer->lod = lod_header(rendered.lods);
  answer->samples = rendered.samples;
  answer->headers.emplace_back("X-Toond-Cost", cost_header(rendered.price));
  return answer;
}

// `pose`: posing on the request's thread before the frames were queued (a
// request with `animation`; 0: none, and no entry).
std::string server_timing(const Rendered& rendered) {
  std::ostringstream s;
  s.precision(3);
  s << std::fixed;
  if (rendered.pose_ms > 0) s << "pose;dur=" << rendered.pose_ms << ", ";
  s << "queue;dur=" << rendered.queue_ms;
  for (const auto& t : rendered.timings) {
    s << ", " << t.pass << ";dur=" << t.ms;
    // Software GL shades vertices on the render thread at draw time, which
    // its timer queries do not count: the thread's own time goes alongside.
    if (t.gpu) s << ";desc=gpu;cpu=" << t.cpu_ms;
  }
  s << ", " << rendered.encoded.stage << ";dur=" << rendered.encode_ms;
  // The request's own work, posing, then from the render thread's first
  // pass to the last encoded byte, without the queue: GPU-timed passes may
  // overlap the thread's time, so the entries above need not add up to it.
  s << ", total;dur=" << rendered.pose_ms + rendered.render_ms + rendered.encode_ms;
  return s.str();
}

}  // namespace toond::pipeline
