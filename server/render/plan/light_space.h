#pragma once
// Lights given in view space (`lights[].space` "view") turn with the
// camera: their direction, and their position about the point the camera
// orbits, are read along the view's axes (x right, y up, z toward the
// viewer) rather than the scene's. A sheet turns the camera about the model
// to draw its directions, so view-space lights light every direction alike:
// the character turns under the light, as it does in a game.
#include <vector>

#include <glm/glm.hpp>

#include "render/plan/render_params.h"

namespace toond::render {

// A view-space vector in scene coordinates, for the camera's yaw and pitch.
glm::dvec3 view_to_scene(const CameraParams& camera, const glm::dvec3& v);

// `lights` with every view-space light put into scene coordinates, for the
// camera's yaw and pitch orbiting `centre` (scene coordinates); model-space
// lights as they are. Same order and count.
std::vector<Light> lights_in_scene(const std::vector<Light>& lights, const CameraParams& camera,
                                   const glm::dvec3& centre);

}  // namespace toond::render
