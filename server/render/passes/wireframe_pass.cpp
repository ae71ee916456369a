#include "render/passes/outline_colour.h"
#include "render/passes/passes.h"

namespace toond::render {

// After the model: its front faces hide the back-face lines except where
// they show past the silhouette or over folds. Line pixels of back faces
// lie behind the front faces they border, so no stencil is needed.
void draw_wireframe_pass(PassContext& context) {
  const FrameContext& frame = context.frame;
  context.target->bind_for_drawing();
  glDisable(GL_STENCIL_TEST);
  OutlineVariant variant = frame.plan.outline;
  variant.set(OutlineFeature::LineSegment);
  gpu::Program& program =
      context.programs.get(std::vector<std::string>{"wire.vert", "wire.geom", "hull.frag"}, variant.defines());
  program.use();
  // Multisampled, the line's coverage picks the samples it writes, each
  // written opaque. With one sample a pixel alpha to coverage does nothing
  // and the coverage would land in the image's alpha: the line is blended
  // over what is there by its coverage instead.
  const bool multisampled = context.target->samples() > 1;
  if (multisampled) {
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glEnable(GL_SAMPLE_ALPHA_TO_ONE);
  } else {
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  draw_outline_objects(context, [](std::size_t) { return FaceSkip{}; });
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glDisable(GL_SAMPLE_ALPHA_TO_ONE);
  glDisable(GL_BLEND);
}

}  // namespace toond::render
