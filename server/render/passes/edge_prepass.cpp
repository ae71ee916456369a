#include "render/frame/texture_unit.h"
#include "render/passes/passes.h"

namespace toond::render {
namespace {

// Samples per pixel of the prepass when it places silhouettes: a quarter
// pixel of coverage per sample, which AnalyticOracle.OutlineWidthPerMethod
// measures as widths within 0.4 px.
constexpr int kSilhouetteSamples = 4;

}  // namespace

// Each pixel's normal, distance from the eye and covered share, for the
// edge pass. Silhouettes are placed by the share of a pixel the model
// covers, which takes samples; creases and depth jumps are found on whole
// pixels, so a pass drawing creases alone does with one.
void draw_edge_prepass(PassContext& context) {
  const FrameContext& frame = context.frame;
  const int samples = frame.plan.creases_only ? 1 : kSilhouetteSamples;
  gpu::NormalDepthTarget& normals = context.resources.normal_depth_for(frame.draw_width, frame.draw_height, samples);
  normals.bind_for_drawing();
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  const bool alpha_tested = frame.plan.alpha_tested_outlines;
  const DepthVariant variant = DepthVariant{}.set(DepthFeature::AlphaMask, alpha_tested);
  gpu::Program& prepass = context.programs.get("toon.vert", "normal_depth.frag", variant.defines());
  prepass.use();
  draw_objects(context, {.faces = [&](std::size_t i) { return frame.main_faces[i]; },
                         .draw =
                             [&](std::size_t i) {
                               if (alpha_tested)
                                 draw_by_material(context, i);
                               else
                                 draw_whole_object(context, i);
                             }});
  if (!normals.needs_resolve()) return;
  normals.bind_for_resolve();
  glDisable(GL_DEPTH_TEST);
  gpu::Program& resolve = context.programs.get("fullscreen.vert", "normal_depth_resolve.frag", {});
  resolve.use();
  glBindTextureUnit(texture_unit::kPrepassSamples, normals.sample_texture());
  resolve.set("u_sample_count", normals.samples());
  context.resources.draw_fullscreen_triangle();
}

}  // namespace toond::render
