// Near-duplicate positions become one; distinct ones stay apart; the weld
// stays linear in the number of positions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "scene/crease_profile.h"
#include "scene/mesh_processing.h"
#include "scene/position_weld.h"

namespace toond::scene {
namespace {

TEST(PositionWeld, PointsARoundingErrorApartBecomeOne) {
  // A pole as an exporter writes it: sin(π) is 1.2e-16, not 0.
  std::vector<glm::vec3> p = {{1.2246e-16f, -1, 0}, {0, -1, -1.2246e-16f}, {-1.2246e-16f, -1, 1e-16f},
                              {1, 0, 0}, {-1, 1, 0}};
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
TEST(CreaseProfile, ACubeIsHardEdgedAndASmoothSphereIsNot) {
  std::vector<glm::vec3> positions, normals;
  std::vector<std::uint32_t> indices;
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int a = 0; a < 3; ++a) {
    for (const float s : {-1.0f, 1.0f}) {
      const glm::vec3 n = axes[a] * s, u = axes[(a + 1) % 3], v = axes[(a + 2) % 3] * s;
      const auto base = static_cast<std::uint32_t>(positions.size());
      for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
        positions.push_back(n + u * c.x + v * c.y);
        normals.push_back(n);
      }
      for (const std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(base + i);
    }
  }
  const CreaseProfile cube = measure_creases(positions, normals, indices);
  EXPECT_TRUE(cube.hard_edged(40));
  EXPECT_TRUE(cube.hard_edged(89));
  EXPECT_FALSE(cube.hard_edged(91));

  // The same cube with one normal per corner (pointing out of the corner):
  // nothing turns across an edge.
  for (std::size_t i = 0; i < positions.size(); ++i) normals[i] = glm::normalize(positions[i]);
  EXPECT_FALSE(measure_creases(positions, normals, indices).hard_edged(40));
}

}  // namespace
}  // namespace toond::scene
