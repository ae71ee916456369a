#pragma once
// The shadow map's projection: an orthographic box looking along the light,
// fitted to the model's bounds so every texel of the map covers the model.
// Pure maths, unit-tested without GL.
#include <glm/glm.hpp>

#include "scene/mesh/model.h"

namespace toond::render {

struct ShadowFit {
  glm::dmat4 view_projection{1.0};  // frame coordinates (those of `bounds`) → light clip space
  double texel_world = 0;           // world size of one shadow-map texel
};

// `direction` is the way the light travels (need not be unit length, must
// not be zero).
ShadowFit fit_shadow(const glm::dvec3& direction, const scene::Bounds& bounds, int map_size);

}  // namespace toond::render
