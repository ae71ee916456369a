#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "scene/mesh/mesh_processing.h"

namespace toond::scene {
namespace {

constexpr float kTol = 1e-5f;

struct TestMesh {
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;
};

// Unit cube around the origin. shared: 8 vertices; otherwise 4 per face
// (hard edges, as an exporter writes flat-shaded boxes).
TestMesh make_cube(bool shared) {
  TestMesh m;
  const auto corner = [](int i) {
    return glm::vec3((i & 1) ? 0.5f : -0.5f, (i & 2) ? 0.5f : -0.5f, (i & 4) ? 0.5f : -0.5f);
  };
  // Faces as corner bit patterns, counter-clockwise seen from outside.
  const int faces[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
  if (shared) {
    for (int i = 0; i < 8; ++i) m.positions.push_back(corner(i));
  }
  for (const auto& f : faces) {
    std::uint32_t idx[4];
    for (int k = 0; k < 4; ++k) {
      if (shared) {
        idx[k] = static_cast<std::uint32_t>(f[k]);
      } else {
        idx[k] = static_cast<std::uint32_t>(m.positions.size());
        m.positions.push_back(corner(f[k]));
      }
    }
    m.indices.insert(m.indices.end(), {idx[0], idx[1], idx[2], idx[0], idx[2], idx[3]});
  }
  return m;
}

TestMesh make_sphere(int segments, int rings, float radius, glm::vec3 centre) {
  TestMesh m;
  for (int r = 0; r <= rings; ++r) {
    for (int s = 0; s <= segments; ++s) {  // seam column duplicated, as with UVs
      const double theta = std::numbers::pi * r / rings;
      const double phi = 2 * std::numbers::pi * s / segments;
      m.positions.push_back(centre + radius * glm::vec3(std::sin(theta) * std::sin(phi), std::cos(theta),
                                                        std::sin(theta) * std::cos(phi)));
    }
  }
  const auto at = [&](int r, int s) { return static_cast<std::uint32_t>(r * (segments + 1) + s); };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      if (r > 0) m.indices.insert(m.indices.end(), {at(r, s), at(r + 1, s), at(r, s + 1)});
      if (r + 1 < rings) m.indices.insert(m.indices.end(), {at(r, s + 1), at(r + 1, s), at(r + 1, s + 1)});
    }
  }
  return m;
}

void expect_unit(const glm::vec3& n) { EXPECT_NEAR(glm::length(n), 1.0f, kTol); }

TEST(MeshProcessing, SharedCubeNormalsPointAlongTheDiagonals) {
  const TestMesh cube = make_cube(true);
  const auto normals = compute_angle_weighted_normals(cube.positions, cube.indices);
  ASSERT_EQ(normals.size(), 8u);
  for (std::size_t v = 0; v < 8; ++v) {
    expect_unit(normals[v]);
    // Each face meets a corner with 90 degrees in total however it was
    // split, so angle weighting gives the exact diagonal (area or count
    // weighting would not).
    const glm::vec3 diagonal = glm::normalize(cube.positions[v]);
    EXPECT_NEAR(glm::dot(normals[v], diagonal), 1.0f, kTol) << "vertex " << v;
  }
}

TEST(MeshProcessing, HardCubeKeepsFaceNormalsButSharesOutlineNormals) {
  const TestMesh cube = make_cube(false);
  ASSERT_EQ(cube.positions.size(), 24u);
  const auto normals = compute_angle_weighted_normals(cube.positions, cube.indices);
  const auto outline = compute_outline_normals(cube.positions, cube.indices, normals);
  for (std::size_t face = 0; face < 6; ++face) {
    const glm::vec3 n = normals[face * 4];
    for (std::size_t k = 0; k < 4; ++k) {
      EXPECT_NEAR(glm::length(normals[face * 4 + k] - n), 0.0f, kTol);
    }
    // Axis-aligned and outward.
    EXPECT_NEAR(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0f, kTol);
    EXPECT_GT(glm::dot(n, cube.positions[face * 4]), 0.0f);
  }
  // The three copies of each corner get one outline offset: the diagonal,
  // mitred so that each of the three faces moves out by exactly one unit.
  for (std::size_t v = 0; v < 24; ++v) {
    EXPECT_NEAR(glm::length(outline[v]), std::sqrt(3.0f), kTol) << "vertex " << v;
    EXPECT_NEAR(glm::dot(glm::normalize(outline[v]), glm::normalize(cube.positions[v])), 1.0f, kTol) << "vertex " << v;
    for (std::size_t face = 0; face < 6; ++face) {
      const glm::vec3 n = normals[face * 4];
      // Faces that meet at this corner see the plane move by one unit.
      if (glm::dot(n, cube.positions[v]) > 0.0f) {
        EXPECT_NEAR(glm::dot(outline[v], n), 1.0f, kTol);
      }
    }
    for (std::size_t w = 0; w < 24; ++w) {
      if (cube.positions[w] == cube.positions[v]) {
        EXPECT_EQ(outline[w], outline[v]);
      }
    }
  }
}

TEST(MeshProcessing, SphereNormalsAreUnitAndOutward) {
  const glm::vec3 centre(3.0f, -2.0f, 1.0f);
  const TestMesh sphere = make_sphere(32, 16, 2.0f, centre);
  const auto normals = compute_angle_weighted_normals(sphere.positions, sphere.indices);
  const auto outline = compute_outline_normals(sphere.positions, sphere.indices, normals);
  std::vector<bool> used(sphere.positions.size(), false);
  for (const auto i : sphere.indices) used[i] = true;
  for (std::size_t v = 0; v < sphere.positions.size(); ++v) {
    if (!used[v]) continue;  // one pole copy closes no triangle
    const glm::vec3 radial = glm::normalize(sphere.positions[v] - centre);
    expect_unit(normals[v]);
    // On a smooth surface the mitre is nearly nothing: unit length within
    // the facets' deviation from the averaged normal.
    EXPECT_GE(glm::length(outline[v]), 1.0f - kTol);
    EXPECT_LT(glm::length(outline[v]), 1.05f);
    EXPECT_GT(glm::dot(glm::normalize(outline[v]), radial), 0.99f) << "vertex " << v;
    // Split seam and pole vertices see only part of their fan; the outline
    // normal, averaged over the whole position, is the one that must be
    // radial. Interior vertices are radial already.
    EXPECT_GT(glm::dot(normals[v], radial), 0.7f) << "vertex " << v;
  }
}

TEST(MeshProcessing, GroupByPositionMergesIdenticalCoordinatesOnly) {
  const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {-0.0f, 0, 0}, {1, 0, 0}, {1, 0, 1e-7f}};
  const auto g = group_by_position(p);
  EXPECT_EQ(g, (std::vector<std::uint32_t>{0, 1, 0, 1, 2}));
}

