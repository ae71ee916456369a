#include "render/passes/outline_colour.h"

#include "render/passes/alpha_mask.h"

namespace toond::render {
namespace {

// The colour or the alpha test comes from each material, so draw material
// by material.
void draw_by_material(const FrameContext& frame, gpu::Program& program, std::size_t i) {
  const GpuModel& model = frame.objects[i].model;
  for (const scene::Submesh& sub : model.submeshes(frame.lod_of(i))) {
    const GpuMaterial& material = model.materials()[static_cast<std::size_t>(sub.material)];
    if (frame.plan.alpha_tested_outlines) set_alpha_mask_uniforms(program, model, material);
    program.set("u_base_color", material.diffuse);
    const bool textured = material.texture >= 0;
    program.set("u_has_texture", textured ? 1 : 0);
    if (textured) {
      glBindTextureUnit(0, model.texture(material.texture));
      program.set("u_diffuse_map", 0);
    }
    model.draw(sub);
  }
}

}  // namespace

void draw_outline_objects(PassContext& context, gpu::Program& program,
                          const std::function<FaceSkip(std::size_t)>& faces) {
  const FrameContext& frame = context.frame;
  program.set("u_outline_color", frame.params.outline.color);
  program.set("u_darken", frame.params.outline.darken);
  const bool per_material = frame.plan.outline.per_material() || frame.plan.alpha_tested_outlines;
  draw_objects(frame, {.program = &program,
                       .faces = faces,
                       .draw = [&](std::size_t i) {
                         if (per_material) draw_by_material(frame, program, i);
                         else draw_whole_object(frame, i);
                       }});
}

}  // namespace toond::render
