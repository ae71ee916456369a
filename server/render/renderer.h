#pragma once
// Draws a frame: works out what its passes share (frame_context.h), runs
// the passes of its plan in order (passes/passes.h) and reads the image
// back. Render thread only.
#include <optional>
#include <string>
#include <vector>

#include "gpu/program_cache.h"
#include "image/float_image.h"
#include "image/image.h"
#include "render/draw_pacing.h"
#include "render/frame_context.h"
#include "render/frame_resources.h"
#include "render/pass_timing.h"
#include "render/render_params.h"

namespace toond::render {

struct RenderOutput {
  image::Image image;  // empty for a data layer
  // A data layer's values (output depth, normal or id), turned into its
  // PNG by the caller, who knows what the ids stand for.
  image::FloatImage layer;
  // An animated sheet's frames, in the atlas's order, each tile-sized (no
  // sheet is laid out: the animation holds them one by one).
  std::vector<image::Image> frames;
  std::vector<PassTiming> timings;
  std::string plan;  // PassPlan::describe()
  std::vector<LodUse> lods;  // one per object, in order
  // Samples per pixel the target really has: `msaa` clamped to the
  // driver's GL_MAX_SAMPLES (llvmpipe: 4).
  int samples = 1;
};

class Renderer {
 public:
  explicit Renderer(gpu::ProgramCache& programs) : programs_(programs) {}

  // On by default. Off draws both sides of every face: for tests that show
  // culling changes no pixel.
  void set_face_culling(bool on) { face_culling_ = on; }

  // Every object shares the camera, the lights and the passes; camera fit,
  // shadow fit and floor use the union of their transformed bounds. With
  // `pacing` the meshes are drawn in its chunks, and a render whose
  // deadline passes throws RenderAborted (render/draw_pacing.h).
  RenderOutput render(const std::vector<RenderObject>& objects, const RenderParams& params,
                      DrawPacing* pacing = nullptr);
  RenderOutput render(const GpuModel& model, const RenderParams& params) {
    return render({RenderObject{model, glm::dmat4(1.0)}}, params);
  }

 private:
  bool real_gpu();

  gpu::ProgramCache& programs_;
  bool face_culling_ = true;
  // Asked of the context at the first render: whether it rasterizes on a
  // GPU or on this CPU's threads (gpu::software_rasterizer). That decides
  // whether GPU time is counted and how pixels come back.
  std::optional<bool> real_gpu_;
  FrameResources resources_;
};

}  // namespace toond::render
