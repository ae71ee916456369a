#pragma once
// The uniform blocks of shaders/view.glsl, object.glsl, material.glsl and
// outline_style.glsl, member for member in their std140 layout (a mat3 is
// three vec4 columns; a vec3 followed by a scalar shares its 16 bytes).
// FrameShading, the shading programs' own block, is in
// render/frame/shading_block.h. UniformBlocks.MatchTheShadersLayout checks
// every block here against what the driver reports.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace toond::render {

// The camera of the frame (binding 1).
struct ViewBlock {
  static constexpr int kBinding = 1;
  glm::mat4 view_projection{1.0f};
  glm::vec3 eye{0.0f};
  std::int32_t orthographic = 0;
  glm::vec3 view_dir{0.0f};
  float world_per_px_at_w1 = 0;
  glm::vec2 viewport_px{0.0f};
  float padding[2] = {};
};

// Where one object stands (binding 2).
struct ObjectBlock {
  static constexpr int kBinding = 2;
  glm::mat4 model{1.0f};
  glm::vec4 normal_matrix[3] = {glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, 1, 0)};  // columns
  std::int32_t skinned = 0;  // the object's model is drawn in a pose (shaders/skinning.glsl)
  float padding[3] = {};

  static ObjectBlock placing(const glm::mat4& model, const glm::mat3& normal_matrix, bool skinned);
};

// One material of a model (binding 3).
struct MaterialBlock {
  static constexpr int kBinding = 3;
  glm::vec3 base_color{0.8f};
  float opacity = 1.0f;
  float alpha_cutoff = -1.0f;  // negative: opaque
  std::int32_t has_texture = 0;
  float padding[2] = {};
};

// The outline's colour and width, and what the edge pass counts as an
// edge (binding 4).
struct OutlineBlock {
  static constexpr int kBinding = 4;
  glm::vec3 outline_color{0.0f};
  float darken = 0;
  float width = 0;            // pixels
  float depth_threshold = 0;  // scene units
  float cos_crease = 1;
  std::int32_t readable_area_px = 0;
  std::int32_t whole_pixels = 0;
  float padding[3] = {};
};

// A block as a test checks it: its GLSL name, binding and size, and its
// members by GLSL name with their offsets here.
struct UniformBlockLayout {
  std::string_view name;
  int binding = 0;
  std::size_t size = 0;
  std::vector<std::pair<std::string_view, std::size_t>> members;
};
std::vector<UniformBlockLayout> uniform_block_layouts();

}  // namespace toond::render
