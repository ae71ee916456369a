#include <cmath>

#include "render/frame/draw_pacing.h"
#include "render/frame/texture_unit.h"
#include "render/passes/passes.h"
#include "render/plan/render_cost.h"

namespace toond::render {

// Lines over the discontinuities the prepass holds, drawn over the whole
// target; the shader gives each pixel the share of it the line covers.
void draw_edge_pass(PassContext& context) {
  const FrameContext& frame = context.frame;
  const OutlineParams& outline = frame.params.outline;
  const gpu::NormalDepthTarget& normals = context.resources.normal_depth();
  context.target->bind_for_drawing();
  glDisable(GL_DEPTH_TEST);
  const EdgeVariant variant = EdgeVariant{}.set(EdgeFeature::CreasesOnly, frame.plan.creases_only);
  gpu::Program& edges = context.programs.get("fullscreen.vert", "edges.frag", variant.defines());
  edges.use();
  glBindTextureUnit(texture_unit::kNormalDepth, normals.texture());
  glBindTextureUnit(texture_unit::kCoverage, normals.coverage_texture());
  edges.set("u_half_width", 0.5f * frame.outline_px);
  edges.set("u_depth_threshold", outline.depth_threshold * 2.0f * frame.scene.bounds.radius());
  edges.set("u_cos_crease", static_cast<float>(std::cos(glm::radians(outline.crease_angle_deg))));
  edges.set("u_edge_color", outline.color);
  edges.set("u_readable_area_px", outline.readable_area_px);
  edges.set("u_whole_pixels", static_cast<int>(outline.whole_pixel_lines));
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  // At 2048² this pass alone can take llvmpipe longer than the meshes: a
  // render priced as long draws it in bands, stepping aside between them.
  const double texels = edge_texels_per_pixel(frame.outline_px, frame.plan.creases_only);
  draw_full_screen(context.pacing, frame.draw_width, frame.draw_height, texels,
                   [&] { context.resources.draw_fullscreen_triangle(); });
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace toond::render
