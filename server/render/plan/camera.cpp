#include "render/plan/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

namespace toond::render {
namespace {

std::vector<glm::dvec3> box_corners(const scene::Bounds& bounds) {
  std::vector<glm::dvec3> corners;
  for (int c = 0; c < 8; ++c) corners.push_back(bounds.corner(c));
  return corners;
}

// The eye distance at which every point projects within `fill` of the
// image's half extents: a point x across and z toward the eye, seen from
// distance d, lands at x / ((d − z)·tan(fov/2)) of the half width.
double fitted_distance(std::span<const glm::dvec3> points, const glm::dvec3& target, const ViewAxes& axes,
                       double tan_half_x, double tan_half_y, double fill) {
  double distance = 0.0;
  for (const glm::dvec3& p : points) {
    const glm::dvec3 q = p - target;
    const double z = glm::dot(q, axes.toward_eye);
    distance = std::max({distance, z + std::abs(glm::dot(q, axes.right)) / (fill * tan_half_x),
                         z + std::abs(glm::dot(q, axes.up)) / (fill * tan_half_y)});
  }
  return distance;
}

// The orthographic half height that holds every point within `fill`.
double fitted_half_height(std::span<const glm::dvec3> points, const glm::dvec3& target, const ViewAxes& axes,
                          double aspect, double fill) {
  double half = 0.0;
  for (const glm::dvec3& p : points) {
    const glm::dvec3 q = p - target;
    half = std::max({half, std::abs(glm::dot(q, axes.up)) / fill, std::abs(glm::dot(q, axes.right)) / (fill * aspect)});
  }
  return half;
}

// The camera's own view and every view its framing must also hold.
std::vector<ViewAxes> framed_axes(const CameraParams& params) {
  std::vector<ViewAxes> views{view_axes(params.yaw_deg, params.pitch_deg)};
  for (const glm::dvec2& view : params.framed_views) views.push_back(view_axes(view.x, view.y));
  return views;
}

}  // namespace

glm::dvec3 toward_eye(double yaw_deg, double pitch_deg) {
  const double yaw = glm::radians(yaw_deg);
  const double pitch = glm::radians(pitch_deg);
  return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch)};
}

ViewAxes view_axes(double yaw_deg, double pitch_deg) {
  ViewAxes axes;
  axes.toward_eye = toward_eye(yaw_deg, pitch_deg);
  // Looking straight up or down makes +Y a bad up vector; pitch is limited
  // to ±89° by the schema, so +Y is always usable.
  axes.right = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), axes.toward_eye));
  axes.up = glm::cross(axes.toward_eye, axes.right);
  return axes;
}

CameraSetup fit_camera(const CameraParams& params, const scene::Bounds& bounds, double aspect,
                       std::span<const glm::dvec3> outline) {
  const glm::dvec3 centre = glm::dvec3(bounds.min + bounds.max) * 0.5;
  double radius = glm::length(glm::dvec3(bounds.max) - glm::dvec3(bounds.min)) * 0.5;
  if (!(radius > 0.0) || !std::isfinite(radius)) radius = 1.0;  // a point or empty model
  const std::vector<glm::dvec3> corners = outline.empty() ? box_corners(bounds) : std::vector<glm::dvec3>{};
  const std::span<const glm::dvec3> points = outline.empty() ? std::span<const glm::dvec3>(corners) : outline;

  const std::vector<ViewAxes> views = framed_axes(params);
  const ViewAxes& axes = views.front();
  const double tan_half_y = std::tan(glm::radians(params.fov_deg) * 0.5);
  const double tan_half_x = tan_half_y * aspect;

  CameraSetup cam;
  const bool ortho = params.projection == Projection::Orthographic;
  // Zoom only scales what fitting chose; an explicit distance is taken as meant.
  const double zoom = params.distance > 0.0 || !(params.zoom > 0.0) ? 1.0 : params.zoom;
  // The eye's distance. An orthographic image does not change with it, so
  // the eye stays where near and far hug the whole model, and a given
  // `distance` sets the view's size instead (below).
  double distance = ortho ? radius * 3.0 : params.distance;
  if (distance <= 0.0) {
    // A flat model seen edge-on projects to a line: the eye still keeps a
    // tenth of a radius clear of it.
    double fitted = 0.0;
    for (const ViewAxes& view : views) {
      fitted = std::max(fitted, fitted_distance(points, centre, view, tan_half_x, tan_half_y, kFrameFill));
    }
    distance = std::max(fitted, radius * 0.1) / zoom;
  }
  // Strafing moves eye and target together, so the view direction (and with
  // it the lighting seen) stays; in radii so it means the same at any scale.
  const glm::dvec3 target = centre + (axes.right * params.shift.x + axes.up * params.shift.y) * radius;
  cam.distance = distance;
  cam.eye = target + axes.toward_eye * distance;
  cam.target = target;
  cam.view = glm::lookAt(cam.eye, target, glm::dvec3(0, 1, 0));

  const double reach = radius * 1.01;
  cam.far_plane = distance + reach;
  if (ortho) {
    cam.near_plane = distance - reach;
    // The view is as tall as a perspective view of `fov` from `sized_at`
    // is at the orbit's centre: the distance given, or the one that holds
    // the fitted frame. Both go through the same product, so asking for
    // `cam.distance` again gives this very view, bit for bit (a sheet's
    // tile as a single render).
    double sized_at = params.distance;
    if (!(sized_at > 0.0)) {
      double half_h = 0.0;
      for (const ViewAxes& view : views)
        half_h = std::max(half_h, fitted_half_height(points, centre, view, aspect, kFrameFill));
      half_h /= zoom;
      if (!(half_h > 0.0)) half_h = radius / zoom;
      sized_at = half_h / tan_half_y;
    }
    const double half_h = sized_at * tan_half_y;
    cam.half_height = half_h;
    cam.distance = sized_at;
    const double half_w = half_h * aspect;
    cam.projection = glm::ortho(-half_w, half_w, -half_h, half_h, cam.near_plane, cam.far_plane);
  } else {
    // A camera inside the bounds still needs a positive near plane; 1e-4 of
    // the far plane keeps 24-bit depth usable.
    cam.near_plane = std::max(distance - reach, cam.far_plane * 1e-4);
    cam.projection = glm::perspective(glm::radians(params.fov_deg), aspect, cam.near_plane, cam.far_plane);
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
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const glm::dmat4& m = frame.matrices[i];
    if (parts[i].extremes.empty()) {
      for (int c = 0; c < 8; ++c) frame.outline.emplace_back(m * glm::dvec4(parts[i].bounds.corner(c), 1.0));
    }
    for (const glm::vec3& p : parts[i].extremes) frame.outline.emplace_back(m * glm::dvec4(glm::dvec3(p), 1.0));
  }
  return frame;
}

}  // namespace toond::render
