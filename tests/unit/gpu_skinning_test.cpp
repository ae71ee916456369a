// A pose drawn by the vertex stages (shaders/skinning.glsl), and the same
// pose posed on the CPU and uploaded (--skinning cpu), against the pose
// worked out by scene::pose_vertices and drawn as a static mesh: both framed alike, through every pass that moves
// vertices (main, hull, wireframe, the edges' prepass, shadow) and the data layers. The models are Blender's exports: a
// walker (13 bones, blended weights, three materials) and a bending bar (3 bones and an animated shape key).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "gltf_import_checks.h"
#include "param_schema.h"
#include "pipeline/render_params_wire.h"
#include "render/frame/gpu_model.h"
#include "render/run/renderer.h"
#include "scene/animation/pose.h"
#include "scene/mesh/extreme_points.h"
#include "support/gl_context_test.h"
#include "support/shared_models.h"
#include "toond_shader_files.h"

namespace toond::render {
namespace {

using scene::Model;

// The rest model with its vertex streams replaced by the CPU's pose: what
// the GPU must draw. Bounds, extremes, caps and seams where parts cross are
// the skin pose's, so the two renders frame, cull and line alike.
Model cpu_posed_copy(const Model& model, const scene::PosedVertices& posed, const scene::SkinPose& skin) {
  Model copy = model;
  copy.rig.reset();
  copy.mesh.motion.clear();
  copy.mesh.positions = posed.positions;
  copy.mesh.normals = posed.normals;
  copy.mesh.outline_normals = posed.outline_normals;
  copy.mesh.tangents = posed.tangents;
  copy.mesh.bounds = skin.bounds;
  copy.mesh.extremes = skin.extremes;
  copy.mesh.caps = skin.caps[0];
  for (std::size_t i = 0; i < copy.mesh.lods.size(); ++i) copy.mesh.lods[i].caps = skin.caps[i + 1];
  // Where its parts cross in the pose, as the pose found them.
  if (!skin.intersections.empty()) {
    copy.mesh.intersections = skin.intersections[0];
    for (std::size_t i = 0; i < copy.mesh.lods.size(); ++i) copy.mesh.lods[i].intersections = skin.intersections[i + 1];
  }
  return copy;
}

// Pixels that differ by more than kLevels (of 255) in a channel: a colour
// image's levels, or a data layer's values scaled to them.
struct Difference {
  int differing = 0;
  double largest = 0;
};
constexpr double kLevels = 8;

Difference compare(const RenderOutput& a, const RenderOutput& b) {
  Difference d;
  const bool layer = a.image.rgba.empty();
  const std::size_t count = layer ? a.layer.values.size() : a.image.rgba.size();
  for (std::size_t k = 0; k < count; k += 4) {
    double worst = 0;
    for (std::size_t c = 0; c < 4; ++c) {
      const double delta = layer ? 255.0 * std::abs(a.layer.values[k + c] - b.layer.values[k + c])
                                 : std::abs(a.image.rgba[k + c] - b.image.rgba[k + c]);
      worst = std::max(worst, delta);
    }
    d.differing += worst > kLevels;
    d.largest = std::max(d.largest, worst);
  }
  return d;
}

class GpuSkinning : public test::GlContextTest {
 protected:
  static RenderParams params(const nlohmann::json& request) {
    return pipeline::render_params_from_wire(proto::ParamSchema::render_params().validate_and_complete(request));
  }

