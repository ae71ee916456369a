// Skins, morph targets and clips: the samplers' interpolation, clip lookup,
// and glTF files posed by the importer's rig checked against the test's own
// evaluation of the same file (hierarchy, skinning, morphs), written here
// from the glTF rules, not from the server's code.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "gltf_import_checks.h"
#include "pose_checks.h"
#include "scene/animation/clip_sampling.h"
#include "scene/animation/pose.h"
#include "support/gltf_rig_writer.h"

namespace toond::scene {
namespace {

using test_checks::import_error;
using test_checks::import_files;

Channel rotation_channel(std::vector<double> times, std::vector<glm::dquat> keys, Interpolation interpolation) {
  Channel ch;
  ch.path = ChannelPath::Rotation;
  ch.width = 4;
  ch.interpolation = interpolation;
  ch.times = std::move(times);
  for (const glm::dquat& q : keys) ch.values.insert(ch.values.end(), {q.x, q.y, q.z, q.w});
  return ch;
}

glm::dquat sampled_rotation(const Channel& ch, double t) {
  std::array<double, 4> v{};
  sample_channel(ch, t, v);
  return {v[3], v[0], v[1], v[2]};
}

double angle_between(const glm::dquat& a, const glm::dquat& b) {
  return 2.0 * std::acos(std::min(1.0, std::abs(glm::dot(glm::normalize(a), glm::normalize(b)))));
}

TEST(ClipSampling, StepHoldsTheEarlierKeyUntilTheNext) {
  Channel ch;
  ch.interpolation = Interpolation::Step;
  ch.times = {0.5, 1.25};
  ch.values = {1, 2, 3, 4, 5, 6};
  std::array<double, 3> v{};
  sample_channel(ch, 1.0, v);
  EXPECT_EQ(v, (std::array<double, 3>{1, 2, 3}));
  sample_channel(ch, 1.25, v);
  EXPECT_EQ(v, (std::array<double, 3>{4, 5, 6}));
}

TEST(ClipSampling, BeforeTheFirstKeyAndAfterTheLastTheEndsHold) {
  Channel ch;
  ch.times = {0.3, 0.7};  // a clip whose first key is not at 0
  ch.values = {1, 1, 1, 3, 3, 3};
  std::array<double, 3> v{};
  sample_channel(ch, 0.0, v);
  EXPECT_EQ(v[0], 1.0);
  sample_channel(ch, 5.0, v);
  EXPECT_EQ(v[0], 3.0);
  sample_channel(ch, 0.5, v);
  EXPECT_NEAR(v[0], 2.0, 1e-12);
}

TEST(ClipSampling, LinearRotationTakesTheShortWayWhicheverSignTheFileStores) {
  const glm::dquat quarter = glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 0, 1));
  // -q is the same rotation as q; interpolating the numbers as stored would
  // turn 270° the long way round.
  const Channel ch = rotation_channel({0, 1}, {glm::dquat(1, 0, 0, 0), -quarter}, Interpolation::Linear);
  const glm::dquat half = sampled_rotation(ch, 0.5);
  EXPECT_NEAR(angle_between(half, glm::angleAxis(glm::radians(45.0), glm::dvec3(0, 0, 1))), 0.0, 1e-9);
  EXPECT_NEAR(glm::length(half), 1.0, 1e-12);
}

TEST(ClipSampling, HalfTurnStepsStayOnTheShortPathAndOfUnitLength) {
  const glm::dvec3 y(0, 1, 0);
  const auto about_y = [&](double degrees) { return glm::angleAxis(glm::radians(degrees), y); };
  // Keys 179° apart at irregular times: each interval turns forward, the
  // shorter way, so 358° is reached through 268.5°.
  const Channel near_half =
      rotation_channel({0, 0.1, 0.75}, {about_y(0), about_y(179), about_y(358)}, Interpolation::Linear);
  EXPECT_NEAR(angle_between(sampled_rotation(near_half, 0.425), about_y(268.5)), 0.0, 1e-9);
  // Keys exactly 180° apart: both ways are as short; either way the
  // middle is a quarter turn from each key, and of unit length.
  const Channel half = rotation_channel({0, 1}, {about_y(0), about_y(180)}, Interpolation::Linear);
  for (const double t : {0.25, 0.5, 0.75}) {
    const glm::dquat q = sampled_rotation(half, t);
    EXPECT_NEAR(glm::length(q), 1.0, 1e-12) << t;
    EXPECT_NEAR(angle_between(q, about_y(0)), glm::radians(180.0 * t), 1e-9) << t;
  }
}