// Many points, most of them written several times and some in both zeros:
// the ids are those a map from coordinates to the next free number gives,
// in order of first appearance, however the points crowd the table.
TEST(MeshProcessing, GroupByPositionNumbersPointsInOrderOfFirstAppearance) {
  std::vector<glm::vec3> p;
  for (int i = 0; i < 60000; ++i) {
    const int k = (i * 7919) % 20011;  // repeats, out of order
    const float zero = i % 2 ? 0.0f : -0.0f;
    p.emplace_back(static_cast<float>(k % 101), static_cast<float>(k / 101) * 0.5f, k % 3 == 0 ? zero : 1.0f);
  }
  std::map<std::array<float, 3>, std::uint32_t> seen;
  std::vector<std::uint32_t> expected;
  for (const glm::vec3& q : p) {
    const std::array<float, 3> key = {q.x + 0.0f, q.y + 0.0f, q.z + 0.0f};
    expected.push_back(seen.emplace(key, static_cast<std::uint32_t>(seen.size())).first->second);
  }
  ASSERT_LT(seen.size(), p.size());
  EXPECT_EQ(group_by_position(p), expected);
}

TEST(MeshProcessing, OutlineNormalFallsBackWhereFacesCancel) {
  // A two-sided sheet: the same triangle twice, opposite windings.
  const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<std::uint32_t> idx = {0, 1, 2, 3, 5, 4};
  const auto normals = compute_angle_weighted_normals(p, idx);
  EXPECT_NEAR(glm::length(normals[0] - glm::vec3(0, 0, 1)), 0.0f, kTol);
  EXPECT_NEAR(glm::length(normals[3] - glm::vec3(0, 0, -1)), 0.0f, kTol);
  const auto outline = compute_outline_normals(p, idx, normals);
  for (std::size_t v = 0; v < p.size(); ++v) {
    EXPECT_EQ(outline[v], normals[v]);
    EXPECT_FALSE(std::isnan(outline[v].x));
  }
}

