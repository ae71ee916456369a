#pragma once
// Orbit camera fitted to the model's bounds. Pure maths, in double precision:
// the matrices are only rounded to float once, after the model's origin has
// been taken out, so large offsets and extreme scales lose nothing.
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/plan/render_params.h"
#include "scene/mesh/model.h"

namespace toond::render {

struct CameraSetup {
  glm::dmat4 view{1.0};
  glm::dmat4 projection{1.0};
  glm::dvec3 eye{0.0};     // in the mesh's (recentred) coordinates
  glm::dvec3 target{0.0};  // the point looked at: the bounds' centre
  double near_plane = 0.1;
  double far_plane = 100;
  // The camera.distance that asks for this view again: from eye to target
  // in perspective; in orthographic, where the eye stays 3 radii out, the
  // distance that sets this half_height (half_height / tan(fov / 2)).
  double distance = 0;
  double half_height = 0;  // orthographic: half the view's height in model units; perspective: 0
  glm::mat4 view_projection() const { return glm::mat4(projection * view); }
};

// The unit vector from the target toward the eye at this yaw and pitch.
glm::dvec3 toward_eye(double yaw_deg, double pitch_deg);

// The view's axes in scene coordinates: right and up across the image,
// toward_eye out of it.
struct ViewAxes {
  glm::dvec3 right, up, toward_eye;
};
ViewAxes view_axes(double yaw_deg, double pitch_deg);

// yaw 0, pitch 0 puts the eye on +Z of the bounds' centre, looking toward -Z.
// Orthographic, a given distance sets the view's size: as tall as the
// perspective view of fov from that distance is at the bounds' centre.
// With distance 0 the eye backs off (orthographic: the view widens) until
// every point of `outline` lies within kFrameFill of the image's half
// width and half height: the model fills that much of the limiting
// dimension whatever its shape. Without points the box's corners stand in.
// With `params.framed_views` the fit must hold in each of those views too:
// the widest fit of them all is used.
// near/far hug the bounds so depth precision does not depend on the
// model's scale.
inline constexpr double kFrameFill = 0.88;
CameraSetup fit_camera(const CameraParams& params, const scene::Bounds& bounds, double aspect,
                       std::span<const glm::dvec3> outline = {});

// One object of a scene as the framing sees it: its mesh's bounds (relative
// to the mesh's origin), that origin, and its transform (model → scene).
struct ScenePart {
  scene::Bounds bounds;
  glm::dvec3 origin{0.0};
  glm::dmat4 transform{1.0};
  std::span<const glm::vec3> extremes{};  // the mesh's (scene::Mesh::extremes); empty: box corners
};

// The coordinates a render works in: scene coordinates less `origin`, a
// point at the scene's middle, so that float maths on the GPU stays precise
// however far the scene sits from its own origin.
struct SceneFrame {
  glm::dvec3 origin{0.0};            // in scene coordinates
  std::vector<glm::dmat4> matrices;  // per part: mesh coordinates → frame
  scene::Bounds bounds;              // union of the parts' bounds, frame coordinates
  std::vector<glm::dvec3> outline;   // every part's extreme points, frame coordinates
};

// Matrices are T(-origin) × transform × T(part origin), in double. One part
// frames on its own transformed origin, so a single untransformed model gets
// exactly the identity and its own bounds (renders bit for bit as before
// scenes existed); several frame on the centre of the union of their
// transformed bounds (each box's eight corners through its matrix).
SceneFrame frame_scene(const std::vector<ScenePart>& parts);

}  // namespace toond::render
