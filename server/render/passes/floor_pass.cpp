#include "render/frame/texture_unit.h"
#include "render/passes/passes.h"

namespace toond::render {

// Same shading as the model, but no stencil mark: the floor is never
// outlined, and the model's outline may cross it. In the lines layer it
// writes depth alone: it hides the lines behind it, as in the color render.
void draw_floor_pass(PassContext& context) {
  const FrameContext& frame = context.frame;
  const FloorParams& params = frame.params.floor;
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  const bool textured = frame.plan.floor_textured && params.image;
  const GpuModel& floor = context.resources.floor_for(frame.scene.bounds, params, textured);
  ToonVariant variant = frame.plan.shading;
  variant.set(ToonFeature::HasTexture, textured);
  gpu::Program& program = context.programs.get("toon.vert", "toon.frag", variant.defines());
  program.use();
  // The floor is made in frame coordinates already.
  context.blocks.bind_frame_placement();
  bind_own_material(floor, 0);
  if (frame.shadow) glBindTextureUnit(texture_unit::kShadowMap, context.resources.shadow_map().texture());
  floor.bind();
  const bool depth_only = frame.plan.output == Output::Lines;
  if (depth_only) glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  floor.draw_all(0, context.pacing);
  if (depth_only) glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace toond::render
