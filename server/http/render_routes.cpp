// POST /render: JSON parameters → PNG (output svg, or Accept:
// image/svg+xml without an output: SVG); or multipart (bundle files + a
// `params` part) to upload and render in one call. With `sheet`: a sprite
// sheet with its atlas in a tEXt chunk, or (?atlas=json) the atlas alone, or
// (?atlas=aseprite, ?atlas=godot) an .aseprite file or a Godot SpriteFrames
// resource, or (sheet.animate) its frames as an animated WebP. The route parses the
// request, hands it to the render pipeline (server/pipeline/pipeline.h),
// and answers; the result cache sits between the pipeline's resolve stage
// and the rest.
#include <chrono>
#include <sstream>

#include <nlohmann/json.hpp>

#include "http/bundle_upload.h"
#include "http/render_answer.h"
#include "http/render_params_wire.h"
#include "http/request_limits.h"
#include "http/routes.h"
#include "http/sheet_query.h"
#include "http/store_upload.h"
#include "http/svg_request.h"
#include "param_schema.h"
#include "pipeline/pipeline.h"
#include "presets.h"
#include "request_error.h"

namespace toond::http {
namespace {

using Clock = std::chrono::steady_clock;

// `pose`: posing on the request's thread before the frames were queued (a
// request with `animation`; 0: none, and no entry).
std::string server_timing(const pipeline::Rendered& r) {
  std::ostringstream s;
  s.precision(3);
  s << std::fixed;
  if (r.pose_ms > 0) s << "pose;dur=" << r.pose_ms << ", ";
  s << "queue;dur=" << r.queue_ms;
  for (const auto& t : r.timings) {
    s << ", " << t.pass << ";dur=" << t.ms;
    // Software GL shades vertices on the render thread at draw time, which
    // its timer queries do not count: the thread's own time goes alongside.
    if (t.gpu) s << ";desc=gpu;cpu=" << t.cpu_ms;
  }
  s << ", " << r.encoded.stage << ";dur=" << r.encode_ms;
  // The request's own work, posing, then from the render thread's first
  // pass to the last encoded byte, without the queue: GPU-timed passes may
  // overlap the thread's time, so the entries above need not add up to it.
  s << ", total;dur=" << r.pose_ms + r.render_ms + r.encode_ms;
  return s.str();
}

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
std::string cost_header(const pipeline::RenderPrice& price) {
  std::ostringstream s;
  s.precision(4);
  const render::RenderCost& c = price.total;
  s << "cost=" << c.units() << "; frames=" << price.frames << "; samples=" << c.samples << "; triangles=" << c.triangles
    << "; tiles=" << c.tiles << "; framebuffer=" << c.framebuffer << "; edge_texels=" << c.edge_texels
    << "; crease_edges=" << c.crease_edges;
  if (c.line_triangles > 0) s << "; line_triangles=" << c.line_triangles << "; line_edges=" << c.line_edges;
  return s.str();
}

// POST /models/{id}/render takes its model from the path (so a load
// balancer can hash on it); a `model` in the body must agree.
void apply_path_model(nlohmann::json& request, const std::string& id) {
  if (!request.is_object()) return;  // validation reports the body's type
  if (request.contains("model") && request["model"] != id) {
    throw RequestError(400, "model_mismatch", "/model: the body names a different model than the path (" + id + ")",
                       "/model");
  }
  request["model"] = id;
}

// The request's parameters as sent: the body, or a multipart request's
// `params` part, its bundle stored and named as `model`.
nlohmann::json read_request(const httplib::Request& req, ServiceContext& context) {
  nlohmann::json request;
  if (req.is_multipart_form_data()) {
    const auto params_part = req.files.find("params");
    request = parse_limited_json(params_part == req.files.end() ? "" : params_part->second.content, context.limits,
                                 "the params part");
    const scene::Bundle bundle = bundle_from_multipart(req, "params", context.limits);
    request["model"] = store_upload(context, bundle).info.id;
  } else {
    request = parse_limited_json(req.body, context.limits, "the request body");
  }
  if (req.matches.size() > 1) apply_path_model(request, req.matches[1].str());
  return request;
}

// Checks what the client sent first, so errors point at its own fields;
// then lays it over its preset and fills the defaults.
nlohmann::json complete_request(const nlohmann::json& request, const RequestLimits& limits) {
  const auto& schema = proto::ParamSchema::render_params();
  check_request_counts(request, limits);
  schema.validate(request);
  // A scene names its models per object; one request cannot do both (a
  // multipart upload names the uploaded bundle as `model`, so it cannot
  // carry objects either).
  if (request.contains("model") && request.contains("objects")) {
    throw RequestError(400, "invalid_parameter", "/objects: give either `model` or `objects`, not both", "/objects");
  }
  return schema.validate_and_complete(proto::Presets::builtin().expand(request));
}

pipeline::Services services_of(ServiceContext& context) {
  return {context.library,       context.renderer,        context.clip_framings,
          context.limits.render, context.render_deadline, context.line_drawings};
}

// The pipeline's render, with what /metrics counts of it.
pipeline::Rendered render_counted(pipeline::Request request, const std::string& client, ServiceContext& context) {
  pipeline::Services services = services_of(context);
  try {
    pipeline::Rendered rendered = pipeline::render(std::move(request), client, services);
    context.metrics.observe_cost(rendered.price.total.units(), rendered.long_lane, rendered.render_ms / 1000.0);
    return rendered;
  } catch (const pipeline::CostRefused&) {
    context.metrics.count_cost_refusal();
    throw;
  } catch (const render::RenderAborted&) {
    context.metrics.count_abort();
    throw;
  }
}

// Answers the render (or 304), keeps it for the next identical request and
// records the request's times.
void answer_rendered(const httplib::Request& req, httplib::Response& res, pipeline::Rendered& rendered,
                     const std::string& cache_key, Clock::time_point started, ServiceContext& context) {
  res.set_header("Server-Timing", server_timing(rendered));
  auto answer = std::make_shared<CachedRender>();
  answer->body = std::move(rendered.encoded.body);
  answer->content_type = rendered.encoded.content_type;
  answer->headers = std::move(rendered.encoded.headers);
  answer->etag = etag_of(answer->body);
  answer->passes = rendered.plan;
  answer->lod = lod_header(rendered.lods);
  answer->samples = rendered.samples;
  answer->headers.emplace_back("X-Toond-Cost", cost_header(rendered.price));
  answer_render(req, res, *answer);
  if (context.results) context.results->put(cache_key, std::move(answer));
  context.metrics.observe_render(std::chrono::duration<double>(Clock::now() - started).count(), rendered.timings,
                                 rendered.queue_ms, rendered.encode_ms, rendered.encoded.stage);
}

}  // namespace

void register_render_routes(httplib::Server& server, ServiceContext& context) {
  const auto render = [&context](const httplib::Request& req, httplib::Response& res) {
    const auto started = Clock::now();
    nlohmann::json sent = read_request(req, context);
    apply_svg_accept(req.get_header_value("Accept"), sent);
    const nlohmann::json completed = complete_request(sent, context.limits);
    check_svg_fields(sent, completed);
    // Held until the answer is sent: the store lets none of these models go.
    scene::ModelPins pins(context.store);
    pipeline::Request request =
        pipeline::resolve(render_params_from_wire(completed), context.library, pins, context.limits.render);
    request.answer = sheet_answer_of(req);
    pipeline::check_sheet_answer(request);
    if (!pipeline::needs_drawing(request)) {
      pipeline::Services services = services_of(context);
      const pipeline::Encoded file = pipeline::sheet_file(request, services);
      for (const auto& [name, value] : file.headers) res.set_header(name, value);
      res.set_content(file.body, file.content_type);
      return;
    }
    // Completed parameters name content-addressed models (and bundle files
    // inside them): they decide every byte of the answer, with the query
    // that says which file of the sheet it is.
    const std::string cache_key = completed.dump() + sheet_answer_key(request.answer);
    if (answer_from_cache(context.results.get(), cache_key, req, res)) return;
    pipeline::Rendered rendered = render_counted(std::move(request), req.remote_addr, context);
    answer_rendered(req, res, rendered, cache_key, started, context);
  };
  server.Post("/render", render);
  server.Post("/models/([0-9a-f]{16,64})/render", render);
}

}  // namespace toond::http
