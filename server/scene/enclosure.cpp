#include "scene/enclosure.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "scene/mesh_processing.h"

namespace toond::scene {
namespace {

// Union-find over position groups: which triangles hang together.
class Components {
 public:
  explicit Components(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
  std::uint32_t root(std::uint32_t v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  void join(std::uint32_t a, std::uint32_t b) { parent_[root(a)] = root(b); }

 private:
  std::vector<std::uint32_t> parent_;
};

// Every edge crossed as often one way as the other.
bool edges_balance(std::span<const std::uint32_t> group, std::span<const std::uint32_t> indices) {
  std::unordered_map<std::uint64_t, int> balance;
  balance.reserve(indices.size());
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint64_t a = group[indices[t + k]];
      const std::uint64_t b = group[indices[t + (k + 1) % 3]];
      if (a == b) continue;  // a collapsed corner: no edge
      if (a < b) ++balance[a << 32 | b];
      else --balance[b << 32 | a];
    }
  }
  return std::all_of(balance.begin(), balance.end(), [](const auto& e) { return e.second == 0; });
}

struct Part {
  double volume = 0;  // signed: positive when counter-clockwise faces look out
  glm::dvec3 min{std::numeric_limits<double>::max()};
  glm::dvec3 max{std::numeric_limits<double>::lowest()};
};

}  // namespace

Enclosure classify_enclosure(std::span<const glm::vec3> positions, std::span<const std::uint32_t> position_group,
                             std::span<const std::uint32_t> indices) {
  if (indices.size() < 3 || !edges_balance(position_group, indices)) return Enclosure::Open;

  const std::size_t groups =
      position_group.empty() ? 0 : *std::max_element(position_group.begin(), position_group.end()) + 1u;
  Components components(groups);
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    components.join(position_group[indices[t]], position_group[indices[t + 1]]);
    components.join(position_group[indices[t]], position_group[indices[t + 2]]);
  }
  // Each closed part's volume by the divergence theorem: the sum of the
  // tetrahedra its triangles make with the origin.
  std::unordered_map<std::uint32_t, Part> parts;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const glm::dvec3 a(positions[indices[t]]), b(positions[indices[t + 1]]), c(positions[indices[t + 2]]);
    Part& part = parts[components.root(position_group[indices[t]])];
    part.volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    for (const glm::dvec3& p : {a, b, c}) {
      part.min = glm::min(part.min, p);
      part.max = glm::max(part.max, p);
    }
  }
  int outward = 0;
  int inward = 0;
  for (const auto& [root, part] : parts) {
    // Against the cube of its own size, so a small part counts as much as a
    // large one; what stays under this is a flat or two-sided sheet.
    const double size = glm::length(part.max - part.min);
    const double least = 1e-7 * size * size * size;
    if (part.volume > least) ++outward;
    else if (part.volume < -least) ++inward;
    else return Enclosure::Open;
  }
  if (inward == 0) return Enclosure::Outward;
  if (outward == 0) return Enclosure::Inward;
  return Enclosure::Open;
}

void classify_enclosures(Mesh& mesh) {
  const std::vector<std::uint32_t> group = group_by_position(mesh.positions);
  mesh.enclosure = classify_enclosure(mesh.positions, group, mesh.indices);
  for (MeshLod& lod : mesh.lods) lod.enclosure = classify_enclosure(mesh.positions, group, lod.indices);
}

}  // namespace toond::scene
