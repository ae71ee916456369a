#include "render/frame/gpu_skin.h"

#include <algorithm>
#include <bit>

#include <glm/gtc/type_ptr.hpp>

namespace toond::render {
namespace {

// A storage buffer's size must not be 0: an empty list (a rig without
// morph targets) still gets one zeroed element.
template <class T>
gpu::Buffer immutable_buffer(const std::vector<T>& items, std::size_t& bytes) {
  const std::size_t size = std::max<std::size_t>(items.size() * sizeof(T), 16);
  std::vector<std::uint8_t> data(size, 0);
  std::copy_n(reinterpret_cast<const std::uint8_t*>(items.data()), items.size() * sizeof(T), data.data());
  gpu::Buffer buffer = gpu::Buffer::create();
  glNamedBufferStorage(buffer.id(), static_cast<GLsizeiptr>(size), data.data(), 0);
  bytes += size;
  return buffer;
}

template <class T>
void stream_into(const gpu::Buffer& buffer, const std::vector<T>& items) {
  const std::size_t size = std::max<std::size_t>(items.size() * sizeof(T), 16);
  std::vector<std::uint8_t> data(size, 0);
  std::copy_n(reinterpret_cast<const std::uint8_t*>(items.data()), items.size() * sizeof(T), data.data());
  glNamedBufferData(buffer.id(), static_cast<GLsizeiptr>(size), data.data(), GL_STREAM_DRAW);
}

// Each motion's influences, written out again with the joint's place in
// the pose's one list of joints (every binding's, binding after binding).
struct MotionTables {
  std::vector<glm::uvec4> motions;
  std::vector<glm::uvec2> influences;
};

MotionTables motion_tables(const scene::Rig& rig) {
  const std::vector<std::uint32_t> offsets = scene::binding_joint_offsets(rig);
  MotionTables tables;
  for (const scene::VertexMotion& motion : rig.motions) {
    const auto first = static_cast<std::uint32_t>(tables.influences.size());
    for (std::uint32_t k = 0; k < motion.influence_count; ++k) {
      const scene::Influence& influence = rig.influences[motion.first_influence + k];
      tables.influences.push_back(
          {offsets[motion.binding] + influence.joint, std::bit_cast<std::uint32_t>(influence.weight)});
    }
    tables.motions.push_back(
        {first, motion.influence_count, static_cast<std::uint32_t>(motion.morph_set + 1), motion.morph_vertex});
  }
  return tables;
}

}  // namespace

GpuSkin::GpuSkin(const scene::Mesh& mesh, const scene::Rig& rig) {
  const MotionTables tables = motion_tables(rig);
  std::vector<glm::vec4> deltas;  // threes: position, normal, tangent
  const auto delta_or_none = [](const std::vector<glm::vec3>& deltas_of_set, std::size_t i) {
    return glm::vec4(deltas_of_set.empty() ? glm::vec3(0.0f) : deltas_of_set[i], 0.0f);
  };
  for (const scene::MorphSet& set : rig.morph_sets) {
    morph_first_delta_.push_back(static_cast<std::uint32_t>(deltas.size() / 3));
    morph_vertices_.push_back(static_cast<std::uint32_t>(set.vertices));
    for (std::size_t i = 0; i < set.position_deltas.size(); ++i) {
      deltas.emplace_back(set.position_deltas[i], 0.0f);
      deltas.push_back(delta_or_none(set.normal_deltas, i));
      deltas.push_back(delta_or_none(set.tangent_deltas, i));
    }
  }
  vertex_motions_ = immutable_buffer(mesh.motion, gpu_bytes_);
  motions_ = immutable_buffer(tables.motions, gpu_bytes_);
  influences_ = immutable_buffer(tables.influences, gpu_bytes_);
  morph_deltas_ = immutable_buffer(deltas, gpu_bytes_);
  pose_joints_ = gpu::Buffer::create();
  pose_morphs_ = gpu::Buffer::create();
}

void GpuSkin::upload(const scene::SkinPose& pose) {
  stream_into(pose_joints_, pose.joints);
  // Each set's header, then the targets it weights (nonzero only).
  const std::size_t sets = morph_first_delta_.size();
  std::vector<glm::uvec4> morphs(sets);
  for (std::size_t s = 0; s < sets; ++s) {
    const auto first_target = static_cast<std::uint32_t>(morphs.size());
    const std::vector<float>& weights = pose.morph_weights[s];
    std::uint32_t weighted = 0;
    for (std::size_t t = 0; t < weights.size(); ++t) {
      if (weights[t] == 0.0f) continue;
      morphs.push_back({static_cast<std::uint32_t>(t), std::bit_cast<std::uint32_t>(weights[t]), 0u, 0u});
      ++weighted;
    }
    morphs[s] = {morph_first_delta_[s], morph_vertices_[s], first_target, weighted};
  }
  stream_into(pose_morphs_, morphs);
}

void GpuSkin::bind() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVertexMotionsBlock, vertex_motions_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMotionsBlock, motions_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInfluencesBlock, influences_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMorphDeltasBlock, morph_deltas_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPoseJointsBlock, pose_joints_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPoseMorphsBlock, pose_morphs_.id());
}

}  // namespace toond::render
