#pragma once
// The pipeline's posing stage: each frame's pose of each object, worked
// out on the request's thread (the vertex stages, or the render thread's
// cores, move the vertices), each framed by the reach of the clip's part
// that plays (the whole clip, or its range) so that every time of it is
// framed alike. A framing is computed once per model, clip and range, then
// kept.
#include <cstddef>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "pipeline/request.h"
#include "scene/animation/pose.h"

namespace toond::pipeline {

// The framings of recently used clips, by model id, clip index and range,
// and of rest poses (scene::rest_pose_moves_vertices), by model id.
class ClipFramings {
 public:
  static constexpr std::size_t kCapacity = 64;
  std::shared_ptr<const scene::ClipFraming> get(const std::string& model_id, const scene::Model& model,
                                                std::size_t clip, scene::ClipRange range);
  std::shared_ptr<const scene::ClipFraming> rest(const std::string& model_id, const scene::Model& model);

 private:
  template <class Compute>
  std::shared_ptr<const scene::ClipFraming> cached(const std::string& key, Compute compute);
  using Entry = std::pair<std::string, std::shared_ptr<const scene::ClipFraming>>;
  std::mutex mutex_;
  std::list<Entry> recent_;  // most recently used first
};

// One frame's pose of each of the request's objects, in their order; null:
// drawn as imported.
using ObjectPoses = std::vector<std::shared_ptr<const scene::SkinPose>>;

// Every frame's poses, in layout order (a single image: one frame):
// - an animated sheet (resolved clips): its one object at each frame's
//   time of its clip, all framed over every pose of every clip's span of
//   the sheet; the directions of one time share one pose;
// - with `animation` (its clip resolved): its one object at that time,
//   wrapped into the clip's span, every frame alike;
// - otherwise each object whose model's rest pose is not where the import
//   put its vertices (scene::rest_pose_moves_vertices) in that rest pose.
// RequestError 422 bad_pose when a pose leaves float range. `where`: the
// render service's skinning().
std::vector<ObjectPoses> pose_frames(const Request& request, ClipFramings& framings, scene::Skinning where);

}  // namespace toond::pipeline
