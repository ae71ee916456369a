#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <deque>
#include <map>
#include <random>
#include <vector>

#include "model_checks.h"
#include "render/plan/lod_choice.h"
#include "scene/import/bundle_import.h"
#include "scene/mesh/mesh_lod.h"
#include "scene/mesh/mesh_processing.h"
#include "support/generated_models.h"

namespace toond::scene {
namespace {

using test_checks::make_bundle;

Mesh imported_sphere(int segments = 128, int rings = 64) {
  return import_bundle(make_bundle({{"sphere.obj", toond::test::sphere_obj(segments, rings)}})).mesh;
}

using Triangle = std::array<std::uint32_t, 3>;

// The triangle with its smallest index first, winding kept.
Triangle canonical(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  if (b < a && b < c) return {b, c, a};
  if (c < a && c < b) return {c, a, b};
  return {a, b, c};
}

std::vector<Triangle> sorted_triangles(const std::vector<std::uint32_t>& indices, const Submesh& sub) {
  std::vector<Triangle> out;
  for (std::uint32_t i = sub.first_index; i < sub.first_index + sub.index_count; i += 3) {
    out.push_back(canonical(indices[i], indices[i + 1], indices[i + 2]));
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Vertices a 16-entry FIFO post-transform cache misses, per triangle.
double fifo_misses_per_triangle(const std::vector<std::uint32_t>& indices) {
  std::deque<std::uint32_t> cache;
  std::size_t misses = 0;
  for (const std::uint32_t v : indices) {
    if (std::find(cache.begin(), cache.end(), v) != cache.end()) continue;
    ++misses;
    cache.push_back(v);
    if (cache.size() > 16) cache.pop_front();
  }
  return static_cast<double>(misses) / static_cast<double>(indices.size() / 3);
}

// Edges by position (split copies of a vertex count as one), with how many
// triangles use each. A surface is closed when every edge has exactly two.
std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_uses(const Mesh& mesh,
                                                                 const std::vector<std::uint32_t>& indices) {
  // The generator's seam copies differ in the last bits (sin 2π ≠ 0):
  // weld at 1e-9 first.
  std::vector<glm::vec3> welded;
  for (const glm::vec3& p : mesh.positions) welded.push_back(glm::round(p * 1e6f) / 1e6f);
  const auto group = group_by_position(welded);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = group[indices[t + static_cast<std::size_t>(k)]];
      std::uint32_t b = group[indices[t + static_cast<std::size_t>((k + 1) % 3)]];
      if (a > b) std::swap(a, b);
      ++uses[{a, b}];
    }
  }
  return uses;
}

// Edges only one triangle uses: the rims of holes and cracks, where a hull
// would gap. (The simplifier leaves a few edges shared by more than two
// triangles, folded pairs: the surface stays closed there.)
std::size_t open_edges(const Mesh& mesh, const std::vector<std::uint32_t>& indices) {
  std::size_t open = 0;
  for (const auto& [edge, count] : edge_uses(mesh, indices)) open += count == 1 ? 1 : 0;
  return open;
}

TEST(MeshLod, ImportBuildsAChainThatShrinksWhileItsErrorGrows) {
  const Mesh mesh = imported_sphere();
  ASSERT_GE(mesh.lods.size(), 4u);
  std::size_t previous_triangles = mesh.triangle_count();
  double previous_error = 0;
  for (const MeshLod& lod : mesh.lods) {
    EXPECT_LE(static_cast<double>(lod.triangle_count()), 0.85 * static_cast<double>(previous_triangles));
    EXPECT_GE(lod.triangle_count(), 64u);
    EXPECT_GT(lod.error, previous_error);
    ASSERT_EQ(lod.submeshes.size(), mesh.submeshes.size());
    std::size_t covered = 0;
    for (const Submesh& sub : lod.submeshes) covered += sub.index_count;
    EXPECT_EQ(covered, lod.indices.size());
    for (const std::uint32_t i : lod.indices) ASSERT_LT(i, mesh.positions.size());
    previous_triangles = lod.triangle_count();
    previous_error = lod.error;
  }
}

TEST(MeshLod, ErrorBoundsHowFarALevelStraysFromTheSphere) {
  // A unit sphere's simplified surface lies inside it: the farthest a level
  // strays is the sagitta at a triangle's middle, which the level's error
  // must cover. Vertices stay on the sphere.
  const Mesh mesh = imported_sphere();
  for (const MeshLod& lod : mesh.lods) {
    double worst = 0;
    for (std::size_t t = 0; t < lod.indices.size(); t += 3) {
      const glm::dvec3 a = mesh.positions[lod.indices[t]], b = mesh.positions[lod.indices[t + 1]],
                       c = mesh.positions[lod.indices[t + 2]];
      worst = std::max(worst, 1.0 - glm::length((a + b + c) / 3.0));
    }
    EXPECT_GT(worst, 0.0);
    EXPECT_LE(worst, lod.error) << lod.triangle_count() << " triangles";
  }
}

// meshopt occasionally tears a coarse level (one open edge seen at 512 of
// the sphere's triangles): the chain ends before such a level.
TEST(MeshLod, LevelsOfAClosedMeshStayClosedSoTheHullHasNoGaps) {
  const Mesh mesh = imported_sphere();
  ASSERT_EQ(open_edges(mesh, mesh.indices), 0u);
  for (const MeshLod& lod : mesh.lods) EXPECT_EQ(open_edges(mesh, lod.indices), 0u) << lod.triangle_count();
  // The hull offsets are the full mesh's, per position: every copy of a
  // vertex moves by the same offset, so a closed level gives a closed hull.
  const auto group = group_by_position(mesh.positions);
  std::map<std::uint32_t, glm::vec3> offset_of_group;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const auto [it, fresh] = offset_of_group.emplace(group[v], mesh.outline_normals[v]);
    if (!fresh) {
      EXPECT_EQ(it->second, mesh.outline_normals[v]) << "vertex " << v;
    }
  }
}

TEST(MeshLod, MaterialsMeetWithoutCracksOnEveryLevel) {
  // The sphere split into two materials at its equator: each submesh is
  // simplified on its own, with its border locked.
  Mesh mesh = imported_sphere();
  const auto half = static_cast<std::uint32_t>(mesh.indices.size() / 6 * 3);
  mesh.submeshes = {{0, half, 0}, {half, static_cast<std::uint32_t>(mesh.indices.size()) - half, 1}};
  const auto chain = build_lod_chain(mesh);
  ASSERT_GE(chain.size(), 3u);
  for (const MeshLod& lod : chain) {
    ASSERT_EQ(lod.submeshes.size(), 2u);
    EXPECT_EQ(lod.submeshes[0].material, 0);
    EXPECT_EQ(lod.submeshes[1].material, 1);
    EXPECT_GT(lod.submeshes[0].index_count, 0u);
    EXPECT_GT(lod.submeshes[1].index_count, 0u);
    EXPECT_EQ(open_edges(mesh, lod.indices), 0u) << lod.triangle_count();
  }
}

// A welded sphere without normals, as a scanner or the bench writes it:
// every level the simplifier makes has a few edges shared by four
// triangles (folded pairs) but no hole, so none may be dropped — the chain
// steps by 60 % from the start instead of jumping from 62k to 5k triangles.
TEST(MeshLod, FoldedButClosedLevelsAreKept) {
  const int rings = 125, segments = 250;
  std::string obj = "v 0 1 0\n";
  for (int r = 1; r < rings; ++r) {
    const double theta = std::acos(-1.0) * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2.0 * std::acos(-1.0) * s / segments;
      obj += "v " + std::to_string(std::sin(theta) * std::cos(phi)) + " " + std::to_string(std::cos(theta)) + " " +
             std::to_string(-std::sin(theta) * std::sin(phi)) + "\n";
    }
  }
  obj += "v 0 -1 0\n";
  const int south = 2 + (rings - 1) * segments;
  auto at = [&](int r, int s) { return std::to_string(2 + (r - 1) * segments + (s % segments)); };
  for (int s = 0; s < segments; ++s) {
    obj += "f 1 " + at(1, s) + " " + at(1, s + 1) + "\n";
    obj += "f " + std::to_string(south) + " " + at(rings - 1, s + 1) + " " + at(rings - 1, s) + "\n";
  }
  for (int r = 1; r + 1 < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      obj += "f " + at(r, s) + " " + at(r + 1, s) + " " + at(r + 1, s + 1) + "\n";
      obj += "f " + at(r, s) + " " + at(r + 1, s + 1) + " " + at(r, s + 1) + "\n";
    }
  }
  const Mesh mesh = import_bundle(make_bundle({{"sphere.obj", obj}})).mesh;
  ASSERT_EQ(open_edges(mesh, mesh.indices), 0u);
  ASSERT_FALSE(mesh.lods.empty());
  const double full = static_cast<double>(mesh.indices.size() / 3);
  EXPECT_GT(static_cast<double>(mesh.lods.front().triangle_count()), 0.5 * full);
  for (const MeshLod& lod : mesh.lods) EXPECT_EQ(open_edges(mesh, lod.indices), 0u) << lod.triangle_count();
}

