#include "render/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

namespace toond::render {
namespace {
// Leaves a little air between the model and the image border.
constexpr double kFrameMargin = 1.08;
}  // namespace

CameraSetup fit_camera(const CameraParams& params, const scene::Bounds& bounds, double aspect) {
  const glm::dvec3 centre = glm::dvec3(bounds.min + bounds.max) * 0.5;
  double radius = glm::length(glm::dvec3(bounds.max) - glm::dvec3(bounds.min)) * 0.5;
  if (!(radius > 0.0) || !std::isfinite(radius)) radius = 1.0;  // a point or empty model

  const double yaw = glm::radians(params.yaw_deg);
  const double pitch = glm::radians(params.pitch_deg);
  const glm::dvec3 toward_eye(std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                              std::cos(yaw) * std::cos(pitch));

  const double fov_y = glm::radians(params.fov_deg);
  // The narrower field decides how far back the eye must be.
  const double fov_x = 2.0 * std::atan(std::tan(fov_y * 0.5) * aspect);
  const double fov_min = std::min(fov_y, fov_x);

  CameraSetup cam;
  double distance = params.distance;
  const bool ortho = params.projection == Projection::Orthographic;
  // Zoom only scales what fitting chose; an explicit distance is taken as meant.
  const double zoom = params.distance > 0.0 || !(params.zoom > 0.0) ? 1.0 : params.zoom;
  if (distance <= 0.0) {
    distance = ortho ? radius * 3.0 : radius * kFrameMargin / std::sin(fov_min * 0.5) / zoom;
  }
  // Looking straight up or down makes +Y a bad up vector; pitch is limited to
  // ±89° by the schema, so +Y is always usable.
  const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), toward_eye));
  const glm::dvec3 up = glm::cross(toward_eye, right);
  // Strafing moves eye and target together, so the view direction (and with
  // it the lighting seen) stays; in radii so it means the same at any scale.
  const glm::dvec3 target = centre + (right * params.shift.x + up * params.shift.y) * radius;
  cam.eye = target + toward_eye * distance;
  cam.target = target;
  cam.view = glm::lookAt(cam.eye, target, glm::dvec3(0, 1, 0));

  const double reach = radius * 1.01;
  cam.far_plane = distance + reach;
  if (ortho) {
    cam.near_plane = distance - reach;
    double half_h = radius * kFrameMargin / zoom;
    if (aspect < 1.0) half_h /= aspect;
    const double half_w = half_h * aspect;
    cam.projection = glm::ortho(-half_w, half_w, -half_h, half_h, cam.near_plane, cam.far_plane);
  } else {
    // A camera inside the bounds still needs a positive near plane; 1e-4 of
    // the far plane keeps 24-bit depth usable.
    cam.near_plane = std::max(distance - reach, cam.far_plane * 1e-4);
    cam.projection = glm::perspective(fov_y, aspect, cam.near_plane, cam.far_plane);
  }
  return cam;
}

SceneFrame frame_scene(const std::vector<ScenePart>& parts) {
  auto translation = [](const glm::dvec3& d) {
    glm::dmat4 m(1.0);
    m[3] = glm::dvec4(d, 1.0);
    return m;
  };
  // The union of the parts' boxes, each box's corners through `matrix(i)`.
  auto union_bounds = [&](auto&& matrix) {
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const glm::dmat4 m = matrix(i);
      const glm::dvec3 a(parts[i].bounds.min), b(parts[i].bounds.max);
      for (int c = 0; c < 8; ++c) {
        const glm::dvec3 corner(c & 1 ? b.x : a.x, c & 2 ? b.y : a.y, c & 4 ? b.z : a.z);
        const glm::dvec3 p(m * glm::dvec4(corner, 1.0));
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
    }
    return std::pair{lo, hi};
  };
  std::vector<glm::dmat4> to_scene;
  for (const ScenePart& part : parts) to_scene.push_back(part.transform * translation(part.origin));

  SceneFrame frame;
  if (parts.empty()) return frame;
  if (parts.size() == 1) {
    frame.origin = glm::dvec3(to_scene[0][3]);
  } else {
    const auto [lo, hi] = union_bounds([&](std::size_t i) { return to_scene[i]; });
    frame.origin = (lo + hi) * 0.5;
  }
  const glm::dmat4 recentre = translation(-frame.origin);
  for (const glm::dmat4& m : to_scene) frame.matrices.push_back(recentre * m);
  const auto [lo, hi] = union_bounds([&](std::size_t i) { return frame.matrices[i]; });
  frame.bounds = {glm::vec3(lo), glm::vec3(hi)};
  return frame;
}

}  // namespace toond::render
