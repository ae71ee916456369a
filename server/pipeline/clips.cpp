#include "pipeline/clips.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "request_error.h"

namespace toond::pipeline {
namespace {

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

}  // namespace

void resolve_sheet_clips(render::RenderParams& params, const scene::Model& model) {
  if (!params.sheet || params.sheet->clips.empty()) return;
  render::SheetParams& sheet = *params.sheet;
  if (!params.objects.empty()) {
    throw RequestError(400, "invalid_parameter",
                       "/sheet/animation: a scene of `objects` cannot be animated; give `model`", "/sheet/animation");
  }
  if (params.animation) {
    throw RequestError(400, "invalid_parameter",
                       "/animation: an animated sheet takes its clips from sheet.animation; leave `animation` out",
                       "/animation");
  }
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

std::size_t resolve_animation_clip(const render::RenderParams& params, const scene::Model& model) {
  if (!params.objects.empty()) {
    throw RequestError(400, "invalid_parameter",
                       "/animation: a scene of `objects` cannot be animated; give `model` with `animation`",
                       "/animation");
  }
  const render::AnimationParams& animation = *params.animation;
  return find_clip(model, animation.clip, animation.clip_index, "/animation/clip");
}

}  // namespace toond::pipeline
