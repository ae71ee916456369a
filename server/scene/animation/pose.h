#pragma once
// A rigged model at one time of one clip: its nodes' world matrices, then
// what moves its vertices (skins and morph targets). A render draws a pose
// from a SkinPose: the few matrices and weights of that time, with which
// every vertex stage moves the rest vertices on the GPU
// (shaders/skinning.glsl); or, where the vertex stage is itself the CPU (a
// software rasterizer runs it again for every pass), the vertices posed
// once on the CPU by pose_vertices, the same sum. pose_vertices also frames
// a clip and is the reference the GPU is checked against.
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "scene/animation/clip_sampling.h"
#include "scene/mesh/model.h"
#include "scene/mesh/rig.h"

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
};

PosedVertices pose_vertices(const Mesh& rest, const Rig& rig, const NodePose& pose);

// One pose's sums per motion, what posing a vertex reads: each motion's
// blended joint matrix and its cofactor (normals), each morph set's weights.
struct PoseSums {
  std::vector<glm::mat4> blends;
  std::vector<glm::mat3> normal_matrices;
  std::vector<std::vector<double>> morph_weights;
};
PoseSums pose_sums(const Rig& rig, const NodePose& pose);

// Vertex v of `rest` in the pose (what pose_vertices writes for it);
// without `with_tangent` the tangent is the rest one (a model without
// normal maps never reads it).
struct PosedVertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec3 outline_normal;
  glm::vec4 tangent;
};
PosedVertex pose_vertex(const Mesh& rest, const Rig& rig, const PoseSums& sums, std::size_t v, bool with_tangent);

// Calls pose(first, end) for runs of [0, count) over the cores: posing a
// large mesh is most of a posed request's own work.
void for_each_vertex_run(std::size_t count, const std::function<void(std::size_t first, std::size_t end)>& pose);

// Where each binding's joints start in one list of every binding's joints,
// binding after binding: SkinPose::joints and the GPU's influences index
// that list.
std::vector<std::uint32_t> binding_joint_offsets(const Rig& rig);

// What the GPU needs to draw the rest mesh in a pose: each joint's matrix
// (rest mesh space → posed mesh space) in binding_joint_offsets' order, and
// each morph set's target weights. Bounds and extremes are the framing's,
// set by whoever frames the pose (a whole clip's reach); caps are the
// mesh's hole caps posed on the CPU, per level of detail (full mesh first),
// for the culling decision made before drawing.
struct SkinPose {
  // Set by skin_pose when asked to pose on the CPU: the GPU copy poses its
  // rest vertices with these sums straight into its vertex buffer
  // (render/frame/gpu_model.h), and the vertex stages draw them as they are.
  std::shared_ptr<const PoseSums> cpu_sums;
  std::vector<glm::mat4> joints;
  std::vector<std::vector<float>> morph_weights;
  std::vector<std::vector<glm::vec3>> caps;
  // Where the mesh's parts cross in this pose, per level of detail (full
  // mesh first), found on its vertices posed on the CPU as import finds
  // them at rest (scene/mesh/intersection_lines.h): the seams move as the parts
  // do. Empty for a mesh of one part.
  std::vector<IntersectionLines> intersections;
  Bounds bounds;
  std::vector<glm::vec3> extremes;
  // How much this pose may lengthen any distance on the rest mesh
  // (largest_joint_stretch): a level of detail's error in the pose is at
  // most its error at rest times this.
  double stretch = 1.0;
  // Whether every joint matrix and weight is a finite float: a joint scaled
  // past float range cannot be drawn.
  bool finite() const;
};

// Where a pose's vertices are moved.
enum class Skinning { VertexStage, Cpu };

SkinPose skin_pose(const Mesh& rest, const Rig& rig, const NodePose& pose, Skinning where = Skinning::VertexStage);

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
// The same over `range` of the clip alone (its keys inside the range, the
// range's ends, the grid over the range): a walk cut from a timeline that
// also lies down is framed by the walk.
ClipFraming frame_clip(const Mesh& rest, const Rig& rig, std::size_t clip, ClipRange range);

// Whether the rig's rest pose (glTF's: skinned meshes placed by their
// joints at their nodes' rest transforms, the mesh's default morph
// weights) puts any vertex elsewhere than the import did (it bakes the
// mesh node's transform, which glTF ignores for a skinned mesh, and draws
// morph targets at weight 0). Most exports' rest pose is their bind pose:
// then a render without `animation` needs no pose.
bool rest_pose_moves_vertices(const Rig& rig);

// The bounds and extreme points of the rest pose, for framing it.
ClipFraming frame_rest_pose(const Mesh& rest, const Rig& rig);

}  // namespace toond::scene
