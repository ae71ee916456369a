#include "scene/mesh/mesh_lod.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>

#include "scene/mesh/edge_table.h"
#include "scene/mesh/flat_map.h"
#include "scene/mesh/mesh_processing.h"

namespace toond::scene {
namespace {

constexpr double kQuadricToWorstStray = 2.5;

// The simplifier's cost grows with the square of a vertex's valence: a fan
// of 40,000 triangles on one edge, or one triangle written 40,000 times,
// took it seconds. Triangles at a position more than this many triangles
// meet are kept at full detail in every level instead; real meshes have
// few such hubs (a UV sphere's poles, a cylinder cap's centre), and their
// fans are thin.
constexpr std::uint32_t kMaxSimplifiedValence = 128;

std::array<std::uint32_t, 3> corner_groups(const std::vector<std::uint32_t>& position_group,
                                           const std::uint32_t* triangle) {
  return {position_group[triangle[0]], position_group[triangle[1]], position_group[triangle[2]]};
}

struct CornerGroupsHash {
  std::size_t operator()(const std::array<std::uint32_t, 3>& g) const noexcept {
    std::uint64_t h = 1469598103934665603ull;
    for (const auto v : g) h = (h ^ v) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

// Which triangles of `indices` a coarser level may do without: those with
// two corners at one position (no area to show) and repeats of an earlier
// triangle over the same positions in the same turn (a second copy draws
// nothing new; the opposite turn is a back side and stays).
std::vector<bool> droppable_triangles(const std::vector<std::uint32_t>& position_group,
                                      const std::vector<std::uint32_t>& indices) {
  std::vector<bool> drop(indices.size() / 3, false);
  FlatMap<std::array<std::uint32_t, 3>, bool, CornerGroupsHash> seen(drop.size());
  for (std::size_t t = 0; t < drop.size(); ++t) {
    auto g = corner_groups(position_group, &indices[3 * t]);
    if (g[0] == g[1] || g[1] == g[2] || g[2] == g[0]) {
      drop[t] = true;
      continue;
    }
    std::rotate(g.begin(), std::min_element(g.begin(), g.end()), g.end());
    drop[t] = !seen.try_emplace(g, true).second;
  }
  return drop;
}

// How many kept triangles meet at each position.
std::vector<std::uint32_t> valence_of_positions(const std::vector<std::uint32_t>& position_group,
                                                const std::vector<std::uint32_t>& indices,
                                                const std::vector<bool>& dropped) {
  std::vector<std::uint32_t> valence(position_group.size(), 0);
  for (std::size_t t = 0; t < dropped.size(); ++t) {
    if (dropped[t]) continue;
    for (const auto g : corner_groups(position_group, &indices[3 * t])) ++valence[g];
  }
  return valence;
}

// Dense local ids for the model vertices a submesh uses, in first-use
// order: meshoptimizer's tables are as long as the vertex count it is
// given, so each submesh goes to it on its own compact numbering.
class CompactIds {
 public:
  std::uint32_t local(std::uint32_t model_id) {
    const auto [local, added] = local_of_.try_emplace(model_id, static_cast<std::uint32_t>(to_model_.size()));
    if (added) to_model_.push_back(model_id);
    return local;
  }
  const std::vector<std::uint32_t>& to_model() const { return to_model_; }

 private:
  FlatMap<std::uint32_t, std::uint32_t, std::hash<std::uint32_t>> local_of_;
  std::vector<std::uint32_t> to_model_;
};

// The position groups refined by how vertices move: two vertices are one
// point for the levels only where they also move alike, so a triangle whose
// corners a pose pulls apart is never taken for a sliver.
std::vector<std::uint32_t> groups_moving_alike(std::span<const std::uint32_t> position_group,
                                               const std::vector<std::uint32_t>& motion_class) {
  std::vector<std::uint32_t> groups(position_group.begin(), position_group.end());
  if (motion_class.empty()) return groups;
  FlatMap<std::uint64_t, std::uint32_t, std::hash<std::uint64_t>> refined(groups.size());
  for (std::size_t v = 0; v < groups.size(); ++v) {
    const std::uint64_t key = (std::uint64_t{groups[v]} << 32) | motion_class[v];
    groups[v] = refined.try_emplace(key, static_cast<std::uint32_t>(refined.size())).first;
  }
  return groups;
}

bool corners_move_alike(const std::vector<std::uint32_t>& motion_class, const std::uint32_t* triangle) {
  if (motion_class.empty()) return true;
  return motion_class[triangle[0]] == motion_class[triangle[1]] &&
         motion_class[triangle[1]] == motion_class[triangle[2]];
}

// One submesh's triangles sorted for simplification: those at a hub, and
// those whose corners move apart in a pose, pass through unchanged (their
// corners then lie on the border of what is simplified, which stays); the
// rest go to the simplifier on their own compact vertex list, so its cost
// follows the submesh, not the whole model.
struct SubmeshSplit {
  std::vector<std::uint32_t> pinned;  // model vertex ids, kept as they are
  std::vector<std::uint32_t> free;    // local ids of `ids`
  CompactIds ids;
  std::vector<glm::vec3> local_positions;  // per local id
};

SubmeshSplit split_submesh(const Mesh& mesh, const std::vector<std::uint32_t>& position_group,
                           const std::vector<std::uint32_t>& source, const Submesh& sub,
                           const std::vector<bool>& dropped, const std::vector<std::uint32_t>& valence,
                           const std::vector<std::uint32_t>& motion_class) {
  SubmeshSplit split;
  for (std::size_t i = sub.first_index; i + 2 < std::size_t{sub.first_index} + sub.index_count; i += 3) {
    if (dropped[i / 3]) continue;
    const std::uint32_t* tri = &source[i];
    const auto g = corner_groups(position_group, tri);
    const bool at_hub =
        std::any_of(g.begin(), g.end(), [&](std::uint32_t p) { return valence[p] > kMaxSimplifiedValence; });
    if (at_hub || !corners_move_alike(motion_class, tri)) {
      split.pinned.insert(split.pinned.end(), tri, tri + 3);
      continue;
    }
    for (int k = 0; k < 3; ++k) split.free.push_back(split.ids.local(tri[k]));
  }
  for (const std::uint32_t v : split.ids.to_model()) split.local_positions.push_back(mesh.positions[v]);
  return split;
}

// Appends to `out` one submesh of the next level: its triangles at hubs as
// they are, the rest simplified toward `options.ratio` of the submesh with
// its border locked. Returns the step's error bound in the mesh's units.
double simplify_submesh(const Mesh& mesh, const std::vector<std::uint32_t>& position_group,
                        const std::vector<std::uint32_t>& source, const Submesh& sub, const std::vector<bool>& dropped,
                        const std::vector<std::uint32_t>& valence, const LodOptions& options,
                        std::vector<std::uint32_t>& out) {
  constexpr std::size_t stride = sizeof(glm::vec3);
  const SubmeshSplit split = split_submesh(mesh, position_group, source, sub, dropped, valence, options.motion_class);
  out.insert(out.end(), split.pinned.begin(), split.pinned.end());
  if (split.free.empty()) return 0.0;
  const std::size_t target_indices =
      std::max<std::size_t>(3, static_cast<std::size_t>(std::floor(sub.index_count * options.ratio / 3.0)) * 3);
  const std::size_t free_target =
      std::min(split.free.size(), target_indices > split.pinned.size() ? target_indices - split.pinned.size() : 0);
  std::vector<std::uint32_t> simplified(split.free.size());
  float error = 0;
  // No error cap: the triangle target drives each step, the error is
  // measured and kept beside the level.
  const std::size_t written =
      meshopt_simplify(simplified.data(), split.free.data(), split.free.size(), &split.local_positions[0].x,
                       split.local_positions.size(), stride, free_target, 1.0f, meshopt_SimplifyLockBorder, &error);
  for (std::size_t i = 0; i < written; ++i) out.push_back(split.ids.to_model()[simplified[i]]);
  // meshopt's error is a quadric estimate relative to the extent of what
  // it was given; on a sphere the true farthest stray measured up to ~2×
  // more with 75 % steps (mesh_lod_test), so it is taken 2.5 times to keep
  // the pixel budget an upper bound of the worst stray, not of a typical one.
  const double extent = meshopt_simplifyScale(&split.local_positions[0].x, split.local_positions.size(), stride);
  return kQuadricToWorstStray * static_cast<double>(error) * extent;
}

// Reorders one submesh's triangles for the vertex cache, on compact ids (a
// model of many small submeshes would otherwise pay the whole model's
// vertex count for each one). The optimiser also
// scores every triangle of each vertex in its cache at each step, so a hub
// would cost the square of its valence; triangles at hubs follow the rest
// in their own order (a hub stays in the cache anyway).
void reorder_range(std::uint32_t* indices, std::size_t count) {
  CompactIds ids;
  std::vector<std::uint32_t> local(count);
  for (std::size_t i = 0; i < count; ++i) local[i] = ids.local(indices[i]);
  const std::vector<std::uint32_t>& local_to_model = ids.to_model();
  std::vector<std::uint32_t> valence(local_to_model.size(), 0);
  for (const auto v : local) ++valence[v];
  std::vector<std::uint32_t> ordinary;
  std::vector<std::uint32_t> at_hubs;
  ordinary.reserve(count);
  for (std::size_t t = 0; t + 2 < count; t += 3) {
    const bool at_hub = valence[local[t]] > kMaxSimplifiedValence || valence[local[t + 1]] > kMaxSimplifiedValence ||
                        valence[local[t + 2]] > kMaxSimplifiedValence;
    auto& to = at_hub ? at_hubs : ordinary;
    to.insert(to.end(), &local[t], &local[t] + 3);
  }
  std::vector<std::uint32_t> reordered(ordinary.size());
  meshopt_optimizeVertexCache(reordered.data(), ordinary.data(), ordinary.size(), local_to_model.size());
  reordered.insert(reordered.end(), at_hubs.begin(), at_hubs.end());
  for (std::size_t i = 0; i < reordered.size(); ++i) indices[i] = local_to_model[reordered[i]];
}

void reorder_ranges(std::vector<std::uint32_t>& indices, const std::vector<Submesh>& submeshes) {
  for (const Submesh& sub : submeshes) {
    if (sub.index_count > 0) reorder_range(indices.data() + sub.first_index, sub.index_count);
  }
}

// Edges (between positions, split copies of a vertex counting as one) that
// only one triangle uses: the rims of holes, which an inverted hull shows as
// gaps. Edges more than two triangles share (the simplifier leaves a few
// folded pairs) close the surface all the same and do not count.
std::size_t open_edge_count(const std::vector<std::uint32_t>& position_group,
                            const std::vector<std::uint32_t>& indices) {
  EdgeTable uses(indices.size());
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = position_group[indices[t + k]];
      const std::uint32_t b = position_group[indices[t + (k + 1) % 3]];
      if (a != b) ++uses[EdgeTable::key(a, b)];
    }
  }
  std::size_t open = 0;
  uses.for_each([&](std::uint64_t, int count) { open += count == 1 ? 1 : 0; });
  return open;
}

}  // namespace

void optimize_for_vertex_cache(Mesh& mesh) {
  reorder_ranges(mesh.indices, mesh.submeshes);
  for (MeshLod& lod : mesh.lods) reorder_ranges(lod.indices, lod.submeshes);
}

std::vector<MeshLod> build_lod_chain(const Mesh& mesh, const LodOptions& options) {
  return build_lod_chain(mesh, group_by_position(mesh.positions), options);
}

std::vector<MeshLod> build_lod_chain(const Mesh& mesh, std::span<const std::uint32_t> groups,
                                     const LodOptions& options) {
  std::vector<MeshLod> chain;
  if (mesh.positions.empty() || mesh.indices.empty()) return chain;

  // Each level is simplified from the one before (cheap: every step works on
  // half the triangles of the last); its error is the sum of the steps'.
  // A level may not open the surface more than the full mesh is open:
  // meshopt occasionally tears one open, and a torn level would show
  // through the outline as a gap in the hull.
  const std::vector<std::uint32_t> position_group = groups_moving_alike(groups, options.motion_class);
  // Counted once a level is made: a mesh that gives none (a fan around one
  // hub, whose triangles all stay) need not count them.
  std::optional<std::size_t> full_open_edges;

  std::vector<std::uint32_t> source = mesh.indices;
  std::vector<Submesh> source_subs = mesh.submeshes;
  double source_error = 0;
  std::size_t source_triangles = source.size() / 3;
  while (chain.size() < options.max_levels) {
    const auto target_triangles =
        static_cast<std::size_t>(std::floor(static_cast<double>(source_triangles) * options.ratio));
    if (target_triangles < options.min_triangles) break;
    if (options.between_levels) options.between_levels();
    MeshLod lod;
    double step_error = 0;
    const std::vector<bool> dropped = droppable_triangles(position_group, source);
    const std::vector<std::uint32_t> valence = valence_of_positions(position_group, source, dropped);
    for (const Submesh& sub : source_subs) {
      Submesh out{static_cast<std::uint32_t>(lod.indices.size()), 0, sub.material};
      if (sub.index_count > 0) {
        const double error =
            simplify_submesh(mesh, position_group, source, sub, dropped, valence, options, lod.indices);
        out.index_count = static_cast<std::uint32_t>(lod.indices.size() - out.first_index);
        step_error = std::max(step_error, error);
      }
      lod.submeshes.push_back(out);
    }
    const std::size_t triangles = lod.triangle_count();
    if (static_cast<double>(triangles) > options.min_shrink * static_cast<double>(source_triangles)) break;
    lod.error = source_error + step_error;
    source = lod.indices;
    source_subs = lod.submeshes;
    source_error = lod.error;
    source_triangles = triangles;
    // The next level still grows from a torn one (seen to close again),
    // but a torn level is never drawn.
    if (!full_open_edges) full_open_edges = open_edge_count(position_group, mesh.indices);
    if (open_edge_count(position_group, lod.indices) <= *full_open_edges) chain.push_back(std::move(lod));
  }
  return chain;
}

void prepare_levels_of_detail(Mesh& mesh, const LodOptions& options) {
  prepare_levels_of_detail(mesh, group_by_position(mesh.positions), options);
}

void prepare_levels_of_detail(Mesh& mesh, std::span<const std::uint32_t> position_group, const LodOptions& options) {
  mesh.lods = build_lod_chain(mesh, position_group, options);
  optimize_for_vertex_cache(mesh);
}

}  // namespace toond::scene
