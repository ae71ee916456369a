#pragma once
// Orbit camera fitted to the model's bounds. Pure maths, in double precision:
// the matrices are only rounded to float once, after the model's origin has
// been taken out, so large offsets and extreme scales lose nothing.
#include <glm/glm.hpp>

#include "render/render_params.h"
#include "scene/model.h"

namespace toond::render {

struct CameraSetup {
  glm::dmat4 view{1.0};
  glm::dmat4 projection{1.0};
  glm::dvec3 eye{0.0};     // in the mesh's (recentred) coordinates
  glm::dvec3 target{0.0};  // the point looked at: the bounds' centre
  double near_plane = 0.1;
  double far_plane = 100;
  glm::mat4 view_projection() const { return glm::mat4(projection * view); }
};

// yaw 0, pitch 0 puts the eye on +Z of the bounds' centre, looking toward -Z.
// With distance 0 the eye backs off until the bounding sphere fills the
// narrower of the two fields of view; near/far hug the bounds so depth
// precision does not depend on the model's scale.
CameraSetup fit_camera(const CameraParams& params, const scene::Bounds& bounds, double aspect);

}  // namespace toond::render
