#include "render/plan/outline_width.h"

#include <algorithm>

namespace toond::render {

double outline_width_px(const OutlineParams& outline, const CameraSetup& camera, bool orthographic, int output_height) {
  if (outline.units == OutlineUnits::Pixels) return std::min<double>(outline.width, kMaxOutlinePx);
  // projection[1][1] maps a view-space height to NDC (at depth 1 in
  // perspective), and NDC spans `output_height` pixels over 2 units.
  double px_per_unit = camera.projection[1][1] * 0.5 * static_cast<double>(output_height);
  if (!orthographic) px_per_unit /= glm::length(camera.target - camera.eye);
  return std::clamp(outline.width * px_per_unit, 0.0, kMaxOutlinePx);
}

}  // namespace toond::render
