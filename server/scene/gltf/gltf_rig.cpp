#include "scene/gltf/gltf_rig.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/animation/pose.h"
#include "scene/reading/import_error.h"

namespace toond::scene {
namespace {

bool all_finite(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

std::optional<ChannelPath> path_of(const std::string& path) {
  if (path == "translation") return ChannelPath::Translation;
  if (path == "rotation") return ChannelPath::Rotation;
  if (path == "scale") return ChannelPath::Scale;
  if (path == "weights") return ChannelPath::Weights;
  return std::nullopt;
}

std::optional<Interpolation> interpolation_of(const std::string& name) {
  if (name.empty() || name == "LINEAR") return Interpolation::Linear;
  if (name == "STEP") return Interpolation::Step;
  if (name == "CUBICSPLINE") return Interpolation::CubicSpline;
  return std::nullopt;
}

std::size_t morph_targets_of(const tinygltf::Mesh& mesh) {
  std::size_t targets = mesh.weights.size();
  for (const auto& primitive : mesh.primitives) targets = std::max(targets, primitive.targets.size());
  return targets;
}

// A joint index as the file gives it, for a message: a whole number as
// such, anything else (a fraction, NaN, a float past any integer) as %g
// writes it, never cast to an integer it does not fit.
std::string joint_text(double joint) {
  if (std::isfinite(joint) && std::abs(joint) < 1e15 && joint == std::floor(joint)) {
    return std::to_string(static_cast<long long>(joint));
  }
  char text[32];
  std::snprintf(text, sizeof text, "%g", joint);
  return text;
}

}  // namespace

GltfRigReader::GltfRigReader(const tinygltf::Model& gltf, const GltfAccessorReader& reader, std::string file,
                             const std::vector<bool>& drawn_nodes, const glm::dmat3& turn, ImportWarnings& warnings)
    : gltf_(gltf), reader_(reader), file_(std::move(file)), turn_(turn), warnings_(warnings) {
  moves_ = !gltf_.animations.empty();
  for (std::size_t i = 0; i < gltf_.nodes.size() && i < drawn_nodes.size(); ++i) {
    const tinygltf::Node& node = gltf_.nodes[i];
    if (!drawn_nodes[i] || node.mesh < 0 || static_cast<std::size_t>(node.mesh) >= gltf_.meshes.size()) continue;
    if (node.skin >= 0 || morph_targets_of(gltf_.meshes[static_cast<std::size_t>(node.mesh)]) > 0) moves_ = true;
  }
  if (!moves_) return;
  read_nodes();
  check_skins_are_drawn(drawn_nodes);
}

void GltfRigReader::fail(const std::string& message) const { throw ImportError(file_, file_ + ": " + message); }

// Accessor `index` read as `components` per element, once its declared
// count is known to be `expected`: an accessor without a buffer view reads
// as zeros, as many as it declares, so a count is checked before reading.
std::vector<double> GltfRigReader::read_counted(int index, const std::string& role, int components,
                                                std::size_t expected) const {
  const std::size_t declared = reader_.accessor(index, role).count;
  if (declared != expected) {
    fail(role + " has " + std::to_string(declared) + " elements where " + std::to_string(expected) + " are needed");
  }
  return reader_.read(index, role, components);
}

// Parents from the children lists, checked to form a forest; the order
// world matrices are computed in (parents first); the rest pose.
void GltfRigReader::read_nodes() {
  const std::size_t count = gltf_.nodes.size();
  rig_.nodes.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const tinygltf::Node& node = gltf_.nodes[i];
    RigNode& out = rig_.nodes[i];
    if (node.matrix.size() == 16) out.matrix = glm::make_mat4(node.matrix.data());
    if (node.translation.size() == 3) out.translation = glm::make_vec3(node.translation.data());
    if (node.rotation.size() == 4) {
      out.rotation = glm::normalize(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
    }
    if (node.scale.size() == 3) out.scale = glm::make_vec3(node.scale.data());
    out.weights = node.weights;
    for (const int child : node.children) {
      if (child < 0 || static_cast<std::size_t>(child) >= count) {
        fail("node " + std::to_string(i) + " has the child " + std::to_string(child) + ", which does not exist");
      }
      RigNode& c = rig_.nodes[static_cast<std::size_t>(child)];
      if (c.parent >= 0 || static_cast<std::size_t>(child) == i) {
        fail("node " + std::to_string(child) +
             " has two parents or is its own ancestor: a rigged model's nodes must form a tree");
      }
      c.parent = static_cast<int>(i);
    }
  }
  // Depth first from every root; a node not reached sits on a cycle.
  std::vector<std::vector<int>> children(count);
  for (std::size_t i = 0; i < count; ++i) {
    if (rig_.nodes[i].parent >= 0)
      children[static_cast<std::size_t>(rig_.nodes[i].parent)].push_back(static_cast<int>(i));
  }
  std::vector<int> stack;
  for (std::size_t i = count; i-- > 0;) {
    if (rig_.nodes[i].parent < 0) stack.push_back(static_cast<int>(i));
  }
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    rig_.node_order.push_back(n);
    for (auto it = children[static_cast<std::size_t>(n)].rbegin(); it != children[static_cast<std::size_t>(n)].rend();
         ++it) {
      stack.push_back(*it);
    }
  }
  if (rig_.node_order.size() != count) {
    std::vector<bool> reached(count, false);
    for (const int n : rig_.node_order) reached[static_cast<std::size_t>(n)] = true;
    const auto first = std::find(reached.begin(), reached.end(), false) - reached.begin();
    fail("the node hierarchy has a cycle through node " + std::to_string(first) +
         ": a rigged model's nodes must form a tree");
  }
  rest_world_ = pose_nodes(rig_, nullptr, 0.0).world;
}

void GltfRigReader::check_skins_are_drawn(const std::vector<bool>& drawn_nodes) const {
  for (std::size_t s = 0; s < gltf_.skins.size(); ++s) {
    const tinygltf::Skin& skin = gltf_.skins[s];
    if (skin.joints.empty()) fail("skin " + std::to_string(s) + " has no joints");
    for (std::size_t j = 0; j < skin.joints.size(); ++j) {
      const int node = skin.joints[j];
      if (node < 0 || static_cast<std::size_t>(node) >= gltf_.nodes.size()) {
        fail("skin " + std::to_string(s) + " joint " + std::to_string(j) + " is node " + std::to_string(node) +
             ", which does not exist");
      }
      if (static_cast<std::size_t>(node) >= drawn_nodes.size() || !drawn_nodes[static_cast<std::size_t>(node)]) {
        fail("skin " + std::to_string(s) + " joint " + std::to_string(j) + " (node " + std::to_string(node) +
             ") is not in the scene that is drawn");
      }
    }
  }
}

std::uint32_t GltfRigReader::binding_of(int skin, int node) {
  const auto [it, added] = bindings_.try_emplace({skin, node}, static_cast<std::uint32_t>(rig_.bindings.size()));
  if (!added) return it->second;
  Binding binding;
  binding.node = node;
  if (skin < 0) {
    // Moved by its own node alone: rigid node animation.
    binding.joints = {node};
    binding.inverse_binds = {glm::dmat4(1.0)};
  } else {
    const tinygltf::Skin& s = gltf_.skins[static_cast<std::size_t>(skin)];
    binding.joints = s.joints;
    binding.inverse_binds.assign(s.joints.size(), glm::dmat4(1.0));
    if (s.inverseBindMatrices >= 0) {
      const std::string role = "skin " + std::to_string(skin) + " inverseBindMatrices";
      const std::vector<double> m = read_counted(s.inverseBindMatrices, role, 16, s.joints.size());
      if (m.size() != 16 * s.joints.size()) {
        fail(role + " has " + std::to_string(m.size() / 16) + " matrices for " + std::to_string(s.joints.size()) +
             " joints");
      }
      if (!all_finite(m)) fail(role + " holds a number that is not finite");
      for (std::size_t j = 0; j < s.joints.size(); ++j) binding.inverse_binds[j] = glm::make_mat4(m.data() + 16 * j);
    }
  }
  rig_.bindings.push_back(std::move(binding));
  return it->second;
}

// Every JOINTS_n / WEIGHTS_n pair, four influences each: `joints` gets the
// joint indices, the result the weights, `sets` how many pairs there were.
std::vector<double> GltfRigReader::read_weights_of(int node, const tinygltf::Primitive& primitive, std::size_t count,
                                                   const std::string& name, std::vector<double>& joints, int& sets) {
  const std::size_t joint_count =
      gltf_.skins[static_cast<std::size_t>(gltf_.nodes[static_cast<std::size_t>(node)].skin)].joints.size();
  std::vector<double> weights;
  for (sets = 0;; ++sets) {
    const auto j = primitive.attributes.find("JOINTS_" + std::to_string(sets));
    const auto w = primitive.attributes.find("WEIGHTS_" + std::to_string(sets));
    if (j == primitive.attributes.end() || w == primitive.attributes.end()) break;
    const std::string joints_role = name + " JOINTS_" + std::to_string(sets);
    std::vector<double> js = read_counted(j->second, joints_role, 4, count);
    std::vector<double> ws = read_counted(w->second, name + " WEIGHTS_" + std::to_string(sets), 4, count);
    if (js.size() != 4 * count || ws.size() != 4 * count) {
      fail(name + " has " + std::to_string(std::min(js.size(), ws.size()) / 4) + " joint influences for " +
           std::to_string(count) + " positions");
    }
    for (const double joint : js) {
      if (!(joint >= 0.0) || joint >= static_cast<double>(joint_count)) {
        fail(joints_role + " names joint " + joint_text(joint) + ", past the skin's " + std::to_string(joint_count) +
             " joints");
      }
    }
    for (const double weight : ws) {
      if (!std::isfinite(weight) || weight < 0.0)
        fail(name + " WEIGHTS_" + std::to_string(sets) + " holds a weight that is negative or not finite");
    }
    joints.insert(joints.end(), js.begin(), js.end());
    weights.insert(weights.end(), ws.begin(), ws.end());
  }
  if (sets == 0) fail(name + " is drawn by a skinned node but has no JOINTS_0 and WEIGHTS_0");
  return weights;
}

std::int32_t GltfRigReader::morph_set_of(int node, const tinygltf::Primitive& primitive, std::size_t count,
                                         const std::string& name) {
  if (primitive.targets.empty()) return -1;
  const tinygltf::Mesh& mesh = gltf_.meshes[static_cast<std::size_t>(gltf_.nodes[static_cast<std::size_t>(node)].mesh)];
  MorphSet set;
  set.node = node;
  set.vertices = count;
  // Deltas for the primitive's own targets only: a mesh may list more
  // weights than its primitives have targets.
  set.default_weights = mesh.weights;
  set.default_weights.resize(primitive.targets.size(), 0.0);
  // Deltas are in the mesh's own coordinates: the node's rest transform
  // and the upload's turn take them to the mesh's space.
  const glm::dmat3 linear = turn_ * glm::dmat3(rest_world_[static_cast<std::size_t>(node)]);
  const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
  set.position_deltas.assign(set.targets() * count, glm::vec3(0.0f));
  const auto any_target_has = [&](const char* attribute) {
    return std::any_of(primitive.targets.begin(), primitive.targets.end(),
                       [&](const auto& target) { return target.count(attribute) > 0; });
  };
  if (any_target_has("NORMAL")) set.normal_deltas.assign(set.targets() * count, glm::vec3(0.0f));
  if (any_target_has("TANGENT")) set.tangent_deltas.assign(set.targets() * count, glm::vec3(0.0f));
  for (std::size_t t = 0; t < primitive.targets.size(); ++t) {
    const auto read = [&](const char* attribute, std::vector<glm::vec3>& into, const glm::dmat3& by) {
      const auto it = primitive.targets[t].find(attribute);
      if (it == primitive.targets[t].end()) return;
      const std::string role = name + " target " + std::to_string(t) + " " + attribute;
      const std::vector<double> d = read_counted(it->second, role, 3, count);
      if (d.size() != 3 * count)
        fail(role + " has " + std::to_string(d.size() / 3) + " deltas for " + std::to_string(count) + " positions");
      if (!all_finite(d)) fail(role + " holds a number that is not finite");
      for (std::size_t v = 0; v < count; ++v)
        into[t * count + v] = glm::vec3(by * glm::dvec3(d[3 * v], d[3 * v + 1], d[3 * v + 2]));
    };
    read("POSITION", set.position_deltas, linear);
    read("NORMAL", set.normal_deltas, normal_matrix);
    // A tangent lies in the surface: it turns as positions do.
    read("TANGENT", set.tangent_deltas, linear);
  }
  if (meshes_with_targets_.insert(gltf_.nodes[static_cast<std::size_t>(node)].mesh).second) {
    rig_.morph_target_count += set.targets();
  }
  rig_.morph_sets.push_back(std::move(set));
  return static_cast<std::int32_t>(rig_.morph_sets.size() - 1);
}

std::vector<std::uint32_t> GltfRigReader::motions_of(int node, const tinygltf::Primitive& primitive, std::size_t count,
                                                     const std::string& name) {
  const int skin = gltf_.nodes[static_cast<std::size_t>(node)].skin;
  if (skin >= 0 && static_cast<std::size_t>(skin) >= gltf_.skins.size()) {
    fail("node " + std::to_string(node) + " refers to skin " + std::to_string(skin) + ", which does not exist");
  }
  const std::uint32_t binding = binding_of(skin, node);
  std::vector<double> joints;
  int sets = 0;
  const std::vector<double> weights =
      skin >= 0 ? read_weights_of(node, primitive, count, name, joints, sets) : std::vector<double>{};
  const std::int32_t morph = morph_set_of(node, primitive, count, name);
  std::size_t unweighted = 0;
  std::vector<std::uint32_t> motions(count);
  for (std::size_t v = 0; v < count; ++v) {
    std::vector<std::uint64_t> influences;
    if (skin < 0) {
      influences.push_back(std::uint64_t{std::bit_cast<std::uint32_t>(1.0f)});
    } else {
      // The weights of every set, summed per joint and normalised.
      std::map<std::uint32_t, double> by_joint;
      double sum = 0;
      for (int s = 0; s < sets; ++s) {
        for (int k = 0; k < 4; ++k) {
          const std::size_t at = (static_cast<std::size_t>(s) * count + v) * 4 + static_cast<std::size_t>(k);
          if (weights[at] == 0.0) continue;
          by_joint[static_cast<std::uint32_t>(joints[at])] += weights[at];
          sum += weights[at];
        }
      }
      if (!(sum > 0.0)) {
        ++unweighted;
        by_joint = {{0u, 1.0}};
        sum = 1.0;
      }
      for (const auto& [joint, weight] : by_joint) {
        influences.push_back(std::uint64_t{joint} << 32 |
                             std::bit_cast<std::uint32_t>(static_cast<float>(weight / sum)));
      }
    }
    const MotionKey key{binding, influences, morph, morph >= 0 ? static_cast<std::uint32_t>(v) : 0u};
    const auto [it, added] = motion_ids_.try_emplace(key, static_cast<std::uint32_t>(rig_.motions.size()));
    if (added) {
      VertexMotion motion{binding, static_cast<std::uint32_t>(rig_.influences.size()),
                          static_cast<std::uint32_t>(influences.size()), morph, std::get<3>(key)};
      for (const std::uint64_t packed : influences) {
        rig_.influences.push_back(
            {static_cast<std::uint32_t>(packed >> 32), std::bit_cast<float>(static_cast<std::uint32_t>(packed))});
      }
      rig_.motions.push_back(motion);
    }
    motions[v] = it->second;
  }
  if (unweighted > 0) {
    warnings_.add(name + ": " + std::to_string(unweighted) +
                  " vertices have no skin weight; they follow the skin's first joint");
  }
  return motions;
}

Channel GltfRigReader::read_channel(std::size_t a, std::size_t c) {
  const tinygltf::Animation& animation = gltf_.animations[a];
  const tinygltf::AnimationChannel& channel = animation.channels[c];
  const std::string name = "animation " + std::to_string(a) + " channel " + std::to_string(c);
  Channel out;
  out.node = channel.target_node;
  if (out.node < 0 || static_cast<std::size_t>(out.node) >= gltf_.nodes.size()) {
    fail(name + " targets node " + std::to_string(out.node) + ", which does not exist");
  }
  const std::optional<ChannelPath> path = path_of(channel.target_path);
  if (!path) fail(name + " animates \"" + channel.target_path + "\", which is not a node property");
  out.path = *path;
  if (channel.sampler < 0 || static_cast<std::size_t>(channel.sampler) >= animation.samplers.size()) {
    fail(name + " uses sampler " + std::to_string(channel.sampler) + ", which does not exist");
  }
  const tinygltf::AnimationSampler& sampler = animation.samplers[static_cast<std::size_t>(channel.sampler)];
  const std::optional<Interpolation> interpolation = interpolation_of(sampler.interpolation);
  if (!interpolation) fail(name + " has the interpolation \"" + sampler.interpolation + "\"");
  out.interpolation = *interpolation;
  const std::string sampler_name = "animation " + std::to_string(a) + " sampler " + std::to_string(channel.sampler);
  const std::size_t keys_declared = reader_.accessor(sampler.input, sampler_name + " input").count;
  if (keys_declared > kMaxClipNumbers - clip_numbers_) {
    fail("the clips hold more than " + std::to_string(kMaxClipNumbers) + " key times and values");
  }
  out.times = reader_.read(sampler.input, sampler_name + " input", 1);
  if (out.times.empty()) fail(sampler_name + " input has no keys");
  if (!all_finite(out.times)) fail(sampler_name + " input holds a key time that is not finite");
  for (std::size_t k = 1; k < out.times.size(); ++k) {
    if (!(out.times[k] > out.times[k - 1])) {
      fail(sampler_name + " input is not increasing: key " + std::to_string(k) + " at " + std::to_string(out.times[k]) +
           " s follows " + std::to_string(out.times[k - 1]) + " s");
    }
  }
  const std::size_t groups = out.interpolation == Interpolation::CubicSpline ? 3 : 1;
  const std::size_t keys = out.times.size();
  if (out.path == ChannelPath::Weights) {
    const tinygltf::Node& node = gltf_.nodes[static_cast<std::size_t>(out.node)];
    const std::size_t targets = node.mesh >= 0 && static_cast<std::size_t>(node.mesh) < gltf_.meshes.size()
                                    ? morph_targets_of(gltf_.meshes[static_cast<std::size_t>(node.mesh)])
                                    : 0;
    if (targets == 0)
      fail(name + " animates the morph weights of node " + std::to_string(out.node) +
           ", whose mesh has no morph targets");
    out.width = static_cast<int>(targets);
  } else {
    out.width = out.path == ChannelPath::Rotation ? 4 : 3;
  }
  const std::size_t expected = keys * groups * static_cast<std::size_t>(out.width);
  if (expected > kMaxClipNumbers - clip_numbers_ - keys) {
    fail("the clips hold more than " + std::to_string(kMaxClipNumbers) + " key times and values");
  }
  const int components = out.path == ChannelPath::Weights ? 1 : out.width;
  const std::string output_role = sampler_name + " output";
  // The count is checked before anything is read: an accessor without a
  // buffer view reads as zeros, as many as it declares.
  const std::size_t declared = reader_.accessor(sampler.output, output_role).count;
  if (declared * static_cast<std::size_t>(components) != expected) {
    fail(output_role + " has " + std::to_string(declared * static_cast<std::size_t>(components)) +
         " numbers where its " + std::to_string(keys) + " keys need " + std::to_string(expected));
  }
  out.values = reader_.read(sampler.output, output_role, components);
  clip_numbers_ += keys + expected;
  if (out.values.size() != expected) {
    fail(sampler_name + " output has " + std::to_string(out.values.size()) + " numbers where its " +
         std::to_string(keys) + " keys need " + std::to_string(expected));
  }
  if (!all_finite(out.values)) fail(sampler_name + " output holds a value that is not finite");
  return out;
}

void GltfRigReader::read_clips() {
  for (std::size_t a = 0; a < gltf_.animations.size(); ++a) {
    const tinygltf::Animation& animation = gltf_.animations[a];
    Clip clip;
    clip.name = animation.name.empty() ? "animation " + std::to_string(a) : animation.name;
    std::size_t skipped = 0;
    for (std::size_t c = 0; c < animation.channels.size(); ++c) {
      Channel channel = read_channel(a, c);
      if (rig_.nodes[static_cast<std::size_t>(channel.node)].matrix && channel.path != ChannelPath::Weights) {
        ++skipped;  // a node given by a matrix is not animated (glTF 2.0 §3.11)
        continue;
      }
      clip.duration = std::max(clip.duration, channel.times.back());
      clip.channels.push_back(std::move(channel));
    }
    if (skipped > 0) {
      warnings_.add(file_ + ": clip \"" + clip.name + "\": " + std::to_string(skipped) +
                    " channels animate nodes given by a matrix and are not played");
    }
    rig_.clips.push_back(std::move(clip));
  }
}

Rig GltfRigReader::finish(const glm::dmat4& file_to_mesh) {
  read_clips();
  rig_.file_to_mesh = file_to_mesh;
  const glm::dmat4 mesh_to_file = glm::inverse(file_to_mesh);
  for (Binding& binding : rig_.bindings) {
    binding.mesh_to_local = glm::inverse(rest_world_[static_cast<std::size_t>(binding.node)]) * mesh_to_file;
  }
  std::set<int> joints;
  for (const tinygltf::Skin& skin : gltf_.skins) joints.insert(skin.joints.begin(), skin.joints.end());
  rig_.joint_count = joints.size();
  return std::move(rig_);
}

}  // namespace toond::scene
