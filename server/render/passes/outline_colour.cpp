#include "render/passes/outline_colour.h"

namespace toond::render {

void draw_outline_objects(PassContext& context, const std::function<FaceSkip(std::size_t)>& faces) {
  const FrameContext& frame = context.frame;
  // The colour or the alpha test comes from each material: draw material
  // by material.
  const bool per_material = frame.plan.outline.per_material() || frame.plan.alpha_tested_outlines;
  draw_objects(frame, context.blocks,
               {.faces = faces, .draw = [&](std::size_t i) {
                  if (per_material) draw_by_material(frame, i);
                  else draw_whole_object(frame, i);
                }});
}

}  // namespace toond::render
