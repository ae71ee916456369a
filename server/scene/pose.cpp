#include "scene/pose.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/clip_sampling.h"
#include "scene/extreme_points.h"
#include "scene/mesh_processing.h"

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

// Each binding joint's matrix from the rest mesh's space to the posed
// mesh's: the file's skinning (joint world · inverse bind) taken from the
// mesh's space and back. At rest it is the identity for a mesh bound as it
// was drawn, so an unanimated vertex stays where the import put it.
std::vector<std::vector<glm::mat4>> joint_matrices(const Rig& rig, const NodePose& rest, const NodePose& pose) {
  const glm::dmat4 mesh_to_file = glm::inverse(rig.file_to_mesh);
  std::vector<std::vector<glm::mat4>> matrices(rig.bindings.size());
  for (std::size_t b = 0; b < rig.bindings.size(); ++b) {
    const Binding& binding = rig.bindings[b];
    // The import baked the mesh's node transform into its positions; the
    // skin works on the mesh's own coordinates, so that is undone first.
    const glm::dmat4 to_local = glm::inverse(rest.world[static_cast<std::size_t>(binding.node)]) * mesh_to_file;
    for (std::size_t j = 0; j < binding.joints.size(); ++j) {
      const glm::dmat4 skin = pose.world[static_cast<std::size_t>(binding.joints[j])] * binding.inverse_binds[j];
      matrices[b].push_back(glm::mat4(rig.file_to_mesh * skin * to_local));
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
    std::vector<double> w = !pose.weights[node].empty()     ? pose.weights[node]
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

PosedVertices pose_vertices(const Mesh& rest, const Rig& rig, const NodePose& pose) {
  const NodePose at_rest = pose_nodes(rig, nullptr, 0.0);
  const std::vector<std::vector<glm::mat4>> joints = joint_matrices(rig, at_rest, pose);
  const std::vector<std::vector<double>> weights = morph_weights(rig, pose);

  PosedVertices out;
  const std::size_t count = rest.positions.size();
  out.positions.resize(count);
  out.normals.resize(count);
  out.outline_normals.resize(count);
  out.tangents.resize(count);
  for (std::size_t v = 0; v < count; ++v) {
    const VertexMotion& motion = rig.motions[rest.motion[v]];
    glm::vec3 position = rest.positions[v];
    glm::vec3 normal = rest.normals[v];
    if (motion.morph_set >= 0) {
      const MorphSet& set = rig.morph_sets[static_cast<std::size_t>(motion.morph_set)];
      const std::vector<double>& w = weights[static_cast<std::size_t>(motion.morph_set)];
      for (std::size_t t = 0; t < set.targets(); ++t) {
        if (w[t] == 0.0) continue;
        const std::size_t at = t * set.vertices + motion.morph_vertex;
        position += static_cast<float>(w[t]) * set.position_deltas[at];
        if (!set.normal_deltas.empty()) normal += static_cast<float>(w[t]) * set.normal_deltas[at];
      }
    }
    glm::mat4 blend(0.0f);
    const std::vector<glm::mat4>& binding = joints[motion.binding];
    for (std::uint32_t k = 0; k < motion.influence_count; ++k) {
      const Influence& influence = rig.influences[motion.first_influence + k];
      blend += influence.weight * binding[influence.joint];
    }
    const glm::mat3 linear(blend);
    const glm::mat3 normal_matrix = cofactor(linear);
    out.positions[v] = glm::vec3(blend * glm::vec4(position, 1.0f));
    out.normals[v] = unit_or(normal_matrix * normal, rest.normals[v]);
    const glm::vec3 outline = rest.outline_normals[v];
    out.outline_normals[v] = unit_or(normal_matrix * outline, out.normals[v]) * glm::length(outline);
    const glm::vec4 tangent = rest.tangents[v];
    const glm::vec3 along = linear * glm::vec3(tangent);
    const glm::vec3 posed_normal = out.normals[v];
    out.tangents[v] =
        glm::vec4(unit_or(along - posed_normal * glm::dot(posed_normal, along), glm::vec3(tangent)), tangent.w);
  }
  out.bounds = compute_bounds(out.positions);
  out.extremes = extreme_points(out.positions);
  return out;
}

namespace {

// The times a clip's framing samples, in order: every key, three times
// evenly between neighbouring keys, and kFramingGrid times evenly over the
// clip (so a long interval is not crossed in four steps); at most
// kMaxFramingPoses, evenly over the clip, where that would be more.
constexpr std::size_t kFramingGrid = 120;

std::vector<double> framing_times(const Clip& clip) {
  std::set<double> keys{0.0, clip.duration};
  for (const Channel& ch : clip.channels) keys.insert(ch.times.begin(), ch.times.end());
  std::set<double> times;
  for (auto it = keys.begin(); it != keys.end(); ++it) {
    if (*it < 0.0 || *it > clip.duration) continue;
    times.insert(*it);
    const auto next = std::next(it);
    if (next == keys.end() || *next > clip.duration) continue;
    for (int k = 1; k <= 3; ++k) times.insert(*it + (*next - *it) * k / 4.0);
  }
  const auto even = [&](std::size_t count) {
    for (std::size_t k = 0; k < count; ++k) {
      times.insert(clip.duration * static_cast<double>(k) / static_cast<double>(count - 1));
    }
  };
  even(kFramingGrid);
  if (times.size() > kMaxFramingPoses) {
    times.clear();
    even(kMaxFramingPoses);
  }
  return {times.begin(), times.end()};
}

}  // namespace

ClipFraming frame_clip(const Mesh& rest, const Rig& rig, std::size_t clip_index) {
  const Clip& clip = rig.clips[clip_index];
  const std::vector<double> times = framing_times(clip);
  std::vector<glm::vec3> reached;  // every pose's extreme points
  std::vector<glm::vec3> corners;  // every pose's box
  std::vector<glm::vec3> previous;
  // Between two samples a vertex strays from both by at most half of its
  // step from one to the other (a turn of less than half a circle), so the
  // largest step halved pads the framing.
  float largest_step = 0;
  for (const double t : times) {
    PosedVertices posed = pose_vertices(rest, rig, pose_nodes(rig, &clip, t));
    reached.insert(reached.end(), posed.extremes.begin(), posed.extremes.end());
    corners.push_back(posed.bounds.min);
    corners.push_back(posed.bounds.max);
    for (std::size_t v = 0; v < previous.size(); ++v) {
      largest_step = std::max(largest_step, glm::length(posed.positions[v] - previous[v]));
    }
    previous = std::move(posed.positions);
  }
  const float margin = largest_step * 0.5f;
  ClipFraming framing;
  framing.poses = times.size();
  framing.margin = margin;
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

}  // namespace toond::scene