TEST(ClipSampling, CubicSplineTangentsAreScaledByTheKeyInterval) {
  // y = 2t through keys at t = 1 and t = 3 with slope 2 per second as both
  // tangents: the Hermite curve is the line itself only when the tangents
  // are multiplied by the 2-second interval.
  Channel ch;
  ch.interpolation = Interpolation::CubicSpline;
  ch.width = 1;
  ch.times = {1.0, 3.0};
  ch.values = {2, 2, 2, 2, 6, 2};  // (in, value, out) per key
  std::array<double, 1> v{};
  for (const double t : {1.5, 2.0, 2.75}) {
    sample_channel(ch, t, v);
    EXPECT_NEAR(v[0], 2 * t, 1e-12) << t;
  }
}

TEST(ClipTime, LoopsOverTheDurationAndCountsBackFromTheEnd) {
  Clip clip;
  clip.duration = 2.0;
  EXPECT_DOUBLE_EQ(clip_time(clip, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(clip_time(clip, 5.5), 1.5);
  EXPECT_DOUBLE_EQ(clip_time(clip, -0.5), 1.5);
  EXPECT_DOUBLE_EQ(clip_time(clip, std::numeric_limits<double>::infinity()), 0.0);
  Clip instant;  // a zero-length clip is always at its one pose
  EXPECT_DOUBLE_EQ(clip_time(instant, 3.0), 0.0);
}

TEST(RangeTime, CountsFromTheStartAndLoopsInsideTheRange) {
  const ClipRange walk{5.6, 6.2};
  EXPECT_DOUBLE_EQ(range_time(walk, 0.0), 5.6);
  EXPECT_NEAR(range_time(walk, 0.25), 5.85, 1e-12);
  EXPECT_NEAR(range_time(walk, 0.85), 5.85, 1e-12);   // one loop of 0.6 s on
  EXPECT_NEAR(range_time(walk, -0.15), 6.05, 1e-12);  // back from the end
  EXPECT_DOUBLE_EQ(range_time(walk, std::numeric_limits<double>::quiet_NaN()), 5.6);
  EXPECT_DOUBLE_EQ(range_time({2.0, 2.0}, 7.0), 2.0);  // no length: its one pose
  Clip clip;
  clip.duration = 3.5;
  EXPECT_DOUBLE_EQ(whole_clip(clip).start, 0.0);
  EXPECT_DOUBLE_EQ(whole_clip(clip).end, 3.5);
}

TEST(RigClips, AreFoundByNameOrByThePartAfterTheBarWhenUnique) {
  Rig rig;
  for (const char* name : {"Armature|Walk", "Armature|Run", "Other|Run", "idle"})
    rig.clips.push_back({name, 1.0, {}, {}});
  EXPECT_EQ(rig.find_clip("Armature|Walk"), 0u);
  EXPECT_EQ(rig.find_clip("Walk"), 0u);
  EXPECT_EQ(rig.find_clip("idle"), 3u);
  EXPECT_EQ(rig.find_clip("Run"), std::nullopt);  // two clips end so
  EXPECT_EQ(rig.find_clip("walk"), std::nullopt);
  EXPECT_EQ(rig.clip_names(), "\"Armature|Walk\", \"Armature|Run\", \"Other|Run\", \"idle\"");
}

// ---- glTF files with skins, morphs and clips -------------------------------

constexpr double kQuarter = 1.5707963267948966;

// A bar of three rings (y = 0, 1, 2) skinned to two joints: node 1 (the
// root joint, `root` its rest transform) and node 2 one unit up; ring 0
// follows joint 0, ring 1 both by half (the two weights in two JOINTS/
// WEIGHTS sets), ring 2 joint 1 (weight 2, normalised on import). Clip
// "Bend": node 2 turns a quarter about +Z over a second (LINEAR); node 1
// jumps by (0.5, 0, 0) at 0.25 s (STEP). Morph target 0 moves ring 1 by
// +0.5 along X; its weight goes 0 → 1 over the first second. The clip
// lasts a second.
struct RiggedBar {
  glm::dmat4 root{1.0};
  test::GltfParts parts;
};

RiggedBar rigged_bar(const glm::dmat4& root = glm::dmat4(1.0), double root_scale = 1.0) {
  RiggedBar bar;
  bar.root = root;
  test::GltfDocument doc;
  doc.meshes = {{test::bar_primitive(3)}};
  doc.nodes.resize(3);
  doc.nodes[0].mesh = 0;
  doc.nodes[1].children = {2};
  doc.nodes[1].translation = glm::dvec3(root[3]);
  doc.nodes[1].scale = glm::dvec3(root_scale);
  doc.nodes[2].translation = glm::dvec3(0, 1, 0);
  doc.scene_roots = {0, 1};
  bar.parts = test::build_gltf(doc);
  test::GltfParts& p = bar.parts;
  // Influences: set 0 carries each vertex's first joint, set 1 the second.
  std::vector<std::uint16_t> joints0, joints1;
  std::vector<float> weights0, weights1;
  for (int ring = 0; ring < 3; ++ring) {
    for (int k = 0; k < 4; ++k) {
      joints0.insert(joints0.end(), {static_cast<std::uint16_t>(ring == 2 ? 1 : 0), 0, 0, 0});
      joints1.insert(joints1.end(), {1, 0, 0, 0});
      weights0.insert(weights0.end(), {ring == 1 ? 0.5f : ring == 2 ? 2.0f : 1.0f, 0, 0, 0});
      weights1.insert(weights1.end(), {ring == 1 ? 0.5f : 0.0f, 0, 0, 0});
    }
  }
  nlohmann::json& attributes = p.json["meshes"][0]["primitives"][0]["attributes"];
  attributes["JOINTS_0"] = test::append_joints_accessor(p, joints0);
  attributes["WEIGHTS_0"] = test::append_float_accessor(p, weights0, "VEC4");
  attributes["JOINTS_1"] = test::append_joints_accessor(p, joints1);
  attributes["WEIGHTS_1"] = test::append_float_accessor(p, weights1, "VEC4");
  std::vector<float> morph(12 * 3, 0.0f);
  for (int k = 4; k < 8; ++k) morph[static_cast<std::size_t>(k * 3)] = 0.5f;
  p.json["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", test::append_float_accessor(p, morph, "VEC3")}}};
  p.json["meshes"][0]["weights"] = {0.0};
  // Inverse bind matrices: the joints' rest world transforms inverted.
  const glm::dmat4 joint0 =
      glm::translate(glm::dmat4(1.0), glm::dvec3(root[3])) * glm::scale(glm::dmat4(1.0), glm::dvec3(root_scale));
  const glm::dmat4 joint1 = joint0 * glm::translate(glm::dmat4(1.0), glm::dvec3(0, 1, 0));
  std::vector<float> ibm;
  for (const glm::dmat4& j : {glm::inverse(joint0), glm::inverse(joint1)}) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) ibm.push_back(static_cast<float>(j[c][r]));
  }
  p.json["skins"] = {{{"joints", {1, 2}}, {"inverseBindMatrices", test::append_float_accessor(p, ibm, "MAT4")}}};
  p.json["nodes"][0]["skin"] = 0;
  const glm::dquat turn = glm::angleAxis(kQuarter, glm::dvec3(0, 0, 1));
  const int times = test::append_float_accessor(p, {0.0f, 1.0f}, "SCALAR");
  const int turns = test::append_float_accessor(p,
                                                {0, 0, 0, 1, static_cast<float>(turn.x), static_cast<float>(turn.y),
                                                 static_cast<float>(turn.z), static_cast<float>(turn.w)},
                                                "VEC4");
  const glm::dvec3 rest(root[3]);
  const int jump_times = test::append_float_accessor(p, {0.0f, 0.25f}, "SCALAR");
  const int jumps = test::append_float_accessor(
      p,
      {static_cast<float>(rest.x), static_cast<float>(rest.y), static_cast<float>(rest.z),
       static_cast<float>(rest.x + 0.5), static_cast<float>(rest.y), static_cast<float>(rest.z)},
      "VEC3");
  const int morph_weights = test::append_float_accessor(p, {0.0f, 1.0f}, "SCALAR");
  p.json["animations"] = {{{"name", "Armature|Bend"},
                           {"samplers",
                            {{{"input", times}, {"output", turns}},
                             {{"input", jump_times}, {"output", jumps}, {"interpolation", "STEP"}},
                             {{"input", times}, {"output", morph_weights}}}},
                           {"channels",
                            {{{"sampler", 0}, {"target", {{"node", 2}, {"path", "rotation"}}}},
                             {{"sampler", 1}, {"target", {{"node", 1}, {"path", "translation"}}}},
                             {{"sampler", 2}, {"target", {{"node", 0}, {"path", "weights"}}}}}}}};
  return bar;
}

