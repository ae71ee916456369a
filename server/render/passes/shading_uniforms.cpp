#include "render/passes/shading_uniforms.h"

#include "render/passes/shading_block.h"

namespace toond::render {

void upload_shading_block(PassContext& context) {
  const ShadingBlock block = shading_block_for(context.frame);
  const gpu::Buffer& buffer = context.resources.uniform_buffer(sizeof(ShadingBlock));
  glNamedBufferSubData(buffer.id(), 0, sizeof(ShadingBlock), &block);
  glBindBufferBase(GL_UNIFORM_BUFFER, ShadingBlock::kBinding, buffer.id());
}

void set_camera_uniforms(gpu::Program& program, const FrameContext& frame) {
  program.set("u_view_projection", frame.view_projection);
}

void set_shadow_uniforms(gpu::Program& program, const PassContext& context) {
  glBindTextureUnit(1, context.resources.shadow_map().texture());
  program.set("u_shadow_map", 1);
}

}  // namespace toond::render
