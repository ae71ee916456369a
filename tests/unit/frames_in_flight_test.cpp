// Frames in flight (Renderer::start / finish with a pixel buffer each): the
// render thread records the next frame into the same target before the last
// one's pixels are copied out, and every frame still comes back exactly as
// the synchronous path reads it. On llvmpipe the path is taken whenever it
// is switched on, so this runs wherever the tests do.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "model_checks.h"
#include "param_schema.h"
#include "pipeline/render_params_wire.h"
#include "render/frame/gpu_model.h"
#include "render/run/renderer.h"
#include "scene/import/bundle_import.h"
#include "support/generated_models.h"
#include "support/gl_context_test.h"
#include "toond_shader_files.h"

namespace toond::render {
namespace {

RenderParams in_flight_params(const nlohmann::json& request) {
  return pipeline::render_params_from_wire(proto::ParamSchema::render_params().validate_and_complete(request));
}

// Requests whose frames differ (camera, size, sampling, output), in the
// order a queue might bring them: two of the same size in a row share a
// target and a pixel buffer's size.
std::vector<nlohmann::json> in_flight_requests() {
  return {
      {{"width", 96}, {"height", 80}, {"camera", {{"yaw", 10}}}},
      {{"width", 96}, {"height", 80}, {"camera", {{"yaw", 70}}}, {"outline", {{"method", "edges"}}}},
      {{"width", 64}, {"height", 64}, {"msaa", 1}, {"supersample", 2}, {"camera", {{"yaw", 200}}}},
      {{"width", 64}, {"height", 64}, {"output", "lines"}, {"camera", {{"yaw", 120}}}},
      {{"width", 64}, {"height", 64}, {"output", "depth"}},
      {{"width", 96}, {"height", 80}, {"background", {0.2, 0.3, 0.4, 0.5}}, {"camera", {{"pitch", 40}}}},
  };
}

class FramesInFlight : public test::GlContextTest {
 protected:
  void SetUp() override {
    programs_ = std::make_unique<gpu::ProgramCache>(
        [](const std::string& name) { return std::string(shader_files::find(name)); });
    sphere_ = std::make_unique<scene::Model>(
        scene::import_bundle(scene::test_checks::make_bundle({{"m.obj", test::sphere_obj(24, 12)}})));
    model_ = std::make_unique<GpuModel>(*sphere_);
  }
  std::vector<RenderObject> objects() const { return {RenderObject{*model_, *sphere_, glm::dmat4(1.0)}}; }

  std::unique_ptr<gpu::ProgramCache> programs_;
  std::unique_ptr<scene::Model> sphere_;
  std::unique_ptr<GpuModel> model_;
};

TEST_F(FramesInFlight, EachFrameComesBackAsTheSynchronousPathReadsIt) {
  Renderer at_once(*programs_);
  std::vector<RenderOutput> expected;
  for (const nlohmann::json& request : in_flight_requests()) {
    expected.push_back(at_once.render(objects(), in_flight_params(request)));
  }

  // Each frame is started before the one ahead of it is finished, so the
  // next frame's passes overwrite the target while its pixels are on their
  // way back.
  Renderer in_flight(*programs_);
  in_flight.set_frames_in_flight(true);
  std::vector<RenderOutput> got;
  std::unique_ptr<PendingFrame> ahead;
  int packed = 0;
  for (const nlohmann::json& request : in_flight_requests()) {
    std::unique_ptr<PendingFrame> next = in_flight.start(objects(), in_flight_params(request));
    packed += next->readback != nullptr;
    if (ahead) got.push_back(in_flight.finish(std::move(ahead)));
    ahead = std::move(next);
  }
  got.push_back(in_flight.finish(std::move(ahead)));

  // Every colour frame went through a pixel buffer; the depth layer was read
  // at once, as data layers always are.
  EXPECT_EQ(packed, 5);
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    SCOPED_TRACE(in_flight_requests()[i].dump());
    EXPECT_EQ(got[i].image.width, expected[i].image.width);
    EXPECT_EQ(got[i].image.height, expected[i].image.height);
    EXPECT_TRUE(got[i].image.rgba == expected[i].image.rgba);
    EXPECT_TRUE(got[i].layer.values == expected[i].layer.values);
    EXPECT_EQ(got[i].plan, expected[i].plan);
    ASSERT_FALSE(got[i].timings.empty());
    // The readback's figure includes the wait for the pixels; the lines
    // layer's CPU step comes after it.
    bool has_readback = false;
    for (const PassTiming& t : got[i].timings) has_readback = has_readback || t.pass == "readback";
    EXPECT_TRUE(has_readback);
  }
  EXPECT_FALSE(expected[0].image.rgba == expected[1].image.rgba);  // the frames do differ
}

TEST_F(FramesInFlight, AFrameDroppedBeforeItsPixelsLandLeavesTheNextOneWhole) {
  Renderer in_flight(*programs_);
  in_flight.set_frames_in_flight(true);
  const RenderParams p = in_flight_params({{"width", 64}, {"height", 64}});
  // A request whose caller went away: its pending frame is dropped unread.
  in_flight.start(objects(), in_flight_params({{"width", 64}, {"height", 64}, {"camera", {{"yaw", 90}}}})).reset();
  const RenderOutput kept = in_flight.finish(in_flight.start(objects(), p));
  Renderer at_once(*programs_);
  EXPECT_TRUE(kept.image.rgba == at_once.render(objects(), p).image.rgba);
}

}  // namespace
}  // namespace toond::render
