#include "pipeline/plan.h"

#include "pipeline/frames.h"
#include "pipeline/sheet_layers.h"

namespace toond::pipeline {

std::vector<render::PlannedObject> planned_objects(const Request& request, const ObjectPoses& poses) {
  std::vector<render::PlannedObject> planned;
  for (std::size_t i = 0; i < request.objects.size(); ++i) {
    const render::JobObject& o = request.objects[i];
    planned.push_back({*o.model, o.transform, i < poses.size() ? poses[i].get() : nullptr});
  }
  return planned;
}

std::vector<render::FramePlan> plan_frames(const Request& request, const std::vector<ObjectPoses>& poses) {
  return plan_frames(request, poses, request.params, request.layout);
}

std::vector<render::FramePlan> plan_frames(const Request& request, const std::vector<ObjectPoses>& poses,
                                           const render::RenderParams& params,
                                           const std::optional<render::SheetLayout>& layout) {
  const std::vector<render::RenderParams> drawn = drawn_frames(params, layout);
  // Every frame's poses are framed alike (pose.h): one framing for all.
  const auto scene = render::frame_scene_of(planned_objects(request, poses.front()));
  std::vector<render::FramePlan> plans;
  for (const render::Output layer : drawn_layers(params, request.answer.file)) {
    for (std::size_t i = 0; i < drawn.size(); ++i) {
      plans.push_back(
          render::plan_frame(layer_params(drawn[i], layer, params), planned_objects(request, poses[i]), scene));
    }
  }
  return plans;
}

}  // namespace toond::pipeline
