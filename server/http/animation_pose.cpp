#include "http/animation_pose.h"

#include <algorithm>

#include "request_error.h"
#include "scene/clip_sampling.h"

namespace toond::http {
namespace {

std::size_t find_clip(const scene::Model& model, const render::AnimationParams& animation) {
  const std::string pointer = "/animation/clip";
  if (!model.rig || model.rig->clips.empty()) {
    throw RequestError(422, "unknown_clip", pointer + ": the model has no animation clips", pointer);
  }
  const scene::Rig& rig = *model.rig;
  if (animation.clip_index >= 0) {
    if (static_cast<std::size_t>(animation.clip_index) < rig.clips.size()) {
      return static_cast<std::size_t>(animation.clip_index);
    }
    throw RequestError(422, "unknown_clip",
                       pointer + ": clip " + std::to_string(animation.clip_index) + " does not exist; the model has " +
                           std::to_string(rig.clips.size()) + " (" + rig.clip_names() + ")",
                       pointer);
  }
  if (const std::optional<std::size_t> found = rig.find_clip(animation.clip)) return *found;
  throw RequestError(422, "unknown_clip",
                     pointer + ": the model has no clip \"" + animation.clip + "\"; its clips are " + rig.clip_names(),
                     pointer);
}

}  // namespace

std::shared_ptr<const scene::ClipFraming> ClipFramings::get(const std::string& model_id, const scene::Model& model,
                                                            std::size_t clip) {
  const std::string key = model_id + "/" + std::to_string(clip);
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
  auto framing = std::make_shared<const scene::ClipFraming>(scene::frame_clip(model.mesh, *model.rig, clip));
  std::lock_guard lock(mutex_);
  recent_.emplace_front(key, framing);
  if (recent_.size() > kCapacity) recent_.pop_back();
  return framing;
}

void pose_for_animation(ClipFramings& framings, render::RenderJob& job) {
  if (!job.params.animation) return;
  if (!job.params.objects.empty()) {
    throw RequestError(400, "invalid_parameter",
                       "/animation: a scene of `objects` cannot be animated; give `model` with `animation`",
                       "/animation");
  }
  render::JobObject& object = job.objects.front();
  const scene::Model& model = *object.model;
  const std::size_t clip_index = find_clip(model, *job.params.animation);
  const scene::Rig& rig = *model.rig;
  const scene::Clip& clip = rig.clips[clip_index];
  const double time = scene::clip_time(clip, job.params.animation->time);
  auto posed = std::make_shared<scene::PosedVertices>(
      scene::pose_vertices(model.mesh, rig, scene::pose_nodes(rig, &clip, time)));
  const std::shared_ptr<const scene::ClipFraming> framing = framings.get(object.model_key, model, clip_index);
  posed->bounds = framing->bounds;
  posed->extremes = framing->extremes;
  object.pose = std::move(posed);
}

}  // namespace toond::http
