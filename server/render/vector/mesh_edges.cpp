#include "render/vector/mesh_edges.h"

#include <algorithm>

#include "scene/mesh/mesh_processing.h"

namespace toond::render::vector {
namespace {

// One side of a triangle, keyed by its two positions (the smaller first),
// so that the sides of one edge sort together, in the order of their
// triangles.
struct Side {
  std::uint64_t key;
  std::uint32_t corner;  // 3 × face + which side
  bool operator<(const Side& other) const { return key != other.key ? key < other.key : corner < other.corner; }
};

std::vector<Side> sides_of(std::span<const std::uint32_t> indices, std::span<const std::uint32_t> group) {
  std::vector<Side> sides;
  sides.reserve(indices.size());
  for (std::size_t corner = 0; corner < indices.size(); ++corner) {
    const std::size_t next = corner % 3 == 2 ? corner - 2 : corner + 1;
    const std::uint32_t ga = group[indices[corner]];
    const std::uint32_t gb = group[indices[next]];
    if (ga == gb) continue;  // a side of no length borders nothing
    const auto [lo, hi] = std::minmax(ga, gb);
    sides.push_back({static_cast<std::uint64_t>(lo) << 32 | hi, static_cast<std::uint32_t>(corner)});
  }
  std::sort(sides.begin(), sides.end());
  return sides;
}

}  // namespace

std::vector<MeshEdge> find_mesh_edges(std::span<const std::uint32_t> indices, std::span<const std::uint32_t> group) {
  const std::vector<Side> sides = sides_of(indices, group);
  std::vector<std::pair<std::uint32_t, MeshEdge>> by_corner;  // each edge by its first side
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t end = i + 1;
    while (end < sides.size() && sides[end].key == sides[i].key) ++end;
    const std::uint32_t corner = sides[i].corner;
    const std::uint32_t next = corner % 3 == 2 ? corner - 2 : corner + 1;
    MeshEdge edge;
    edge.a = indices[corner];
    edge.b = indices[next];
    edge.face0 = corner / 3;
    if (end - i > 1) edge.face1 = sides[i + 1].corner / 3;
    by_corner.emplace_back(corner, edge);
    i = end;
  }
  // In the order the triangles name them: neighbours stay near each other.
  std::sort(by_corner.begin(), by_corner.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<MeshEdge> edges;
  edges.reserve(by_corner.size());
  for (const auto& [corner, edge] : by_corner) edges.push_back(edge);
  return edges;
}

ModelEdges model_edges(const scene::Model& model, std::size_t level) {
  const scene::Mesh& mesh = model.mesh;
  ModelEdges edges;
  edges.group = scene::group_by_position(mesh.positions);
  if (!edges.group.empty()) edges.group_count = 1 + *std::max_element(edges.group.begin(), edges.group.end());
  edges.edges = find_mesh_edges(level == 0 ? mesh.indices : mesh.lods[level - 1].indices, edges.group);
  return edges;
}

std::shared_ptr<const ModelEdges> EdgeCache::get(const std::shared_ptr<const scene::Model>& model, std::size_t level) {
  {
    std::lock_guard lock(mutex_);
    std::erase_if(recent_, [](const Entry& e) { return e.model.expired(); });
    for (auto it = recent_.begin(); it != recent_.end(); ++it) {
      if (it->address != model.get() || it->level != level) continue;
      std::rotate(recent_.begin(), it, it + 1);
      return recent_.front().edges;
    }
  }
  // Worked out unlocked: another model's drawing need not wait for it.
  auto edges = std::make_shared<const ModelEdges>(model_edges(*model, level));
  std::lock_guard lock(mutex_);
  recent_.insert(recent_.begin(), Entry{model, model.get(), level, edges});
  if (recent_.size() > kCapacity) recent_.pop_back();
  return edges;
}

}  // namespace toond::render::vector
