#include "pipeline/render_entry.h"

#include <utility>

#include "pipeline/pipeline.h"
#include "pipeline/render_failure.h"
#include "pipeline/render_params_wire.h"
#include "pipeline/rendered_answer.h"
#include "pipeline/resolve.h"
#include "pipeline/sheet_answer.h"
#include "render/run/render_service.h"
#include "scene/store/model_library.h"
#include "scene/store/model_pins.h"

namespace toond::pipeline {

struct RenderEntry::Shared {
  ClipFramings framings;
  LineDrawings lines;
};

struct ResolvedRender::State {
  explicit State(scene::ModelStore& store) : pins(store) {}
  scene::ModelPins pins;
  Request request;
  // The completed parameters' text. They name content-addressed models
  // (and bundle files inside them): they decide every byte of the answer,
  // with the query that says which file of a sheet it is.
  std::string parameters;
};

ResolvedRender::ResolvedRender(std::unique_ptr<State> state) : state_(std::move(state)) {}
ResolvedRender::ResolvedRender(ResolvedRender&&) noexcept = default;
ResolvedRender& ResolvedRender::operator=(ResolvedRender&&) noexcept = default;
ResolvedRender::~ResolvedRender() = default;

namespace {

// What sets a sheet's file apart from the image of the same parameters,
// for the result cache's key: "" for the image.
std::string sheet_answer_key(const SheetAnswer& answer) {
  switch (answer.file) {
    case SheetFile::Image:
      return "";
    case SheetFile::AtlasJson:
      return "?atlas=json";
    case SheetFile::Aseprite:
      return "?atlas=aseprite";
    case SheetFile::Godot:
      return "?atlas=godot&texture=" + answer.godot_texture;
  }
  return "";
}

Answer file_answer(Encoded file) {
  auto render = std::make_shared<CachedRender>();
  render->body = std::move(file.body);
  render->content_type = std::move(file.content_type);
  render->headers = std::move(file.headers);
  return {std::move(render), Answer::From::File, {}};
}

// The pipeline's render, counted by the caller's observer, with the render
// threads' and the GPU's failures said as RenderFailure.
Rendered render_observed(Request request, const Caller& caller, Services& services) {
  try {
    Rendered rendered = render(std::move(request), caller.client, services);
    caller.observer.observe_cost(rendered.price.total.units(), rendered.long_lane, rendered.render_ms / 1000.0);
    return rendered;
  } catch (const CostRefused&) {
    caller.observer.count_cost_refusal();
    throw;
  } catch (const render::RenderAborted&) {
    caller.observer.count_abort();
    rethrow_as_render_failure(std::current_exception());
  } catch (...) {
    rethrow_as_render_failure(std::current_exception());
  }
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

RenderEntry::RenderEntry(scene::ModelStore& store, scene::ModelLibrary& library, render::RenderService& renderer,
                         const Settings& settings)
    : store_(store), library_(library), renderer_(renderer), settings_(settings), shared_(std::make_unique<Shared>()) {
  if (settings.result_cache_bytes > 0) results_ = std::make_unique<ResultCache>(settings.result_cache_bytes);
}

RenderEntry::~RenderEntry() = default;

ResolvedRender RenderEntry::resolve(const nlohmann::json& completed) {
  auto state = std::make_unique<ResolvedRender::State>(store_);
  state->request = pipeline::resolve(render_params_from_wire(completed), library_, state->pins, settings_.limits);
  state->parameters = completed.dump();
  return ResolvedRender(std::move(state));
}

Answer RenderEntry::answer(ResolvedRender resolved, const SheetAnswer& sheet, const Caller& caller) {
  Request& request = resolved.state_->request;
  request.answer = sheet;
  check_sheet_answer(request);
  Services services{library_, renderer_, shared_->framings, settings_.limits, settings_.deadline, shared_->lines};
  if (!needs_drawing(request)) return file_answer(sheet_file(request, services));
  const std::string key = resolved.state_->parameters + sheet_answer_key(sheet);
  if (results_) {
    if (auto hit = results_->find(key)) return {std::move(hit), Answer::From::Cache, {}};
  }
  Rendered rendered = render_observed(std::move(request), caller, services);
  const std::string timing = server_timing(rendered);
  std::shared_ptr<const CachedRender> render = cached_render_of(rendered);
  if (results_ && !render->stream) results_->put(key, render);
  caller.observer.observe_render(seconds_since(caller.arrived), rendered.timings, rendered.queue_ms, rendered.encode_ms,
                                 rendered.encoded.stage);
  return {std::move(render), Answer::From::Render, timing};
}

void RenderEntry::forget(const std::string& model_id) {
  library_.forget(model_id);
  renderer_.forget(model_id);
}

nlohmann::json RenderEntry::gl_document() const {
  const gpu::GlInfo& gl = renderer_.gl_info();
  return {{"vendor", gl.vendor},
          {"renderer", gl.renderer},
          {"version", gl.version},
          {"glsl_version", gl.glsl_version},
          {"platform", gl.platform}};
}

std::size_t RenderEntry::queue_depth() const { return renderer_.queue_depth(); }
std::size_t RenderEntry::gpu_resets() const { return renderer_.gpu_resets(); }
std::size_t RenderEntry::overlapped_frames() const { return renderer_.overlapped_frames(); }
std::size_t RenderEntry::gpu_models_loaded() const { return renderer_.gpu_models_loaded(); }
std::size_t RenderEntry::gpu_model_bytes() const { return renderer_.gpu_model_bytes(); }

}  // namespace toond::pipeline
