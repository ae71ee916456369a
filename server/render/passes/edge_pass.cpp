#include "render/frame/draw_pacing.h"
#include "render/frame/texture_unit.h"
#include "render/passes/passes.h"
#include "render/plan/render_cost.h"

namespace toond::render {

// Lines over the discontinuities the prepass holds, drawn over the whole
// target; the shader gives each pixel the share of it the line covers.
void draw_edge_pass(PassContext& context) {
  const FrameContext& frame = context.frame;
  const gpu::NormalDepthTarget& normals = context.resources.normal_depth();
  context.target->bind_for_drawing();
  glDisable(GL_DEPTH_TEST);
  const EdgeVariant variant = EdgeVariant{}.set(EdgeFeature::CreasesOnly, frame.plan.creases_only);
  gpu::Program& edges = context.programs.get("fullscreen.vert", "edges.frag", variant.defines());
  edges.use();
  glBindTextureUnit(texture_unit::kNormalDepth, normals.texture());
  glBindTextureUnit(texture_unit::kCoverage, normals.coverage_texture());
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
