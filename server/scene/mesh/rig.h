#pragma once
// What moves in a model: its node hierarchy at rest, the skins and morph
// targets bound to its vertices and the clips that animate them, as the
// file gives them. Plain data; scene/animation/pose.h evaluates it. A model without
// any of these has no Rig.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace toond::scene {

// A node's own transform at rest: translation · rotation · scale, or a
// matrix (which clips do not animate).
struct RigNode {
  int parent = -1;  // index into Rig::nodes, -1 for a root
  glm::dvec3 translation{0.0};
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 scale{1.0};
  std::optional<glm::dmat4> matrix;
  // The morph weights the node gives its mesh; empty: the mesh's own.
  std::vector<double> weights;
};

enum class ChannelPath : std::uint8_t { Translation, Rotation, Scale, Weights };
enum class Interpolation : std::uint8_t { Step, Linear, CubicSpline };

// One animated property of one node: key times (strictly increasing) and
// `width` values per key (3 for translation and scale, 4 for rotation as
// x, y, z, w, the morph target count for weights); CUBICSPLINE keys hold
// three groups each: in-tangent, value, out-tangent.
struct Channel {
  int node = 0;
  ChannelPath path = ChannelPath::Translation;
  Interpolation interpolation = Interpolation::Linear;
  std::vector<double> times;
  std::vector<double> values;
  int width = 3;
};

struct Clip {
  std::string name;
  // The last key's time, seconds on the file's time base: a clip loops over
  // [0, duration), as three.js plays it.
  double duration = 0;
  // Frames per second, where the format keys its clips by frame (B3D, FBX,
  // MilkShape 3D through the assimp helper); none where it has no frames
  // (glTF keys by seconds, COLLADA by milliseconds).
  std::optional<double> frame_rate;
  std::vector<Channel> channels;
};

// Which nodes move a vertex and how much each: a skin's joints with their
// inverse bind matrices, seen from the node that draws the mesh (`node`);
// a mesh without a skin is bound to its own node alone (joint = node,
// inverse bind = identity), which is how rigid node animation moves it.
struct Binding {
  int node = -1;                          // the node whose mesh this is
  std::vector<int> joints;                // node indices
  std::vector<glm::dmat4> inverse_binds;  // one per joint
  // From the mesh's space to the mesh's own coordinates: the import baked
  // the node's rest transform (and the upload's turn and recentring) into
  // the positions, and a skin works on the coordinates the file gave.
  glm::dmat4 mesh_to_local{1.0};
};

// The morph targets of one mesh drawn by one node: deltas per target per
// vertex of the set, in the mesh's own (recentred, up-turned) space at rest.
struct MorphSet {
  int node = -1;
  std::vector<double> default_weights;  // the mesh's `weights`, 0 where absent
  std::size_t vertices = 0;
  std::vector<glm::vec3> position_deltas;  // [target * vertices + vertex]
  std::vector<glm::vec3> normal_deltas;    // same layout, or empty
  std::vector<glm::vec3> tangent_deltas;   // same layout, or empty
  std::size_t targets() const { return default_weights.size(); }
};

// How one distinct source position moves: weighted influences of a
// binding's joints and, optionally, a vertex of a morph set.
struct VertexMotion {
  std::uint32_t binding = 0;
  std::uint32_t first_influence = 0;  // into Rig::influences
  std::uint32_t influence_count = 0;
  std::int32_t morph_set = -1;  // into Rig::morph_sets
  std::uint32_t morph_vertex = 0;
};

struct Influence {
  std::uint32_t joint = 0;  // index into the binding's joints
  float weight = 0;         // the vertex's weights sum to 1
};

struct Rig {
  std::vector<RigNode> nodes;
  // Parents before children: the order world matrices are computed in.
  std::vector<int> node_order;
  std::vector<Binding> bindings;
  std::vector<MorphSet> morph_sets;
  std::vector<Influence> influences;
  std::vector<VertexMotion> motions;  // Mesh::motion indexes these
  std::vector<Clip> clips;
  // From the file's world space to the mesh's (turned up, recentred):
  // where posed positions are drawn.
  glm::dmat4 file_to_mesh{1.0};
  std::size_t joint_count = 0;         // distinct nodes used as joints by skins
  std::size_t morph_target_count = 0;  // over every mesh with targets

  // The clip named `name` as the file names it, or by the part after the
  // last '|' (Blender's "Armature|Walk") where that is unique; nullopt when
  // none matches.
  std::optional<std::size_t> find_clip(const std::string& name) const;
  // "walk, idle" (quoted, comma-separated), for messages.
  std::string clip_names() const;
};

}  // namespace toond::scene
