#include "scene/animation/pose.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <functional>
#include <set>
#include <unordered_map>

#include <glm/gtc/matrix_transform.hpp>

#include "parallel/parallel_tasks.h"
#include "scene/animation/clip_sampling.h"
#include "scene/animation/motion_classes.h"
#include "scene/mesh/extreme_points.h"
#include "scene/mesh/intersection_lines.h"
#include "scene/mesh/mesh_processing.h"

namespace toond::scene {
namespace {

struct Trs {
  glm::dvec3 translation;
  glm::dquat rotation;
  glm::dvec3 scale;
};

glm::dmat4 matrix_of(const Trs& trs) {
  return glm::translate(glm::dmat4(1.0), trs.translation) * glm::mat4_cast(trs.rotation) *
         glm::scale(glm::dmat4(1.0), trs.scale);
}

// Each joint's matrix from the rest mesh's space to the posed mesh's, in
// binding_joint_offsets' order: the file's skinning (joint world · inverse
// bind) taken from the mesh's space and back. At rest it is the identity
// for a mesh bound as it was drawn, so an unanimated vertex stays where the
// import put it.
std::vector<glm::mat4> joint_matrices(const Rig& rig, const NodePose& pose) {
  std::vector<glm::mat4> matrices;
  for (const Binding& binding : rig.bindings) {
    for (std::size_t j = 0; j < binding.joints.size(); ++j) {
      const glm::dmat4 skin = pose.world[static_cast<std::size_t>(binding.joints[j])] * binding.inverse_binds[j];
      matrices.push_back(glm::mat4(rig.file_to_mesh * skin * binding.mesh_to_local));
    }
  }
  return matrices;
}

// Per morph set, the weight of each target in this pose: the clip's, else
// the node's, else the mesh's.
std::vector<std::vector<double>> morph_weights(const Rig& rig, const NodePose& pose) {
  std::vector<std::vector<double>> weights;
  for (const MorphSet& set : rig.morph_sets) {
    const auto node = static_cast<std::size_t>(set.node);
    std::vector<double> w = !pose.weights[node].empty()        ? pose.weights[node]
                            : !rig.nodes[node].weights.empty() ? rig.nodes[node].weights
                                                               : set.default_weights;
    w.resize(set.targets(), 0.0);
    weights.push_back(std::move(w));
  }
  return weights;
}

// The columns of M's cofactor matrix: det(M)·M^-T without dividing, so a
// joint scaled to nothing gives a zero normal instead of NaN.
glm::mat3 cofactor(const glm::mat3& m) {
  return {glm::cross(m[1], m[2]), glm::cross(m[2], m[0]), glm::cross(m[0], m[1])};
}

glm::vec3 unit_or(const glm::vec3& v, const glm::vec3& fallback) {
  const float length = glm::length(v);
  return length > 1e-20f && std::isfinite(length) ? v / length : fallback;
}

}  // namespace

NodePose pose_nodes(const Rig& rig, const Clip* clip, double time) {
  std::vector<Trs> local(rig.nodes.size());
  for (std::size_t i = 0; i < rig.nodes.size(); ++i) {
    local[i] = {rig.nodes[i].translation, rig.nodes[i].rotation, rig.nodes[i].scale};
  }
  NodePose pose;
  pose.weights.resize(rig.nodes.size());
  if (clip) {
    std::array<double, 4> value{};
    for (const Channel& ch : clip->channels) {
      const auto node = static_cast<std::size_t>(ch.node);
      if (ch.path == ChannelPath::Weights) {
        pose.weights[node].assign(static_cast<std::size_t>(ch.width), 0.0);
        sample_channel(ch, time, pose.weights[node]);
        continue;
      }
      sample_channel(ch, time, value);
      if (ch.path == ChannelPath::Translation) local[node].translation = {value[0], value[1], value[2]};
      if (ch.path == ChannelPath::Scale) local[node].scale = {value[0], value[1], value[2]};
      if (ch.path == ChannelPath::Rotation) local[node].rotation = glm::dquat(value[3], value[0], value[1], value[2]);
    }
  }
  pose.world.assign(rig.nodes.size(), glm::dmat4(1.0));
  for (const int index : rig.node_order) {
    const auto i = static_cast<std::size_t>(index);
    const RigNode& node = rig.nodes[i];
    const glm::dmat4 own = node.matrix ? *node.matrix : matrix_of(local[i]);
    pose.world[i] = node.parent < 0 ? own : pose.world[static_cast<std::size_t>(node.parent)] * own;
  }
  return pose;
}

namespace {

constexpr std::size_t kPoseRun = 16384;

// One motion's blend of its joints' matrices.
glm::mat4 blend_of(const Rig& rig, const std::vector<glm::mat4>& joints, const std::vector<std::uint32_t>& offsets,
                   const VertexMotion& motion) {
  glm::mat4 blend(0.0f);
  for (std::uint32_t k = 0; k < motion.influence_count; ++k) {
    const Influence& influence = rig.influences[motion.first_influence + k];
    blend += influence.weight * joints[offsets[motion.binding] + influence.joint];
  }
  return blend;
}

// Each motion's blended joint matrix in one pose: vertices that move alike
// share it (a flat-shaded mesh has several vertices per position).
std::vector<glm::mat4> motion_matrices(const Rig& rig, const NodePose& pose) {
  const std::vector<glm::mat4> joints = joint_matrices(rig, pose);
  const std::vector<std::uint32_t> offsets = binding_joint_offsets(rig);
  std::vector<glm::mat4> blends(rig.motions.size());
  for (std::size_t m = 0; m < rig.motions.size(); ++m) blends[m] = blend_of(rig, joints, offsets, rig.motions[m]);
  return blends;
}

// Adds the morph targets' weighted deltas of the vertex's motion; normal
// and tangent only where given.
void add_morphs(const Rig& rig, const std::vector<std::vector<double>>& weights, const VertexMotion& motion,
                glm::vec3& position, glm::vec3* normal = nullptr, glm::vec3* tangent = nullptr) {
  if (motion.morph_set < 0) return;
  const MorphSet& set = rig.morph_sets[static_cast<std::size_t>(motion.morph_set)];
  const std::vector<double>& w = weights[static_cast<std::size_t>(motion.morph_set)];
  for (std::size_t t = 0; t < set.targets(); ++t) {
    if (w[t] == 0.0) continue;
    const std::size_t at = t * set.vertices + motion.morph_vertex;
    const auto weight = static_cast<float>(w[t]);
    position += weight * set.position_deltas[at];
    if (normal && !set.normal_deltas.empty()) *normal += weight * set.normal_deltas[at];
    if (tangent && !set.tangent_deltas.empty()) *tangent += weight * set.tangent_deltas[at];
  }
}

}  // namespace

PoseSums pose_sums(const Rig& rig, const NodePose& pose) {
  PoseSums sums;
  sums.blends = motion_matrices(rig, pose);
  sums.normal_matrices.resize(sums.blends.size());
  for (std::size_t m = 0; m < sums.blends.size(); ++m) sums.normal_matrices[m] = cofactor(glm::mat3(sums.blends[m]));
  sums.morph_weights = morph_weights(rig, pose);
  return sums;
}

PosedVertex pose_vertex(const Mesh& rest, const Rig& rig, const PoseSums& sums, std::size_t v, bool with_tangent) {
  const std::uint32_t m = rest.motion[v];
  glm::vec3 position = rest.positions[v];
  glm::vec3 normal = rest.normals[v];
  const glm::vec4 tangent = rest.tangents[v];
  glm::vec3 tangent_direction(tangent);
  add_morphs(rig, sums.morph_weights, rig.motions[m], position, &normal, &tangent_direction);
  const glm::mat4& blend = sums.blends[m];
  const glm::mat3& normal_matrix = sums.normal_matrices[m];
  PosedVertex out;
  out.position = glm::vec3(blend * glm::vec4(position, 1.0f));
  out.normal = unit_or(normal_matrix * normal, rest.normals[v]);
  const glm::vec3 outline = rest.outline_normals[v];
  out.outline_normal = unit_or(normal_matrix * outline, out.normal) * glm::length(outline);
  if (!with_tangent) {
    out.tangent = tangent;
    return out;
  }
  const glm::vec3 along = glm::mat3(blend) * tangent_direction;
  out.tangent = glm::vec4(unit_or(along - out.normal * glm::dot(out.normal, along), glm::vec3(tangent)), tangent.w);
  return out;
}

void for_each_vertex_run(std::size_t count, const std::function<void(std::size_t first, std::size_t end)>& pose) {
  const int runs = static_cast<int>((count + kPoseRun - 1) / kPoseRun);
  parallel::run_tasks(runs, parallel::hardware_threads(), [&](int run) {
    const std::size_t first = static_cast<std::size_t>(run) * kPoseRun;
    pose(first, std::min(count, first + kPoseRun));
  });
}

PosedVertices pose_vertices(const Mesh& rest, const Rig& rig, const NodePose& pose) {
  const PoseSums sums = pose_sums(rig, pose);
  PosedVertices out;
  const std::size_t count = rest.positions.size();
  out.positions.resize(count);
  out.normals.resize(count);
  out.outline_normals.resize(count);
  out.tangents.resize(count);
  for_each_vertex_run(count, [&](std::size_t first, std::size_t end) {
    for (std::size_t v = first; v < end; ++v) {
      const PosedVertex posed = pose_vertex(rest, rig, sums, v, true);
      out.positions[v] = posed.position;
      out.normals[v] = posed.normal;
      out.outline_normals[v] = posed.outline_normal;
      out.tangents[v] = posed.tangent;
    }
  });
  out.bounds = compute_bounds(out.positions);
  return out;
}

std::vector<std::uint32_t> binding_joint_offsets(const Rig& rig) {
  std::vector<std::uint32_t> offsets;
  std::uint32_t next = 0;
  for (const Binding& binding : rig.bindings) {
    offsets.push_back(next);
    next += static_cast<std::uint32_t>(binding.joints.size());
  }
  return offsets;
}

bool SkinPose::finite() const {
  const auto finite_matrix = [](const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (!std::isfinite(m[c][r])) return false;
    return true;
  };
  const auto finite_weights = [](const std::vector<float>& w) {
    return std::all_of(w.begin(), w.end(), [](float x) { return std::isfinite(x); });
  };
  return std::all_of(joints.begin(), joints.end(), finite_matrix) &&
         std::all_of(morph_weights.begin(), morph_weights.end(), finite_weights);
}

namespace {

// The vertices `indices` names, posed on the CPU (a few: the hole caps).
std::vector<glm::vec3> pose_some(const Mesh& rest, const Rig& rig, const std::vector<glm::mat4>& joints,
                                 const std::vector<std::vector<double>>& weights,
                                 const std::vector<std::uint32_t>& indices) {
  const std::vector<std::uint32_t> offsets = binding_joint_offsets(rig);
  std::vector<glm::vec3> posed;
  posed.reserve(indices.size());
  for (const std::uint32_t v : indices) {
    const VertexMotion& motion = rig.motions[rest.motion[v]];
    glm::vec3 position = rest.positions[v];
    add_morphs(rig, weights, motion, position, nullptr);
    posed.push_back(glm::vec3(blend_of(rig, joints, offsets, motion) * glm::vec4(position, 1.0f)));
  }
  return posed;
}

// Where the parts of `rest` cross in `pose`: every vertex posed (position
// and normal), then searched as import searches the rest mesh.
std::vector<IntersectionLines> posed_intersections(const Mesh& rest, const Rig& rig, const NodePose& pose) {
  const PoseSums sums = pose_sums(rig, pose);
  const std::size_t count = rest.positions.size();
  std::vector<glm::vec3> positions(count), normals(count);
  for_each_vertex_run(count, [&](std::size_t first, std::size_t end) {
    for (std::size_t v = first; v < end; ++v) {
      const PosedVertex posed = pose_vertex(rest, rig, sums, v, false);
      positions[v] = posed.position;
      normals[v] = posed.normal;
    }
  });
  return find_intersection_lines(rest, positions, normals);
}

}  // namespace

SkinPose skin_pose(const Mesh& rest, const Rig& rig, const NodePose& pose, Skinning where) {
  SkinPose out;
  if (where == Skinning::Cpu) out.cpu_sums = std::make_shared<const PoseSums>(pose_sums(rig, pose));
  out.joints = joint_matrices(rig, pose);
  out.stretch = largest_joint_stretch(out.joints);
  const std::vector<std::vector<double>> weights = morph_weights(rig, pose);
  for (const std::vector<double>& w : weights) out.morph_weights.emplace_back(w.begin(), w.end());
  out.caps.push_back(pose_some(rest, rig, out.joints, weights, rest.cap_indices));
  for (const MeshLod& lod : rest.lods) out.caps.push_back(pose_some(rest, rig, out.joints, weights, lod.cap_indices));
  if (rest.parts > 1) out.intersections = posed_intersections(rest, rig, pose);
  out.bounds = rest.bounds;
  out.extremes = rest.extremes;
  return out;
}

namespace {

// The times a clip's framing samples over `range`, in order: every key in
// it, three times evenly between neighbouring keys, and kFramingGrid times
// evenly over the range (so a long interval is not crossed in four steps);
// at most kMaxFramingPoses, evenly over the range, where that would be
// more.
constexpr std::size_t kFramingGrid = 120;

// Poses × points a framing may evaluate: a mesh of many points is sampled
// at fewer times between its keys (down to 16 over the clip), each padded
// by the larger step that leaves.
constexpr std::size_t kFramingPointBudget = 2'000'000;

std::vector<double> framing_times(const Clip& clip, ClipRange range, std::size_t points) {
  const std::size_t affordable = kFramingPointBudget / std::max<std::size_t>(points, 1);
  std::set<double> keys{range.start, range.end};
  for (const Channel& ch : clip.channels) keys.insert(ch.times.begin(), ch.times.end());
  std::set<double> times;
  for (auto it = keys.begin(); it != keys.end(); ++it) {
    if (*it < range.start || *it > range.end) continue;
    times.insert(*it);
    const auto next = std::next(it);
    if (next == keys.end() || *next > range.end) continue;
    if (affordable >= 4 * keys.size()) {
      for (int k = 1; k <= 3; ++k) times.insert(*it + (*next - *it) * k / 4.0);
    }
  }
  const auto even = [&](std::size_t count) {
    for (std::size_t k = 0; k < count; ++k) {
      times.insert(range.start + (range.end - range.start) * static_cast<double>(k) / static_cast<double>(count - 1));
    }
  };
  even(std::clamp<std::size_t>(affordable, 16, kFramingGrid));
  if (times.size() > kMaxFramingPoses) {
    times.clear();
    even(kMaxFramingPoses);
  }
  return {times.begin(), times.end()};
}

// The distinct (position, motion) pairs of a mesh: what framing poses (a
// flat-shaded mesh repeats each position for every face around it).
struct FramingPoints {
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> motions;
};

FramingPoints framing_points(const Mesh& rest) {
  FramingPoints points;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> seen;  // hash → indices into points
  for (std::size_t v = 0; v < rest.positions.size(); ++v) {
    const glm::vec3& p = rest.positions[v];
    const std::uint64_t key = (std::uint64_t{std::bit_cast<std::uint32_t>(p.x)} * 0x9E3779B97F4A7C15ull) ^
                              (std::uint64_t{std::bit_cast<std::uint32_t>(p.y)} * 0xC2B2AE3D27D4EB4Full) ^
                              (std::uint64_t{std::bit_cast<std::uint32_t>(p.z)} * 0x165667B19E3779F9ull) ^
                              rest.motion[v];
    std::vector<std::uint32_t>& same = seen[key];
    const bool known = std::any_of(same.begin(), same.end(), [&](std::uint32_t i) {
      return points.positions[i] == p && points.motions[i] == rest.motion[v];
    });
    if (known) continue;
    same.push_back(static_cast<std::uint32_t>(points.positions.size()));
    points.positions.push_back(p);
    points.motions.push_back(rest.motion[v]);
  }
  return points;
}

std::vector<glm::vec3> pose_points(const FramingPoints& points, const Rig& rig, const NodePose& pose) {
  const std::vector<glm::mat4> blends = motion_matrices(rig, pose);
  const std::vector<std::vector<double>> weights = morph_weights(rig, pose);
  std::vector<glm::vec3> posed(points.positions.size());
  for (std::size_t i = 0; i < posed.size(); ++i) {
    glm::vec3 position = points.positions[i];
    add_morphs(rig, weights, rig.motions[points.motions[i]], position, nullptr);
    posed[i] = glm::vec3(blends[points.motions[i]] * glm::vec4(position, 1.0f));
  }
  return posed;
}

}  // namespace

ClipFraming frame_clip(const Mesh& rest, const Rig& rig, std::size_t clip_index) {
  return frame_clip(rest, rig, clip_index, whole_clip(rig.clips[clip_index]));
}

ClipFraming frame_clip(const Mesh& rest, const Rig& rig, std::size_t clip_index, ClipRange range) {
  const Clip& clip = rig.clips[clip_index];
  const FramingPoints points = framing_points(rest);
  const std::vector<double> times = framing_times(clip, range, points.positions.size());
  // Each sample's extreme points, box and the largest step any point took
  // from the sample before: samples are posed over the cores, each run
  // posing the sample before its first once more.
  struct Sampled {
    std::vector<glm::vec3> extremes;
    Bounds bounds;
    float step = 0;
  };
  std::vector<Sampled> sampled(times.size());
  const int threads = parallel::hardware_threads();
  const std::size_t per_run =
      (times.size() + static_cast<std::size_t>(threads) - 1) / static_cast<std::size_t>(threads);
  parallel::run_tasks(threads, threads, [&](int run) {
    const std::size_t first = static_cast<std::size_t>(run) * per_run;
    const std::size_t end = std::min(times.size(), first + per_run);
    std::vector<glm::vec3> previous;
    if (first > 0 && first < end) previous = pose_points(points, rig, pose_nodes(rig, &clip, times[first - 1]));
    for (std::size_t i = first; i < end; ++i) {
      std::vector<glm::vec3> posed = pose_points(points, rig, pose_nodes(rig, &clip, times[i]));
      sampled[i].extremes = extreme_points(posed);
      sampled[i].bounds = compute_bounds(posed);
      for (std::size_t v = 0; v < previous.size(); ++v) {
        sampled[i].step = std::max(sampled[i].step, glm::length(posed[v] - previous[v]));
      }
      previous = std::move(posed);
    }
  });
  std::vector<glm::vec3> reached;  // every pose's extreme points
  std::vector<glm::vec3> corners;  // every pose's box
  // Between two samples a point strays from both by at most half of its
  // step from one to the other (a turn of less than half a circle), so the
  // largest step halved pads the framing.
  float largest_step = 0;
  for (const Sampled& s : sampled) {
    reached.insert(reached.end(), s.extremes.begin(), s.extremes.end());
    corners.push_back(s.bounds.min);
    corners.push_back(s.bounds.max);
    largest_step = std::max(largest_step, s.step);
  }
  const float margin = largest_step * 0.5f;
  ClipFraming framing;
  framing.poses = times.size();
  framing.bounds = compute_bounds(corners);
  framing.bounds.min -= glm::vec3(margin);
  framing.bounds.max += glm::vec3(margin);
  for (const glm::vec3& p : extreme_points(reached)) {
    framing.extremes.push_back(p);
    if (margin == 0.0f) continue;
    for (int axis = 0; axis < 3; ++axis) {
      for (const float side : {-margin, margin}) {
        glm::vec3 padded = p;
        padded[axis] += side;
        framing.extremes.push_back(padded);
      }
    }
  }
  return framing;
}

bool rest_pose_moves_vertices(const Rig& rig) {
  const NodePose rest = pose_nodes(rig, nullptr, 0.0);
  // A joint matrix is the identity up to float rounding of the products
  // that make it (each entry about 1e-7 of the matrix's scale).
  constexpr float kTolerance = 1e-5f;
  for (const glm::mat4& m : joint_matrices(rig, rest)) {
    float scale = 0;
    for (int c = 0; c < 4; ++c) scale = std::max(scale, glm::length(m[c]));
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) {
        const float identity = c == r ? 1.0f : 0.0f;
        if (!(std::abs(m[c][r] - identity) <= kTolerance * std::max(scale, 1.0f))) return true;
      }
    }
  }
  for (const std::vector<double>& weights : morph_weights(rig, rest)) {
    if (std::any_of(weights.begin(), weights.end(), [](double w) { return w != 0.0; })) return true;
  }
  return false;
}

ClipFraming frame_rest_pose(const Mesh& rest, const Rig& rig) {
  const FramingPoints points = framing_points(rest);
  const std::vector<glm::vec3> posed = pose_points(points, rig, pose_nodes(rig, nullptr, 0.0));
  ClipFraming framing;
  framing.poses = 1;
  framing.bounds = compute_bounds(posed);
  framing.extremes = extreme_points(posed);
  return framing;
}

}  // namespace toond::scene
