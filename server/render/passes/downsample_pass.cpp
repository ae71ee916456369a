#include "render/frame/texture_unit.h"
#include "render/passes/passes.h"

namespace toond::render {

// Supersampling's last GPU step: the drawn image, resolved to one sample a
// pixel, shrunk by the factor into the target's output-sized framebuffer,
// so only output-sized pixels are read back.
void draw_downsample_pass(PassContext& context) {
  const FrameContext& frame = context.frame;
  const GLuint drawn = context.target->resolve_for_shrinking();
  context.target->bind_for_shrinking();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_BLEND);
  gpu::Program& downsample =
      context.programs.get("fullscreen.vert", "downsample.frag", frame.plan.downsample.defines());
  downsample.use();
  glBindTextureUnit(texture_unit::kDrawn, drawn);
  downsample.set("u_factor", frame.supersample);
  context.resources.draw_fullscreen_triangle();
  glEnable(GL_DEPTH_TEST);
}

}  // namespace toond::render
