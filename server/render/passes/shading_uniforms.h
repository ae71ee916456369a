#pragma once
// What every shading program of a frame (the main pass's and the floor's)
// reads besides its material: the FrameShading block, uploaded once per
// frame, and the shadow map where the frame has one.
#include "gpu/program.h"
#include "render/passes/pass_context.h"

namespace toond::render {

// Fills the frame's FrameShading block and binds it for every program.
void upload_shading_block(PassContext& context);
// The vertex stage's camera; the rest comes from the block.
void set_camera_uniforms(gpu::Program& program, const FrameContext& frame);
// Binds the shadow map to texture unit 1.
void set_shadow_uniforms(gpu::Program& program, const PassContext& context);

}  // namespace toond::render
