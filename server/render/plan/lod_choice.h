#pragma once
// Which level of detail an object draws: the coarsest whose geometric error,
// seen from the camera at the object's nearest point, stays within a budget
// of output pixels. Pure maths, no GL.
#include <cstddef>
#include <span>

#include <glm/glm.hpp>

#include "render/plan/camera.h"
#include "render/plan/face_culling.h"

namespace toond::render {

// The level of detail one object was drawn at (see lod_choice.h).
struct LodUse {
  std::size_t level = 0;      // 0 = full detail
  std::size_t levels = 1;     // how many the model has
  std::size_t triangles = 0;  // drawn per pass
  double error_px = 0;        // the level's error projected to output pixels
  // The side of the faces the main pass skipped (None: both drawn): a
  // closed level seen from outside (face_culling.h), or an open one none
  // of whose holes showed (their caps were checked and hidden).
  HiddenFaces culled = HiddenFaces::None;
};

// Output pixels covered by one unit of frame space at the nearest point of
// the sphere (centre, radius) to the camera, along the view axis. A sphere
// that reaches the near plane counts as at the near plane (the most detail).
// `output_height` is the image height the client gets, before supersampling:
// the downsample averages away anything smaller than its pixels.
double pixels_per_unit(const CameraSetup& camera, bool orthographic, const glm::dvec3& centre, double radius,
                       int output_height);

// Index into `level_errors` (level 0 = full detail, error 0, then coarser
// levels with growing error in the object's frame units) of the coarsest
// level with error × px_per_unit ≤ budget_px. Level 0 when none qualifies.
std::size_t choose_lod(std::span<const double> level_errors, double px_per_unit, double budget_px);

}  // namespace toond::render
