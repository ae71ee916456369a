// POST /render: JSON parameters → PNG (output svg, or Accept:
// image/svg+xml without an output: SVG); or multipart (bundle files + a
// `params` part) to upload and render in one call. With `sheet`: a sprite
// sheet with its atlas in a tEXt chunk, or (?atlas=json) the atlas alone, or
// (?atlas=aseprite, ?atlas=godot) an .aseprite file or a Godot SpriteFrames
// resource, or (sheet.animate) its frames as an animated WebP. The route parses the
// request, hands it to the render pipeline's entry
// (server/pipeline/render_entry.h), which answers it from its result cache
// or renders it, and answers.
#include <chrono>

#include <nlohmann/json.hpp>

#include "http/bundle_upload.h"
#include "http/render_answer.h"
#include "http/request_limits.h"
#include "http/routes.h"
#include "http/sheet_query.h"
#include "http/store_upload.h"
#include "http/svg_request.h"
#include "param_schema.h"
#include "pipeline/render_entry.h"
#include "presets.h"
#include "request_error.h"

namespace toond::http {
namespace {

using Clock = std::chrono::steady_clock;

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

}  // namespace

void register_render_routes(httplib::Server& server, ServiceContext& context) {
  const auto render = [&context](const httplib::Request& req, httplib::Response& res) {
    const auto arrived = Clock::now();
    nlohmann::json sent = read_request(req, context);
    apply_svg_accept(req.get_header_value("Accept"), sent);
    const nlohmann::json completed = complete_request(sent, context.limits);
    check_svg_fields(sent, completed);
    // Its models stay pinned in the store until it is answered.
    pipeline::ResolvedRender resolved = context.renders.resolve(completed);
    const pipeline::SheetAnswer sheet = sheet_answer_of(req);
    const auto asked = Clock::now();
    const pipeline::Answer answer =
        context.renders.answer(std::move(resolved), sheet, {req.remote_addr, arrived, context.metrics});
    write_answer(req, res, answer, asked);
  };
  server.Post("/render", render);
  server.Post("/models/([0-9a-f]{16,64})/render", render);
}

}  // namespace toond::http
