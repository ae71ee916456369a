#include <numbers>

#include "render/frame/draw_pacing.h"
#include "render/frame/texture_unit.h"
#include "render/passes/passes.h"

namespace toond::render {
namespace {

// crease.geom's u_culled_winding for object i: the winding on screen of
// the faces that cannot show (those the main pass culls, whether or not
// it does), so a crease between two of them, hidden by the model's own
// faces, is dropped before it is rasterised. None where that side may show
// through a hole.
int culled_winding(const FrameContext& frame, std::size_t i) {
  const FaceSkip& skip = frame.unseen_faces[i];
  if (skip.unless_caps_show) return 0;
  switch (skip.hidden) {
    case HiddenFaces::None:
      return 0;
    case HiddenFaces::Back:
      return 1;
    case HiddenFaces::Front:
      return 2;
  }
  return 0;
}

// Every object's edges creased at the request's angle, and its segments
// where parts cross that turn as far (crease.geom's u_seams); runs of
// edges whose faces all surely turn to the side the main pass culls are
// left out (they hide behind the model's own faces). Counts what it drew
// in `context`.
void draw_crease_edges_of_objects(PassContext& context, gpu::Program& program) {
  const FrameContext& frame = context.frame;
  const double angle = frame.params.outline.crease_angle_deg;
  for (std::size_t i = 0; i < frame.objects.size(); ++i) {
    const GpuModel& model = context.model(i);
    const std::size_t lod = frame.lod_of(i);
    const bool creases = model.creased_edges(lod, angle) > 0;
    const bool seams = model.intersection_segments(lod, angle) > 0;
    if (!creases && !seams) continue;
    context.blocks.bind_object(i);
    program.set("u_culled_winding", culled_winding(frame, i));
    if (creases) {
      model.bind();
      program.set("u_seams", 0);
      const std::optional<MeshViewer> viewer =
          frame.main_faces[i].unless_caps_show ? std::nullopt : turned_away_runs_viewer(context, i);
      context.crease_edges_drawn += model.draw_creases(lod, angle, viewer, context.pacing);
    }
    if (seams) {
      program.set("u_seams", 1);
      context.intersection_segments_drawn += model.draw_intersections(lod, angle, context.pacing);
    }
  }
}

// How far a crease line's primitive reaches to each side of its edge:
// half the outline's width and a margin. Multisampled, the samples are
// tested where they lie, so a hair past the width will do; one sample a
// pixel, the fragment stage's coverage of a pixel reaches half a pixel
// (diagonally √½) past the width.
float line_reach(float outline_px, bool multisampled) {
  return 0.5f * outline_px + (multisampled ? 1.0f / 64.0f : 1.0f);
}

// The width of GL line that holds every point within `reach` of the edge.
// Multisampled, a GL line is a rectangle that wide; without, it spans that
// width along its minor axis (x or y), which at 45° is 1/√2 of it across.
float gl_line_width(float reach, bool multisampled) {
  return 2.0f * reach * (multisampled ? 1.0f : std::numbers::sqrt2_v<float>);
}

// The crease program for this target, in use: lines drawn as wide GL lines
// where the driver draws them that wide (one primitive a line instead of
// two triangles), and the target's sample positions.
gpu::Program& use_crease_program(PassContext& context, bool multisampled) {
  const float reach = line_reach(context.frame.outline_px, multisampled);
  const float line_width = gl_line_width(reach, multisampled);
  const bool wide_lines = context.wide_lines && line_width <= context.resources.widest_line();
  const CreaseVariant variant =
      CreaseVariant{}.set(CreaseFeature::SampleMask, multisampled).set(CreaseFeature::WideLines, wide_lines);
  gpu::Program& program =
      context.programs.get(std::vector<std::string>{"crease.vert", "crease.geom", "crease.frag"}, variant.defines());
  program.use();
  program.set("u_line_reach", reach);
  if (multisampled) program.set_array("u_sample_positions", context.target->sample_positions());
  if (wide_lines) glLineWidth(line_width);
  return program;
}

// One sample a pixel: the pixels' coverage, gathered by crease.frag, laid
// over the image in the outline's colour (in bands when paced, like any
// full-screen pass).
void lay_line_coverage_over(PassContext& context, GLuint coverage) {
  const FrameContext& frame = context.frame;
  context.target->bind_for_drawing();
  glDisable(GL_DEPTH_TEST);
  gpu::Program& program = context.programs.get("fullscreen.vert", "crease_coverage.frag", {});
  program.use();
  glBindTextureUnit(texture_unit::kLineCoverage, coverage);
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  draw_full_screen(context.pacing, frame.draw_width, frame.draw_height, 1.0,
                   [&] { context.resources.draw_fullscreen_triangle(); });
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace

// After the silhouette's outline: a line along every crease edge whose two
// faces show, and along every segment where parts cross (crease.geom),
// depth-tested against what the main pass drew,
// at the cost of the crease edges rather than of the frame's pixels.
// Multisampled, each line writes the samples it covers, opaque; with one
// sample a pixel, the lines' coverage is gathered first, the largest a
// pixel gets kept, and laid over the image once, so that lines joining at
// a point darken it once.
void draw_crease_pass(PassContext& context) {
  const bool multisampled = context.target->samples() > 1;
  glBindTextureUnit(texture_unit::kSceneDepth, context.target->depth_texture());
  GLuint coverage = 0;
  if (multisampled) {
    context.target->bind_colour_alone();
    glDisable(GL_BLEND);
  } else {
    coverage = context.target->bind_line_coverage();
    glEnable(GL_BLEND);
    glBlendEquation(GL_MAX);
  }
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_CULL_FACE);
  // crease.frag tests each sample against the copied depth itself.
  glDisable(GL_DEPTH_TEST);
  gpu::Program& program = use_crease_program(context, multisampled);
  draw_crease_edges_of_objects(context, program);
  glLineWidth(1.0f);
  glEnable(GL_DEPTH_TEST);
  glBlendEquation(GL_FUNC_ADD);
  glDisable(GL_BLEND);
  glBindTextureUnit(texture_unit::kSceneDepth, 0);
  const bool lines_drawn = context.crease_edges_drawn + context.intersection_segments_drawn > 0;
  if (!multisampled && lines_drawn)
    lay_line_coverage_over(context, coverage);
  else
    context.target->bind_for_drawing();
}

}  // namespace toond::render
