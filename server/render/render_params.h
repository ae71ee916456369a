#pragma once
// Render parameters as the renderer uses them. Built only from a request
// that ParamSchema::validate_and_complete() has checked and filled with the
// schema's defaults, so every field is present and in range here; names and
// defaults live in proto/render-params.schema.json, not in this file.
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace toond::render {

enum class ShadingMode { Cel, Phong, Flat };
enum class Rounding { Ceil, Floor, Round };
enum class Projection { Perspective, Orthographic };

struct CameraParams {
  Projection projection = Projection::Perspective;
  double yaw_deg = 0;
  double pitch_deg = 0;
  double fov_deg = 35;
  double distance = 0;  // 0: fit to the model's bounds
};

struct DirectionalLight {
  glm::dvec3 direction{0, 0, -1};  // the way the light travels
  glm::vec3 color{1.0f};           // linear, intensity applied
};

struct OutlineParams {
  bool enabled = true;
  float width_px = 2;
  glm::vec3 color{0.0f};  // linear
};

struct RenderParams {
  std::string model;  // empty: the demo model
  int width = 512;
  int height = 512;
  glm::vec4 background{1.0f};  // linear rgb, alpha
  CameraParams camera;
  std::vector<DirectionalLight> lights;
  float ambient = 0.3f;
  ShadingMode mode = ShadingMode::Cel;
  int steps = 3;
  Rounding rounding = Rounding::Ceil;
  OutlineParams outline;
  int msaa = 1;

  static RenderParams from_json(const nlohmann::json& completed);
};

// sRGB transfer function, for colours given in the wire format.
float srgb_to_linear(float c);
glm::vec3 srgb_to_linear(const glm::vec3& c);

}  // namespace toond::render
