#pragma once
// From the camera's view space to the drawing's pixels: x to the right, y
// down (as SVG and PNG rows go), the image `width` × `height` output pixels.
#include <glm/glm.hpp>
#include <glm/gtc/matrix_inverse.hpp>

namespace toond::render::vector {

struct ScreenMap {
  glm::dmat4 projection{1.0};
  int width = 1;
  int height = 1;
  glm::dmat4 inverse{1.0};  // of `projection`

  static ScreenMap of(const glm::dmat4& projection, int width, int height) {
    return {projection, width, height, glm::inverse(projection)};
  }

  glm::dvec4 clip(const glm::dvec3& view) const { return projection * glm::dvec4(view, 1.0); }
  glm::dvec2 to_pixels(const glm::dvec3& view) const {
    const glm::dvec4 c = clip(view);
    return {(c.x / c.w * 0.5 + 0.5) * width, (0.5 - c.y / c.w * 0.5) * height};
  }
  // The view-space point at pixel `px` on the near plane (ndc_z -1) or the
  // far one (1): the ray through a pixel runs from the first to the second.
  glm::dvec3 unproject(glm::dvec2 px, double ndc_z) const {
    const glm::dvec4 ndc(px.x / width * 2.0 - 1.0, 1.0 - px.y / height * 2.0, ndc_z, 1.0);
    const glm::dvec4 v = inverse * ndc;
    return glm::dvec3(v) / v.w;
  }
};

}  // namespace toond::render::vector
