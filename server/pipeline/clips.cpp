#include "pipeline/clips.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "request_error.h"
#include "scene/animation/clip_sampling.h"

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
                     pointer + ": the model has no clip \"" + name + "\"; its clips are " + rig.clip_names(), pointer);
}

// Seconds as a message shows them.
std::string seconds(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

// How far past either end of its clip a range may reach and still be taken
// as that end: rounded figures (3.6667 for 220 frames at 60 a second), well
// under any file's frame.
constexpr double kRangeSlack = 0.0005;

// A range on a model that has no clips: the field at fault is the range.
void check_model_has_clips(const scene::Model& model, const std::string& pointer) {
  if (model.rig && !model.rig->clips.empty()) return;
  throw RequestError(422, "bad_range", pointer + ": the model has no animation clips to take a range of", pointer);
}

// `range` held to `clip`: 0 <= start < end <= duration, ends within
// kRangeSlack of the clip's moved onto them. 422 `bad_range` at `pointer`.
scene::ClipRange checked_range(const scene::Clip& clip, scene::ClipRange range, const std::string& pointer) {
  const std::string clip_span = "clip \"" + clip.name + "\" runs from 0 to " + seconds(clip.duration) + " s";
  const std::string asked = "[" + seconds(range.start) + ", " + seconds(range.end) + "]";
  if (!(range.end > range.start)) {
    throw RequestError(422, "bad_range",
                       pointer + ": " + asked + " ends where it starts or before; the end must be later", pointer);
  }
  if (range.start < -kRangeSlack || range.end > clip.duration + kRangeSlack) {
    throw RequestError(422, "bad_range", pointer + ": " + asked + " reaches outside the clip: " + clip_span, pointer);
  }
  range.start = std::max(range.start, 0.0);
  range.end = std::min(range.end, clip.duration);
  if (!(range.end > range.start)) {
    throw RequestError(422, "bad_range", pointer + ": " + asked + " has no length inside the clip: " + clip_span,
                       pointer);
  }
  return range;
}

// The frames of a sheet's clip: `frames`, or its span at `fps` (a loop's
// end left out, a one-shot's included), or 8.
int sheet_clip_frames(const render::SheetClip& clip, const std::string& entry) {
  if (clip.frames && clip.fps) {
    throw RequestError(400, "invalid_parameter", entry + "/fps: give frames or fps, not both", entry + "/fps");
  }
  if (clip.frames) return *clip.frames;
  if (!clip.fps) return 8;
  const double frames = std::max(1.0, std::round(clip.duration * *clip.fps)) + (clip.loop ? 0.0 : 1.0);
  if (frames > 64) {
    throw RequestError(400, "invalid_parameter",
                       entry + "/fps: " + std::to_string(*clip.fps) + " frames a second make " +
                           std::to_string(static_cast<long long>(frames)) + " frames of \"" + clip.name + "\" (" +
                           std::to_string(clip.duration) + " s), more than 64",
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
    if (clip.range) check_model_has_clips(model, entry + "/range");
    clip.index = find_clip(model, clip.clip, clip.clip_index, entry + "/clip");
    const scene::Clip& found = model.rig->clips[clip.index];
    clip.name = found.name;
    clip.span = clip.range ? checked_range(found, *clip.range, entry + "/range") : scene::whole_clip(found);
    clip.duration = clip.span.end - clip.span.start;
    clip.frame_count = sheet_clip_frames(clip, entry);
    frames +=
        static_cast<std::size_t>(clip.frame_count) * sheet.pitches_deg.size() * static_cast<std::size_t>(sheet.frames);
  }
  if (frames > kMaxAnimatedSheetFrames) {
    throw RequestError(400, "invalid_parameter",
                       "/sheet/animation: the sheet would have " + std::to_string(frames) +
                           " frames (clips × pitches × " + "directions × frames per clip), more than " +
                           std::to_string(kMaxAnimatedSheetFrames),
                       "/sheet/animation");
  }
}

AnimationClip resolve_animation_clip(const render::RenderParams& params, const scene::Model& model) {
  if (!params.objects.empty()) {
    throw RequestError(400, "invalid_parameter",
                       "/animation: a scene of `objects` cannot be animated; give `model` with `animation`",
                       "/animation");
  }
  const render::AnimationParams& animation = *params.animation;
  if (animation.range) check_model_has_clips(model, "/animation/range");
  AnimationClip resolved;
  resolved.index = find_clip(model, animation.clip, animation.clip_index, "/animation/clip");
  const scene::Clip& clip = model.rig->clips[resolved.index];
  resolved.span = animation.range ? checked_range(clip, *animation.range, "/animation/range") : scene::whole_clip(clip);
  return resolved;
}

}  // namespace toond::pipeline
