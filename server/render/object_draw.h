#pragma once
// The one loop every geometry pass shares: each object of the frame drawn
// under its own matrices, with the side of its faces the pass may skip
// culled, and that side drawn after all where one of its hole caps shows.
// Render thread only.
#include <functional>

#include "gpu/program.h"
#include "render/face_culling.h"

namespace toond::render {

struct FrameContext;
class GpuModel;

// Which faces of an object a pass skips.
struct FaceSkip {
  HiddenFaces hidden = HiddenFaces::None;
  // The object has holes whose caps may face the camera: the skipped side
  // is drawn after all wherever one of them shows.
  bool unless_caps_show = false;
};

// Enables culling of `faces` (None: culling off).
void cull(HiddenFaces faces);

// Object i's matrices: u_model and u_normal_matrix.
void set_object_matrices(gpu::Program& program, const FrameContext& frame, std::size_t i);

// Draws every object of the frame: binds the object's buffers, culls what
// `faces(i)` says, sets the object's matrices on `program` and calls
// `draw(i)`. Without a program `draw` picks one per submesh and sets the
// matrices itself. Where caps may show, their check's query lands in
// `cap_checks[i]` when given, so the caller can read the answer later.
struct ObjectDraw {
  gpu::Program* program = nullptr;
  std::function<FaceSkip(std::size_t)> faces{};
  std::function<void(std::size_t)> draw{};
  std::vector<gpu::Query>* cap_checks = nullptr;
};
void draw_objects(const FrameContext& frame, const ObjectDraw& how);

// Every triangle of object i at the frame's level of detail.
void draw_whole_object(const FrameContext& frame, std::size_t i);

}  // namespace toond::render