Model import_bar(const RiggedBar& bar) { return import_files(test::pack_gltf(bar.parts, test::GltfForm::Glb)); }

// The test's own evaluation of the bar at `t` seconds of "Bend": where the
// rest vertex `p` (file coordinates) goes.
glm::dvec3 expected_bar_vertex(const glm::dvec3& p, double t, const glm::dmat4& root, double root_scale) {
  const int ring = static_cast<int>(std::lround(p.y));
  const glm::dvec3 rest_root(root[3]);
  const glm::dvec3 root_at_t = t >= 0.25 ? rest_root + glm::dvec3(0.5, 0, 0) : rest_root;
  const glm::dmat4 s = glm::scale(glm::dmat4(1.0), glm::dvec3(root_scale));
  const glm::dmat4 joint0_rest = glm::translate(glm::dmat4(1.0), rest_root) * s;
  const glm::dmat4 joint1_rest = joint0_rest * glm::translate(glm::dmat4(1.0), glm::dvec3(0, 1, 0));
  const glm::dmat4 joint0 = glm::translate(glm::dmat4(1.0), root_at_t) * s;
  const glm::dmat4 joint1 = joint0 * glm::translate(glm::dmat4(1.0), glm::dvec3(0, 1, 0)) *
                            glm::mat4_cast(glm::angleAxis(kQuarter * t, glm::dvec3(0, 0, 1)));
  glm::dvec3 local = p;
  if (ring == 1) local.x += 0.5 * t;  // the morph target, weight t
  const glm::dvec4 v(local, 1.0);
  const glm::dvec4 by0 = joint0 * glm::inverse(joint0_rest) * v;
  const glm::dvec4 by1 = joint1 * glm::inverse(joint1_rest) * v;
  const double w1 = ring == 0 ? 0.0 : ring == 1 ? 0.5 : 1.0;
  return glm::dvec3((1.0 - w1) * by0 + w1 * by1);
}

