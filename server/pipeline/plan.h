#pragma once
// The pipeline's planning stage: each frame's plan (render/plan/frame_plan.h),
// made once, after posing and before pricing: the price is the plans'
// costs, and the render threads draw what the plans say.
#include <vector>

#include "pipeline/pose.h"
#include "pipeline/request.h"
#include "render/plan/frame_plan.h"

namespace toond::pipeline {

// The request's objects as a plan sees them, in `poses` (pose.h; empty:
// as imported).
std::vector<render::PlannedObject> planned_objects(const Request& request, const ObjectPoses& poses = {});

// Every frame's plan, in layout order (frames.h): its parameters as drawn
// and its poses, all in one framing; a sheet drawn as several layers
// (sheet_layers.h) has them layer after layer, the output's first.
std::vector<render::FramePlan> plan_frames(const Request& request, const std::vector<ObjectPoses>& poses);
// The same for the request's objects and poses drawn with `params` laid
// out as `layout` instead of its own: the price's what-ifs (price.h).
std::vector<render::FramePlan> plan_frames(const Request& request, const std::vector<ObjectPoses>& poses,
                                           const render::RenderParams& params,
                                           const std::optional<render::SheetLayout>& layout);

}  // namespace toond::pipeline
