#pragma once
// A rigged model at one time of one clip: its nodes' world matrices, then
// its vertices moved by them (skins and morph targets). Posing runs on the
// CPU once per request, before the render thread sees the job, so every
// pass draws the same posed vertices and none of them needs a variant.
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "scene/model.h"
#include "scene/rig.h"

namespace toond::scene {

// The node hierarchy at one time (clip == nullptr: at rest).
struct NodePose {
  std::vector<glm::dmat4> world;  // per node, the file's world space
  // Per node, morph weights a clip animates; empty where it does not.
  std::vector<std::vector<double>> weights;
};

// `time` is on the clip's loop already (clip_time).
NodePose pose_nodes(const Rig& rig, const Clip* clip, double time);

// The vertex streams of `rest` (a Mesh whose Mesh::motion indexes
// rig.motions) in `pose`, in the mesh's space: what the GPU copy draws
// instead of the rest streams. Topology (indices, levels of detail) is the
// rest mesh's.
struct PosedVertices {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec3> outline_normals;
  std::vector<glm::vec4> tangents;
  Bounds bounds;
  // Points for framing (scene/extreme_points.h): not made by pose_vertices
  // (a request frames by its whole clip: frame_clip).
  std::vector<glm::vec3> extremes;
};

PosedVertices pose_vertices(const Mesh& rest, const Rig& rig, const NodePose& pose);

// Where a clip's poses reach: bounds and extreme points over poses sampled
// at every key time of the clip, at three times evenly between each two
// neighbouring keys and at 120 times evenly over the clip (at most
// kMaxFramingPoses poses, evenly over the clip, where that makes more; a
// mesh of many points gets fewer samples between its keys, down to 16 over
// the clip), padded by half the largest step any point takes from one
// sample to the next. Framing a render by these keeps the camera still from
// one time of the clip to the next.
inline constexpr std::size_t kMaxFramingPoses = 240;
struct ClipFraming {
  Bounds bounds;
  std::vector<glm::vec3> extremes;
  std::size_t poses = 0;  // how many were sampled
};
ClipFraming frame_clip(const Mesh& rest, const Rig& rig, std::size_t clip);

}  // namespace toond::scene
