#include "scene/mesh_lod.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "scene/mesh_processing.h"

namespace toond::scene {
namespace {

constexpr double kQuadricToWorstStray = 2.5;

void reorder_ranges(std::vector<std::uint32_t>& indices, std::vector<Submesh>& submeshes,
                    std::size_t vertex_count) {
  // Anything outside a submesh range (there should be nothing) stays put.
  std::vector<std::uint32_t> reordered = indices;
  for (const Submesh& sub : submeshes) {
    if (sub.index_count == 0) continue;
    meshopt_optimizeVertexCache(reordered.data() + sub.first_index, indices.data() + sub.first_index,
                                sub.index_count, vertex_count);
  }
  indices = std::move(reordered);
}

// Edges (between positions, split copies of a vertex counting as one) that
// only one triangle uses: the rims of holes, which an inverted hull shows as
// gaps. Edges more than two triangles share (the simplifier leaves a few
// folded pairs) close the surface all the same and do not count.
std::size_t open_edge_count(const std::vector<std::uint32_t>& position_group,
                            const std::vector<std::uint32_t>& indices) {
  std::unordered_map<std::uint64_t, int> uses;
  uses.reserve(indices.size());
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    for (std::size_t k = 0; k < 3; ++k) {
      std::uint64_t a = position_group[indices[t + k]];
      std::uint64_t b = position_group[indices[t + (k + 1) % 3]];
      if (a == b) continue;
      if (a > b) std::swap(a, b);
      ++uses[a << 32 | b];
    }
  }
  return static_cast<std::size_t>(std::count_if(uses.begin(), uses.end(), [](const auto& e) { return e.second == 1; }));
}

}  // namespace

void optimize_for_vertex_cache(Mesh& mesh) {
  const std::size_t vertex_count = mesh.positions.size();
  reorder_ranges(mesh.indices, mesh.submeshes, vertex_count);
  for (MeshLod& lod : mesh.lods) reorder_ranges(lod.indices, lod.submeshes, vertex_count);
}

std::vector<MeshLod> build_lod_chain(const Mesh& mesh, const LodOptions& options) {
  std::vector<MeshLod> chain;
  if (mesh.positions.empty() || mesh.indices.empty()) return chain;
  const float* positions = &mesh.positions[0].x;
  const std::size_t vertex_count = mesh.positions.size();
  const std::size_t stride = sizeof(glm::vec3);
  // meshopt reports errors relative to the mesh's extent.
  const double scale = meshopt_simplifyScale(positions, vertex_count, stride);

  // Each level is simplified from the one before (cheap: every step works on
  // half the triangles of the last); its error is the sum of the steps'.
  // A level may not open the surface more than the full mesh is open:
  // meshopt occasionally tears one open, and a torn level would show
  // through the outline as a gap in the hull.
  const std::vector<std::uint32_t> position_group = group_by_position(mesh.positions);
  const std::size_t full_open_edges = open_edge_count(position_group, mesh.indices);

  std::vector<std::uint32_t> source = mesh.indices;
  std::vector<Submesh> source_subs = mesh.submeshes;
  double source_error = 0;
  std::size_t source_triangles = source.size() / 3;
  while (chain.size() < options.max_levels) {
    const auto target_triangles =
        static_cast<std::size_t>(std::floor(static_cast<double>(source_triangles) * options.ratio));
    if (target_triangles < options.min_triangles) break;
    MeshLod lod;
    double step_error = 0;
    for (const Submesh& sub : source_subs) {
      Submesh out{static_cast<std::uint32_t>(lod.indices.size()), 0, sub.material};
      if (sub.index_count > 0) {
        const std::size_t target_indices = std::max<std::size_t>(
            3, static_cast<std::size_t>(std::floor(sub.index_count * options.ratio / 3.0)) * 3);
        std::vector<std::uint32_t> simplified(sub.index_count);
        float sub_error = 0;
        // No error cap: the triangle target drives each step, the error is
        // measured and kept beside the level.
        const std::size_t written = meshopt_simplify(
            simplified.data(), source.data() + sub.first_index, sub.index_count, positions, vertex_count, stride,
            target_indices, 1.0f, meshopt_SimplifyLockBorder, &sub_error);
        lod.indices.insert(lod.indices.end(), simplified.begin(),
                           simplified.begin() + static_cast<std::ptrdiff_t>(written));
        out.index_count = static_cast<std::uint32_t>(written);
        // meshopt's error is a quadric estimate; on a sphere the true
        // farthest stray measured up to ~2× more with 75 % steps
        // (mesh_lod_test), so it is taken 2.5 times to keep the pixel budget
        // an upper bound of the worst stray, not of a typical one.
        step_error = std::max(step_error, kQuadricToWorstStray * static_cast<double>(sub_error) * scale);
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
    if (open_edge_count(position_group, lod.indices) <= full_open_edges) chain.push_back(std::move(lod));
  }
  return chain;
}

void prepare_levels_of_detail(Mesh& mesh, const LodOptions& options) {
  mesh.lods = build_lod_chain(mesh, options);
  optimize_for_vertex_cache(mesh);
}

}  // namespace toond::scene
