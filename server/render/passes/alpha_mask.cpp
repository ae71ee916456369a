#include "render/passes/alpha_mask.h"

namespace toond::render {

void set_alpha_mask_uniforms(gpu::Program& program, const GpuModel& model, const GpuMaterial& material) {
  constexpr int kMaskUnit = 3;
  const bool masked = material.alpha_cutoff >= 0.0f;
  const bool textured = masked && material.texture >= 0;
  program.set("u_mask_opacity", material.opacity);
  program.set("u_mask_cutoff", masked ? material.alpha_cutoff : -1.0f);
  program.set("u_mask_has_texture", textured ? 1 : 0);
  if (textured) glBindTextureUnit(kMaskUnit, model.texture(material.texture));
  program.set("u_mask_map", kMaskUnit);
}

void draw_alpha_tested(const FrameContext& frame, gpu::Program& program, std::size_t i) {
  const GpuModel& model = frame.objects[i].model;
  for (const scene::Submesh& sub : model.submeshes(frame.lod_of(i))) {
    set_alpha_mask_uniforms(program, model, model.materials()[static_cast<std::size_t>(sub.material)]);
    model.draw(sub);
  }
}

}  // namespace toond::render
