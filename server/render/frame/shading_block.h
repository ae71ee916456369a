#pragma once
// The FrameShading uniform block (shaders/frame_shading.glsl), member for member in its
// std140 layout: what every shading program of a frame shares, uploaded
// once per frame. std140 gives a vec3 a 16-byte slot only when a scalar
// does not follow it, and every array element a 16-byte stride, hence the
// vec4 arrays. ShadingBlock.MatchesTheShadersLayout checks each member's
// offset against what the driver reports.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "render/frame/frame_context.h"

namespace toond::render {

struct ShadingBlock {
  static constexpr int kBinding = 0;  // layout(binding = 0) in frame_shading.glsl
  static constexpr std::size_t kLights = 8;
  static constexpr std::size_t kRampStops = 16;

  float ambient = 0;
  float steps = 0;
  float shininess = 0;
  float rim_power = 0;
  glm::vec3 specular_color{0.0f};
  float contour_width = 0;
  glm::vec3 rim_color{0.0f};
  float halftone_cell = 0;
  glm::vec3 contour_color{0.0f};
  float specular_min_n_dot_h = 0;
  glm::vec3 halftone_ink{0.0f};
  float specular_strength = 0;
  float rim_strength = 0;
  float rim_threshold = 0;
  float contour_threshold = 0;
  float halftone_angle = 0;
  float halftone_ink_mix = 0;
  float two_tone_threshold = 0;
  float two_tone_shadow = 0;
  float padding_0 = 0;
  glm::vec4 light_vec[kLights] = {};        // .xyz
  glm::vec4 light_color[kLights] = {};      // .xyz
  glm::ivec4 light_is_point[kLights] = {};  // .x
  glm::vec4 light_radius[kLights] = {};     // .x
  glm::vec4 ramp_at[kRampStops] = {};       // .x
  glm::vec4 ramp_color[kRampStops] = {};    // .xyz
  glm::mat4 shadow_matrix{1.0f};
  std::int32_t shadow_light = -1;
  float shadow_texel = 0;
  float shadow_offset = 0;
  float padding_1 = 0;
};

// The block's members by their GLSL names and their offsets here.
std::vector<std::pair<std::string_view, std::size_t>> shading_block_members();

ShadingBlock shading_block_for(const FrameContext& frame);

}  // namespace toond::render
