#pragma once
// Geometry the image cannot show is skipped: at import every submesh's
// triangles are reordered for the post-transform vertex cache, and a chain
// of coarser index buffers (levels of detail) is built over the same
// vertices. A render then draws the coarsest level whose geometric error,
// projected to pixels, stays under a threshold (see render/plan/lod_choice.h).
//
// The levels share the full mesh's vertices, so each keeps the full mesh's
// shading normals, texcoords, outline normals and, for a rigged model, how
// each vertex moves; triangles that a pose would bend are kept whole. The outline normals are
// per position (every vertex at one position moves by the same offset), and
// the simplifier keeps a closed surface closed, so the inverted hull of a
// level is as closed as its triangles.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "scene/mesh/model.h"

namespace toond::scene {

struct LodOptions {
  // Each level aims at this fraction of the previous level's triangles.
  // Coarser steps left a model filling the default frame with a choice
  // between full detail and a level whose band edges moved visibly; at 75 %
  // there is a level in between (Lod.AutoDrawsACoarserLevelThatLooksLike-
  // FullDetail holds the bunny's default to 0.5 % of pixels).
  double ratio = 0.75;
  // No level below this many triangles; the chain stops there.
  std::size_t min_triangles = 64;
  // A level that keeps more than this fraction of the previous one's
  // triangles is not worth a draw call of its own; the chain stops.
  double min_shrink = 0.85;
  // At most this many coarser levels.
  std::size_t max_levels = 12;
  // Called before each level is made (the import's time limit, which may
  // throw to abandon the import).
  std::function<void()> between_levels;
  // Per vertex, which vertices move alike in every pose
  // (scene/animation/motion_classes.h); empty for a model that does not move. Only
  // triangles whose corners all share a class are simplified, and a class
  // is never merged into another, so every level poses as the full mesh
  // does, within its error times the pose's stretch.
  std::vector<std::uint32_t> motion_class;
};

// Reorders the triangles of each submesh (and of each level already built)
// for the vertex cache. Triangles stay the same: only their order, and the
// rotation of corners within a triangle, may change.
void optimize_for_vertex_cache(Mesh& mesh);

// The chain of coarser levels for `mesh`, finest first (level 1 onwards;
// level 0 is the mesh itself). Each submesh is simplified on its own with
// its border locked, so materials meet without cracks. `error` is an upper
// bound of how far a level's surface strays from the full mesh, in the
// mesh's own units (summed over the simplification steps that made it).
std::vector<MeshLod> build_lod_chain(const Mesh& mesh, const LodOptions& options = {});
// The same for a caller that has group_by_position(mesh.positions) already.
std::vector<MeshLod> build_lod_chain(const Mesh& mesh, std::span<const std::uint32_t> position_group,
                                     const LodOptions& options);

// Both of the above, as the importer runs them: the chain is built and
// every index buffer reordered for the vertex cache.
void prepare_levels_of_detail(Mesh& mesh, const LodOptions& options = {});
void prepare_levels_of_detail(Mesh& mesh, std::span<const std::uint32_t> position_group, const LodOptions& options);

}  // namespace toond::scene
