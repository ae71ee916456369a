#include "render/render_params.h"

#include <cmath>

namespace toond::render {
namespace {

using nlohmann::json;

glm::vec3 vec3_of(const json& a) {
  return {a.at(0).get<float>(), a.at(1).get<float>(), a.at(2).get<float>()};
}

}  // namespace

float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

glm::vec3 srgb_to_linear(const glm::vec3& c) {
  return {srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b)};
}

RenderParams RenderParams::from_json(const json& j) {
  RenderParams p;
  p.model = j.value("model", "");
  p.width = j.at("width").get<int>();
  p.height = j.at("height").get<int>();
  const json& bg = j.at("background");
  p.background = glm::vec4(srgb_to_linear(vec3_of(bg)), bg.size() > 3 ? bg[3].get<float>() : 1.0f);

  const json& cam = j.at("camera");
  p.camera.projection = cam.at("projection") == "orthographic" ? Projection::Orthographic
                                                               : Projection::Perspective;
  p.camera.yaw_deg = cam.at("yaw").get<double>();
  p.camera.pitch_deg = cam.at("pitch").get<double>();
  p.camera.fov_deg = cam.at("fov").get<double>();
  p.camera.distance = cam.at("distance").get<double>();

  for (const json& l : j.at("lights")) {
    DirectionalLight light;
    const json& d = l.at("direction");
    light.direction = {d.at(0).get<double>(), d.at(1).get<double>(), d.at(2).get<double>()};
    light.color = srgb_to_linear(vec3_of(l.at("color"))) * l.at("intensity").get<float>();
    p.lights.push_back(light);
  }
  p.ambient = j.at("ambient").get<float>();

  const json& shading = j.at("shading");
  const std::string mode = shading.at("mode");
  p.mode = mode == "phong" ? ShadingMode::Phong : mode == "flat" ? ShadingMode::Flat : ShadingMode::Cel;
  p.steps = shading.at("steps").get<int>();
  const std::string rounding = shading.at("rounding");
  p.rounding = rounding == "floor" ? Rounding::Floor
               : rounding == "round" ? Rounding::Round
                                     : Rounding::Ceil;

  const json& outline = j.at("outline");
  p.outline.enabled = outline.at("enabled").get<bool>();
  p.outline.width_px = outline.at("width").get<float>();
  p.outline.color = srgb_to_linear(vec3_of(outline.at("color")));

  p.msaa = j.at("msaa").get<int>();
  return p;
}

}  // namespace toond::render
