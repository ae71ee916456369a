#include "http/animation_pose.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "request_error.h"
#include "render/sheet_layout.h"
#include "scene/clip_sampling.h"

namespace toond::http {
namespace {

// A pose whose joints or vertices left float range (joints scaled past it)
// cannot be framed or drawn. The clip's framing posed every vertex at many
// times of it, so a clip that throws vertices out of range shows there.
void check_finite(const scene::SkinPose& pose, const scene::Bounds& framing, const std::string& pointer) {
  bool finite = pose.finite();
  for (int axis = 0; axis < 3; ++axis) finite = finite && std::isfinite(framing.min[axis]) && std::isfinite(framing.max[axis]);
  if (!finite) {
    throw RequestError(422, "bad_pose", pointer + ": the clip moves vertices beyond the range of numbers drawn",
                       pointer);
  }
}

// The index of the clip `name` (or `index` >= 0) in the model, or a 422 at
// `pointer` naming the clips there are.
std::size_t find_clip(const scene::Model& model, const std::string& name, int index, const std::string& pointer) {
  if (!model.rig || model.rig->clips.empty()) {
    throw RequestError(422, "unknown_clip", pointer + ": the model has no animation clips", pointer);
  }
  const scene::Rig& rig = *model.rig;
  if (index >= 0) {
    if (static_cast<std::size_t>(index) < rig.clips.size()) return static_cast<std::size_t>(index);
    throw RequestError(422, "unknown_clip",
                       pointer + ": clip " + std::to_string(index) + " does not exist; the model has " +
                           std::to_string(rig.clips.size()) + " (" + rig.clip_names() + ")",
                       pointer);
  }
  if (const std::optional<std::size_t> found = rig.find_clip(name)) return *found;
  throw RequestError(422, "unknown_clip",
                     pointer + ": the model has no clip \"" + name + "\"; its clips are " + rig.clip_names(),
                     pointer);
}

int sheet_clip_frames(const render::SheetClip& clip, const std::string& entry) {
  if (clip.frames && clip.fps) {
    throw RequestError(400, "invalid_parameter", entry + "/fps: give frames or fps, not both", entry + "/fps");
  }
  if (clip.frames) return *clip.frames;
  if (!clip.fps) return 8;
  const double frames = std::max(1.0, std::round(clip.duration * *clip.fps));
  if (frames > 64) {
    throw RequestError(400, "invalid_parameter",
                       entry + "/fps: " + std::to_string(*clip.fps) + " frames a second make " +
                           std::to_string(static_cast<long long>(frames)) + " frames of \"" + clip.name +
                           "\" (" + std::to_string(clip.duration) + " s), more than 64",
                       entry + "/fps");
  }
  return static_cast<int>(frames);
}

// Bounds and extreme points that hold every clip's framing.
scene::ClipFraming framing_of_all(ClipFramings& framings, const render::JobObject& object,
                                  const std::vector<render::SheetClip>& clips) {
  scene::ClipFraming all;
  for (std::size_t c = 0; c < clips.size(); ++c) {
    const std::shared_ptr<const scene::ClipFraming> one = framings.get(object.model_key, *object.model, clips[c].index);
    all.bounds = c == 0 ? one->bounds
                        : scene::Bounds{glm::min(all.bounds.min, one->bounds.min), glm::max(all.bounds.max, one->bounds.max)};
    all.extremes.insert(all.extremes.end(), one->extremes.begin(), one->extremes.end());
  }
  return all;
}

// The model posed at `time` of clip `clip`, framed as `framing` says (a
// whole clip's reach, or a whole sheet's).
std::shared_ptr<const scene::SkinPose> posed_at(const scene::Model& model, std::size_t clip, double time,
                                                const scene::ClipFraming& framing, const std::string& pointer,
                                                scene::Skinning where) {
  const scene::Rig& rig = *model.rig;
  auto posed = std::make_shared<scene::SkinPose>(
      scene::skin_pose(model.mesh, rig, scene::pose_nodes(rig, &rig.clips[clip], time), where));
  check_finite(*posed, framing.bounds, pointer);
  posed->bounds = framing.bounds;
  posed->extremes = framing.extremes;
  return posed;
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
                                                            std::size_t clip) {
  return cached(model_id + "/" + std::to_string(clip),
                [&] { return scene::frame_clip(model.mesh, *model.rig, clip); });
}

std::shared_ptr<const scene::ClipFraming> ClipFramings::rest(const std::string& model_id, const scene::Model& model) {
  return cached(model_id + "/rest", [&] { return scene::frame_rest_pose(model.mesh, *model.rig); });
}

void resolve_sheet_clips(render::RenderJob& job) {
  if (!job.params.sheet || job.params.sheet->clips.empty()) return;
  render::SheetParams& sheet = *job.params.sheet;
  if (!job.params.objects.empty()) {
    throw RequestError(400, "invalid_parameter",
                       "/sheet/animation: a scene of `objects` cannot be animated; give `model`", "/sheet/animation");
  }
  if (job.params.animation) {
    throw RequestError(400, "invalid_parameter",
                       "/animation: an animated sheet takes its clips from sheet.animation; leave `animation` out",
                       "/animation");
  }
  const scene::Model& model = *job.objects.front().model;
  std::size_t frames = 0;
  for (std::size_t i = 0; i < sheet.clips.size(); ++i) {
    render::SheetClip& clip = sheet.clips[i];
    const std::string entry = "/sheet/animation" + (sheet.clip_list ? "/" + std::to_string(i) : std::string());
    clip.index = find_clip(model, clip.clip, clip.clip_index, entry + "/clip");
    clip.name = model.rig->clips[clip.index].name;
    clip.duration = model.rig->clips[clip.index].duration;
    clip.frame_count = sheet_clip_frames(clip, entry);
    frames += static_cast<std::size_t>(clip.frame_count) * sheet.pitches_deg.size() * static_cast<std::size_t>(sheet.frames);
  }
  if (frames > kMaxAnimatedSheetFrames) {
    throw RequestError(400, "invalid_parameter",
                       "/sheet/animation: the sheet would have " + std::to_string(frames) + " frames (clips × pitches × " +
                           "directions × frames per clip), more than " + std::to_string(kMaxAnimatedSheetFrames),
                       "/sheet/animation");
  }
}

bool pose_at_rest(ClipFramings& framings, render::RenderJob& job, scene::Skinning where) {
  bool posed = false;
  for (render::JobObject& object : job.objects) {
    const scene::Model& model = *object.model;
    if (!model.rig || !scene::rest_pose_moves_vertices(*model.rig)) continue;
    const std::shared_ptr<const scene::ClipFraming> framing = framings.rest(object.model_key, model);
    auto pose = std::make_shared<scene::SkinPose>(
        scene::skin_pose(model.mesh, *model.rig, scene::pose_nodes(*model.rig, nullptr, 0.0), where));
    check_finite(*pose, framing->bounds, "/model");
    pose->bounds = framing->bounds;
    pose->extremes = framing->extremes;
    object.pose = std::move(pose);
    posed = true;
  }
  return posed;
}

void pose_for_animation(ClipFramings& framings, render::RenderJob& job, scene::Skinning where) {
  if (!job.params.animation) return;
  if (!job.params.objects.empty()) {
    throw RequestError(400, "invalid_parameter",
                       "/animation: a scene of `objects` cannot be animated; give `model` with `animation`",
                       "/animation");
  }
  render::JobObject& object = job.objects.front();
  const scene::Model& model = *object.model;
  const render::AnimationParams& animation = *job.params.animation;
  const std::size_t clip = find_clip(model, animation.clip, animation.clip_index, "/animation/clip");
  const double time = scene::clip_time(model.rig->clips[clip], animation.time);
  object.pose = posed_at(model, clip, time, *framings.get(object.model_key, model, clip), "/animation/clip", where);
}

std::vector<std::shared_ptr<const scene::SkinPose>> pose_sheet_frames(ClipFramings& framings,
                                                                      render::RenderJob& job,
                                                                      const render::SheetLayout& layout,
                                                                      scene::Skinning where) {
  const render::SheetParams& sheet = *job.params.sheet;
  render::JobObject& object = job.objects.front();
  const scene::Model& model = *object.model;
  const scene::ClipFraming framing = framing_of_all(framings, object, sheet.clips);
  // Every direction of one time shares one pose.
  std::map<std::pair<int, double>, std::shared_ptr<const scene::SkinPose>> by_time;
  std::vector<std::shared_ptr<const scene::SkinPose>> poses;
  for (const render::SheetFrame& frame : layout.frames) {
    auto& pose = by_time[{frame.clip, frame.time}];
    if (!pose) {
      pose = posed_at(model, sheet.clips[static_cast<std::size_t>(frame.clip)].index, frame.time, framing,
                      "/sheet/animation", where);
    }
    poses.push_back(pose);
  }
  object.pose = poses.front();
  return poses;
}

}  // namespace toond::http
