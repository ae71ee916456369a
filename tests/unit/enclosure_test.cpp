// Which meshes close around a volume, and which way they face: the licence
// for skipping the faces turned away from the camera.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "model_checks.h"
#include "scene/import/bundle_import.h"
#include "scene/mesh/enclosure.h"
#include "scene/mesh/mesh_processing.h"
#include "support/generated_models.h"

namespace toond::scene {
namespace {

using test_checks::make_bundle;

Mesh imported(const std::string& obj) { return import_bundle(make_bundle({{"m.obj", obj}})).mesh; }

Enclosure classify(const Mesh& mesh) {
  return classify_enclosure(mesh.positions, group_by_position(mesh.positions), mesh.indices);
}

Mesh reversed(Mesh mesh) {
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
  return mesh;
}

// Both meshes' triangles over both meshes' vertices.
Mesh joined(const Mesh& a, const Mesh& b) {
  Mesh out = a;
  const auto base = static_cast<std::uint32_t>(a.positions.size());
  out.positions.insert(out.positions.end(), b.positions.begin(), b.positions.end());
  for (std::uint32_t i : b.indices) out.indices.push_back(i + base);
  return out;
}

Mesh moved(Mesh mesh, const glm::vec3& by) {
  for (glm::vec3& p : mesh.positions) p += by;
  return mesh;
}

TEST(Enclosure, ASphereAndAHardEdgedCubeFaceOutward) {
  // The cube's corners are split three ways (one copy per face normal):
  // edges count between positions, not vertex indices.
  EXPECT_EQ(classify(imported(test::sphere_obj(32, 16))), Enclosure::Outward);
  const Mesh cube = imported(test::cube_obj());
  ASSERT_GT(cube.positions.size(), 8u);
  EXPECT_EQ(classify(cube), Enclosure::Outward);
}

TEST(Enclosure, AMeshWoundInsideOutFacesInward) {
  EXPECT_EQ(classify(reversed(imported(test::cube_obj()))), Enclosure::Inward);
}

TEST(Enclosure, AHoleIsCappedAndAFlippedTriangleOpensIt) {
  Mesh holed = imported(test::cube_obj());
  holed.indices.resize(holed.indices.size() - 3);
  // Without caps a hole leaves it open.
  EXPECT_EQ(classify(holed), Enclosure::Open);
  // With them: the one triangle over the three-edge rim, wound like the
  // missing face.
  std::vector<glm::vec3> caps;
  EXPECT_EQ(classify_enclosure(holed.positions, group_by_position(holed.positions), holed.indices, &caps),
            Enclosure::Outward);
  ASSERT_EQ(caps.size(), 3u);
  const Mesh full = imported(test::cube_obj());
  const glm::vec3 missing_normal = glm::cross(
      full.positions[full.indices[full.indices.size() - 2]] - full.positions[full.indices[full.indices.size() - 3]],
      full.positions[full.indices[full.indices.size() - 1]] - full.positions[full.indices[full.indices.size() - 3]]);
  for (std::size_t t = 0; t < caps.size(); t += 3) {
    const glm::vec3 n = glm::cross(caps[t + 1] - caps[t], caps[t + 2] - caps[t]);
    EXPECT_GT(glm::dot(n, missing_normal), 0.0f) << "cap " << t / 3 << " faces out like the missing face";
  }

  Mesh flipped = imported(test::cube_obj());
  std::swap(flipped.indices[1], flipped.indices[2]);
  EXPECT_EQ(classify(flipped), Enclosure::Open);
  EXPECT_EQ(classify_enclosure(flipped.positions, group_by_position(flipped.positions), flipped.indices, &caps),
            Enclosure::Open);
  EXPECT_TRUE(caps.empty());
}

TEST(Enclosure, FlatAndTwoSidedSheetsAreOpen) {
  const Mesh disk = imported(test::disk_obj(24));
  EXPECT_EQ(classify(disk), Enclosure::Open);
  // Capped, a disk is a two-sided sheet too.
  EXPECT_EQ(disk.enclosure, Enclosure::Open);
  EXPECT_TRUE(disk.caps.empty());
  // Every edge balanced, but the "volume" is nothing: either side may face
  // the camera.
  EXPECT_EQ(classify(joined(disk, reversed(disk))), Enclosure::Open);
}

TEST(Enclosure, PartsMustAgreeOnTheirDirection) {
  const Mesh cube = imported(test::cube_obj());
  const Mesh apart = moved(cube, glm::vec3(5, 0, 0));
  EXPECT_EQ(classify(joined(cube, apart)), Enclosure::Outward);
  EXPECT_EQ(classify(joined(reversed(cube), reversed(apart))), Enclosure::Inward);
  // One part inside out: from some side its inner faces are the ones that
  // show, so nothing may be skipped.
  EXPECT_EQ(classify(joined(cube, reversed(apart))), Enclosure::Open);
  // A hollow shell (a cavity facing inward) is left alone for the same reason.
  const Mesh cavity = reversed(imported(test::cube_obj(0.5)));
  EXPECT_EQ(classify(joined(cube, cavity)), Enclosure::Open);
}

TEST(Enclosure, ImportMarksTheFullMeshAndEveryLevel) {
  const Mesh sphere = imported(test::sphere_obj(96, 48));
  EXPECT_EQ(sphere.enclosure, Enclosure::Outward);
  ASSERT_FALSE(sphere.lods.empty());
  EXPECT_TRUE(sphere.caps.empty());
  for (const MeshLod& lod : sphere.lods) {
    EXPECT_EQ(lod.enclosure, Enclosure::Outward) << lod.triangle_count();
    EXPECT_TRUE(lod.caps.empty());
  }
  EXPECT_EQ(imported(test::disk_obj(24)).enclosure, Enclosure::Open);
}

// A sphere with a band cut out of its middle has two rims of 512 points:
// capping them would cost more than the import should spend, so it stays
// open (and is drawn both sides) instead of taking seconds.
TEST(Enclosure, RimsTooLongToCapLeaveItOpen) {
  Mesh mesh = imported(test::sphere_obj(512, 8));
  std::vector<std::uint32_t> kept;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const float y = (mesh.positions[mesh.indices[t]].y + mesh.positions[mesh.indices[t + 1]].y +
                     mesh.positions[mesh.indices[t + 2]].y) /
                    3.0f;
    if (std::abs(y) > 0.2f) kept.insert(kept.end(), &mesh.indices[t], &mesh.indices[t] + 3);
  }
  ASSERT_LT(kept.size(), mesh.indices.size());
  std::vector<glm::vec3> caps;
  EXPECT_EQ(classify_enclosure(mesh.positions, group_by_position(mesh.positions), kept, &caps), Enclosure::Open);
  EXPECT_TRUE(caps.empty());
}

// An open tube around the z axis through x = `x`, faces out, each of its
// two rims `segments` long.
Mesh tube(int segments, float x) {
  Mesh mesh;
  for (int i = 0; i < segments; ++i) {
    const float a = 6.2831853f * static_cast<float>(i) / static_cast<float>(segments);
    mesh.positions.emplace_back(x + std::cos(a), std::sin(a), -1.0f);
    mesh.positions.emplace_back(x + std::cos(a), std::sin(a), 1.0f);
  }
  for (int i = 0; i < segments; ++i) {
    const auto bottom = static_cast<std::uint32_t>(2 * i), next = static_cast<std::uint32_t>(2 * ((i + 1) % segments));
    mesh.indices.insert(mesh.indices.end(), {bottom, next, next + 1, bottom, next + 1, bottom + 1});
  }
  return mesh;
}

// Rims short enough to cap one by one, but so many that capping them all
// would cost more than the budget: one tube's two rims of 200 are capped,
// three tubes' six are not.
TEST(Enclosure, ManyRimsOverTheCappingBudgetLeaveItOpen) {
  const Mesh one = tube(200, 0.0f);
  std::vector<glm::vec3> caps;
  EXPECT_EQ(classify_enclosure(one.positions, group_by_position(one.positions), one.indices, &caps),
            Enclosure::Outward);
  EXPECT_FALSE(caps.empty());
  const Mesh three = joined(joined(one, tube(200, 3.0f)), tube(200, 6.0f));
  EXPECT_EQ(classify_enclosure(three.positions, group_by_position(three.positions), three.indices, &caps),
            Enclosure::Open);
  EXPECT_TRUE(caps.empty());
}

TEST(Enclosure, EmptyAndCollapsedMeshesAreOpen) {
  EXPECT_EQ(classify(Mesh{}), Enclosure::Open);
  Mesh dot;
  dot.positions = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  dot.indices = {0, 1, 2};
  EXPECT_EQ(classify(dot), Enclosure::Open);
}

}  // namespace
}  // namespace toond::scene
