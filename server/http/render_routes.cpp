// POST /render: JSON parameters → PNG; or multipart (bundle files + a
// `params` part) to upload and render in one call. With `sheet`: a sprite
// sheet with its atlas in a tEXt chunk, or (?atlas=json) the atlas alone, or
// (sheet.animate) its frames as an animated WebP.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "http/animation_pose.h"
#include "http/bundle_upload.h"
#include "http/output_png.h"
#include "http/render_answer.h"
#include "http/render_params_wire.h"
#include "http/render_wait.h"
#include "http/sheet_checks.h"
#include "http/sheet_render.h"
#include "http/request_limits.h"
#include "http/routes.h"
#include "http/store_upload.h"
#include "image/png_codec.h"
#include "image/webp_animation.h"
#include "render/ramp_image.h"
#include "http/render_budget.h"
#include "http/render_price.h"
#include "limit_error.h"
#include "render/sheet_atlas.h"
#include "render/sheet_layout.h"
#include "param_schema.h"
#include "presets.h"
#include "request_error.h"

namespace toond::http {
namespace {

using Clock = std::chrono::steady_clock;

// The render thread's own time for the job, pass by pass.
double render_thread_ms(const render::RenderOutput& out) {
  double ms = 0;
  for (const auto& t : out.timings) ms += t.cpu_ms;
  return ms;
}

// `pose_ms`: posing on the request's thread before the job was queued (a
// request with `animation`; 0: none, and no entry).
std::string server_timing(const render::RenderOutput& out, double pose_ms, double queue_ms,
                          const std::string& encode_stage, double encode_ms) {
  std::ostringstream s;
  s.precision(3);
  s << std::fixed;
  if (pose_ms > 0) s << "pose;dur=" << pose_ms << ", ";
  s << "queue;dur=" << queue_ms;
  for (const auto& t : out.timings) {
    s << ", " << t.pass << ";dur=" << t.ms;
    // Software GL shades vertices on the render thread at draw time, which
    // its timer queries do not count: the thread's own time goes alongside.
    if (t.gpu) s << ";desc=gpu;cpu=" << t.cpu_ms;
  }
  s << ", " << encode_stage << ";dur=" << encode_ms;
  // The request's own work, posing, then from the render thread's first
  // pass to the last encoded byte, without the queue: GPU-timed passes may
  // overlap the thread's time, so the entries above need not add up to it.
  s << ", total;dur=" << pose_ms + render_thread_ms(out) + encode_ms;
  return s.str();
}

// An image file a parameter names (at JSON pointer `pointer`), looked up in
// the bundles of the job's models, first object first.
std::shared_ptr<const scene::Texture> bundle_image(ServiceContext& context, const render::RenderJob& job,
                                                   const std::string& path, const std::string& pointer) {
  for (const render::JobObject& o : job.objects) {
    try {
      if (auto image = context.library.bundle_image(o.model_key, path)) return image;
    } catch (const std::exception& e) {
      throw RequestError(422, "bad_image", pointer + ": \"" + path + "\" is not a readable image: " + e.what(),
                         pointer);
    }
  }
  throw RequestError(422, "missing_file", pointer + ": the model's bundle has no file \"" + path + "\"", pointer);
}

// Turns the file names of a request into the images the render thread uses.
void load_bundle_images(ServiceContext& context, render::RenderJob& job) {
  render::RenderParams& params = job.params;
  if (!params.ramp_image.empty()) {
    const std::string pointer = "/shading/ramp_image";
    try {
      params.ramp = render::ramp_from_image(*bundle_image(context, job, params.ramp_image, pointer));
    } catch (const render::RampImageError& e) {
      throw RequestError(422, "bad_image", pointer + ": " + e.what(), pointer);
    }
  }
  if (params.floor.enabled && !params.floor.texture.empty()) {
    params.floor.image = bundle_image(context, job, params.floor.texture, "/floor/texture");
  }
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

// POST /models/{id}/render takes its model from the path (so a load
// balancer can hash on it); a `model` in the body must agree.
void apply_path_model(nlohmann::json& request, const std::string& id) {
  if (!request.is_object()) return;  // validation reports the body's type
  if (request.contains("model") && request["model"] != id) {
    throw RequestError(400, "model_mismatch",
                       "/model: the body names a different model than the path (" + id + ")", "/model");
  }
  request["model"] = id;
}

// `?atlas=json` answers a sheet's atlas alone, without rendering; the
// query names nothing else.
bool wants_atlas_only(const httplib::Request& req, const render::RenderParams& params) {
  if (!req.has_param("atlas")) return false;
  if (req.get_param_value("atlas") != "json") {
    throw RequestError(400, "invalid_parameter", "?atlas: the only value is json (the sheet's atlas alone)",
                       "?atlas");
  }
  if (!params.sheet) {
    throw RequestError(400, "invalid_parameter", "?atlas=json needs a `sheet` in the parameters", "/sheet");
  }
  return true;
}

// Prices the job, refuses it over --max-render-cost, and marks it with what
// the price decides: its queue lane and whether its draws are paced. The
// client is the connection's address: clients take turns in the queue.
RenderPrice admit_by_price(ServiceContext& context, render::RenderJob& job, const httplib::Request& req) {
  const RenderPrice price = price_render(job);
  try {
    check_render_cost(job, price, context.limits.render);
  } catch (const LimitError&) {
    context.metrics.count_cost_refusal();
    throw;
  }
  job.client = req.remote_addr;
  job.cost = price.total.units();
  job.paced_chunk_triangles = paced_chunk_triangles(price.per_frame());
  job.paced_band_texels = paced_band_texels(price.per_frame());
  return price;
}

// "cost=12.3; frames=1; samples=…; triangles=…; tiles=…; framebuffer=…;
// edge_texels=…":
// the predicted Msamples and what they are made of, for clients that size
// their requests and for the cost benchmark, which fits the weights.
std::string cost_header(const RenderPrice& price) {
  std::ostringstream s;
  s.precision(4);
  const render::RenderCost& c = price.total;
  s << "cost=" << c.units() << "; frames=" << price.frames << "; samples=" << c.samples << "; triangles=" << c.triangles
    << "; tiles=" << c.tiles << "; framebuffer=" << c.framebuffer << "; edge_texels=" << c.edge_texels
    << "; crease_edges=" << c.crease_edges;
  return s.str();
}

}  // namespace

void register_render_routes(httplib::Server& server, ServiceContext& context) {
  const auto render = [&context](const httplib::Request& req, httplib::Response& res) {
    const auto started = Clock::now();
    nlohmann::json request;
    if (req.is_multipart_form_data()) {
      const auto params_part = req.files.find("params");
      request = parse_limited_json(params_part == req.files.end() ? "" : params_part->second.content,
                                   context.limits, "the params part");
      const scene::Bundle bundle = bundle_from_multipart(req, "params", context.limits);
      request["model"] = store_upload(context, bundle).info.id;
    } else {
      request = parse_limited_json(req.body, context.limits, "the request body");
    }
    if (req.matches.size() > 1) apply_path_model(request, req.matches[1].str());

    const auto& schema = proto::ParamSchema::render_params();
    // Check what the client sent first, so errors point at its own fields;
    // then lay it over its preset and fill the defaults.
    check_request_counts(request, context.limits);
    schema.validate(request);
    // A scene names its models per object; one request cannot do both (a
    // multipart upload names the uploaded bundle as `model`, so it cannot
    // carry objects either).
    if (request.contains("model") && request.contains("objects")) {
      throw RequestError(400, "invalid_parameter",
                         "/objects: give either `model` or `objects`, not both", "/objects");
    }
    render::RenderJob job;
    // Held until the answer is sent: the store lets none of these models go.
    scene::ModelPins pins(context.store);
    const nlohmann::json completed = schema.validate_and_complete(proto::Presets::builtin().expand(request));
    job.params = render_params_from_wire(completed);
    check_sheet_params(job.params);
    if (!job.params.objects.empty()) {
      for (std::size_t i = 0; i < job.params.objects.size(); ++i) {
        const render::SceneObject& object = job.params.objects[i];
        render::JobObject o;
        o.model_key = object.model;
        o.model = context.library.get(object.model, pins);
        if (!o.model) {
          throw RequestError(404, "unknown_model", "no stored model with id " + object.model,
                             "/objects/" + std::to_string(i) + "/model");
        }
        o.transform = object.matrix();
        job.objects.push_back(std::move(o));
      }
    } else if (job.params.model.empty()) {
      job.objects.push_back({"demo", context.library.demo(), glm::dmat4(1.0), nullptr});
    } else {
      render::JobObject o;
      o.model_key = job.params.model;
      o.model = context.library.get(job.params.model, pins);
      if (!o.model) {
        throw RequestError(404, "unknown_model", "no stored model with id " + job.params.model,
                           "/model");
      }
      job.objects.push_back(std::move(o));
    }

    // An animated sheet's size follows its clips' lengths: they are looked
    // up before the sheet is held to the budget.
    resolve_sheet_clips(job);
    check_render_budget(job.params, context.limits.render);
    const OutputDescription output = describe_output(job);
    load_bundle_images(context, job);
    std::optional<render::SheetLayout> layout;
    if (job.params.sheet) layout = render::layout_sheet(*job.params.sheet, job.params.width, job.params.height);
    // A sheet is posed before its atlas, which frames it as its frames
    // are; a single image after the result cache had its chance.
    std::vector<std::shared_ptr<const scene::SkinPose>> sheet_poses;
    double pose_ms = 0;
    const auto pose = [&] {
      const auto start = Clock::now();
      if (layout && !job.params.sheet->clips.empty()) {
        sheet_poses = pose_sheet_frames(context.clip_framings, job, *layout, context.renderer.skinning());
      } else if (job.params.animation) {
        pose_for_animation(context.clip_framings, job, context.renderer.skinning());
      } else if (!pose_at_rest(context.clip_framings, job, context.renderer.skinning())) {
        return;
      }
      pose_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    };
    if (layout) pose();
    const bool atlas_only = wants_atlas_only(req, job.params);
    image::PngOptions png_options;
    png_options.compression_level = job.params.png_compression;
    if (layout) {
      const nlohmann::ordered_json atlas = render::sheet_atlas(
          *layout, job.params, scene_of(job), job.params.sheet->animate ? "sheet.webp" : "sheet.png");
      if (atlas_only) {
        res.set_content(atlas.dump(2), "application/json");
        return;
      }
      // An animation is a WebP: the atlas comes with ?atlas=json alone.
      if (!job.params.sheet->animate) png_options.text.emplace_back("toond:atlas", atlas.dump());
    }
    // With `sheet.animate` the frames go out as an animated WebP instead.
    std::optional<image::WebpAnimationOptions> animation;
    if (job.params.sheet && job.params.sheet->animate) {
      animation.emplace();
      animation->frame_ms = job.params.sheet->frame_ms;
      // An animated sheet's frames show as long as the clip's own: whole
      // milliseconds that add up as the exact times do (83, 84, 83 ms for
      // 1/12 s), so a long loop does not drift.
      if (!job.params.sheet->clips.empty()) {
        double elapsed = 0;
        for (const render::SheetFrame& frame : layout->frames) {
          const double next = elapsed + frame.duration_ms;
          animation->durations_ms.push_back(
              std::max(1, static_cast<int>(std::lround(next)) - static_cast<int>(std::lround(elapsed))));
          elapsed = next;
        }
      }
    }
    // Completed parameters name content-addressed models (and bundle files
    // inside them): they decide every byte of the PNG.
    const std::string cache_key = completed.dump();
    if (answer_from_cache(context.results.get(), cache_key, req, res)) return;
    if (!layout) pose();

    pins.lease();  // queued from here: every replica sees the models in use
    const RenderPrice price = admit_by_price(context, job, req);
    const auto submitted = Clock::now();
    // Past the deadline the render thread skips the job instead of drawing
    // an image nobody waits for any more.
    const auto deadline = submitted + context.render_deadline;
    render::RenderOutput out;
    try {
      if (layout) {
        out = render_sheet(context, job, *layout, sheet_poses, deadline);
      } else {
        job.deadline = deadline;
        const auto waited = wait_limit(job, deadline);
        auto future = context.renderer.submit(std::move(job));
        out = await_render(future, waited, context.render_deadline);
      }
    } catch (const render::RenderAborted&) {
      context.metrics.count_abort();
      throw;
    }
    const double render_ms = render_thread_ms(out);
    context.metrics.observe_cost(price.total.units(), context.renderer.is_long(price.total.units()),
                                 render_ms / 1000.0);
    const double queue_ms =
        std::chrono::duration<double, std::milli>(Clock::now() - submitted).count() - render_ms;

    const auto encode_start = Clock::now();
    auto answer = std::make_shared<CachedRender>();
    const std::string encode_stage = animation ? "webp" : "png";
    if (animation) {
      answer->body = image::encode_webp_animation(out.frames, *animation);
      answer->content_type = "image/webp";
    } else {
      OutputPng encoded = encode_output(out, output, png_options);
      answer->body = std::move(encoded.png);
      answer->headers = std::move(encoded.headers);
    }
    const double encode_ms = std::chrono::duration<double, std::milli>(Clock::now() - encode_start).count();

    res.set_header("Server-Timing",
                   server_timing(out, pose_ms, queue_ms < 0 ? 0 : queue_ms, encode_stage, encode_ms));
    answer->etag = etag_of(answer->body);
    answer->passes = out.plan;
    answer->lod = lod_header(out.lods);
    answer->samples = out.samples;
    answer->headers.emplace_back("X-Toond-Cost", cost_header(price));
    answer_render(req, res, *answer);
    if (context.results) context.results->put(cache_key, std::move(answer));
    context.metrics.observe_render(std::chrono::duration<double>(Clock::now() - started).count(), out.timings,
                                   queue_ms < 0 ? 0 : queue_ms, encode_ms, encode_stage);
  };
  server.Post("/render", render);
  server.Post("/models/([0-9a-f]{16,64})/render", render);
}

}  // namespace toond::http
