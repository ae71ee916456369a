#include "render/run/renderer.h"

#include <chrono>

#include "gpu/egl_context.h"
#include "gpu/gpu_error.h"
#include "image/unpremultiply.h"
#include "render/frame/pass_timer.h"
#include "render/passes/passes.h"

namespace toond::render {
namespace {

void check_gl(const char* where) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) {
    throw gpu::GpuError(std::string("GL error 0x") + std::to_string(error) + " in the " + where + " pass");
  }
}

// Whether object i's caps showed in the main pass, so it drew both sides.
void report_cap_checks(const std::vector<gpu::Query>& checks, std::vector<LodUse>& lods) {
  for (std::size_t i = 0; i < checks.size(); ++i) {
    if (!checks[i]) continue;
    GLuint shown = 0;
    glGetQueryObjectuiv(checks[i].id(), GL_QUERY_RESULT, &shown);
    if (shown) lods[i].culled = HiddenFaces::None;
  }
}

// What the frame's arithmetic sees of each object: the model as imported,
// in the pose its GPU copy draws.
std::vector<FrameObject> frame_objects(const std::vector<RenderObject>& objects) {
  std::vector<FrameObject> frame;
  for (const RenderObject& o : objects) frame.push_back({o.model, o.pose.get(), o.gpu.skinned()});
  return frame;
}

}  // namespace

std::unique_ptr<PendingFrame> Renderer::start(const std::vector<RenderObject>& objects, const RenderParams& params,
                                              DrawPacing* pacing) {
  std::vector<PlannedObject> planned;
  for (const RenderObject& o : objects) planned.push_back({o.model, o.transform, o.pose.get()});
  return start(objects, plan_frame(params, planned), pacing);
}

bool Renderer::real_gpu() {
  if (!real_gpu_) {
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    real_gpu_ = !gpu::software_rasterizer(name ? name : "");
  }
  return *real_gpu_;
}

std::unique_ptr<PendingFrame> Renderer::start(const std::vector<RenderObject>& objects, const FramePlan& plan,
                                              DrawPacing* pacing) {
  if (objects.empty()) throw gpu::GpuError("a render needs at least one object");
  const FrameContext frame = build_frame_context(frame_objects(objects), plan, face_culling_);
  // GPU time only on a GPU: a CPU rasterizer's queries do not see its
  // raster threads (they stamp commands as they are recorded), and llvmpipe
  // records a query into every screen tile, which costs a pass over the
  // image per query (toond_bench sweep shows it).
  auto pending = std::make_unique<PendingFrame>(real_gpu());
  RenderOutput& out = pending->out;
  out.plan = frame.plan.describe();
  out.lods = frame.lods;
  const bool data_layer = frame.plan.has(Pass::Layer);
  // A data layer leaves the colour target as it is: a compositor asking for
  // colour and depth in turn would otherwise reallocate it every time.
  gpu::RenderTarget* target = data_layer ? nullptr
                                         : &resources_.target_for(frame.draw_width, frame.draw_height,
                                                                  frame.plan.samples, frame.supersample, real_gpu());
  out.samples = target ? target->samples() : 1;
  const FrameBlocks blocks(frame, resources_.frame_uniforms());
  PassContext context{.frame = frame,
                      .objects = objects,
                      .blocks = blocks,
                      .programs = programs_,
                      .resources = resources_,
                      .target = target,
                      .pacing = pacing,
                      .cull_hull = hull_cull_.value_or(!real_gpu()),
                      .skip_turned_away_runs = skip_runs_,
                      .wide_lines = wide_lines_,
                      .background = background_};
  if (frame.plan.has(Pass::HullOutline)) start_hull_cull(context);
  for (Pass pass : frame.plan.passes) {
    if (pacing && pacing->expired()) break;
    const DrawPass draw = drawing_pass(pass);
    if (!draw) continue;
    draw(context);
    check_gl(pass_name(pass));
    // Each pass goes to the driver as soon as it is recorded: llvmpipe then
    // rasterizes it on its threads while this one records the next.
    glFlush();
    pending->timer.mark(pass);
  }
  glBindVertexArray(0);
  glDisable(GL_STENCIL_TEST);
  if (pacing && pacing->expired()) {
    throw RenderAborted("the render was stopped at its deadline after " + std::to_string(pacing->chunks_drawn()) +
                        " chunks of triangles");
  }
  pending->cap_checks = std::move(context.main_cap_checks);
  out.hull_faces_culled = context.hull_faces_culled;
  out.hull_faces_turned_away = context.hull_faces_turned_away;
  out.main_triangles_skipped = context.main_triangles_skipped;
  out.crease_edges_drawn = context.crease_edges_drawn;
  out.intersection_segments_drawn = context.intersection_segments_drawn;
  pending->unpremultiply = frame.plan.has(Pass::Unpremultiply);
  // Without supersampling the multisample resolve is a blit inside
  // read_back(); its time is part of the readback figure, since the
  // readback waits for it anyway (with it, the downsample pass resolves).
  if (data_layer) {
    out.layer = resources_.normal_depth().read_pixels();
  } else if (frames_in_flight_) {
    pending->readback = resources_.readback_buffer(target->read_width(), target->read_height());
    target->start_read_back(*pending->readback);
    check_gl("readback");
    glFlush();  // the pack must reach the driver before this thread waits on anything else
    pending->timer.mark_in_flight(Pass::Readback);
    return pending;
  } else {
    out.image = target->read_back();
  }
  check_gl("readback");
  pending->timer.mark(Pass::Readback);
  return pending;
}

RenderOutput Renderer::finish(std::unique_ptr<PendingFrame> pending) {
  RenderOutput& out = pending->out;
  if (pending->readback) {
    const auto waiting = std::chrono::steady_clock::now();
    out.image = pending->readback->finish();
    resources_.give_back(std::move(pending->readback));
    pending->timer.landed(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - waiting).count());
  }
  report_cap_checks(pending->cap_checks, out.lods);
  if (pending->unpremultiply) {
    image::unpremultiply_linear(out.image);
    pending->timer.mark(Pass::Unpremultiply);
  }
  return std::move(out);
}

}  // namespace toond::render
