#include "scene/animation/motion_classes.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <map>

namespace toond::scene {
namespace {

// What moves a vertex with no morph: its binding, then each joint it
// follows (by index) with its weight's bits, in joint order. Influences of
// weight 0 move nothing and are left out, so "A 1, B 0" is "A 1".
std::vector<std::uint64_t> skin_key(const Rig& rig, const VertexMotion& motion) {
  std::vector<std::uint64_t> influences;
  for (std::uint32_t k = 0; k < motion.influence_count; ++k) {
    const Influence& influence = rig.influences[motion.first_influence + k];
    if (influence.weight == 0.0f) continue;
    influences.push_back((std::uint64_t{influence.joint} << 32) | std::bit_cast<std::uint32_t>(influence.weight));
  }
  std::sort(influences.begin(), influences.end());
  std::vector<std::uint64_t> key{motion.binding};
  key.insert(key.end(), influences.begin(), influences.end());
  return key;
}

bool morphed(const Rig& rig, const VertexMotion& motion) {
  if (motion.morph_set < 0) return false;
  const MorphSet& set = rig.morph_sets[static_cast<std::size_t>(motion.morph_set)];
  for (std::size_t t = 0; t < set.targets(); ++t) {
    if (set.position_deltas[t * set.vertices + motion.morph_vertex] != glm::vec3(0.0f)) return true;
  }
  return false;
}

// The largest eigenvalue of a symmetric 3×3 matrix, in closed form: the
// three roots of its characteristic cubic by the trigonometric solution.
double largest_eigenvalue(const glm::dmat3& s) {
  const double off = s[0][1] * s[0][1] + s[0][2] * s[0][2] + s[1][2] * s[1][2];
  if (off == 0.0) return std::max({s[0][0], s[1][1], s[2][2]});
  const double mean = (s[0][0] + s[1][1] + s[2][2]) / 3.0;
  const double spread2 = (s[0][0] - mean) * (s[0][0] - mean) + (s[1][1] - mean) * (s[1][1] - mean) +
                         (s[2][2] - mean) * (s[2][2] - mean) + 2.0 * off;
  const double spread = std::sqrt(spread2 / 6.0);
  const glm::dmat3 shifted = (s - mean * glm::dmat3(1.0)) / spread;
  const double half_det = std::clamp(glm::determinant(shifted) / 2.0, -1.0, 1.0);
  return mean + 2.0 * spread * std::cos(std::acos(half_det) / 3.0);
}

}  // namespace

std::vector<std::uint32_t> motion_classes(const Mesh& mesh, const Rig& rig) {
  std::vector<std::uint32_t> class_of_motion(rig.motions.size());
  std::map<std::vector<std::uint64_t>, std::uint32_t> skins;
  std::uint32_t next = 0;
  for (std::size_t m = 0; m < rig.motions.size(); ++m) {
    const VertexMotion& motion = rig.motions[m];
    if (morphed(rig, motion)) {
      class_of_motion[m] = next++;
      continue;
    }
    const auto [it, added] = skins.emplace(skin_key(rig, motion), next);
    if (added) ++next;
    class_of_motion[m] = it->second;
  }
  std::vector<std::uint32_t> classes(mesh.motion.size());
  for (std::size_t v = 0; v < classes.size(); ++v) classes[v] = class_of_motion[mesh.motion[v]];
  return classes;
}

double largest_joint_stretch(const std::vector<glm::mat4>& joint_matrices) {
  if (joint_matrices.empty()) return 1.0;
  double largest = 0.0;
  for (const glm::mat4& joint : joint_matrices) {
    const glm::dmat3 linear(joint);
    const double stretch = std::sqrt(std::max(0.0, largest_eigenvalue(glm::transpose(linear) * linear)));
    if (!std::isfinite(stretch)) return std::numeric_limits<double>::infinity();
    largest = std::max(largest, stretch);
  }
  // The closed form rounds; a thousandth more keeps the bound a bound.
  return largest * 1.001;
}

}  // namespace toond::scene
