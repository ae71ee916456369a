// Normals by angle for files without normals: sharp edges split, shallow
// ones smooth, on the meshes exporters write.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "model_checks.h"
#include "scene/import/obj_import.h"
#include "scene/mesh/mesh_processing.h"
#include "scene/mesh/normals_by_angle.h"

namespace toond::scene {
namespace {

using test_checks::make_bundle;

// A closed cylinder of `segments` sides, radius 1, height 2, positions and
// faces only (as STL or a bare OBJ export gives it).
std::string cylinder_obj(int segments) {
  std::string obj;
  for (int i = 0; i < segments; ++i) {
    const double a = 2 * 3.14159265358979 * i / segments;
    obj += "v " + std::to_string(std::cos(a)) + " -1 " + std::to_string(std::sin(a)) + "\n";
    obj += "v " + std::to_string(std::cos(a)) + " 1 " + std::to_string(std::sin(a)) + "\n";
  }
  const auto bottom = [](int i) { return std::to_string(2 * i + 1); };
  const auto top = [](int i) { return std::to_string(2 * i + 2); };
  for (int i = 0; i < segments; ++i) {
    const int j = (i + 1) % segments;
    obj += "f " + bottom(i) + " " + top(i) + " " + top(j) + " " + bottom(j) + "\n";
  }
  std::string cap_top = "f", cap_bottom = "f";
  for (int i = 0; i < segments; ++i) {
    cap_top += " " + top(segments - 1 - i);
    cap_bottom += " " + bottom(i);
  }
  return obj + cap_top + "\n" + cap_bottom + "\n";
}

TEST(NormalsByAngle, ACylinderHasSmoothSidesAndFlatCaps) {
  const Model m = import_obj_bundle(make_bundle({{"cylinder.obj", cylinder_obj(32)}}));
  for (std::size_t t = 0; t < m.mesh.indices.size(); t += 3) {
    const glm::dvec3 face = triangle_normal(glm::dvec3(m.mesh.positions[m.mesh.indices[t]]),
                                            glm::dvec3(m.mesh.positions[m.mesh.indices[t + 1]]),
                                            glm::dvec3(m.mesh.positions[m.mesh.indices[t + 2]]));
    const bool cap = std::abs(face.y) > 0.99;
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 p = m.mesh.positions[m.mesh.indices[t + k]];
      const glm::vec3 n = m.mesh.normals[m.mesh.indices[t + k]];
      if (cap) {
        EXPECT_NEAR(glm::dot(glm::dvec3(n), face), 1.0, 1e-5) << "a cap is flat";
      } else {
        // A side's normal points straight out from the axis: smoothed
        // across the 11.25° edges between sides, not bent toward the caps.
        EXPECT_NEAR(n.y, 0.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(n, glm::normalize(glm::vec3(p.x, 0, p.z))), 1.0f, 1e-4f);
      }
    }
  }
  // Each rim point is a vertex of the side and one of the cap.
  EXPECT_EQ(m.mesh.positions.size(), 4u * 32u);
}

TEST(NormalsByAngle, TheAngleDecides) {
  const std::string obj = cylinder_obj(8);  // sides meet at 45°
  ImportChoices wide;
  wide.smooth_angle = 50;
  ImportChoices narrow;
  narrow.smooth_angle = 40;
  const Model smooth = import_obj_bundle(make_bundle({{"c.obj", obj}}), {}, wide);
  const Model faceted = import_obj_bundle(make_bundle({{"c.obj", obj}}), {}, narrow);
  EXPECT_EQ(smooth.mesh.positions.size(), 4u * 8u);
  EXPECT_EQ(faceted.mesh.positions.size(), 2u * 8u + 4u * 8u);  // caps + a quad of four a side
}

TEST(NormalsByAngle, SmoothingGroupsDecideWhereAFileHasThem) {
  // One smoothing group over the whole cube: smooth, whatever the angle.
  const std::string cube =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\ns 1\n"
      "f 1 4 3 2\nf 5 6 7 8\nf 1 5 8 4\nf 2 3 7 6\nf 4 8 7 3\nf 1 2 6 5\n";
  const Model m = import_obj_bundle(make_bundle({{"cube.obj", cube}}));
  EXPECT_EQ(m.mesh.positions.size(), 8u);
}

TEST(NormalsByAngle, AFinIsSharpAndAFanIsLinear) {
  // Three faces on one edge (a fin) and 100,000 faces on one edge: each
  // face keeps its own normal, and the grouping does not look at every
  // pair of faces around the edge.
  std::vector<glm::vec3> positions = {{0, 0, -1}, {0, 0, 1}};
  std::vector<std::uint32_t> indices;
  const int pages = 100000;
  for (int i = 0; i < pages; ++i) {
    const double a = 2 * 3.14159265358979 * i / pages;
    positions.emplace_back(std::cos(a), std::sin(a), 0);
    indices.insert(indices.end(), {0u, 1u, static_cast<std::uint32_t>(i + 2)});
  }
  std::vector<std::uint32_t> classes(positions.size());
  for (std::uint32_t i = 0; i < classes.size(); ++i) classes[i] = i;
  const std::vector<std::uint8_t> eligible(indices.size(), 1);
  const std::vector<std::uint32_t> groups = corner_groups_by_angle(positions, classes, indices, eligible, 179);
  EXPECT_EQ(std::set<std::uint32_t>(groups.begin(), groups.end()).size(), indices.size());
}

TEST(NormalsByAngle, ZeroSplitsEveryEdgeAnd180JoinsEveryTwoSidedOne) {
  // Two triangles of one quad, and a third folded up at 90°.
  const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 0, 1}};
  const std::vector<std::uint32_t> indices = {0, 1, 2, 0, 2, 3, 1, 4, 2};
  const std::vector<std::uint32_t> classes = {0, 1, 2, 3, 4};
  const std::vector<std::uint8_t> eligible(indices.size(), 1);
  const auto count = [](const std::vector<std::uint32_t>& g) {
    return std::set<std::uint32_t>(g.begin(), g.end()).size();
  };
  EXPECT_EQ(count(corner_groups_by_angle(positions, classes, indices, eligible, 0)), 9u);
  // The quad's diagonal joins corners 0 and 2 of both its triangles.
  EXPECT_EQ(count(corner_groups_by_angle(positions, classes, indices, eligible, 30)), 7u);
  // At 180 the fold joins too: corners at 1 and 2 of the third triangle.
  EXPECT_EQ(count(corner_groups_by_angle(positions, classes, indices, eligible, 180)), 5u);
  // A corner not eligible (its vertex has a normal of its own) joins nothing.
  std::vector<std::uint8_t> some = eligible;
  some[0] = 0;
  EXPECT_EQ(count(corner_groups_by_angle(positions, classes, indices, some, 30)), 8u);
}

}  // namespace
}  // namespace toond::scene
