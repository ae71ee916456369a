// A frame is planned once, before it is queued (render/plan/frame_plan.h): the
// plan's passes, camera, outline width and cost are what the render thread
// draws with, the frame's context is worked out from it without GL, and a
// request's price is its frames' plans' costs.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "model_checks.h"
#include "pipeline/plan.h"
#include "pipeline/price.h"
#include "render/frame/frame_context.h"
#include "render/frame/gpu_model.h"
#include "render/plan/frame_plan.h"
#include "render/run/renderer.h"
#include "support/generated_models.h"
#include "support/gl_context_test.h"
#include "support/in_process_render.h"
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

  const FrameContext frame = build_frame_context({FrameObject{model}}, plan, true);
  EXPECT_EQ(frame.draw_width, 400);
  EXPECT_EQ(frame.draw_height, 200);
  EXPECT_EQ(frame.outline_px, plan.outline_px);
  EXPECT_EQ(&frame.camera, &plan.camera) << "the plan's camera, not one fitted again";
  ASSERT_EQ(frame.lods.size(), 1u);
  EXPECT_EQ(frame.lods[0].levels, 1 + model.mesh.lods.size());
  EXPECT_EQ(frame.lods[0].triangles, frame.objects[0].triangles(frame.lods[0].level));
  // A closed sphere seen from outside: its back faces cannot show.
  EXPECT_EQ(frame.main_faces[0].hidden, HiddenFaces::Back);
}

// The frames of a sheet share one framing, and what a request costs from
// its plans is what it costs from its parameters (the refusal's what-ifs).
TEST(FramePlan, ASheetsFramesShareTheirFramingAndThePriceIsThePlansCosts) {
  const auto model = std::make_shared<const scene::Model>(sphere());
  for (const nlohmann::json& request : {nlohmann::json{{"width", 96}, {"height", 96}},
                                        nlohmann::json{{"width", 64}, {"height", 64}, {"sheet", {{"frames", 6}}}}}) {
    pipeline::Request r;
    r.objects.push_back({"m", model, glm::dmat4(1.0), nullptr});
    r.params = test::complete_params(request);
    const std::vector<pipeline::ObjectPoses> poses(r.params.sheet ? 6 : 1, pipeline::ObjectPoses{nullptr});
    const std::vector<FramePlan> plans = pipeline::plan_frames(r, poses);
    ASSERT_EQ(plans.size(), poses.size()) << request;
    for (const FramePlan& plan : plans) EXPECT_EQ(plan.scene, plans.front().scene) << request;
    const pipeline::RenderPrice from_plans = pipeline::price_of(plans);
    const pipeline::RenderPrice from_params = pipeline::price_render(r);
    EXPECT_EQ(from_plans.frames, from_params.frames) << request;
    EXPECT_EQ(from_plans.total.units(), from_params.total.units()) << request;
  }
  // A single image is one frame drawn with the request's own parameters.
  pipeline::Request single;
  single.objects.push_back({"m", model, glm::dmat4(1.0), nullptr});
  single.params = test::complete_params({{"width", 96}, {"height", 80}, {"camera", {{"yaw", 33}}}});
  const std::vector<pipeline::ObjectPoses> one_frame(1, pipeline::ObjectPoses{nullptr});
  const std::vector<FramePlan> single_plans = pipeline::plan_frames(single, one_frame);
  ASSERT_EQ(single_plans.size(), 1u);
  const FramePlan& plan = single_plans.front();
  EXPECT_EQ(plan.params.width, 96);
  EXPECT_EQ(plan.params.camera.yaw_deg, 33.0);
  EXPECT_TRUE(plan.params.camera.framed_views.empty());
}

class FramePlanRender : public test::GlContextTest {};

// The render thread draws what the plan says: a plan given another
// frame's camera draws that frame's view, byte for byte.
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
  front.camera = side.camera;
  const image::Image moved = renderer.render(objects, front).image;
  EXPECT_TRUE(moved.rgba == renderer.render(objects, side).image.rgba);
  EXPECT_FALSE(moved.rgba == front_image.rgba);
}

}  // namespace
}  // namespace toond::render
