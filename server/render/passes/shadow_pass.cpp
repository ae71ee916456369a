#include "render/passes/passes.h"

namespace toond::render {

void draw_shadow_pass(PassContext& context) {
  const FrameContext& frame = context.frame;
  const RenderParams& params = frame.params;
  gpu::ShadowMap& map = context.resources.shadow_map_for(params.shadows.map_size);
  map.bind_for_drawing();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_STENCIL_TEST);
  // Slope-scaled bias for surfaces the light grazes; the normal offset in
  // the main pass handles the rest.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 2.0f);
  // Masked materials cast a shadow only where the main pass draws them.
  const bool alpha_tested = frame.plan.alpha_tested_shadows;
  const DepthVariant variant = DepthVariant{}.set(DepthFeature::AlphaMask, alpha_tested);
  gpu::Program& program = context.programs.get("shadow.vert", "shadow.frag", variant.defines());
  program.use();
  program.set("u_light_view_projection", glm::mat4(frame.shadow->view_projection));
  draw_objects(context,
               {// The nearest surface seen from the light is the same with
                // the far side skipped, so the map is too.
                .faces = [&](std::size_t i) { return FaceSkip{frame.shadow_faces[i]}; },
                .draw =
                    [&](std::size_t i) {
                      if (alpha_tested)
                        draw_by_material(context, i);
                      else
                        draw_whole_object(context, i);
                    }});
  glDisable(GL_POLYGON_OFFSET_FILL);
}

}  // namespace toond::render
