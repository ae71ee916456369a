#pragma once
// The alpha test of masked materials (glTF alphaMode MASK) in the passes
// that draw outlines, so a line follows what the main pass drew: the
// material's opacity times its texture's alpha against its cutoff. Shaders
// declare it under ALPHA_MASK; an opaque material gets a cutoff that
// nothing fails.
#include "gpu/program.h"
#include "render/frame_context.h"
#include "render/gpu_model.h"

namespace toond::render {

// Texture unit 3 carries the material's texture.
void set_alpha_mask_uniforms(gpu::Program& program, const GpuModel& model, const GpuMaterial& material);

// Object i of the frame, material by material, each with its alpha test.
void draw_alpha_tested(const FrameContext& frame, gpu::Program& program, std::size_t i);

}  // namespace toond::render