TEST(MeshLod, VertexCacheOrderKeepsEveryTriangleAndMissesLess) {
  Mesh mesh = imported_sphere(64, 32);
  // Shuffle the triangles, as a careless exporter might write them.
  std::vector<Triangle> triangles;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    triangles.push_back({mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]});
  }
  std::shuffle(triangles.begin(), triangles.end(), std::mt19937(7));
  mesh.indices.clear();
  for (const Triangle& t : triangles) mesh.indices.insert(mesh.indices.end(), t.begin(), t.end());
  mesh.lods.clear();
  const auto before = sorted_triangles(mesh.indices, mesh.submeshes[0]);
  const double misses_before = fifo_misses_per_triangle(mesh.indices);

  optimize_for_vertex_cache(mesh);

  EXPECT_EQ(sorted_triangles(mesh.indices, mesh.submeshes[0]), before);
  const double misses_after = fifo_misses_per_triangle(mesh.indices);
  EXPECT_LT(misses_after, 0.5 * misses_before) << misses_before << " -> " << misses_after;
  EXPECT_LT(misses_after, 1.0);
}

}  // namespace
}  // namespace toond::scene

namespace toond::render {
namespace {

TEST(LodChoice, PicksTheCoarsestLevelWithinTheBudget) {
  const std::vector<double> errors = {0.0, 0.001, 0.004, 0.016, 0.064};
  // 100 px per unit: errors of 0, 0.1, 0.4, 1.6, 6.4 px.
  EXPECT_EQ(choose_lod(errors, 100.0, 0.5), 2u);
  EXPECT_EQ(choose_lod(errors, 100.0, 0.05), 0u);
  EXPECT_EQ(choose_lod(errors, 100.0, 10.0), 4u);
  EXPECT_EQ(choose_lod(errors, 400.0, 0.5), 1u);  // 0.4 px, then 1.6 px
  EXPECT_EQ(choose_lod(errors, 100.0, 0.0), 0u);  // a budget of 0 means full detail
  EXPECT_EQ(choose_lod({}, 100.0, 1.0), 0u);
}

TEST(LodChoice, PixelsPerUnitFollowTheProjection) {
  CameraParams params;
  params.fov_deg = 90;
  const scene::Bounds unit{glm::vec3(-1), glm::vec3(1)};
  const CameraSetup cam = fit_camera(params, unit, 1.0);
  // fov 90°: at depth d one unit spans (H / 2) / d pixels.
  const glm::dvec3 forward = glm::normalize(cam.target - cam.eye);
  const glm::dvec3 at_depth_4 = cam.eye + forward * 5.0;  // sphere of radius 1: nearest point at 4
  EXPECT_NEAR(pixels_per_unit(cam, false, at_depth_4, 1.0, 512), 256.0 / 4.0, 1e-9);
  // Twice as far, half as many pixels; twice the image, twice as many.
  EXPECT_NEAR(pixels_per_unit(cam, false, cam.eye + forward * 9.0, 1.0, 512), 256.0 / 8.0, 1e-9);
  EXPECT_NEAR(pixels_per_unit(cam, false, at_depth_4, 1.0, 1024), 512.0 / 4.0, 1e-9);
  // A sphere around the eye is as near as the near plane allows.
  EXPECT_NEAR(pixels_per_unit(cam, false, cam.eye, 1.0, 512), 256.0 / cam.near_plane, 1e-6);

  params.projection = Projection::Orthographic;
  const CameraSetup ortho = fit_camera(params, unit, 1.0);
  const double expected = ortho.projection[1][1] * 256.0;
  EXPECT_NEAR(pixels_per_unit(ortho, true, ortho.target, 1.0, 512), expected, 1e-9);
  EXPECT_NEAR(pixels_per_unit(ortho, true, ortho.eye, 1.0, 512), expected, 1e-9);
}

}  // namespace
}  // namespace toond::render
