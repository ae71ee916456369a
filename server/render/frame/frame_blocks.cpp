#include "render/frame/frame_blocks.h"

#include <cmath>

#include "render/frame/shading_block.h"
#include "render/frame/uniform_blocks.h"

namespace toond::render {
namespace {

ViewBlock view_block_for(const FrameContext& frame) {
  ViewBlock view;
  view.view_projection = frame.view_projection;
  view.eye = frame.eye();
  view.orthographic = frame.orthographic() ? 1 : 0;
  view.view_dir = frame.view_dir();
  view.world_per_px_at_w1 = static_cast<float>(frame.world_per_px_at_w1());
  view.viewport_px = glm::vec2(static_cast<float>(frame.draw_width), static_cast<float>(frame.draw_height));
  return view;
}

OutlineBlock outline_block_for(const FrameContext& frame) {
  const OutlineParams& params = frame.params.outline;
  OutlineBlock outline;
  outline.outline_color = params.color;
  outline.darken = params.darken;
  outline.width = frame.outline_px;
  outline.depth_threshold = params.depth_threshold * 2.0f * frame.scene.bounds.radius();
  outline.cos_crease = static_cast<float>(std::cos(glm::radians(params.crease_angle_deg)));
  outline.readable_area_px = params.readable_area_px;
  outline.whole_pixels = params.whole_pixel_lines ? 1 : 0;
  return outline;
}

MaterialBlock material_block(const scene::Material& material, const DrawnMaterial& drawn) {
  MaterialBlock block;
  block.base_color = material.diffuse;
  block.opacity = material.opacity;
  block.alpha_cutoff = drawn.tested_cutoff();
  block.has_texture = drawn.has_texture() ? 1 : 0;
  return block;
}

}  // namespace

FrameBlocks::FrameBlocks(const FrameContext& frame, gpu::UniformArena& arena) : arena_(arena) {
  arena.clear();
  const std::size_t view = arena.add(view_block_for(frame));
  const std::size_t shading = arena.add(shading_block_for(frame));
  const std::size_t outline = arena.add(outline_block_for(frame));
  for (std::size_t i = 0; i < frame.objects.size(); ++i) {
    objects_.push_back(
        arena.add(ObjectBlock::placing(frame.model_matrices[i], frame.normal_matrices[i], frame.objects[i].skinned)));
  }
  frame_placement_ = arena.add(ObjectBlock{});
  for (std::size_t i = 0; i < frame.objects.size(); ++i) {
    const std::vector<scene::Material>& materials = frame.objects[i].model.materials;
    std::vector<std::size_t>& offsets = materials_.emplace_back();
    for (std::size_t m = 0; m < materials.size() && m < frame.materials[i].size(); ++m) {
      offsets.push_back(arena.add(material_block(materials[m], frame.materials[i][m])));
    }
  }
  arena.upload();
  arena.bind(ViewBlock::kBinding, view, sizeof(ViewBlock));
  arena.bind(ShadingBlock::kBinding, shading, sizeof(ShadingBlock));
  arena.bind(OutlineBlock::kBinding, outline, sizeof(OutlineBlock));
}

void FrameBlocks::bind_object(std::size_t i) const {
  arena_.bind(ObjectBlock::kBinding, objects_[i], sizeof(ObjectBlock));
}

void FrameBlocks::bind_material(std::size_t i, int m) const {
  arena_.bind(MaterialBlock::kBinding, materials_[i][static_cast<std::size_t>(m)], sizeof(MaterialBlock));
}

void FrameBlocks::bind_frame_placement() const {
  arena_.bind(ObjectBlock::kBinding, frame_placement_, sizeof(ObjectBlock));
}

}  // namespace toond::render