TEST(MeshProcessing, DegenerateTriangles) {
  const glm::dvec3 a(0, 0, 0), b(1, 0, 0), c(2, 0, 0), d(0, 1, 0);
  EXPECT_TRUE(is_degenerate_triangle(a, b, c));  // collinear
  EXPECT_TRUE(is_degenerate_triangle(a, a, d));  // repeated corner
  EXPECT_TRUE(is_degenerate_triangle(a, a, a));
  EXPECT_FALSE(is_degenerate_triangle(a, b, d));
  // Thin but real, and tiny but well-shaped: both kept.
  EXPECT_FALSE(is_degenerate_triangle(a, glm::dvec3(1000, 0, 0), glm::dvec3(500, 1e-4, 0)));
  EXPECT_FALSE(is_degenerate_triangle(a * 1e-9, b * 1e-9, d * 1e-9));
  EXPECT_EQ(triangle_normal(a, b, c), glm::dvec3(0.0));
  EXPECT_EQ(triangle_normal(a, b, d), glm::dvec3(0, 0, 1));
}

TEST(MeshProcessing, TriangleAnglesSumToPi) {
  const glm::dvec3 angles = triangle_angles({0, 0, 0}, {3, 0, 0}, {0, 4, 0});
  EXPECT_NEAR(angles.x, std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(angles.x + angles.y + angles.z, std::numbers::pi, 1e-12);
  EXPECT_NEAR(angles.y, std::atan2(4.0, 3.0), 1e-12);
}

// A unit quad in the XY plane facing +Z, two triangles, with the given UVs.
struct TangentCase {
  std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  std::vector<glm::vec3> normals = std::vector<glm::vec3>(4, glm::vec3(0, 0, 1));
  std::vector<std::uint32_t> indices{0, 1, 2, 0, 2, 3};
  std::vector<glm::vec2> uvs;
  std::vector<glm::vec4> run() const { return compute_tangents(positions, normals, uvs, indices); }
};

void expect_tangent_frame(const glm::vec4& t, const glm::vec3& n) {
  ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z) && std::isfinite(t.w));
  EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, kTol);
  EXPECT_NEAR(glm::dot(glm::vec3(t), n), 0.0f, kTol);
  EXPECT_TRUE(t.w == 1.0f || t.w == -1.0f);
}

TEST(MeshProcessing, TangentAlongUWithRightHandedUVs) {
  TangentCase q;
  q.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const auto& t : q.run()) {
    expect_tangent_frame(t, {0, 0, 1});
    EXPECT_NEAR(glm::length(glm::vec3(t) - glm::vec3(1, 0, 0)), 0.0f, kTol);
    EXPECT_EQ(t.w, 1.0f);
    // bitangent = w * cross(n, t) runs along +V, i.e. +Y here.
    EXPECT_NEAR(glm::length(t.w * glm::cross(glm::vec3(0, 0, 1), glm::vec3(t)) - glm::vec3(0, 1, 0)), 0.0f, kTol);
  }
  // Scaled and rotated UVs: U along +Y, V along -X; still right-handed.
  q.uvs = {{0, 0}, {0, -3}, {3, -3}, {3, 0}};
  for (const auto& t : q.run()) {
    expect_tangent_frame(t, {0, 0, 1});
    EXPECT_NEAR(glm::length(glm::vec3(t) - glm::vec3(0, 1, 0)), 0.0f, kTol);
    EXPECT_EQ(t.w, 1.0f);
  }
}

