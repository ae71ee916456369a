#include "render/passes/shading_uniforms.h"

namespace toond::render {

void set_shading_uniforms(gpu::Program& program, const FrameContext& frame) {
  const RenderParams& params = frame.params;
  const float px = static_cast<float>(frame.supersample);
  program.set("u_view_projection", frame.view_projection);
  program.set("u_ambient", params.ambient);
  program.set("u_steps", static_cast<float>(params.steps));
  program.set("u_eye", frame.eye());
  program.set("u_view_dir", frame.view_dir());
  program.set("u_orthographic", frame.orthographic() ? 1 : 0);
  program.set_array("u_light_vec", frame.lights.vec);
  program.set_array("u_light_color", frame.lights.color);
  program.set_array("u_light_is_point", frame.lights.is_point);
  program.set_array("u_light_radius", frame.lights.radius);
  program.set("u_specular_color", params.specular.color);
  program.set("u_shininess", params.specular.shininess);
  program.set("u_specular_threshold", params.specular.threshold);
  program.set("u_specular_strength", params.specular.strength);
  program.set("u_rim_color", params.rim.color);
  program.set("u_rim_power", params.rim.power);
  program.set("u_rim_strength", params.rim.strength);
  program.set("u_rim_threshold", params.rim.threshold);
  program.set("u_contour_color", params.contour.color);
  program.set("u_contour_width", params.contour.width_px * px);
  program.set("u_contour_threshold", params.contour.threshold);
  program.set("u_halftone_cell", params.halftone.cell_px * px);
  program.set("u_halftone_angle", static_cast<float>(glm::radians(params.halftone.angle_deg)));
  program.set("u_halftone_ink", params.halftone.ink);
  program.set("u_halftone_ink_mix", params.halftone.ink_mix);
  program.set("u_two_tone_threshold", params.two_tone.threshold);
  program.set("u_two_tone_shadow", params.two_tone.shadow_factor);
  program.set_array("u_ramp_at", frame.ramp_at);
  program.set_array("u_ramp_color", frame.ramp_color);
}

void set_shadow_uniforms(gpu::Program& program, const PassContext& context) {
  const FrameContext& frame = context.frame;
  const ShadowParams& shadows = frame.params.shadows;
  program.set("u_shadow_matrix", glm::mat4(frame.shadow->view_projection));
  program.set("u_shadow_light", frame.plan.shadow_light);
  program.set("u_shadow_texel", 1.0f / static_cast<float>(shadows.map_size));
  program.set("u_shadow_offset", static_cast<float>(frame.shadow->texel_world * shadows.bias_texels));
  glBindTextureUnit(1, context.resources.shadow_map().texture());
  program.set("u_shadow_map", 1);
}

}  // namespace toond::render
