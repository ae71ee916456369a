#pragma once
// The uniforms every shading program of a frame shares (the main pass's
// and the floor's): camera, lights, and each effect's settings, and the
// shadow map where the frame has one.
#include "gpu/program.h"
#include "render/passes/pass_context.h"

namespace toond::render {

void set_shading_uniforms(gpu::Program& program, const FrameContext& frame);
// Binds the shadow map to texture unit 1.
void set_shadow_uniforms(gpu::Program& program, const PassContext& context);

}  // namespace toond::render
