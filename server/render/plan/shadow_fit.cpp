#include "render/plan/shadow_fit.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace toond::render {

ShadowFit fit_shadow(const glm::dvec3& direction, const scene::Bounds& bounds, int map_size) {
  const glm::dvec3 dir = glm::normalize(direction);
  const glm::dvec3 lo(bounds.min), hi(bounds.max);
  const glm::dvec3 centre = (lo + hi) * 0.5;
  double radius = glm::length(hi - lo) * 0.5;
  if (!(radius > 0.0)) radius = 1.0;
  // Any up vector not parallel to the light will do.
  const glm::dvec3 up = std::abs(dir.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  const glm::dmat4 view = glm::lookAt(centre - dir * (2.0 * radius), centre, up);

  // The box around the bounds' eight corners as the light sees them.
  glm::dvec3 mn(1e300), mx(-1e300);
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 corner(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    const glm::dvec3 p = glm::dvec3(view * glm::dvec4(corner, 1.0));
    mn = glm::min(mn, p);
    mx = glm::max(mx, p);
  }
  // A texel's margin on each side keeps PCF taps at the border on the map.
  const double texel = std::max(mx.x - mn.x, mx.y - mn.y) / std::max(map_size - 4, 1);
  mn -= glm::dvec3(2 * texel);
  mx += glm::dvec3(2 * texel);
  // View space looks down -Z: near/far are the negated z range.
  const glm::dmat4 projection = glm::ortho(mn.x, mx.x, mn.y, mx.y, -mx.z - radius * 0.01, -mn.z + radius * 0.01);
  ShadowFit fit;
  fit.view_projection = projection * view;
  fit.texel_world = std::max(mx.x - mn.x, mx.y - mn.y) / map_size;
  return fit;
}

}  // namespace toond::render
