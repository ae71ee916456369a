#pragma once
// A request's `animation` applied to its model: the clip looked up (by
// name, by the part after '|', or by index), the time wrapped onto the
// clip's loop, the pose's joints and weights worked out on the request's
// thread (the vertex stages move the vertices), and the whole
// clip's framing (computed once per model and clip, then kept) put on the
// pose so that every time of one clip is framed alike.
#include <cstddef>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <utility>

#include "render/render_service.h"
#include "render/sheet_layout.h"
#include "scene/pose.h"

namespace toond::http {

// The framings of recently used clips, by model id and clip index, and of
// rest poses (scene::rest_pose_moves_vertices), by model id.
class ClipFramings {
 public:
  static constexpr std::size_t kCapacity = 64;
  std::shared_ptr<const scene::ClipFraming> get(const std::string& model_id, const scene::Model& model,
                                                std::size_t clip);
  std::shared_ptr<const scene::ClipFraming> rest(const std::string& model_id, const scene::Model& model);

 private:
  template <class Compute>
  std::shared_ptr<const scene::ClipFraming> cached(const std::string& key, Compute compute);
  using Entry = std::pair<std::string, std::shared_ptr<const scene::ClipFraming>>;
  std::mutex mutex_;
  std::list<Entry> recent_;  // most recently used first
};

// The most frames an animated sheet may have (clips × pitches × directions
// × frames per clip).
inline constexpr std::size_t kMaxAnimatedSheetFrames = 1024;

// Looks each clip of an animated sheet (`sheet.animation`) up in the job's
// model and sets its index, name, duration and frame count. RequestError
// 422 `unknown_clip` at /sheet/animation[/N]/clip when the model has no
// such clip; 400 for a scene of objects, for a top-level `animation` beside
// it, for frames and fps together, and beyond kMaxAnimatedSheetFrames.
void resolve_sheet_clips(render::RenderJob& job);

// Poses each object whose model's rest pose is not where the import put
// its vertices (scene::rest_pose_moves_vertices) in that rest pose, framed
// by it: a render without `animation`. Returns whether any was posed.
bool pose_at_rest(ClipFramings& framings, render::RenderJob& job, scene::Skinning where);

// Poses the job's one object as job.params.animation asks (nothing when it
// asks nothing). RequestError 400 when the job is a scene of objects, 422
// (path /animation/clip) when the model has no such clip, 422 bad_pose
// when the pose leaves float range.
// `where`: the render service's skinning().
void pose_for_animation(ClipFramings& framings, render::RenderJob& job, scene::Skinning where);

// An animated sheet's (resolved clips, laid out as `layout`) pose of each
// frame, by frame index, all framed over every pose of every clip of the
// sheet. The object itself gets the first frame's, whose framing the atlas
// then uses.
std::vector<std::shared_ptr<const scene::SkinPose>> pose_sheet_frames(ClipFramings& framings,
                                                                      render::RenderJob& job,
                                                                      const render::SheetLayout& layout,
                                                                      scene::Skinning where);

}  // namespace toond::http
