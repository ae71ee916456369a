#include "render/passes/passes.h"
#include "render/passes/shading_uniforms.h"

namespace toond::render {

// Same shading as the model, but no stencil mark: the floor is never
// outlined, and the model's outline may cross it.
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
  set_camera_uniforms(program, frame);
  // The floor is made in frame coordinates already.
  program.set("u_model", glm::mat4(1.0f));
  program.set("u_normal_matrix", glm::mat3(1.0f));
  program.set("u_base_color", params.color);
  if (textured) {
    glBindTextureUnit(0, floor.texture(0));
    program.set("u_diffuse_map", 0);
  }
  if (frame.shadow) set_shadow_uniforms(program, context);
  floor.bind();
  floor.draw_all();
}

}  // namespace toond::render