void expect_bar_posed_like_the_oracle(const glm::dmat4& root, double root_scale, double tolerance) {
  const Model model = import_bar(rigged_bar(root, root_scale));
  ASSERT_TRUE(model.rig);
  const Rig& rig = *model.rig;
  ASSERT_EQ(rig.clips.size(), 1u);
  EXPECT_EQ(rig.clips[0].name, "Armature|Bend");
  EXPECT_DOUBLE_EQ(rig.clips[0].duration, 1.0);
  EXPECT_EQ(rig.joint_count, 2u);
  EXPECT_EQ(rig.morph_target_count, 1u);
  const Mesh& mesh = model.mesh;
  for (const double t : {0.0, 0.2, 0.3, 0.5, 1.0}) {
    const PosedVertices posed = pose_vertices(mesh, rig, pose_nodes(rig, &rig.clips[0], t));
    double worst = 0;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const glm::dvec3 rest = glm::dvec3(mesh.positions[v]) + mesh.origin;
      const glm::dvec3 expected = expected_bar_vertex(rest, t, root, root_scale);
      worst = std::max(worst, glm::length(glm::dvec3(posed.positions[v]) + mesh.origin - expected));
    }
    EXPECT_LT(worst, tolerance) << "at " << t << " s";
  }
}

TEST(GltfRig, ASkinnedMorphedBarIsPosedAsTheGltfRulesSay) {
  expect_bar_posed_like_the_oracle(glm::dmat4(1.0), 1.0, 1e-5);
}

TEST(GltfRig, JointsFarFromTheOriginAtATinyScaleKeepTheirPrecision) {
  // Joints 1e4 units out with scale 1e-3: the bar is 2 mm long there.
  expect_bar_posed_like_the_oracle(glm::translate(glm::dmat4(1.0), glm::dvec3(1e4, -1e4, 1e4)), 1e-3, 1e-6 * 1e4);
}

