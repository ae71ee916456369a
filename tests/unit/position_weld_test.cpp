// Near-duplicate positions become one; distinct ones stay apart; the weld
// stays linear in the number of positions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "scene/mesh/crease_edges.h"
#include "scene/mesh/crease_profile.h"
#include "scene/mesh/mesh_processing.h"
#include "scene/mesh/position_weld.h"

namespace toond::scene {
namespace {

TEST(PositionWeld, PointsARoundingErrorApartBecomeOne) {
  // A pole as an exporter writes it: sin(π) is 1.2e-16, not 0.
  std::vector<glm::vec3> p = {
      {1.2246e-16f, -1, 0}, {0, -1, -1.2246e-16f}, {-1.2246e-16f, -1, 1e-16f}, {1, 0, 0}, {-1, 1, 0}};
  const WeldReport report = weld_positions(p);
  EXPECT_NEAR(report.tolerance, std::sqrt(4.0 + 4.0 + 0.0) * kWeldRelativeTolerance, 1e-12);
  EXPECT_EQ(report.moved, 2u);
  EXPECT_EQ(p[1], p[0]);
  EXPECT_EQ(p[2], p[0]);
  EXPECT_NE(p[3], p[0]);
  const std::vector<std::uint32_t> groups = group_by_position(p);
  EXPECT_EQ(groups[0], groups[2]);
  EXPECT_NE(groups[0], groups[3]);
}

TEST(PositionWeld, PointsFartherThanTheToleranceStayApart) {
  std::vector<glm::vec3> p = {{0, 0, 0}, {1, 1, 1}, {0, 0, 3e-6f}};
  const std::vector<glm::vec3> before = p;
  const WeldReport report = weld_positions(p);
  ASSERT_LT(report.tolerance, 3e-6);
  EXPECT_EQ(report.moved, 0u);
  EXPECT_EQ(p, before);
}

// Many copies of a point, and a dense cloud of distinct points: n and 2n
// take time in proportion (a ratio, so it holds on a noisy machine).
// A cube with a normal per face is creased along every edge it has; a
// sphere with smooth normals nowhere.
struct FlatCube {
  std::vector<glm::vec3> positions, normals;
  std::vector<std::uint32_t> indices;
};

// A cube of side 2, a normal per face (each face's four corners its own
// vertices), its faces wound counter-clockwise from outside.
FlatCube flat_cube() {
  FlatCube cube;
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int a = 0; a < 3; ++a) {
    for (const float s : {-1.0f, 1.0f}) {
      const glm::vec3 n = axes[a] * s, u = axes[(a + 1) % 3], v = axes[(a + 2) % 3] * s;
      const auto base = static_cast<std::uint32_t>(cube.positions.size());
      for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        cube.positions.push_back(n + u * c.x + v * c.y);
        cube.normals.push_back(n);
      }
      for (const std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) cube.indices.push_back(base + i);
    }
  }
  return cube;
}

TEST(CreaseProfile, ACubeIsHardEdgedAndASmoothSphereIsNot) {
  FlatCube flat = flat_cube();
  std::vector<glm::vec3>& positions = flat.positions;
  std::vector<glm::vec3>& normals = flat.normals;
  const std::vector<std::uint32_t>& indices = flat.indices;
  const CreaseProfile cube = measure_creases(positions, normals, indices);
  EXPECT_TRUE(cube.hard_edged(40));
  EXPECT_TRUE(cube.hard_edged(89));
  EXPECT_FALSE(cube.hard_edged(91));

  // The same cube with one normal per corner (pointing out of the corner):
  // nothing turns across an edge.
  for (std::size_t i = 0; i < positions.size(); ++i) normals[i] = glm::normalize(positions[i]);
  EXPECT_FALSE(measure_creases(positions, normals, indices).hard_edged(40));
}

// Whether (x, y, z) is a triangle of `indices` in its own winding.
bool wound_triangle(const std::vector<std::uint32_t>& indices, std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    for (int k = 0; k < 3; ++k) {
      if (indices[t + k] == x && indices[t + (k + 1) % 3] == y && indices[t + (k + 2) % 3] == z) return true;
    }
  }
  return false;
}

