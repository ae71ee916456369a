#pragma once
// The moving parts of a glTF file (glTF 2.0 §3.7.3 skins, §3.7.2.2 morph
// targets, §3.11 animations) read into a scene::Rig, and each drawn
// vertex's motion: which joints with which weights, which morph deltas.
// Everything is checked as it is read: the file is untrusted.
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <glm/glm.hpp>

#include "scene/gltf/gltf_accessor.h"
#include "scene/mesh/rig.h"
#include "scene/reading/mesh_builder.h"

namespace tinygltf {
class Model;
struct Primitive;
}  // namespace tinygltf

namespace toond::scene {

class GltfRigReader {
 public:
  // `drawn_nodes`: the nodes of the scene that is drawn; `turn`: the
  // upload's up-axis turn (identity, or +Z to +Y), applied to morph deltas.
  GltfRigReader(const tinygltf::Model& gltf, const GltfAccessorReader& reader, std::string file,
                const std::vector<bool>& drawn_nodes, const glm::dmat3& turn, ImportWarnings& warnings);

  // Whether anything moves: skins on drawn nodes, morph targets on drawn
  // meshes, or clips. Without, the model needs no rig.
  bool moves() const { return moves_; }

  // Per vertex of `primitive` (of the mesh drawn by `node`), an index into
  // the rig's motions; `count` vertices, `name` for messages. Vertices that
  // move alike share one motion.
  std::vector<std::uint32_t> motions_of(int node, const tinygltf::Primitive& primitive, std::size_t count,
                                        const std::string& name);

  // The rig, its clips read and checked; `file_to_mesh` as Rig has it.
  Rig finish(const glm::dmat4& file_to_mesh);

 private:
  [[noreturn]] void fail(const std::string& message) const;
  std::vector<double> read_counted(int index, const std::string& role, int components, std::size_t expected) const;
  void read_nodes();
  void check_skins_are_drawn(const std::vector<bool>& drawn_nodes) const;
  std::uint32_t binding_of(int skin, int node);
  std::vector<double> read_weights_of(int node, const tinygltf::Primitive& primitive, std::size_t count,
                                      const std::string& name, std::vector<double>& joints, int& sets);
  std::int32_t morph_set_of(int node, const tinygltf::Primitive& primitive, std::size_t count, const std::string& name);
  void read_clips();
  Channel read_channel(std::size_t animation, std::size_t index);

  const tinygltf::Model& gltf_;
  const GltfAccessorReader& reader_;
  std::string file_;
  glm::dmat3 turn_;
  ImportWarnings& warnings_;
  bool moves_ = false;
  Rig rig_;
  std::vector<glm::dmat4> rest_world_;
  std::map<std::pair<int, int>, std::uint32_t> bindings_;  // (skin or -1, node) → Rig::bindings
  // A motion's identity: binding, influences (joint, weight bits), morph.
  using MotionKey = std::tuple<std::uint32_t, std::vector<std::uint64_t>, std::int32_t, std::uint32_t>;
  std::map<MotionKey, std::uint32_t> motion_ids_;
  std::set<int> meshes_with_targets_;  // counted once in Rig::morph_target_count
  // Key times and values read so far, at most kMaxClipNumbers (160 MB).
  static constexpr std::size_t kMaxClipNumbers = 20'000'000;
  std::size_t clip_numbers_ = 0;
};

}  // namespace toond::scene