TEST(GltfRig, PosedNormalsTurnWithTheJoints) {
  const Model model = import_bar(rigged_bar());
  const Rig& rig = *model.rig;
  const PosedVertices posed = pose_vertices(model.mesh, rig, pose_nodes(rig, &rig.clips[0], 1.0));
  // The top cap's normal was +Y; joint 1 turned a quarter about +Z.
  bool found = false;
  for (std::size_t v = 0; v < model.mesh.positions.size(); ++v) {
    if (model.mesh.normals[v].y > 0.99f && model.mesh.positions[v].y + model.mesh.origin.y > 1.5) {
      EXPECT_NEAR(posed.normals[v].x, -1.0f, 1e-5f);
      found = true;
    }
  }
  EXPECT_TRUE(found);
}

// A TANGENT target's delta is added to the tangent before the skin turns
// it: at the clip's end (weight 1) the foot ring, which only moved, has
// its rest tangent plus the delta, made square to the normal.
TEST(GltfRig, MorphTargetsMoveTangentsToo) {
  const glm::vec3 delta(0.0f, 3.0f, -4.0f);
  RiggedBar bar = rigged_bar();
  std::vector<float> tangent_deltas;
  for (int k = 0; k < 12; ++k) tangent_deltas.insert(tangent_deltas.end(), {delta.x, delta.y, delta.z});
  bar.parts.json["meshes"][0]["primitives"][0]["targets"][0]["TANGENT"] =
      test::append_float_accessor(bar.parts, tangent_deltas, "VEC3");
  const Model model = import_bar(bar);
  const Rig& rig = *model.rig;
  ASSERT_EQ(rig.morph_sets.size(), 1u);
  ASSERT_EQ(rig.morph_sets[0].tangent_deltas.size(), rig.morph_sets[0].position_deltas.size());
  const PosedVertices posed = pose_vertices(model.mesh, rig, pose_nodes(rig, &rig.clips[0], 1.0));
  int foot = 0, turned = 0;
  for (std::size_t v = 0; v < model.mesh.positions.size(); ++v) {
    if (model.mesh.positions[v].y + model.mesh.origin.y > 0.5) continue;
    ++foot;
    const glm::vec3 n = model.mesh.normals[v];
    const glm::vec3 moved = glm::vec3(model.mesh.tangents[v]) + delta;
    const glm::vec3 expected = glm::normalize(moved - n * glm::dot(n, moved));
    EXPECT_NEAR(glm::length(glm::vec3(posed.tangents[v]) - expected), 0.0f, 1e-5f) << "vertex " << v;
    turned += glm::length(glm::vec3(posed.tangents[v]) - glm::vec3(model.mesh.tangents[v])) > 0.5f;
  }
  EXPECT_GT(foot, 0);
  EXPECT_GT(turned, 0) << "the delta turned some tangent";
}

TEST(GltfRig, TheRestPoseIsTheImportAsBefore) {
  const Model model = import_bar(rigged_bar());
  const Rig& rig = *model.rig;
  const PosedVertices rest = pose_vertices(model.mesh, rig, pose_nodes(rig, nullptr, 0.0));
  for (std::size_t v = 0; v < model.mesh.positions.size(); ++v) {
    EXPECT_NEAR(glm::length(rest.positions[v] - model.mesh.positions[v]), 0.0f, 1e-6f);
  }
}

TEST(GltfRig, RigidNodeAnimationMovesAMeshWithoutASkin) {
  test::GltfDocument doc;
  doc.meshes = {{test::bar_primitive(2)}};
  doc.nodes.resize(1);
  doc.nodes[0].mesh = 0;
  doc.scene_roots = {0};
  test::GltfParts p = test::build_gltf(doc);
  const int times = test::append_float_accessor(p, {0.0f, 1.0f}, "SCALAR");
  const int moves = test::append_float_accessor(p, {0, 0, 0, 0, 3, 0}, "VEC3");
  p.json["animations"] = {{{"samplers", {{{"input", times}, {"output", moves}}}},
                           {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}}}};
  const Model model = import_files(test::pack_gltf(p, test::GltfForm::Glb));
  ASSERT_TRUE(model.rig);
  EXPECT_EQ(model.rig->clips[0].name, "animation 0");
  const PosedVertices posed = pose_vertices(model.mesh, *model.rig, pose_nodes(*model.rig, &model.rig->clips[0], 0.5));
  for (std::size_t v = 0; v < model.mesh.positions.size(); ++v) {
    EXPECT_NEAR(posed.positions[v].y - model.mesh.positions[v].y, 1.5f, 1e-6f);
  }
  EXPECT_NEAR(posed.bounds.min.y - model.mesh.bounds.min.y, 1.5f, 1e-6f);
}