  // Renders `model` at `time` of its first clip both ways under each
  // request and expects the same picture: a few pixels may differ where the
  // GPU's float sums round a silhouette pixel the other way.
  static void expect_gpu_pose_is_cpu_pose(const Model& model, const std::string& clip, double time) {
    const scene::Rig& rig = *model.rig;
    const scene::NodePose nodes = scene::pose_nodes(rig, &rig.clips[*rig.find_clip(clip)], time);
    const scene::PosedVertices posed = scene::pose_vertices(model.mesh, rig, nodes);
    auto skin = std::make_shared<scene::SkinPose>(scene::skin_pose(model.mesh, rig, nodes));
    skin->bounds = posed.bounds;
    skin->extremes = scene::extreme_points(posed.positions);
    const Model reference = cpu_posed_copy(model, posed, *skin);

    auto skin_on_cpu =
        std::make_shared<scene::SkinPose>(scene::skin_pose(model.mesh, rig, nodes, scene::Skinning::Cpu));
    skin_on_cpu->bounds = skin->bounds;
    skin_on_cpu->extremes = skin->extremes;

    gpu::ProgramCache programs([](const std::string& name) { return std::string(shader_files::find(name)); });
    Renderer renderer(programs);
    GpuModel posed_copy(model);  // posed each way in turn, as the render cache keeps one copy
    GpuModel reference_copy(reference);
    const nlohmann::json requests[] = {
        nlohmann::json::object(),
        {{"outline", {{"method", nlohmann::json::array({"hull", "wireframe", "edges"})}}},
         {"shadows", {{"enabled", true}}}},
        {{"output", "normal"}},
        {{"output", "depth"}},
    };
    for (const nlohmann::json& request : requests) {
      RenderParams p = params(request);
      p.width = p.height = 160;
      const RenderOutput reference_image = renderer.render(reference_copy, reference, p);
      posed_copy.apply_pose(skin, model);
      const RenderOutput in_vertex_stage = renderer.render({RenderObject{posed_copy, model, glm::dmat4(1.0), skin}}, p);
      posed_copy.apply_pose(skin_on_cpu, model);
      const RenderOutput on_cpu = renderer.render({RenderObject{posed_copy, model, glm::dmat4(1.0), skin_on_cpu}}, p);
      posed_copy.apply_pose(nullptr, model);
      const RenderOutput rest = renderer.render(posed_copy, model, p);
      const Difference gpu_vs_cpu = compare(in_vertex_stage, reference_image);
      std::cout << clip << " at " << time << " s, " << request.dump() << ": " << gpu_vs_cpu.differing
                << " pixels differ, largest difference " << gpu_vs_cpu.largest << " levels\n";
      EXPECT_LE(gpu_vs_cpu.differing, 4) << request.dump() << ", largest difference " << gpu_vs_cpu.largest;
      EXPECT_EQ(compare(on_cpu, reference_image).differing, 0) << request.dump();
      // The pose is not the rest (the comparisons above can fail), and a
      // pose taken back draws the rest again.
      EXPECT_GT(compare(rest, reference_image).differing, 40) << request.dump();
      GpuModel fresh(model);
      EXPECT_EQ(compare(rest, renderer.render(fresh, model, p)).differing, 0) << request.dump();
    }
  }
};

TEST_F(GpuSkinning, BlendersWalkerDrawsWhereTheCpuPutsIt) {
  const std::filesystem::path folder = TOOND_EXPORTED_DIR "/blender";
  const Model model = scene::test_checks::import_files({{"walker.glb", test::read_file(folder / "walker.glb")}});
  ASSERT_TRUE(model.rig);
  for (const double t : {0.25, 0.6}) expect_gpu_pose_is_cpu_pose(model, "Walk", t);
}

TEST_F(GpuSkinning, BlendersBarBendsWithItsShapeKeyLikeTheCpu) {
  const std::filesystem::path folder = TOOND_EXPORTED_DIR "/blender";
  const Model model = scene::test_checks::import_files({{"rigged.gltf", test::read_file(folder / "rigged.gltf")},
                                                        {"rigged.bin", test::read_file(folder / "rigged.bin")}});
  ASSERT_TRUE(model.rig);
  ASSERT_EQ(model.rig->morph_target_count, 1u);
  expect_gpu_pose_is_cpu_pose(model, "Bend", 0.5);
  expect_gpu_pose_is_cpu_pose(model, "Twist", 0.3);
}

// Tangents matter only under a normal map: Blender's bar given one (every
// texel tilted toward the tangent) and a TANGENT target on its shape key,
// so the bend's shading follows the morphed tangent frame.
TEST_F(GpuSkinning, MorphedTangentsTurnANormalMapAlike) {
  const std::filesystem::path folder = TOOND_EXPORTED_DIR "/blender";
  Model model = scene::test_checks::import_files({{"rigged.gltf", test::read_file(folder / "rigged.gltf")},
                                                  {"rigged.bin", test::read_file(folder / "rigged.bin")}});
  ASSERT_TRUE(model.rig);
  scene::Texture tilted;
  tilted.width = tilted.height = 4;
  tilted.color_space = scene::ColorSpace::Linear;
  for (int i = 0; i < 16; ++i)
    tilted.rgba.insert(tilted.rgba.end(), {230, 128, 180, 255});  // (0.8, 0, 0.4) in tangent space
  model.textures.push_back(tilted);
  for (scene::Material& m : model.materials) m.normal_texture = static_cast<int>(model.textures.size() - 1);
  auto rig = std::make_shared<scene::Rig>(*model.rig);
  for (scene::MorphSet& set : rig->morph_sets)
    set.tangent_deltas.assign(set.position_deltas.size(), glm::vec3(0, 2, 1));
  model.rig = rig;
  expect_gpu_pose_is_cpu_pose(model, "Bend", 0.5);
}

}  // namespace
}  // namespace toond::render
