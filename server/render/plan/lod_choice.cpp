#include "render/plan/lod_choice.h"

#include <algorithm>
#include <cmath>

namespace toond::render {

double pixels_per_unit(const CameraSetup& camera, bool orthographic, const glm::dvec3& centre, double radius,
                       int output_height) {
  // projection[1][1] maps a view-space height to NDC (at depth 1 in
  // perspective), and NDC spans `output_height` pixels over 2 units.
  const double ndc_per_unit = camera.projection[1][1];
  const double px_per_ndc = 0.5 * static_cast<double>(output_height);
  if (orthographic) return ndc_per_unit * px_per_ndc;
  const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
  const double nearest = glm::dot(centre - camera.eye, forward) - radius;
  const double depth = std::max(nearest, camera.near_plane);
  return ndc_per_unit * px_per_ndc / depth;
}

std::size_t choose_lod(std::span<const double> level_errors, double px_per_unit, double budget_px) {
  std::size_t chosen = 0;
  if (!(budget_px > 0.0) || !std::isfinite(px_per_unit)) return chosen;
  for (std::size_t level = 1; level < level_errors.size(); ++level) {
    if (level_errors[level] * px_per_unit <= budget_px) chosen = level;
  }
  return chosen;
}

}  // namespace toond::render