TEST(GltfRig, AClipsFramingHoldsEveryPose) {
  const Model model = import_bar(rigged_bar());
  const Rig& rig = *model.rig;
  const ClipFraming framing = frame_clip(model.mesh, rig, 0);
  EXPECT_GE(framing.poses, 5u);
  for (double t = 0; t <= 1.0; t += 0.01) {
    const PosedVertices posed = pose_vertices(model.mesh, rig, pose_nodes(rig, &rig.clips[0], t));
    for (const glm::vec3& p : posed.positions) {
      EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, framing.bounds.min - 1e-4f)) &&
                  glm::all(glm::lessThanEqual(p, framing.bounds.max + 1e-4f)))
          << "at " << t;
    }
  }
}

// ---- a file from a real exporter ------------------------------------------

// Blender's glTF of a bending bar (3 bones, blended weights, a shape key
// animated with them) posed here, against the OBJ Blender wrote of the same
// moment from its own armature deform: tests/exported/blender/make_rigged.py.
TEST(BlenderRig, BendAtHalfASecondIsWhereBlenderPutIt) {
  const std::filesystem::path folder = TOOND_EXPORTED_DIR "/blender";
  const Model model = import_files({{"rigged.gltf", test::read_file(folder / "rigged.gltf")},
                                    {"rigged.bin", test::read_file(folder / "rigged.bin")}});
  ASSERT_TRUE(model.rig);
  const Rig& rig = *model.rig;
  EXPECT_EQ(rig.clip_names(), "\"Bend\", \"Twist\"");
  EXPECT_EQ(rig.joint_count, 3u);
  EXPECT_EQ(rig.morph_target_count, 1u);
  const std::vector<glm::dvec3> blender =
      test_checks::obj_positions(test::read_file(folder / "rigged_pose_bend_0_5.obj"));
  ASSERT_EQ(blender.size(), 72u);
  const auto posed_at = [&](double t) { return test_checks::posed_points(model, *rig.find_clip("Bend"), t); };
  // The OBJ's six decimals round by 5e-7; a neighbouring frame (1/24 s
  // away) is 0.03 off.
  const std::vector<glm::dvec3> ours = posed_at(0.5);
  EXPECT_LT(test_checks::farthest_from(ours, blender), 1e-5);
  EXPECT_LT(test_checks::farthest_from(blender, ours), 1e-5);
  EXPECT_GT(test_checks::farthest_from(posed_at(0.5 - 1.0 / 24.0), blender), 1e-2);
}

// glTF places a skinned mesh by its joints and ignores its node's own
// transform; the import bakes that transform like any node's, so a file
// whose skinned node is scaled must be drawn at rest through its joints.
// Blender's bar with its "Arm" node squashed to half its height, and with
// its shape key weighted 1 by default.
Model blenders_bar(const std::function<void(nlohmann::json&)>& change) {
  const std::filesystem::path folder = TOOND_EXPORTED_DIR "/blender";
  nlohmann::json gltf = nlohmann::json::parse(test::read_file(folder / "rigged.gltf"));
  change(gltf);
  return import_files({{"rigged.gltf", gltf.dump()}, {"rigged.bin", test::read_file(folder / "rigged.bin")}});
}

TEST(RestPose, AnExportWhoseRestIsItsBindNeedsNoPose) {
  const Model bar = blenders_bar([](nlohmann::json&) {});
  EXPECT_FALSE(rest_pose_moves_vertices(*bar.rig));
  const std::filesystem::path folder = TOOND_EXPORTED_DIR "/blender";
  const Model walker = import_files({{"walker.glb", test::read_file(folder / "walker.glb")}});
  EXPECT_FALSE(rest_pose_moves_vertices(*walker.rig));
  EXPECT_FALSE(rest_pose_moves_vertices(*import_bar(rigged_bar()).rig));
}

