#pragma once
// A rigged model's skinning on the GPU: what every pose shares (each
// vertex's motion, the motions' influences, the morph targets' deltas),
// uploaded once with the model, and the storage blocks of one pose (joint
// matrices, morph weights), uploaded per render. shaders/skinning.glsl
// reads them; the block bindings here are its.
// Created, used and destroyed on the render thread only.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "gpu/gl_object.h"
#include "scene/animation/pose.h"
#include "scene/mesh/model.h"
#include "scene/mesh/rig.h"

namespace toond::render {

enum SkinBlock : unsigned {
  kVertexMotionsBlock = 0,
  kMotionsBlock = 1,
  kInfluencesBlock = 2,
  kMorphDeltasBlock = 3,
  kPoseJointsBlock = 4,
  kPoseMorphsBlock = 5,
};

class GpuSkin {
 public:
  GpuSkin(const scene::Mesh& mesh, const scene::Rig& rig);

  // The pose the next draws use (its joints in scene::binding_joint_offsets'
  // order, as the influences were laid out).
  void upload(const scene::SkinPose& pose);
  // Binds every block to its binding point, before a posed object draws.
  void bind() const;
  std::size_t gpu_bytes() const { return gpu_bytes_; }

 private:
  gpu::Buffer vertex_motions_;
  gpu::Buffer motions_;
  gpu::Buffer influences_;
  gpu::Buffer morph_deltas_;
  gpu::Buffer pose_joints_;
  gpu::Buffer pose_morphs_;
  // Per morph set: where its deltas start (in delta pairs) and how many
  // vertices it has, for the pose's block.
  std::vector<std::uint32_t> morph_first_delta_;
  std::vector<std::uint32_t> morph_vertices_;
  std::size_t gpu_bytes_ = 0;
};

}  // namespace toond::render
