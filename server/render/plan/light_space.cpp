#include "render/plan/light_space.h"

#include "render/plan/camera.h"

namespace toond::render {

glm::dvec3 view_to_scene(const CameraParams& camera, const glm::dvec3& v) {
  const ViewAxes axes = view_axes(camera.yaw_deg, camera.pitch_deg);
  return axes.right * v.x + axes.up * v.y + axes.toward_eye * v.z;
}

std::vector<Light> lights_in_scene(const std::vector<Light>& lights, const CameraParams& camera,
                                   const glm::dvec3& centre) {
  std::vector<Light> placed = lights;
  for (Light& light : placed) {
    if (light.space != LightSpace::View) continue;
    light.direction = view_to_scene(camera, light.direction);
    light.position = centre + view_to_scene(camera, light.position);
    light.space = LightSpace::Model;
  }
  return placed;
}

}  // namespace toond::render
