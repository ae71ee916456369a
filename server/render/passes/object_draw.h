#pragma once
// The one loop every geometry pass shares: each object of the frame drawn
// with its placement block bound, with the side of its faces the pass may
// skip culled, and that side drawn after all where one of its hole caps
// shows. Render thread only.
#include <functional>

#include "gpu/program.h"
#include "render/plan/face_culling.h"

namespace toond::render {

struct PassContext;
class GpuModel;

// Enables culling of `faces` (None: culling off).
void cull(HiddenFaces faces);

// Draws every object of the frame: binds the object's buffers and its
// placement (the context's blocks), culls what `faces(i)` says and calls
// `draw(i)`.
// Where caps may show, the skipped side is drawn by `redraw(i)` when given
// (a draw that left out faces only that side can show), else by `draw(i)`,
// and their check's query lands in `cap_checks[i]` when given, so the
// caller can read the answer later.
struct ObjectDraw {
  std::function<FaceSkip(std::size_t)> faces{};
  std::function<void(std::size_t)> draw{};
  std::function<void(std::size_t)> redraw{};
  std::vector<gpu::Query>* cap_checks = nullptr;
};
void draw_objects(const PassContext& context, const ObjectDraw& how);

// Every triangle of object i at the frame's level of detail.
void draw_whole_object(const PassContext& context, std::size_t i);

// Object i submesh by submesh, each with its material's block and texture
// bound: for passes whose colour or alpha test comes from the material.
void draw_by_material(const PassContext& context, std::size_t i);

// Binds object i's material as the frame draws it (FrameContext::material):
// its block, and its colour texture (the model's or the request's), when it
// has one, sampled as the frame says.
void bind_material(const PassContext& context, std::size_t i, int material);

// Binds a material of `model` as the model was uploaded (the floor's).
void bind_own_material(const GpuModel& model, int material);

}  // namespace toond::render
