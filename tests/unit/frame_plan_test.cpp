// A frame is planned once, before it is queued (render/plan/frame_plan.h): the
// plan's passes, camera, outline width and cost are what the render thread
// draws with, the frame's context is worked out from it without GL, and a
// request's price is its frames' plans' costs.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

#include "gltf_import_checks.h"
#include "model_checks.h"
#include "pipeline/atlas.h"
#include "pipeline/clips.h"
#include "pipeline/frames.h"
#include "pipeline/plan.h"
#include "pipeline/pose.h"
#include "pipeline/price.h"
#include "render/frame/frame_context.h"
#include "render/frame/gpu_model.h"
#include "render/plan/frame_plan.h"
#include "render/plan/outline_width.h"
#include "render/run/renderer.h"
#include "support/generated_models.h"
#include "support/gl_context_test.h"
#include "support/in_process_render.h"
#include "support/shared_models.h"
#include "toond_shader_files.h"

namespace toond::render {
namespace {

scene::Model sphere() { return scene::test_checks::model_of_obj(test::sphere_obj(64, 32)); }

// No context is made here: the plan and the frame's context are arithmetic.
TEST(FramePlan, TheFramesContextIsWorkedOutFromItsPlanWithoutGl) {
  const scene::Model model = sphere();
  const std::vector<PlannedObject> objects = {{model}};
  const FramePlan plan =
      plan_frame(test::complete_params({{"width", 200}, {"height", 100}, {"supersample", 2}}), objects);
  EXPECT_TRUE(plan.passes.has(Pass::Main));
  EXPECT_EQ(plan.passes.supersample, 2);
  EXPECT_GT(plan.outline_px, 0.0f);
  EXPECT_GT(plan.cost.units(), 0.0);

  // Every decision about the frame is in the plan.
  ASSERT_EQ(plan.objects.size(), 1u);
  EXPECT_EQ(plan.objects[0].lod.levels, 1 + model.mesh.lods.size());
  EXPECT_EQ(plan.objects[0].lod.triangles, objects[0].triangles(plan.objects[0].lod.level));
  // A closed sphere seen from outside: its back faces cannot show.
  EXPECT_EQ(plan.objects[0].main.hidden, HiddenFaces::Back);
  ASSERT_EQ(plan.lights.size(), 1u);

  const FrameContext frame = build_frame_context({FrameObject{model}}, plan, true);
  EXPECT_EQ(frame.draw_width, 400);
  EXPECT_EQ(frame.draw_height, 200);
  EXPECT_EQ(frame.outline_px, plan.outline_px);
  EXPECT_EQ(&frame.camera, &plan.camera) << "the plan's camera, not one fitted again";
  EXPECT_EQ(&frame.clip, &plan.clip);
  EXPECT_EQ(&frame.shadow, &plan.shadow);
  ASSERT_EQ(frame.lods.size(), 1u);
  EXPECT_EQ(frame.lods[0].level, plan.objects[0].lod.level);
  EXPECT_EQ(frame.main_faces[0].hidden, HiddenFaces::Back);
  EXPECT_EQ(frame.lods[0].culled, HiddenFaces::Back);
  // Drawn with both sides of every face, the plan's skips are not taken,
  // but what cannot show to the camera still cannot.
  const FrameContext both_sides = build_frame_context({FrameObject{model}}, plan, false);
  EXPECT_EQ(both_sides.main_faces[0].hidden, HiddenFaces::None);
  EXPECT_EQ(both_sides.lods[0].culled, HiddenFaces::None);
  EXPECT_EQ(both_sides.unseen_faces[0].hidden, HiddenFaces::Back);
}

// The frames of a sheet share one framing, and a request costs what its
// frames' plans cost.
TEST(FramePlan, ASheetsFramesShareTheirFramingAndThePriceIsThePlansCosts) {
  const auto model = std::make_shared<const scene::Model>(sphere());
  for (const nlohmann::json& request : {nlohmann::json{{"width", 96}, {"height", 96}},
                                        nlohmann::json{{"width", 64}, {"height", 64}, {"sheet", {{"frames", 6}}}}}) {
    pipeline::Request r;
    r.objects.push_back({"m", model, glm::dmat4(1.0), nullptr});
    r.params = test::complete_params(request);
    const std::vector<pipeline::ObjectPoses> poses(r.params.sheet ? 6 : 1, pipeline::ObjectPoses{nullptr});
    r.layout = pipeline::layout_of(r.params);
    const std::vector<FramePlan> plans = pipeline::plan_frames(r, poses);
    ASSERT_EQ(plans.size(), poses.size()) << request;
    for (const FramePlan& plan : plans) EXPECT_EQ(plan.scene, plans.front().scene) << request;
    const pipeline::RenderPrice price = pipeline::price_of(plans);
    EXPECT_EQ(price.frames, plans.size()) << request;
    double sum = 0;
    for (const FramePlan& plan : plans) sum += plan.cost.units();
    EXPECT_EQ(price.total.units(), sum) << request;
  }
  // A single image is one frame drawn with the request's own parameters.
  pipeline::Request single;
  single.objects.push_back({"m", model, glm::dmat4(1.0), nullptr});
  single.params = test::complete_params({{"width", 96}, {"height", 80}, {"camera", {{"yaw", 33}}}});
  single.layout = pipeline::layout_of(single.params);
  const std::vector<pipeline::ObjectPoses> one_frame(1, pipeline::ObjectPoses{nullptr});
  const std::vector<FramePlan> single_plans = pipeline::plan_frames(single, one_frame);
  ASSERT_EQ(single_plans.size(), 1u);
  const FramePlan& plan = single_plans.front();
  EXPECT_EQ(plan.params.width, 96);
  EXPECT_EQ(plan.params.camera.yaw_deg, 33.0);
  EXPECT_TRUE(plan.params.camera.framed_views.empty());
}

// A request of the walker from Blender with lines in world units and crease
// lines drawn, planned as the pipeline plans it: resolved, posed, planned.
pipeline::Request walker_request(const std::shared_ptr<const scene::Model>& walker, nlohmann::json params) {
  params["outline"] = {{"units", "world"}, {"width", 0.03}, {"creases", "always"}};
  pipeline::Request r;
  r.objects.push_back({"walker", walker, glm::dmat4(1.0), nullptr});
  r.params = test::complete_params(params);
  pipeline::resolve_sheet_clips(r.params, *walker);
  r.layout = pipeline::layout_of(r.params);
  if (r.params.animation) r.clip = pipeline::resolve_animation_clip(r.params, *walker);
  return r;
}

// What is priced is what is drawn: the price of every frame is its plan's
// cost, worked out from the line width and camera the render thread draws
// with (the frame's context is made of the same plan). For a posed model
// with lines in world units the width differs from the one the camera at
// rest would give, so a price fitted at rest would not be the drawn one.
TEST(FramePlan, TheWidthAndCameraPricedAreTheOnesDrawn) {
  const std::filesystem::path folder = TOOND_EXPORTED_DIR "/blender";
  const auto walker = std::make_shared<const scene::Model>(
      scene::test_checks::import_files({{"walker.glb", test::read_file(folder / "walker.glb")}}));
  const nlohmann::json posed = {{"width", 160}, {"height", 120}, {"animation", {{"clip", "Walk"}, {"time", 0.3}}}};
  const nlohmann::json sheet = {
      {"width", 64}, {"height", 64}, {"sheet", {{"frames", 4}, {"animation", {{"clip", "Walk"}, {"frames", 3}}}}}};
  pipeline::ClipFramings framings;
  for (const nlohmann::json& request : {posed, sheet}) {
    const pipeline::Request r = walker_request(walker, request);
    const std::vector<pipeline::ObjectPoses> poses = pipeline::pose_frames(r, framings, scene::Skinning::Cpu);
    const std::vector<FramePlan> plans = pipeline::plan_frames(r, poses);
    ASSERT_EQ(plans.size(), r.layout ? 12u : 1u) << request;
    for (std::size_t i = 0; i < plans.size(); ++i) {
      const FramePlan& plan = plans[i];
      ASSERT_TRUE(plan.passes.has(Pass::Creases)) << request;
      const std::vector<PlannedObject> planned = pipeline::planned_objects(r, poses[i]);
      const FrameContext drawn = build_frame_context({FrameObject{*walker, poses[i][0].get()}}, plan, true);
      EXPECT_EQ(&drawn.camera, &plan.camera) << request;
      const scene::Mesh* meshes[] = {&walker->mesh};
      const RenderCost at_drawn_width =
          predict_frame_cost({.params = plan.params, .passes = plan.passes, .line_px = drawn.outline_px}, meshes);
      EXPECT_EQ(plan.cost.units(), at_drawn_width.units()) << request << " frame " << i;
      // The posed framing is not the rest's, and neither is the width.
      const CameraSetup at_rest = fit_camera(plan.params.camera, walker->mesh.bounds,
                                             static_cast<double>(plan.params.width) / plan.params.height);
      const double rest_px =
          outline_width_px(plan.params.outline, at_rest, false, plan.params.height) * plan.passes.supersample;
      EXPECT_GT(std::abs(rest_px - drawn.outline_px), 0.01 * drawn.outline_px) << request << " frame " << i;
    }
    if (!r.layout) continue;
    // A sheet's atlas anchors each tile with the camera that tile is drawn with.
    const nlohmann::ordered_json atlas = pipeline::atlas_of(r, plans);
    EXPECT_DOUBLE_EQ(atlas["meta"]["camera"]["distance"].get<double>(), plans.front().camera.distance);
  }
}

class FramePlanRender : public test::GlContextTest {};

// The render thread draws what the plan says: a plan given another
// frame's camera (and what follows from it) draws that frame's view, byte
// for byte.
TEST_F(FramePlanRender, TheRendererDrawsWithThePlansCamera) {
  const scene::Model model = sphere();
  gpu::ProgramCache programs([](const std::string& name) { return std::string(shader_files::find(name)); });
  Renderer renderer(programs);
  const GpuModel gpu(model);
  const std::vector<PlannedObject> planned = {{model}};
  const std::vector<RenderObject> objects = {{gpu, model}};
  const FramePlan side =
      plan_frame(test::complete_params({{"width", 96}, {"height", 96}, {"camera", {{"yaw", 90}}}}), planned);
  FramePlan front = plan_frame(test::complete_params({{"width", 96}, {"height", 96}}), planned);
  const image::Image front_image = renderer.render(objects, front).image;
  // The view and what the plan decided from it.
  front.camera = side.camera;
  front.clip = side.clip;
  front.viewer = side.viewer;
  front.objects = side.objects;
  const image::Image moved = renderer.render(objects, front).image;
  EXPECT_TRUE(moved.rgba == renderer.render(objects, side).image.rgba);
  EXPECT_FALSE(moved.rgba == front_image.rgba);
}

}  // namespace
}  // namespace toond::render
