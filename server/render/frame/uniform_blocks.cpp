#include "render/frame/uniform_blocks.h"

#include "render/frame/shading_block.h"

namespace toond::render {

static_assert(sizeof(ViewBlock) == 112 && sizeof(ObjectBlock) == 128 && sizeof(MaterialBlock) == 32 &&
                  sizeof(OutlineBlock) == 48,
              "std140 sizes");

ObjectBlock ObjectBlock::placing(const glm::mat4& model, const glm::mat3& normal_matrix, bool skinned) {
  ObjectBlock block;
  block.model = model;
  block.skinned = skinned ? 1 : 0;
  for (int c = 0; c < 3; ++c) block.normal_matrix[c] = glm::vec4(normal_matrix[c], 0.0f);
  return block;
}

std::vector<UniformBlockLayout> uniform_block_layouts() {
  using View = ViewBlock;
  return {
      {"FrameShading", ShadingBlock::kBinding, sizeof(ShadingBlock), shading_block_members()},
      {"FrameView",
       View::kBinding,
       sizeof(View),
       {{"u_view_projection", offsetof(View, view_projection)},
        {"u_eye", offsetof(View, eye)},
        {"u_orthographic", offsetof(View, orthographic)},
        {"u_view_dir", offsetof(View, view_dir)},
        {"u_world_per_px_at_w1", offsetof(View, world_per_px_at_w1)},
        {"u_viewport_px", offsetof(View, viewport_px)}}},
      {"ObjectPlacement",
       ObjectBlock::kBinding,
       sizeof(ObjectBlock),
       {{"u_model", offsetof(ObjectBlock, model)},
        {"u_normal_matrix", offsetof(ObjectBlock, normal_matrix)},
        {"u_skinned", offsetof(ObjectBlock, skinned)}}},
      {"Material",
       MaterialBlock::kBinding,
       sizeof(MaterialBlock),
       {{"u_base_color", offsetof(MaterialBlock, base_color)},
        {"u_opacity", offsetof(MaterialBlock, opacity)},
        {"u_alpha_cutoff", offsetof(MaterialBlock, alpha_cutoff)},
        {"u_has_texture", offsetof(MaterialBlock, has_texture)}}},
      {"OutlineStyle",
       OutlineBlock::kBinding,
       sizeof(OutlineBlock),
       {{"u_outline_color", offsetof(OutlineBlock, outline_color)},
        {"u_darken", offsetof(OutlineBlock, darken)},
        {"u_width", offsetof(OutlineBlock, width)},
        {"u_depth_threshold", offsetof(OutlineBlock, depth_threshold)},
        {"u_cos_crease", offsetof(OutlineBlock, cos_crease)},
        {"u_readable_area_px", offsetof(OutlineBlock, readable_area_px)},
        {"u_whole_pixels", offsetof(OutlineBlock, whole_pixels)}}},
  };
}

}  // namespace toond::render
