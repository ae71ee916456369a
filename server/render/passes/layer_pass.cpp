#include "render/passes/passes.h"

namespace toond::render {
namespace {

// What an id layer numbers: the objects of a scene, or the materials of a
// lone model; 0 is the background.
int layer_id(const FrameContext& frame, std::size_t object, int material) {
  return frame.plan.ids_by == IdSource::Object ? static_cast<int>(object) + 1 : material + 1;
}

}  // namespace

// A data layer (depth, normal or id) in place of the colour: each pixel's
// value from the nearest surface, one sample a pixel, into the float
// target the edge prepass also uses (a layer render draws no edges).
void draw_layer_pass(PassContext& context) {
  const FrameContext& frame = context.frame;
  gpu::NormalDepthTarget& layer = context.resources.normal_depth_for(frame.draw_width, frame.draw_height, 1);
  layer.bind_for_drawing();
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  const LayerVariant variant = frame.plan.layer;
  gpu::Program& program = context.programs.get("toon.vert", "layer.frag", variant.defines());
  program.use();
  program.set("u_view_rotation", glm::mat3(frame.camera.view));
  const bool numbered = variant.has(LayerFeature::Id);
  // Submesh by submesh only where the material matters: an id per
  // material, or its alpha test.
  const bool by_material = numbered || variant.has(LayerFeature::AlphaMask);
  draw_objects(context, {.faces = [&](std::size_t i) { return frame.main_faces[i]; },
                         .draw =
                             [&](std::size_t i) {
                               if (!by_material) {
                                 draw_whole_object(context, i);
                                 return;
                               }
                               const GpuModel& model = context.model(i);
                               for (const scene::Submesh& sub : model.submeshes(frame.lod_of(i))) {
                                 bind_material(context, i, sub.material);
                                 if (numbered)
                                   program.set("u_layer_id", static_cast<float>(layer_id(frame, i, sub.material)));
                                 model.draw(sub, context.pacing);
                               }
                             }});
}

}  // namespace toond::render
