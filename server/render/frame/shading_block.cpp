#include "render/frame/shading_block.h"

#include <algorithm>
#include <cmath>

namespace toond::render {

static_assert(sizeof(ShadingBlock) == 1216, "FrameShading's std140 size");
static_assert(offsetof(ShadingBlock, light_vec) == 112, "arrays start on a 16-byte boundary");

std::vector<std::pair<std::string_view, std::size_t>> shading_block_members() {
  return {
      {"u_ambient", offsetof(ShadingBlock, ambient)},
      {"u_steps", offsetof(ShadingBlock, steps)},
      {"u_specular_color", offsetof(ShadingBlock, specular_color)},
      {"u_shininess", offsetof(ShadingBlock, shininess)},
      {"u_rim_color", offsetof(ShadingBlock, rim_color)},
      {"u_rim_power", offsetof(ShadingBlock, rim_power)},
      {"u_contour_color", offsetof(ShadingBlock, contour_color)},
      {"u_contour_width", offsetof(ShadingBlock, contour_width)},
      {"u_halftone_ink", offsetof(ShadingBlock, halftone_ink)},
      {"u_halftone_cell", offsetof(ShadingBlock, halftone_cell)},
      {"u_specular_min_n_dot_h", offsetof(ShadingBlock, specular_min_n_dot_h)},
      {"u_specular_strength", offsetof(ShadingBlock, specular_strength)},
      {"u_rim_strength", offsetof(ShadingBlock, rim_strength)},
      {"u_rim_threshold", offsetof(ShadingBlock, rim_threshold)},
      {"u_contour_threshold", offsetof(ShadingBlock, contour_threshold)},
      {"u_halftone_angle", offsetof(ShadingBlock, halftone_angle)},
      {"u_halftone_ink_mix", offsetof(ShadingBlock, halftone_ink_mix)},
      {"u_two_tone_threshold", offsetof(ShadingBlock, two_tone_threshold)},
      {"u_two_tone_shadow", offsetof(ShadingBlock, two_tone_shadow)},
      {"u_light_vec[0]", offsetof(ShadingBlock, light_vec)},
      {"u_light_color[0]", offsetof(ShadingBlock, light_color)},
      {"u_light_is_point[0]", offsetof(ShadingBlock, light_is_point)},
      {"u_light_radius[0]", offsetof(ShadingBlock, light_radius)},
      {"u_ramp_at[0]", offsetof(ShadingBlock, ramp_at)},
      {"u_ramp_color[0]", offsetof(ShadingBlock, ramp_color)},
      {"u_shadow_matrix", offsetof(ShadingBlock, shadow_matrix)},
      {"u_shadow_light", offsetof(ShadingBlock, shadow_light)},
      {"u_shadow_texel", offsetof(ShadingBlock, shadow_texel)},
      {"u_shadow_offset", offsetof(ShadingBlock, shadow_offset)},
  };
}

ShadingBlock shading_block_for(const FrameContext& frame) {
  const RenderParams& params = frame.params;
  const float px = static_cast<float>(frame.supersample);
  ShadingBlock b;
  b.ambient = params.ambient;
  b.steps = static_cast<float>(params.steps);
  const std::size_t lights = std::min(frame.lights.vec.size(), ShadingBlock::kLights);
  for (std::size_t i = 0; i < lights; ++i) {
    b.light_vec[i] = glm::vec4(frame.lights.vec[i], 0.0f);
    b.light_color[i] = glm::vec4(frame.lights.color[i], 0.0f);
    b.light_is_point[i].x = frame.lights.is_point[i];
    b.light_radius[i].x = frame.lights.radius[i];
  }
  b.specular_color = params.specular.color;
  b.shininess = params.specular.shininess;
  // (N·H)^shininess ≥ threshold is N·H ≥ threshold^(1/shininess): the
  // power taken once here instead of in every pixel (the schema keeps
  // threshold > 0 and shininess ≥ 1).
  b.specular_min_n_dot_h = std::pow(params.specular.threshold, 1.0f / params.specular.shininess);
  b.specular_strength = params.specular.strength;
  b.rim_color = params.rim.color;
  b.rim_power = params.rim.power;
  b.rim_strength = params.rim.strength;
  b.rim_threshold = params.rim.threshold;
  b.contour_color = params.contour.color;
  b.contour_width = params.contour.width_px * px;
  b.contour_threshold = params.contour.threshold;
  b.halftone_cell = params.halftone.cell_px * px;
  b.halftone_angle = static_cast<float>(glm::radians(params.halftone.angle_deg));
  b.halftone_ink = params.halftone.ink;
  b.halftone_ink_mix = params.halftone.ink_mix;
  b.two_tone_threshold = params.two_tone.threshold;
  b.two_tone_shadow = params.two_tone.shadow_factor;
  const std::size_t stops = std::min(frame.ramp_at.size(), ShadingBlock::kRampStops);
  for (std::size_t i = 0; i < stops; ++i) {
    b.ramp_at[i].x = frame.ramp_at[i];
    b.ramp_color[i] = glm::vec4(frame.ramp_color[i], 0.0f);
  }
  if (frame.shadow) {
    b.shadow_matrix = glm::mat4(frame.shadow->view_projection);
    b.shadow_light = frame.plan.shadow_light;
    b.shadow_texel = 1.0f / static_cast<float>(params.shadows.map_size);
    b.shadow_offset = static_cast<float>(frame.shadow->texel_world * params.shadows.bias_texels);
  }
  return b;
}

}  // namespace toond::render
