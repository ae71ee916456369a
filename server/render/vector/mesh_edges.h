#pragma once
// The edges of a mesh's triangles between welded positions, each with the
// faces that border it: where a silhouette can run (one face turned toward
// the eye, the other away) and where the surface is open (one face alone).
// Crease edges and seams are found at import (scene/mesh/crease_edges.h,
// intersection_lines.h); these depend on nothing but the topology, which a
// pose keeps, so they are found once per model and level of detail and
// kept (EdgeCache).
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh/model.h"

namespace toond::render::vector {

inline constexpr std::uint32_t kNoFace = std::numeric_limits<std::uint32_t>::max();

struct MeshEdge {
  std::uint32_t a = 0, b = 0;  // vertex indices, as face0 holds them
  std::uint32_t face0 = 0;
  std::uint32_t face1 = kNoFace;  // kNoFace: an open edge
};

// Edges between two distinct positions (split copies of a vertex count as
// one: `group`, scene::group_by_position), in the order their first
// triangle names them. An edge three or more faces share counts with the
// first two, as crease edges do.
std::vector<MeshEdge> find_mesh_edges(std::span<const std::uint32_t> indices, std::span<const std::uint32_t> group);

// A model's welded positions and the edges of one of its levels of detail
// (0: the full mesh, then scene::Mesh::lods).
struct ModelEdges {
  std::vector<std::uint32_t> group;  // per vertex
  std::uint32_t group_count = 0;     // how many positions
  std::vector<MeshEdge> edges;
};

// The edges of recently drawn models, worked out on first use. Keyed by
// the model's address and the level, checked against a weak reference: a
// model let go and another imported at the same address is not mistaken
// for it.
class EdgeCache {
 public:
  static constexpr std::size_t kCapacity = 16;
  std::shared_ptr<const ModelEdges> get(const std::shared_ptr<const scene::Model>& model, std::size_t level);

 private:
  struct Entry {
    std::weak_ptr<const scene::Model> model;
    const scene::Model* address = nullptr;
    std::size_t level = 0;
    std::shared_ptr<const ModelEdges> edges;
  };
  std::mutex mutex_;
  std::vector<Entry> recent_;  // most recently used first
};

// The edges of `model`'s level of detail `level`.
ModelEdges model_edges(const scene::Model& model, std::size_t level);

}  // namespace toond::render::vector
