#pragma once
// The clips a request names, looked up in its model: `animation.clip`, and
// each clip of an animated sheet (`sheet.animation`), by name, by the part
// after '|', or by index. Resolved before anything is posed or priced, so
// a clip that does not exist is the request's error, named at its field.
#include <cstddef>

#include "render/plan/render_params.h"
#include "scene/mesh/model.h"

namespace toond::pipeline {

// The most frames an animated sheet may have (clips × pitches × directions
// × frames per clip).
inline constexpr std::size_t kMaxAnimatedSheetFrames = 1024;

// Looks each clip of an animated sheet up in `model` and sets its index,
// name, span (its range, or the whole clip), duration and frame count.
// RequestError 422 `unknown_clip` at /sheet/animation[/N]/clip when the
// model has no such clip, 422 `bad_range` at /sheet/animation[/N]/range for
// a range outside the clip, one whose end is not after its start, or a
// range on a model without clips; 400 for a scene of objects
// (`scene_of_objects`), for a top-level `animation` beside it, for frames
// and fps together, and beyond kMaxAnimatedSheetFrames.
void resolve_sheet_clips(render::RenderParams& params, const scene::Model& model);

// `animation`'s clip in `model` and the part of it that plays.
struct AnimationClip {
  std::size_t index = 0;
  scene::ClipRange span;  // animation.range, or the whole clip
};

// RequestError 400 when the request is a scene of objects, 422 (path
// /animation/clip) when the model has no such clip, 422 `bad_range` at
// /animation/range as for a sheet's clip.
AnimationClip resolve_animation_clip(const render::RenderParams& params, const scene::Model& model);

}  // namespace toond::pipeline