// The cube's twelve edges turn by 90° (its faces' diagonals by nothing):
// creased at any angle below 90, none at 90 or above, each drawn with its
// two faces' corners as the crease pass reads them.
TEST(CreaseEdges, ACubesTwelveEdgesAreCreasedBelowNinetyDegrees) {
  const FlatCube cube = flat_cube();
  const CreaseEdges edges = find_crease_edges(cube.positions, cube.normals, cube.indices);
  ASSERT_EQ(edges.size(), 12u);
  EXPECT_EQ(edges.creased_at(1), 12u);
  EXPECT_EQ(edges.creased_at(40), 12u);
  EXPECT_EQ(edges.creased_at(89.5), 12u);
  EXPECT_EQ(edges.creased_at(90), 0u);
  // Twelve edges of length 2 over the diagonal 2√3.
  EXPECT_NEAR(edges.length_at(40), 12.0 * 2.0 / (2.0 * std::sqrt(3.0)), 1e-5);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const std::uint32_t c1 = edges.indices[4 * e], a = edges.indices[4 * e + 1], b = edges.indices[4 * e + 2],
                        c2 = edges.indices[4 * e + 3];
    EXPECT_TRUE(wound_triangle(cube.indices, a, b, c1)) << "edge " << e << ": face 1 is (a, b, c1)";
    // Face 2 has its own copies of a and b, at the same points.
    const glm::vec3 pa = cube.positions[a], pb = cube.positions[b];
    bool face_two = false;
    for (std::size_t t = 0; t + 2 < cube.indices.size(); t += 3) {
      const std::uint32_t* f = &cube.indices[t];
      for (int k = 0; k < 3; ++k) {
        face_two |= f[(k + 2) % 3] == c2 && cube.positions[f[k]] == pb && cube.positions[f[(k + 1) % 3]] == pa;
      }
    }
    EXPECT_TRUE(face_two) << "edge " << e << ": face 2 winds (b, a, c2)";
  }
}

// Edges are sorted by their turn, the greatest first, so the edges creased
// at an angle are the first so many; a smooth surface has none at all.
TEST(CreaseEdges, TheGreatestTurnsComeFirstAndSmoothSurfacesHaveNone) {
  // A strip of three flat faces across a bent profile: the first bend
  // turns by 30°, the second by a further 90°.
  const double kPi = std::acos(-1.0);
  std::vector<glm::vec3> profile = {{0, 0, 0}, {1, 0, 0}};
  for (const double heading : {30.0, 120.0}) {
    const double r = heading * kPi / 180.0;
    profile.push_back(profile.back() + glm::vec3(static_cast<float>(std::cos(r)), static_cast<float>(std::sin(r)), 0));
  }
  std::vector<glm::vec3> positions, normals;
  std::vector<std::uint32_t> indices;
  const glm::vec3 z(0, 0, 1);
  for (std::size_t f = 0; f + 1 < profile.size(); ++f) {
    const glm::vec3 p0 = profile[f], p1 = profile[f + 1];
    const glm::vec3 n = glm::normalize(glm::cross(p1 - p0, z));
    const auto base = static_cast<std::uint32_t>(positions.size());
    for (const glm::vec3& p : {p0, p0 + z, p1 + z, p1}) {
      positions.push_back(p);
      normals.push_back(n);
    }
    for (const std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(base + i);
  }
  const CreaseEdges edges = find_crease_edges(positions, normals, indices);
  ASSERT_EQ(edges.size(), 2u);
  EXPECT_EQ(edges.creased_at(20), 2u);
  EXPECT_EQ(edges.creased_at(40), 1u);
  EXPECT_EQ(edges.creased_at(89), 1u);
  EXPECT_EQ(edges.creased_at(90), 0u);
  // The 90° bend, between the second and third faces, comes first.
  const glm::vec3 first_a = positions[edges.indices[1]];
  EXPECT_NEAR(first_a.x, profile[2].x, 1e-6);
  EXPECT_NEAR(first_a.y, profile[2].y, 1e-6);

  FlatCube cube = flat_cube();
  for (std::size_t i = 0; i < cube.positions.size(); ++i) cube.normals[i] = glm::normalize(cube.positions[i]);
  EXPECT_EQ(find_crease_edges(cube.positions, cube.normals, cube.indices).size(), 0u);
}

}  // namespace
}  // namespace toond::scene
