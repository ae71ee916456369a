#include "render/passes/outline_colour.h"
#include "render/passes/passes.h"

namespace toond::render {

// After the model: its front faces hide the back-face lines except where
// they show past the silhouette or over folds. Line pixels of back faces
// lie behind the front faces they border, so no stencil is needed.
void draw_wireframe_pass(PassContext& context) {
  const FrameContext& frame = context.frame;
  context.target.bind_for_drawing();
  glDisable(GL_STENCIL_TEST);
  OutlineVariant variant = frame.plan.outline;
  variant.set(OutlineFeature::LineSegment);
  gpu::Program& program =
      context.programs.get(std::vector<std::string>{"wire.vert", "wire.geom", "hull.frag"}, variant.defines());
  program.use();
  program.set("u_view_projection", frame.view_projection);
  program.set("u_viewport", glm::vec2(static_cast<float>(frame.draw_width), static_cast<float>(frame.draw_height)));
  // Half of each line lies inside the silhouette, under the front faces:
  // lines twice as wide leave `width` pixels showing.
  program.set("u_line_px", 2.0f * frame.outline_px);
  program.set("u_half_line_px", frame.outline_px);
  program.set("u_eye", frame.eye());
  program.set("u_view_dir", frame.view_dir());
  program.set("u_orthographic", frame.orthographic() ? 1 : 0);
  // The line's coverage picks the samples it writes, each written opaque.
  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glEnable(GL_SAMPLE_ALPHA_TO_ONE);
  draw_outline_objects(context, program, [](std::size_t) { return FaceSkip{}; });
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glDisable(GL_SAMPLE_ALPHA_TO_ONE);
}

}  // namespace toond::render
