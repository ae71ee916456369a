#include <cmath>

#include "render/passes/passes.h"

namespace toond::render {

// Lines over the discontinuities the prepass holds, drawn over the whole
// target; the shader gives each pixel the share of it the line covers.
void draw_edge_pass(PassContext& context) {
  const FrameContext& frame = context.frame;
  const OutlineParams& outline = frame.params.outline;
  const gpu::NormalDepthTarget& normals = context.resources.normal_depth();
  context.target.bind_for_drawing();
  glDisable(GL_DEPTH_TEST);
  gpu::Program& edges =
      context.programs.get("fullscreen.vert", "edges.frag",
                           frame.plan.creases_only ? std::vector<std::string>{"CREASES_ONLY"} : std::vector<std::string>{});
  edges.use();
  glBindTextureUnit(0, normals.texture());
  glBindTextureUnit(1, normals.coverage_texture());
  edges.set("u_normal_depth", 0);
  edges.set("u_coverage", 1);
  edges.set("u_half_width", 0.5f * frame.outline_px);
  edges.set("u_depth_threshold", outline.depth_threshold * 2.0f * frame.scene.bounds.radius());
  edges.set("u_cos_crease", static_cast<float>(std::cos(glm::radians(outline.crease_angle_deg))));
  edges.set("u_edge_color", outline.color);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  context.resources.draw_fullscreen_triangle();
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace toond::render
