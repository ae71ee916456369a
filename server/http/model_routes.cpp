// POST /models, GET /models, GET /models/{id}, DELETE /models/{id}.
#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "http/bundle_upload.h"
#include "http/error_response.h"
#include "http/routes.h"
#include "http/store_upload.h"
#include "request_error.h"

namespace toond::http {
namespace {
constexpr const char* kIdPattern = "/models/([0-9a-f]{16,64})";

// `?scene=N`: the glTF scene the upload asks for.
std::optional<int> gltf_scene(const httplib::Request& req) {
  if (!req.has_param("scene")) return std::nullopt;
  const std::string text = req.get_param_value("scene");
  const bool digits = !text.empty() && text.size() <= 9 &&
                      std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (!digits) {
    throw RequestError(400, "invalid_parameter", "?scene: a glTF scene's index, a whole number from 0", "?scene");
  }
  return std::stoi(text);
}

// `?smooth_angle=D`: degrees, 0 to 180.
std::optional<double> smooth_angle(const httplib::Request& req) {
  if (!req.has_param("smooth_angle")) return std::nullopt;
  const std::string text = req.get_param_value("smooth_angle");
  char* end = nullptr;
  const double angle = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !(angle >= 0.0 && angle <= 180.0)) {
    throw RequestError(400, "invalid_parameter",
                       "?smooth_angle: degrees from 0 (flat faces) to 180 (every edge smoothed), got \"" + text + "\"",
                       "?smooth_angle");
  }
  return angle;
}

// `?up=y` or `?up=z`; without it, the format's convention.
scene::ImportChoices::Up up_axis(const httplib::Request& req) {
  if (!req.has_param("up")) return scene::ImportChoices::Up::FormatDefault;
  const std::string text = req.get_param_value("up");
  if (text != "y" && text != "z") {
    throw RequestError(
        400, "invalid_parameter",
        "?up: y or z (without it, the format's convention: z for STL, PLY, 3MF, AMF and IQM, y for the rest)", "?up");
  }
  return text == "z" ? scene::ImportChoices::Up::Z : scene::ImportChoices::Up::Y;
}

// `?textures=a.png,b.png` (in material order) or `Body:a.png,...` (by
// material name): the images a game would set as the model's skins.
// Whether they are in the bundle and fit the materials is the import's to
// say (scene/import/skins.h).
std::vector<std::string> texture_list(const httplib::Request& req) {
  if (!req.has_param("textures")) return {};
  constexpr std::size_t kMostEntries = 256;
  const std::string text = req.get_param_value("textures");
  std::vector<std::string> entries;
  std::size_t at = 0;
  while (true) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    entries.push_back(text.substr(at, comma - at));
    if (comma == text.size()) break;
    at = comma + 1;
  }
  const bool empty = std::all_of(entries.begin(), entries.end(), [](const std::string& e) { return e.empty(); });
  if (empty || entries.size() > kMostEntries || text.size() > 64 * 1024 || text.find('\0') != std::string::npos) {
    throw RequestError(400, "invalid_parameter",
                       "?textures: images of the upload, comma-separated, in material order (a.png,b.png) or by "
                       "material name (Body:a.png,Tail:b.png), at most " +
                           std::to_string(kMostEntries),
                       "?textures");
  }
  return entries;
}

scene::ImportChoices import_choices(const httplib::Request& req) {
  scene::ImportChoices choices;
  choices.gltf_scene = gltf_scene(req);
  choices.smooth_angle = smooth_angle(req);
  choices.up = up_axis(req);
  choices.textures = texture_list(req);
  return choices;
}

}  // namespace

void register_model_routes(httplib::Server& server, ServiceContext& context) {
  server.Post("/models", [&context](const httplib::Request& req, httplib::Response& res) {
    const scene::ImportChoices choices = import_choices(req);
    const scene::Bundle bundle = bundle_from_multipart(req, {}, context.limits);
    const auto result = store_upload(context, bundle, choices);
    res.status = result.created ? 201 : 200;
    res.set_content(dump_for_client(result.info.to_json()), "application/json");
  });

  server.Get("/models", [&context](const httplib::Request&, httplib::Response& res) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& info : context.store.list()) list.push_back(info.to_json());
    res.set_content(dump_for_client({{"models", list}}), "application/json");
  });

  server.Get(kIdPattern, [&context](const httplib::Request& req, httplib::Response& res) {
    const std::string id = req.matches[1];
    if (auto info = context.store.info(id)) {
      res.set_content(dump_for_client(info->to_json()), "application/json");
    } else {
      write_error(res, 404, "unknown_model", "no model with id " + id, "/models/" + id);
    }
  });

  server.Delete(kIdPattern, [&context](const httplib::Request& req, httplib::Response& res) {
    const std::string id = req.matches[1];
    if (!context.store.remove(id)) {
      write_error(res, 404, "unknown_model", "no model with id " + id, "/models/" + id);
      return;
    }
    context.renders.forget(id);
    res.set_content(nlohmann::json{{"deleted", id}}.dump(), "application/json");
  });
}

}  // namespace toond::http