TEST(RestPose, ASkinnedMeshsOwnNodeTransformIsIgnoredAtRest) {
  const Model plain = blenders_bar([](nlohmann::json&) {});
  const Model squashed = blenders_bar([](nlohmann::json& gltf) { gltf["nodes"][3]["scale"] = {1.0, 0.5, 1.0}; });
  ASSERT_TRUE(squashed.rig);
  EXPECT_TRUE(rest_pose_moves_vertices(*squashed.rig));
  // The import baked the squash; the rest pose undoes it.
  std::vector<glm::dvec3> where_glTF_puts_it;
  for (const glm::vec3& p : plain.mesh.positions) where_glTF_puts_it.push_back(glm::dvec3(p) + plain.mesh.origin);
  const Rig& rig = *squashed.rig;
  const PosedVertices rest = pose_vertices(squashed.mesh, rig, pose_nodes(rig, nullptr, 0.0));
  std::vector<glm::dvec3> posed;
  for (const glm::vec3& p : rest.positions) posed.push_back(glm::dvec3(p) + squashed.mesh.origin);
  std::vector<glm::dvec3> imported;
  for (const glm::vec3& p : squashed.mesh.positions) imported.push_back(glm::dvec3(p) + squashed.mesh.origin);
  ASSERT_EQ(posed.size(), where_glTF_puts_it.size());
  double posed_off = 0, imported_off = 0;
  for (std::size_t i = 0; i < posed.size(); ++i) {
    posed_off = std::max(posed_off, glm::length(posed[i] - where_glTF_puts_it[i]));
    imported_off = std::max(imported_off, glm::length(imported[i] - where_glTF_puts_it[i]));
  }
  EXPECT_LT(posed_off, 1e-5);
  EXPECT_GT(imported_off, 0.3);
  // Normals turn back exactly (the blend's cofactor); the mitred outline
  // offsets do not (a non-uniform scale moves each face plane by its own
  // factor), so only their directions are drawn as close as that allows.
  double normal_off = 0;
  for (std::size_t i = 0; i < posed.size(); ++i) {
    normal_off = std::max(normal_off, double(glm::length(rest.normals[i] - plain.mesh.normals[i])));
  }
  EXPECT_LT(normal_off, 1e-5);
  // The rest framing is the rest pose's reach.
  const ClipFraming framing = frame_rest_pose(squashed.mesh, rig);
  EXPECT_NEAR(framing.bounds.max.y - framing.bounds.min.y, plain.mesh.bounds.max.y - plain.mesh.bounds.min.y, 1e-5);
}

TEST(RestPose, AMeshsDefaultMorphWeightsShowAtRest) {
  const Model keyed = blenders_bar([](nlohmann::json& gltf) { gltf["meshes"][0]["weights"] = {1.0}; });
  EXPECT_TRUE(rest_pose_moves_vertices(*keyed.rig));
}

// ---- what a file gets wrong -----------------------------------------------

std::string bar_error(const std::function<void(nlohmann::json&)>& spoil) {
  RiggedBar bar = rigged_bar();
  spoil(bar.parts.json);
  return import_error(test::pack_gltf(bar.parts, test::GltfForm::Glb));
}

TEST(GltfRigErrors, ACyclicNodeHierarchyIsRefused) {
  EXPECT_NE(bar_error([](nlohmann::json& j) { j["nodes"][2]["children"] = {1}; }).find("must form a tree"),
            std::string::npos);
}

TEST(GltfRigErrors, AJointIndexPastTheSkinsJointsNamesTheAccessor) {
  RiggedBar bar = rigged_bar();
  std::vector<std::uint16_t> joints(12 * 4, 0);
  joints[8] = 5;
  bar.parts.json["meshes"][0]["primitives"][0]["attributes"]["JOINTS_1"] =
      test::append_joints_accessor(bar.parts, joints);
  const std::string error = import_error(test::pack_gltf(bar.parts, test::GltfForm::Glb));
  EXPECT_NE(error.find("JOINTS_1 names joint 5, past the skin's 2 joints"), std::string::npos) << error;
}

