#pragma once
// Draws a frame as its plan says (frame_plan.h): works out what its passes
// share (frame_context.h), runs the passes of the plan in order
// (passes/passes.h) and reads the image back. Render thread only.
#include <optional>
#include <string>
#include <vector>

#include "gpu/program_cache.h"
#include "render/cull/background_thread.h"
#include "render/frame/draw_pacing.h"
#include "render/frame/frame_context.h"
#include "render/frame/frame_resources.h"
#include "render/frame/render_object.h"
#include "render/frame/render_output.h"
#include "render/plan/frame_plan.h"
#include "render/plan/render_params.h"
#include "render/run/pending_frame.h"

namespace toond::render {

class Renderer {
 public:
  explicit Renderer(gpu::ProgramCache& programs) : programs_(programs) {}

  // On by default. Off draws both sides of every face: for tests that show
  // culling changes no pixel.
  void set_face_culling(bool on) { face_culling_ = on; }
  // Whether the hull outline leaves out the faces that cannot show
  // (render/cull/hull_cull.h): by default on a CPU rasterizer only, where
  // setting a triangle up costs the recording thread more than the test.
  // Set for tests that show it changes no byte.
  void set_hull_cull(bool on) { hull_cull_ = on; }
  // Whether the main pass leaves out runs of faces that surely turn to the
  // side it culls (render/cull/facing_runs.h). On by default; off for tests that
  // show it changes no byte.
  void set_skip_turned_away_runs(bool on) { skip_runs_ = on; }
  // Whether crease lines are drawn as wide GL lines where the driver draws
  // them that wide (render/passes/crease_pass.cpp). On by default; off draws
  // each as a quad, as a driver with narrow lines gets: for tests that show
  // both draw the same lines.
  void set_wide_lines(bool on) { wide_lines_ = on; }
  // Returns once the work frames handed off so far is done (a model's cull
  // mesh, built after its first frame): for tests that need it in place.
  void settle() { background_.drain(); }

  // `objects` as the plan was made of them (in its order, in its poses).
  // Every object shares the camera, the lights and the passes; camera fit,
  // shadow fit and floor use the union of their transformed bounds. With
  // `pacing` the meshes are drawn in its chunks, and a render whose
  // deadline passes throws RenderAborted (render/frame/draw_pacing.h).
  RenderOutput render(const std::vector<RenderObject>& objects, const FramePlan& plan, DrawPacing* pacing = nullptr) {
    return finish(start(objects, plan, pacing));
  }
  // The same, planned here from `params` and the objects' transforms and
  // poses (plan_frame).
  RenderOutput render(const std::vector<RenderObject>& objects, const RenderParams& params,
                      DrawPacing* pacing = nullptr) {
    return finish(start(objects, params, pacing));
  }
  RenderOutput render(const GpuModel& gpu, const scene::Model& model, const RenderParams& params) {
    return render({RenderObject{gpu, model}}, params);
  }

  // The same in two halves: start() records the passes and queues the
  // readback; finish() waits for the pixels. Without frames in flight the
  // pixels are read in start() and finish() only tidies up; with them, a
  // colour image is packed into a pixel buffer of its own (on a CPU
  // rasterizer too, so tests there cover the path) and the thread may start
  // other frames before it finishes this one. A data layer is always read
  // in start(). A frame that throws in start() leaves nothing to finish.
  std::unique_ptr<PendingFrame> start(const std::vector<RenderObject>& objects, const FramePlan& plan,
                                      DrawPacing* pacing = nullptr);
  std::unique_ptr<PendingFrame> start(const std::vector<RenderObject>& objects, const RenderParams& params,
                                      DrawPacing* pacing = nullptr);
  RenderOutput finish(std::unique_ptr<PendingFrame> frame);

  // Off by default (RenderService::Options::frames_in_flight).
  void set_frames_in_flight(bool on) { frames_in_flight_ = on; }

 private:
  bool real_gpu();

  gpu::ProgramCache& programs_;
  bool face_culling_ = true;
  std::optional<bool> hull_cull_;
  bool skip_runs_ = true;
  bool wide_lines_ = true;
  bool frames_in_flight_ = false;
  // Asked of the context at the first render: whether it rasterizes on a
  // GPU or on this CPU's threads (gpu::software_rasterizer). That decides
  // whether GPU time is counted and how pixels come back.
  std::optional<bool> real_gpu_;
  FrameResources resources_;
  BackgroundThread background_;
};

}  // namespace toond::render
