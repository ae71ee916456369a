#include "pipeline/pipeline.h"

#include <optional>

#include "pipeline/assemble.h"
#include "pipeline/atlas.h"
#include "pipeline/plan.h"
#include "pipeline/queue.h"
#include "pipeline/sheet_answer.h"
#include "pipeline/sheet_layers.h"

namespace toond::pipeline {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

bool any_posed(const std::vector<ObjectPoses>& frames) {
  for (const ObjectPoses& poses : frames) {
    for (const auto& pose : poses) {
      if (pose) return true;
    }
  }
  return false;
}

// The render thread's own time for the frames, pass by pass.
double render_thread_ms(const render::RenderOutput& out) {
  double ms = 0;
  for (const render::PassTiming& t : out.timings) ms += t.cpu_ms;
  return ms;
}

// Each frame as a job for the render threads, in layout order (layer after
// layer, sheet_layers.h: each layer's frames take the same poses): its
// poses, its plan and the request's schedule (a sheet waits in the lane its
// whole price says, its client's turn, all its frames paced alike).
std::vector<render::RenderJob> frame_jobs(const Request& request, const std::vector<ObjectPoses>& poses,
                                          std::vector<render::FramePlan> plans, const render::Schedule& schedule) {
  std::vector<render::RenderJob> jobs;
  for (std::size_t i = 0; i < plans.size(); ++i) {
    render::RenderJob job{.objects = request.objects, .plan = std::move(plans[i]), .schedule = schedule};
    for (std::size_t k = 0; k < job.objects.size(); ++k) job.objects[k].pose = poses[i % poses.size()][k];
    jobs.push_back(std::move(job));
  }
  return jobs;
}

}  // namespace

nlohmann::ordered_json sheet_atlas(const Request& request, Services& services) {
  const std::vector<ObjectPoses> poses = pose_frames(request, services.framings, services.renderer.skinning());
  return atlas_of(request, plan_frames(request, poses));
}

Encoded sheet_file(const Request& request, Services& services) {
  return encode_sheet_file(nullptr, request, sheet_atlas(request, services));
}

Rendered render(Request request, const std::string& client, Services& services) {
  if (request.params.output == render::Output::Svg) return render_svg(std::move(request), client, services);
  Rendered rendered;
  const auto posing = Clock::now();
  const std::vector<ObjectPoses> poses = pose_frames(request, services.framings, services.renderer.skinning());
  if (any_posed(poses)) rendered.pose_ms = ms_since(posing);
  std::vector<render::FramePlan> plans = plan_frames(request, poses);
  // A sheet's atlas frames it as its frames are; an animation's goes out
  // with ?atlas=json alone.
  std::optional<nlohmann::ordered_json> atlas;
  if (request.layout && !request.params.sheet->animate) atlas = atlas_of(request, plans);

  rendered.price = price_of(plans);
  check_render_cost(request, poses, rendered.price, services.limits);
  rendered.long_lane = services.renderer.is_long(rendered.price.total.units());
  const auto submitted = Clock::now();
  // Past the deadline the render thread skips the job instead of drawing
  // an image nobody waits for any more.
  const render::Schedule schedule{.client = client,
                                  .cost = rendered.price.total.units(),
                                  .pacing = pacing_of(rendered.price),
                                  .deadline = submitted + services.deadline};
  if (request.pins) request.pins->lease();
  Assembly assembly(request.params, request.layout, drawn_layers(request.params, request.answer.file).size());
  queue_frames(services.renderer, frame_jobs(request, poses, std::move(plans), schedule), services.deadline, assembly);
  render::RenderOutput out = assembly.finish();
  if (atlas && request.params.sheet->pack) pack_sheet_output(out, *atlas, request);
  rendered.render_ms = render_thread_ms(out);
  rendered.queue_ms = std::max(0.0, ms_since(submitted) - rendered.render_ms);

  const auto encoding = Clock::now();
  rendered.encoded = encode(out, request, atlas);
  rendered.encode_ms = ms_since(encoding);
  rendered.timings = out.timings;
  rendered.plan = out.plan;
  rendered.lods = out.lods;
  rendered.samples = out.samples;
  return rendered;
}

}  // namespace toond::pipeline