// Joint indices stored as floats may hold anything: a number past every
// integer or NaN is named as the file gives it (casting it to an integer
// for the message was undefined; the fuzzer found it).
TEST(GltfRigErrors, AJointIndexNoIntegerHoldsIsNamedAsGiven) {
  for (const auto& [joint, text] : {std::pair{1e30f, "names joint 1e+30, past"},
                                    std::pair{std::numeric_limits<float>::quiet_NaN(), "names joint nan, past"},
                                    std::pair{2.5f, "names joint 2.5, past"}}) {
    RiggedBar bar = rigged_bar();
    std::vector<float> joints(12 * 4, 0.0f);
    joints[8] = joint;
    bar.parts.json["meshes"][0]["primitives"][0]["attributes"]["JOINTS_1"] =
        test::append_float_accessor(bar.parts, joints, "VEC4");
    const std::string error = import_error(test::pack_gltf(bar.parts, test::GltfForm::Glb));
    EXPECT_NE(error.find(text), std::string::npos) << error;
  }
}

TEST(GltfRigErrors, AJointOutsideTheDrawnSceneIsRefused) {
  const std::string error = bar_error([](nlohmann::json& j) { j["scenes"][0]["nodes"] = {0}; });
  EXPECT_NE(error.find("is not in the scene that is drawn"), std::string::npos) << error;
}

TEST(GltfRigErrors, KeyTimesThatDoNotIncreaseAreRefused) {
  RiggedBar bar = rigged_bar();
  bar.parts.json["animations"][0]["samplers"][0]["input"] =
      test::append_float_accessor(bar.parts, {0.0f, 0.0f}, "SCALAR");
  const std::string error = import_error(test::pack_gltf(bar.parts, test::GltfForm::Glb));
  EXPECT_NE(error.find("sampler 0 input is not increasing"), std::string::npos) << error;
}

TEST(GltfRigErrors, OutputCountsThatDoNotMatchTheKeysAreRefused) {
  RiggedBar bar = rigged_bar();
  bar.parts.json["animations"][0]["samplers"][0]["output"] =
      test::append_float_accessor(bar.parts, {0, 0, 0, 1}, "VEC4");
  const std::string error = import_error(test::pack_gltf(bar.parts, test::GltfForm::Glb));
  EXPECT_NE(error.find("output has 4 numbers where its 2 keys need 8"), std::string::npos) << error;
}

TEST(GltfRigErrors, NanKeysAreRefused) {
  RiggedBar bar = rigged_bar();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  bar.parts.json["animations"][0]["samplers"][0]["input"] =
      test::append_float_accessor(bar.parts, {0.0f, nan}, "SCALAR");
  EXPECT_NE(import_error(test::pack_gltf(bar.parts, test::GltfForm::Glb)).find("not finite"), std::string::npos);
  RiggedBar values = rigged_bar();
  values.parts.json["animations"][0]["samplers"][1]["output"] =
      test::append_float_accessor(values.parts, {0, 0, 0, nan, 0, 0}, "VEC3");
  EXPECT_NE(
      import_error(test::pack_gltf(values.parts, test::GltfForm::Glb)).find("output holds a value that is not finite"),
      std::string::npos);
}

TEST(GltfRigErrors, CountsAreCheckedBeforeAnythingIsRead) {
  // An accessor without a buffer view reads as zeros, as many as it
  // declares: a billion of them must be refused, not allocated.
  const auto empty_accessor = [](nlohmann::json& j, const char* type) {
    j["accessors"].push_back({{"componentType", 5126}, {"count", 1000000000}, {"type", type}});
    return j["accessors"].size() - 1;
  };
  std::string error = bar_error([&](nlohmann::json& j) {
    j["meshes"][0]["primitives"][0]["targets"][0]["POSITION"] = empty_accessor(j, "VEC3");
  });
  EXPECT_NE(error.find("has 1000000000 elements where 12 are needed"), std::string::npos) << error;
  error =
      bar_error([&](nlohmann::json& j) { j["animations"][0]["samplers"][0]["input"] = empty_accessor(j, "SCALAR"); });
  EXPECT_NE(error.find("more than 20000000 key times and values"), std::string::npos) << error;
  error =
      bar_error([&](nlohmann::json& j) { j["animations"][0]["samplers"][0]["output"] = empty_accessor(j, "VEC4"); });
  EXPECT_NE(error.find("output has 4000000000 numbers where its 2 keys need 8"), std::string::npos) << error;
}

TEST(GltfRigErrors, AChannelOnAMissingNodeIsRefused) {
  const std::string error =
      bar_error([](nlohmann::json& j) { j["animations"][0]["channels"][0]["target"]["node"] = 42; });
  EXPECT_NE(error.find("targets node 42, which does not exist"), std::string::npos) << error;
}

}  // namespace
}  // namespace toond::scene
