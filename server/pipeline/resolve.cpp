#include "pipeline/resolve.h"

#include <string>

#include "pipeline/budget.h"
#include "pipeline/clips.h"
#include "pipeline/frames.h"
#include "pipeline/sheet_checks.h"
#include "render/frame/ramp_image.h"
#include "request_error.h"

namespace toond::pipeline {
namespace {

render::JobObject stored_model(scene::ModelLibrary& library, scene::ModelPins& pins, const std::string& id,
                               const std::string& pointer) {
  render::JobObject o;
  o.model_key = id;
  o.model = library.get(id, pins);
  if (!o.model) throw RequestError(404, "unknown_model", "no stored model with id " + id, pointer);
  return o;
}

// A scene's objects each name a stored model; otherwise the request's
// `model`, or the demo model without one.
std::vector<render::JobObject> models_of(const render::RenderParams& params, scene::ModelLibrary& library,
                                         scene::ModelPins& pins) {
  std::vector<render::JobObject> objects;
  for (std::size_t i = 0; i < params.objects.size(); ++i) {
    const render::SceneObject& object = params.objects[i];
    render::JobObject o = stored_model(library, pins, object.model, "/objects/" + std::to_string(i) + "/model");
    o.transform = object.matrix();
    objects.push_back(std::move(o));
  }
  if (!objects.empty()) return objects;
  if (params.model.empty()) return {{"demo", library.demo(), glm::dmat4(1.0), nullptr}};
  return {stored_model(library, pins, params.model, "/model")};
}

// An image file a parameter names (at JSON pointer `pointer`), looked up in
// the bundles of the request's models, first object first.
std::shared_ptr<const scene::Texture> bundle_image(scene::ModelLibrary& library, const Request& request,
                                                   const std::string& path, const std::string& pointer) {
  for (const render::JobObject& o : request.objects) {
    try {
      if (auto image = library.bundle_image(o.model_key, path)) return image;
    } catch (const std::exception& e) {
      throw RequestError(422, "bad_image", pointer + ": \"" + path + "\" is not a readable image: " + e.what(),
                         pointer);
    }
  }
  throw RequestError(422, "missing_file", pointer + ": the model's bundle has no file \"" + path + "\"", pointer);
}

// `name` as one token of a JSON pointer (RFC 6901: ~ as ~0, / as ~1).
std::string pointer_token(const std::string& name) {
  std::string token;
  for (const char c : name) {
    if (c == '~') {
      token += "~0";
    } else if (c == '/') {
      token += "~1";
    } else {
      token += c;
    }
  }
  return token;
}

// A `materials` entry names a material of some model of the request.
void check_material_named(const Request& request, const std::string& name, const std::string& pointer) {
  std::string names;
  for (const render::JobObject& o : request.objects) {
    for (const scene::Material& m : o.model->materials) {
      if (m.name == name) return;
      if (names.size() < 400) names += (names.empty() ? "'" : ", '") + m.name + "'";
    }
  }
  throw RequestError(422, "unknown_material",
                     pointer + ": the model has no material '" + name + "'; its materials are " + names, pointer);
}

// Turns the file names of a request into the images the render thread uses.
void load_bundle_images(scene::ModelLibrary& library, Request& request) {
  render::RenderParams& params = request.params;
  if (!params.ramp_image.empty()) {
    const std::string pointer = "/shading/ramp_image";
    try {
      params.ramp = render::ramp_from_image(*bundle_image(library, request, params.ramp_image, pointer));
    } catch (const render::RampImageError& e) {
      throw RequestError(422, "bad_image", pointer + ": " + e.what(), pointer);
    }
  }
  if (params.floor.enabled && !params.floor.texture.empty()) {
    params.floor.image = bundle_image(library, request, params.floor.texture, "/floor/texture");
  }
  for (auto& [name, material] : params.materials) {
    const std::string pointer = "/materials/" + pointer_token(name);
    check_material_named(request, name, pointer);
    if (!material.texture.empty())
      material.image = bundle_image(library, request, material.texture, pointer + "/texture");
  }
}

}  // namespace

Request resolve(render::RenderParams params, scene::ModelLibrary& library, scene::ModelPins& pins,
                const RenderLimits& limits) {
  check_sheet_params(params);
  Request request;
  request.pins = &pins;
  request.objects = models_of(params, library, pins);
  // An animated sheet's size follows its clips' lengths: they are looked
  // up before the sheet is held to the budget.
  resolve_sheet_clips(params, *request.objects.front().model);
  request.layout = layout_of(params);
  check_render_budget(params, request.layout, limits);
  request.output = describe_output(params, request.objects);
  request.params = std::move(params);
  load_bundle_images(library, request);
  const render::RenderParams& p = request.params;
  if (p.animation) request.clip = resolve_animation_clip(p, *request.objects.front().model);
  return request;
}

}  // namespace toond::pipeline
