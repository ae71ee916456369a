#include <algorithm>
#include <limits>

#include "render/passes/outline_colour.h"
#include "render/passes/passes.h"

namespace toond::render {
namespace {

// How far the hull may stand out of the model's box: up to 3 widths
// (mitred corners), where a pixel's size grows with the depth w, which the
// offset itself adds to. `world_per_px` is a pixel's size at w = 1.
double hull_reach(const FrameContext& frame, double world_per_px) {
  const double k = 3.0 * frame.outline_px * world_per_px;
  if (frame.orthographic()) return k;
  if (k >= 0.5) return std::numeric_limits<double>::infinity();
  double w_max = 1.0;
  for (int corner = 0; corner < 8; ++corner) {
    w_max = std::max(w_max, (frame.clip * glm::dvec4(frame.scene.bounds.corner(corner), 1.0)).w);
  }
  return k * w_max / (1.0 - k);
}

}  // namespace

// The inverted hull, outside the stencil mark the main pass left.
void draw_hull_outline_pass(PassContext& context) {
  const FrameContext& frame = context.frame;
  context.target->bind_for_drawing();
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NOTEQUAL, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  gpu::Program& program = context.programs.get("hull.vert", "hull.frag", frame.plan.outline.defines());
  program.use();
  // The stencil keeps the hull off the model, so its faces toward the
  // camera may draw the ring: where a closed model's back faces may be
  // skipped, the hull's may too. Its front faces lie nearer than its back
  // ones, so they pass every depth test (a floor's) the back ones would.
  // The hull must not be cut by the near or far plane either: where it is,
  // its back faces show through the cut.
  const double reach = hull_reach(frame, frame.world_per_px_at_w1());
  draw_outline_objects(context, [&](std::size_t i) {
    const GpuModel& model = frame.objects[i].model;
    FaceSkip hull;
    if (frame.main_faces[i].hidden == HiddenFaces::None) return hull;
    hull.hidden = hidden_faces(model.enclosure(frame.lod_of(i)), frame.scene.matrices[i], frame.clip, model.bounds(), reach);
    // The hull's holes move with its offset and may turn toward the camera
    // where the model's do not: its own caps, offset like it (they share
    // its vertices), are checked.
    hull.unless_caps_show = hull.hidden != HiddenFaces::None && !model.caps(frame.lod_of(i)).empty();
    return hull;
  });
}

}  // namespace toond::render
