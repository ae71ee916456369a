// Levels of detail of rigged models, checked in poses: a level is made at
// rest, and a straight limb at rest is the easiest thing to simplify (every
// ring between its ends lies on the line), so a level that ignores how the
// rings move draws a bent arm as a straight one. Every level must lie
// within its own error (times the pose's stretch) of the full mesh posed
// the same way, at keys and between them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "gltf_import_checks.h"
#include "scene/animation/motion_classes.h"
#include "scene/animation/pose.h"
#include "support/gltf_rig_writer.h"
#include "support/surface_distance.h"

namespace toond::scene {
namespace {

using test_checks::import_files;

constexpr int kRings = 24;
constexpr int kSegments = 24;
constexpr double kRadius = 0.25;
constexpr double kLength = 3.0;

// A capped cylinder along +Y from the origin, kRings rings of kSegments.
test::GltfPrimitive cylinder() {
  test::GltfPrimitive p;
  for (int r = 0; r < kRings; ++r) {
    const double y = kLength * r / (kRings - 1);
    for (int s = 0; s < kSegments; ++s) {
      const double a = 2.0 * std::numbers::pi * s / kSegments;
      p.positions.emplace_back(kRadius * std::cos(a), y, kRadius * std::sin(a));
    }
  }
  const auto at = [](int r, int s) { return static_cast<std::uint32_t>(r * kSegments + (s % kSegments)); };
  for (int r = 0; r + 1 < kRings; ++r) {
    for (int s = 0; s < kSegments; ++s) {
      p.indices.insert(p.indices.end(),
                       {at(r, s), at(r + 1, s), at(r, s + 1), at(r, s + 1), at(r + 1, s), at(r + 1, s + 1)});
    }
  }
  const auto bottom = static_cast<std::uint32_t>(p.positions.size());
  p.positions.emplace_back(0.0f, 0.0f, 0.0f);
  const auto top = static_cast<std::uint32_t>(p.positions.size());
  p.positions.emplace_back(0.0f, static_cast<float>(kLength), 0.0f);
  for (int s = 0; s < kSegments; ++s) {
    p.indices.insert(p.indices.end(), {bottom, at(0, s), at(0, s + 1)});
    p.indices.insert(p.indices.end(), {top, at(kRings - 1, s + 1), at(kRings - 1, s)});
  }
  return p;
}

enum class Weights { Rigid, Blended };

// How much each of the three bones (0-1, 1-2, 2-3 along Y) moves a point at
// height y: rigid, its own bone alone; blended, shared over 0.6 around
// each joint as automatic weights share them.
std::array<float, 3> bone_weights(double y, Weights kind) {
  std::array<float, 3> w{};
  if (kind == Weights::Rigid) {
    w[static_cast<std::size_t>(std::clamp(static_cast<int>(std::floor(y)), 0, 2))] = 1.0f;
    return w;
  }
  for (int joint = 1; joint <= 2; ++joint) {
    const double into = std::clamp((y - joint + 0.3) / 0.6, 0.0, 1.0);
    if (y >= joint - 0.3) {
      w = {};
      w[static_cast<std::size_t>(joint - 1)] = static_cast<float>(1.0 - into);
      w[static_cast<std::size_t>(joint)] = static_cast<float>(into);
    }
  }
  if (y < 0.7) w = {1.0f, 0.0f, 0.0f};
  return w;
}

// The bending arm: the middle and tip bones turn about X through
// 0, 35, 0, -35, 0 degrees (the tip 1.4 times that) at 0, 0.25 ... 1 s; a
// morph target, animated 0 -> 1 -> 0, pushes the ring nearest the elbow out.
test::GltfFiles bending_arm(Weights kind, bool with_morph) {
  test::GltfDocument doc;
  doc.meshes = {{cylinder()}};
  doc.nodes.resize(4);
  doc.nodes[0].mesh = 0;
  doc.nodes[1].children = {2};
  doc.nodes[2].translation = glm::dvec3(0, 1, 0);
  doc.nodes[2].children = {3};
  doc.nodes[3].translation = glm::dvec3(0, 1, 0);
  doc.scene_roots = {0, 1};
  test::GltfParts p = test::build_gltf(doc);
  const std::vector<glm::vec3>& positions = doc.meshes[0][0].positions;
  std::vector<std::uint16_t> joints;
  std::vector<float> weights;
  std::vector<float> morph;
  for (const glm::vec3& v : positions) {
    const auto w = bone_weights(v.y, kind);
    joints.insert(joints.end(), {0, 1, 2, 0});
    weights.insert(weights.end(), {w[0], w[1], w[2], 0.0f});
    const bool bulges = std::abs(v.y - kLength * 8 / (kRings - 1)) < 1e-4 && glm::length(glm::vec2(v.x, v.z)) > 0.1f;
    const glm::vec3 out = bulges ? 0.2f * glm::normalize(glm::vec3(v.x, 0.0f, v.z)) : glm::vec3(0.0f);
    morph.insert(morph.end(), {out.x, out.y, out.z});
  }
  nlohmann::json& primitive = p.json["meshes"][0]["primitives"][0];
  primitive["attributes"]["JOINTS_0"] = test::append_joints_accessor(p, joints);
  primitive["attributes"]["WEIGHTS_0"] = test::append_float_accessor(p, weights, "VEC4");
  std::vector<float> inverse_binds;
  for (int j = 0; j < 3; ++j) {
    const glm::dmat4 inverse = glm::translate(glm::dmat4(1.0), glm::dvec3(0, -j, 0));
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) inverse_binds.push_back(static_cast<float>(inverse[c][r]));
  }
  p.json["skins"] = {
      {{"joints", {1, 2, 3}}, {"inverseBindMatrices", test::append_float_accessor(p, inverse_binds, "MAT4")}}};
  p.json["nodes"][0]["skin"] = 0;
  const int times = test::append_float_accessor(p, {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}, "SCALAR");
  const auto turns = [&](double scale) {
    std::vector<float> keys;
    for (const double degrees : {0.0, 35.0, 0.0, -35.0, 0.0}) {
      const glm::dquat q = glm::angleAxis(glm::radians(degrees * scale), glm::dvec3(1, 0, 0));
      keys.insert(keys.end(),
                  {static_cast<float>(q.x), static_cast<float>(q.y), static_cast<float>(q.z), static_cast<float>(q.w)});
    }
    return test::append_float_accessor(p, keys, "VEC4");
  };
  nlohmann::json samplers = {{{"input", times}, {"output", turns(1.0)}}, {{"input", times}, {"output", turns(1.4)}}};
  nlohmann::json channels = {{{"sampler", 0}, {"target", {{"node", 2}, {"path", "rotation"}}}},
                             {{"sampler", 1}, {"target", {{"node", 3}, {"path", "rotation"}}}}};
  if (with_morph) {
    primitive["targets"] = {{{"POSITION", test::append_float_accessor(p, morph, "VEC3")}}};
    p.json["meshes"][0]["weights"] = {0.0};
    samplers.push_back({{"input", times}, {"output", test::append_float_accessor(p, {0, 1, 0, 1, 0}, "SCALAR")}});
    channels.push_back({{"sampler", 2}, {"target", {{"node", 0}, {"path", "weights"}}}});
  }
  p.json["animations"] = {{{"name", "Bend"}, {"samplers", samplers}, {"channels", channels}}};
  return test::pack_gltf(p, test::GltfForm::Glb);
}

struct Stray {
  double worst = 0;    // the farthest a full-detail vertex lies from the level
  double allowed = 0;  // the level's error times the pose's stretch
  std::size_t outliers = 0;
};

// How far the full mesh's vertices lie from `level`'s triangles, both posed
// at `time` of the first clip.
Stray stray_in_pose(const Model& model, const MeshLod& level, double time) {
  const Rig& rig = *model.rig;
  const NodePose nodes = pose_nodes(rig, &rig.clips[0], time);
  const PosedVertices posed = pose_vertices(model.mesh, rig, nodes);
  const std::vector<glm::dvec3> points(posed.positions.begin(), posed.positions.end());
  const test::SurfaceDistance surface(points, level.indices);
  Stray stray;
  stray.allowed = level.error * skin_pose(model.mesh, rig, nodes).stretch + 1e-5 * kLength;
  for (const glm::dvec3& p : points) {
    const double d = surface.distance(p);
    stray.worst = std::max(stray.worst, d);
    stray.outliers += d > stray.allowed ? 1 : 0;
  }
  return stray;
}

void expect_every_level_poses_within_its_error(const Model& model) {
  ASSERT_TRUE(model.rig);
  for (const double time : {0.0, 0.1, 0.25, 0.4, 0.6, 0.75, 0.9}) {
    for (std::size_t l = 0; l < model.mesh.lods.size(); ++l) {
      const MeshLod& level = model.mesh.lods[l];
      const Stray stray = stray_in_pose(model, level, time);
      EXPECT_EQ(stray.outliers, 0u) << "level " << l + 1 << " (" << level.triangle_count() << " triangles) at " << time
                                    << " s: worst " << stray.worst << ", allowed " << stray.allowed;
    }
  }
}

TEST(RiggedLevels, ARigidlyWeightedArmIsSimplifiedWithinEachBoneAndBendsAsTheFullMesh) {
  const Model model = import_files(bending_arm(Weights::Rigid, false));
  // Each bone's stretch of cylinder is straight, so its inner rings go, but
  // not the rings where one bone meets the next.
  ASSERT_FALSE(model.mesh.lods.empty());
  EXPECT_LT(model.mesh.lods.back().triangle_count(), model.mesh.triangle_count() / 2);
  expect_every_level_poses_within_its_error(model);
}

TEST(RiggedLevels, ABlendedArmBendsAsTheFullMeshOnEveryLevel) {
  expect_every_level_poses_within_its_error(import_files(bending_arm(Weights::Blended, false)));
}

TEST(RiggedLevels, VerticesAMorphTargetMovesAreKeptOnEveryLevel) {
  expect_every_level_poses_within_its_error(import_files(bending_arm(Weights::Rigid, true)));
}

TEST(MotionClasses, VerticesShareAClassExactlyWhereTheirWeightsAreEqualAndNoMorphMovesThem) {
  const Model model = import_files(bending_arm(Weights::Blended, true));
  const std::vector<std::uint32_t> classes = motion_classes(model.mesh, *model.rig);
  ASSERT_EQ(classes.size(), model.mesh.positions.size());
  // What the file says moves each vertex: its weights by height, or, on the
  // ring the morph target pushes out, its own position.
  const double bulge_y = kLength * 8 / (kRings - 1);
  std::map<std::array<float, 3>, std::set<std::uint32_t>> classes_of_weights;
  std::map<std::uint32_t, std::set<std::array<float, 3>>> weights_of_class;
  std::map<std::uint32_t, std::set<std::array<float, 3>>> bulging_points_of_class;
  for (std::size_t v = 0; v < classes.size(); ++v) {
    const glm::dvec3 p = glm::dvec3(model.mesh.positions[v]) + model.mesh.origin;
    const bool bulges = std::abs(p.y - bulge_y) < 1e-4 && glm::length(glm::dvec2(p.x, p.z)) > 0.1;
    if (bulges) {
      bulging_points_of_class[classes[v]].insert(
          {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
      continue;
    }
    const auto w = bone_weights(p.y, Weights::Blended);
    classes_of_weights[w].insert(classes[v]);
    weights_of_class[classes[v]].insert(w);
  }
  for (const auto& [w, cs] : classes_of_weights) EXPECT_EQ(cs.size(), 1u) << w[0] << " " << w[1] << " " << w[2];
  for (const auto& [c, ws] : weights_of_class) EXPECT_EQ(ws.size(), 1u) << "class " << c;
  EXPECT_EQ(bulging_points_of_class.size(), static_cast<std::size_t>(kSegments));
  for (const auto& [c, points] : bulging_points_of_class) {
    EXPECT_EQ(points.size(), 1u) << "class " << c;
    EXPECT_FALSE(weights_of_class.contains(c)) << "class " << c;
  }
  EXPECT_GT(classes_of_weights.size(), 6u);
}

TEST(MotionClasses, TheLargestStretchIsTheLargestSingularValue) {
  EXPECT_NEAR(largest_joint_stretch({glm::mat4(1.0f)}), 1.0, 2e-3);
  const glm::mat4 turned = glm::rotate(glm::mat4(1.0f), 0.7f, glm::vec3(1, 2, 3));
  const glm::mat4 stretched = turned * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f, 3.0f, 1.0f));
  const double stretch = largest_joint_stretch({glm::mat4(1.0f), stretched});
  EXPECT_GE(stretch, 3.0);
  EXPECT_LE(stretch, 3.0 * 1.002);
  // A shear's largest singular value exceeds each column's length.
  glm::mat4 shear(1.0f);
  shear[1][0] = 1.0f;
  EXPECT_GE(largest_joint_stretch({shear}), (1.0 + std::sqrt(5.0)) / 2.0);
  EXPECT_EQ(largest_joint_stretch({}), 1.0);
}

}  // namespace
}  // namespace toond::scene
