#include "pipeline/pose.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>

#include "request_error.h"
#include "scene/animation/clip_sampling.h"

namespace toond::pipeline {
namespace {

// A pose whose joints or vertices left float range (joints scaled past it)
// cannot be framed or drawn. The clip's framing posed every vertex at many
// times of it, so a clip that throws vertices out of range shows there.
void check_finite(const scene::SkinPose& pose, const scene::Bounds& framing, const std::string& pointer) {
  bool finite = pose.finite();
  for (int axis = 0; axis < 3; ++axis)
    finite = finite && std::isfinite(framing.min[axis]) && std::isfinite(framing.max[axis]);
  if (!finite) {
    throw RequestError(422, "bad_pose", pointer + ": the clip moves vertices beyond the range of numbers drawn",
                       pointer);
  }
}

// Bounds and extreme points that hold every clip's framing.
scene::ClipFraming framing_of_all(ClipFramings& framings, const render::JobObject& object,
                                  const std::vector<render::SheetClip>& clips) {
  scene::ClipFraming all;
  for (std::size_t c = 0; c < clips.size(); ++c) {
    const std::shared_ptr<const scene::ClipFraming> one =
        framings.get(object.model_key, *object.model, clips[c].index, clips[c].span);
    all.bounds =
        c == 0 ? one->bounds
               : scene::Bounds{glm::min(all.bounds.min, one->bounds.min), glm::max(all.bounds.max, one->bounds.max)};
    all.extremes.insert(all.extremes.end(), one->extremes.begin(), one->extremes.end());
  }
  return all;
}

// The model posed at `time` of clip `clip` (nullptr: its rest pose),
// framed as `framing` says (a whole clip's reach, or a whole sheet's).
std::shared_ptr<const scene::SkinPose> posed_at(const scene::Model& model, const scene::Clip* clip, double time,
                                                const scene::ClipFraming& framing, const std::string& pointer,
                                                scene::Skinning where) {
  const scene::Rig& rig = *model.rig;
  auto posed =
      std::make_shared<scene::SkinPose>(scene::skin_pose(model.mesh, rig, scene::pose_nodes(rig, clip, time), where));
  check_finite(*posed, framing.bounds, pointer);
  posed->bounds = framing.bounds;
  posed->extremes = framing.extremes;
  return posed;
}

// Each object whose model's rest pose moves its vertices, in that pose.
ObjectPoses rest_poses(const Request& request, ClipFramings& framings, scene::Skinning where) {
  ObjectPoses poses;
  for (const render::JobObject& object : request.objects) {
    const scene::Model& model = *object.model;
    if (!model.rig || !scene::rest_pose_moves_vertices(*model.rig)) {
      poses.push_back(nullptr);
      continue;
    }
    poses.push_back(posed_at(model, nullptr, 0.0, *framings.rest(object.model_key, model), "/model", where));
  }
  return poses;
}

// The request's one object at `animation`'s time, counted from the start
// of the clip's span and looped inside it.
ObjectPoses animation_pose(const Request& request, ClipFramings& framings, scene::Skinning where) {
  const render::JobObject& object = request.objects.front();
  const scene::Model& model = *object.model;
  const AnimationClip& resolved = *request.clip;
  const scene::Clip& clip = model.rig->clips[resolved.index];
  const double time = scene::range_time(resolved.span, request.params.animation->time);
  return {posed_at(model, &clip, time, *framings.get(object.model_key, model, resolved.index, resolved.span),
                   "/animation/clip", where)};
}

// An animated sheet's pose of each frame; every direction of one time
// shares one pose.
std::vector<ObjectPoses> sheet_clip_poses(const Request& request, ClipFramings& framings, scene::Skinning where) {
  const render::SheetParams& sheet = *request.params.sheet;
  const render::JobObject& object = request.objects.front();
  const scene::Model& model = *object.model;
  const scene::ClipFraming framing = framing_of_all(framings, object, sheet.clips);
  std::map<std::pair<int, double>, std::shared_ptr<const scene::SkinPose>> by_time;
  std::vector<ObjectPoses> poses;
  for (const render::SheetFrame& frame : request.layout->frames) {
    auto& pose = by_time[{frame.clip, frame.time}];
    if (!pose) {
      const std::size_t clip = sheet.clips[static_cast<std::size_t>(frame.clip)].index;
      pose = posed_at(model, &model.rig->clips[clip], frame.time, framing, "/sheet/animation", where);
    }
    poses.push_back({pose});
  }
  return poses;
}

}  // namespace

template <class Compute>
std::shared_ptr<const scene::ClipFraming> ClipFramings::cached(const std::string& key, Compute compute) {
  {
    std::lock_guard lock(mutex_);
    const auto it = std::find_if(recent_.begin(), recent_.end(), [&](const Entry& e) { return e.first == key; });
    if (it != recent_.end()) {
      recent_.splice(recent_.begin(), recent_, it);
      return recent_.front().second;
    }
  }
  // Computed outside the lock: two requests for the same new clip may both
  // compute it, which costs time but gives the same framing.
  auto framing = std::make_shared<const scene::ClipFraming>(compute());
  std::lock_guard lock(mutex_);
  recent_.emplace_front(key, framing);
  if (recent_.size() > kCapacity) recent_.pop_back();
  return framing;
}

std::shared_ptr<const scene::ClipFraming> ClipFramings::get(const std::string& model_id, const scene::Model& model,
                                                            std::size_t clip, scene::ClipRange range) {
  // The range's exact doubles (shortest round-trip text): two ranges that
  // differ at all are framed apart.
  std::array<char, 64> ends{};
  char* end = std::to_chars(ends.data(), ends.data() + ends.size(), range.start).ptr;
  *end++ = ':';
  end = std::to_chars(end, ends.data() + ends.size(), range.end).ptr;
  return cached(model_id + "/" + std::to_string(clip) + "/" + std::string(ends.data(), end),
                [&] { return scene::frame_clip(model.mesh, *model.rig, clip, range); });
}

std::shared_ptr<const scene::ClipFraming> ClipFramings::rest(const std::string& model_id, const scene::Model& model) {
  return cached(model_id + "/rest", [&] { return scene::frame_rest_pose(model.mesh, *model.rig); });
}

std::vector<ObjectPoses> pose_frames(const Request& request, ClipFramings& framings, scene::Skinning where) {
  if (request.layout && !request.params.sheet->clips.empty()) return sheet_clip_poses(request, framings, where);
  const ObjectPoses poses =
      request.clip ? animation_pose(request, framings, where) : rest_poses(request, framings, where);
  return std::vector<ObjectPoses>(request.layout ? request.layout->frames.size() : 1, poses);
}

}  // namespace toond::pipeline
