#include "render/passes/outline_colour.h"

namespace toond::render {

void draw_outline_objects(PassContext& context, const std::function<FaceSkip(std::size_t)>& faces) {
  const FrameContext& frame = context.frame;
  const bool per_material = outline_per_material(frame);
  draw_objects(context, {.faces = faces, .draw = [&](std::size_t i) {
                           if (per_material)
                             draw_by_material(context, i);
                           else
                             draw_whole_object(context, i);
                         }});
}

bool outline_per_material(const FrameContext& frame) {
  return frame.plan.outline.per_material() || frame.plan.alpha_tested_outlines;
}

}  // namespace toond::render