TEST(MeshProcessing, MirroredUVsGiveNegativeHandedness) {
  TangentCase q;
  q.uvs = {{1, 0}, {0, 0}, {0, 1}, {1, 1}};  // U runs along -X
  for (const auto& t : q.run()) {
    expect_tangent_frame(t, {0, 0, 1});
    EXPECT_NEAR(glm::length(glm::vec3(t) - glm::vec3(-1, 0, 0)), 0.0f, kTol);
    EXPECT_EQ(t.w, -1.0f);
    EXPECT_NEAR(glm::length(t.w * glm::cross(glm::vec3(0, 0, 1), glm::vec3(t)) - glm::vec3(0, 1, 0)), 0.0f, kTol);
  }
  q.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};  // V runs along -Y
  for (const auto& t : q.run()) {
    EXPECT_NEAR(glm::length(glm::vec3(t) - glm::vec3(1, 0, 0)), 0.0f, kTol);
    EXPECT_EQ(t.w, -1.0f);
  }
}

TEST(MeshProcessing, TangentIsOrthogonalisedAgainstTheShadingNormal) {
  TangentCase q;
  q.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const glm::vec3 tilted = glm::normalize(glm::vec3(1, 0, 1));
  q.normals.assign(4, tilted);
  for (const auto& t : q.run()) {
    expect_tangent_frame(t, tilted);
    EXPECT_NEAR(glm::length(glm::vec3(t) - glm::normalize(glm::vec3(1, 0, -1))), 0.0f, kTol);
    EXPECT_EQ(t.w, 1.0f);
  }
}

TEST(MeshProcessing, DegenerateOrMissingUVsGiveAPerpendicularTangent) {
  TangentCase q;
  for (const auto& uvs :
       {std::vector<glm::vec2>(4, glm::vec2(0.5f)),                              // all equal
        std::vector<glm::vec2>{{0, 0}, {1, 1}, {2, 2}, {3, 3}},                  // collinear
        std::vector<glm::vec2>{{0, 0}, {1e30f, 0}, {1e30f, 1e30f}, {0, 1e30f}},  // huge (still finite)
        std::vector<glm::vec2>{}}) {                                             // none
    q.uvs = uvs;
    const auto tangents = q.run();
    ASSERT_EQ(tangents.size(), 4u);
    for (const auto& t : tangents) {
      expect_tangent_frame(t, {0, 0, 1});
      EXPECT_EQ(t.w, 1.0f);
    }
  }
  // Zero or non-finite normals still get a finite unit tangent.
  q.uvs = std::vector<glm::vec2>(4, glm::vec2(0.0f));
  q.normals.assign(4, glm::vec3(0.0f));
  q.normals[1] = glm::vec3(std::nanf(""), 0, 0);
  for (const auto& t : q.run()) {
    ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z));
    EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, kTol);
  }
}

TEST(MeshProcessing, AnyPerpendicularIsUnitAndPerpendicular) {
  const TestMesh sphere = make_sphere(16, 8, 1.0f, {0, 0, 0});
  std::vector<glm::vec3> directions = sphere.positions;
  directions.insert(directions.end(), {{0, 0, 1}, {0, 0, -1}, {0, 1, 0}, {1e-30f, 0, -1}, {0, 0, 0}});
  for (const auto& d : directions) {
    const glm::vec3 p = any_perpendicular(d);
    EXPECT_NEAR(glm::length(p), 1.0f, kTol) << d.x << " " << d.y << " " << d.z;
    if (glm::length(d) > 0.0f) {
      EXPECT_NEAR(glm::dot(p, glm::normalize(d)), 0.0f, kTol);
    }
  }
}

TEST(MeshProcessing, BoundsHoldEveryPosition) {
  const TestMesh sphere = make_sphere(8, 4, 1.5f, {10, 20, 30});
  const Bounds b = compute_bounds(sphere.positions);
  EXPECT_NEAR(b.min.y, 18.5f, 1e-4f);
  EXPECT_NEAR(b.max.y, 21.5f, 1e-4f);
  for (const auto& p : sphere.positions) {
    EXPECT_TRUE(glm::all(glm::lessThanEqual(b.min, p)) && glm::all(glm::lessThanEqual(p, b.max)));
  }
  const Bounds empty = compute_bounds({});
  EXPECT_EQ(empty.min, glm::vec3(0.0f));
  EXPECT_EQ(empty.max, glm::vec3(0.0f));
}

}  // namespace
}  // namespace toond::scene
