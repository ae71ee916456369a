// A long render drawn in chunks draws the same image as in one go, and one
// past its deadline stops without breaking the context for the next.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <thread>

#include "gpu/program_cache.h"
#include "render/frame/draw_pacing.h"
#include "render/plan/render_cost.h"
#include "render/run/renderer.h"
#include "scene/import/bundle_import.h"
#include "scene/import/obj_import.h"
#include "support/costly_models.h"
#include "support/generated_models.h"
#include "support/gl_context_test.h"
#include "support/in_process_render.h"
#include "toond_shader_files.h"

namespace toond::render {
namespace {

using Clock = std::chrono::steady_clock;

class DrawPacingTest : public test::GlContextTest {
 protected:
  void SetUp() override {
    scene::Bundle bundle;
    bundle.add("stack.obj", test::stacked_triangles(300));
    model_ = std::make_unique<scene::Model>(scene::import_obj_bundle(bundle));
    programs_ = std::make_unique<gpu::ProgramCache>(
        [](const std::string& name) { return std::string(shader_files::find(name)); });
    renderer_ = std::make_unique<Renderer>(*programs_);
    gpu_model_ = std::make_unique<GpuModel>(*model_);
    params_ = test::complete_params({{"width", 96}, {"height", 96}});
  }

  RenderOutput render(DrawPacing* pacing) {
    return renderer_->render({RenderObject{*gpu_model_, *model_}}, params_, pacing);
  }

  static scene::Model cube_model() {
    scene::Bundle bundle;
    bundle.add("cube.obj", test::cube_obj());
    return scene::import_obj_bundle(bundle);
  }
  // The texels of ten rows of a 96-pixel-wide edge pass (and half a row,
  // for rounding): the hull's crease lines are drawn alone, the edges
  // method draws the silhouette too.
  static std::size_t ten_rows_a_band(const RenderParams& params) {
    return static_cast<std::size_t>(10.5 * 96 * edge_texels_per_pixel(params.outline.width, !params.outline.edges));
  }

  std::unique_ptr<scene::Model> model_;
  std::unique_ptr<gpu::ProgramCache> programs_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<GpuModel> gpu_model_;
  RenderParams params_;
};

TEST_F(DrawPacingTest, ChunksDrawTheSameImageAsOneDrawCall) {
  const image::Image whole = render(nullptr).image;
  int calls = 0;
  DrawPacing pacing(7, 0, Clock::now() + std::chrono::minutes(5), [&] { ++calls; });
  const image::Image chunked = render(&pacing).image;
  // 300 triangles in chunks of 7, in every pass that draws the mesh (the
  // main pass and the hull), a chunk running on from one draw to the next.
  EXPECT_GE(pacing.chunks_drawn(), 2 * 300u / 7);
  EXPECT_EQ(static_cast<std::size_t>(calls), pacing.chunks_drawn());
  EXPECT_FALSE(pacing.expired());
  ASSERT_EQ(whole.width, chunked.width);
  EXPECT_EQ(whole.rgba, chunked.rgba);
}

// The main pass draws a sphere as the ranges between its runs of faces
// turned away (render/cull/facing_runs.h), a few faces each: the chunks still
// hold the set number of triangles, not one range each.
TEST_F(DrawPacingTest, ManyShortDrawsWaitOncePerChunkOfTriangles) {
  scene::Bundle bundle;
  bundle.add("sphere.obj", test::sphere_obj(64, 32));
  const scene::Model sphere = scene::import_bundle(bundle);  // closed, so the main pass culls
  const GpuModel gpu_sphere(sphere);
  const RenderParams params = test::complete_params({{"width", 160}, {"height", 160}});
  const RenderOutput whole = renderer_->render({RenderObject{gpu_sphere, sphere}}, params);
  ASSERT_GT(whole.main_triangles_skipped, 0u);
  constexpr std::size_t kChunk = 2000;
  DrawPacing pacing(kChunk, 0, Clock::now() + std::chrono::minutes(5));
  const RenderOutput paced = renderer_->render({RenderObject{gpu_sphere, sphere}}, params, &pacing);
  // At most the main pass's and the hull's triangles, in full chunks.
  EXPECT_LE(pacing.chunks_drawn(), 2 * sphere.mesh.triangle_count() / kChunk);
  EXPECT_GE(pacing.chunks_drawn(), 1u);
  EXPECT_EQ(paced.image.rgba, whole.image.rgba);
}

// The screen-space edge pass reads every pixel's neighbours; a long render
// draws it in bands of rows, each waited for: the same bytes, silhouettes
// and crease lines alike.
TEST_F(DrawPacingTest, TheEdgePassInBandsDrawsTheSameImage) {
  const scene::Model cube = cube_model();
  const GpuModel gpu_cube(cube);
  for (const nlohmann::json& outline :
       {nlohmann::json{{"method", "edges"}, {"width", 3}}, nlohmann::json{{"creases", "always"}}}) {
    RenderParams params = test::complete_params({{"width", 96}, {"height", 96}, {"outline", outline}});
    // Crease lines as sprite lines find them, in screen space.
    params.outline.screen_space_creases = true;
    const RenderOutput whole = renderer_->render({RenderObject{gpu_cube, cube}}, params);
    // No triangle chunk ever full.
    int steps_aside = 0;
    DrawPacing pacing(1000000, ten_rows_a_band(params), Clock::now() + std::chrono::minutes(5), [&] { ++steps_aside; });
    const RenderOutput banded = renderer_->render({RenderObject{gpu_cube, cube}}, params, &pacing);
    EXPECT_EQ(pacing.chunks_drawn(), 10u) << outline << " " << whole.plan;
    EXPECT_EQ(static_cast<std::size_t>(steps_aside), pacing.chunks_drawn());
    EXPECT_TRUE(banded.image.rgba == whole.image.rgba) << outline;
  }
}

// The crease pass draws its edges in chunks of its own, each worth what a
// band is: the same bytes, and a wait after every chunk of them.
TEST_F(DrawPacingTest, CreaseEdgesInChunksDrawTheSameImage) {
  scene::Bundle bundle;
  bundle.add("cube.obj", test::cube_obj());
  const scene::Model cube = scene::import_bundle(bundle);
  ASSERT_EQ(cube.mesh.crease_edges.creased_at(40), 12u);
  const GpuModel gpu_cube(cube);
  const RenderParams params = test::complete_params({{"width", 96}, {"height", 96}, {"camera", {{"pitch", 30}}}});
  const RenderOutput whole = renderer_->render({RenderObject{gpu_cube, cube}}, params);
  ASSERT_EQ(whole.plan, "main,hull_outline,creases,resolve,readback");
  ASSERT_GE(whole.crease_edges_drawn, 6u);
  // Two crease edges a chunk; no triangle chunk ever full.
  const auto two_edges = static_cast<std::size_t>(std::ceil(2.0 * kCreaseEdgeSamples / kEdgeTexelSamples));
  int steps_aside = 0;
  DrawPacing pacing(1000000, two_edges, Clock::now() + std::chrono::minutes(5), [&] { ++steps_aside; });
  const RenderOutput paced = renderer_->render({RenderObject{gpu_cube, cube}}, params, &pacing);
  EXPECT_EQ(paced.crease_edges_drawn, whole.crease_edges_drawn);
  EXPECT_EQ(pacing.chunks_drawn(), whole.crease_edges_drawn / 2);
  EXPECT_EQ(static_cast<std::size_t>(steps_aside), pacing.chunks_drawn());
  EXPECT_TRUE(paced.image.rgba == whole.image.rgba);
}

TEST_F(DrawPacingTest, PastTheDeadlineTheRenderStopsAndTheNextDrawsAsBefore) {
  const image::Image before = render(nullptr).image;
  DrawPacing late(7, 0, Clock::now() - std::chrono::milliseconds(1));
  EXPECT_THROW(render(&late), RenderAborted);
  EXPECT_TRUE(late.expired());
  EXPECT_EQ(late.chunks_drawn(), 0u);
  // Stopped between passes and draws, nothing was left half set up.
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(render(nullptr).image.rgba, before.rgba);
}

TEST_F(DrawPacingTest, ADeadlineThatPassesMidwayStopsWithinAChunk) {
  // The deadline is far enough off that the frame's setup and three chunks
  // fit before it on any build (ten warm renders' time); the pause after
  // the third chunk then outlasts it, and nothing more is drawn.
  const auto started = Clock::now();
  render(nullptr);
  const auto warm = Clock::now() - started;
  const auto deadline =
      Clock::now() + std::clamp<Clock::duration>(10 * warm, std::chrono::milliseconds(300), std::chrono::seconds(3));
  int pauses = 0;
  DrawPacing stopping(7, 0, deadline, [&] {
    if (++pauses == 3) std::this_thread::sleep_until(deadline + std::chrono::milliseconds(5));
  });
  EXPECT_THROW(render(&stopping), RenderAborted);
  EXPECT_EQ(stopping.chunks_drawn(), 3u);
}

// A deadline that passes between two bands of the edge pass stops it
// there; the bands' viewport is given back, so the next render draws as
// before.
TEST_F(DrawPacingTest, ADeadlineThatPassesBetweenBandsStopsTheEdgePass) {
  const scene::Model cube = cube_model();
  const GpuModel gpu_cube(cube);
  const RenderParams params =
      test::complete_params({{"width", 96}, {"height", 96}, {"outline", {{"method", "edges"}}}});
  const auto started = Clock::now();
  const image::Image before = renderer_->render({RenderObject{gpu_cube, cube}}, params).image;
  const auto warm = Clock::now() - started;
  const auto deadline =
      Clock::now() + std::clamp<Clock::duration>(10 * warm, std::chrono::milliseconds(300), std::chrono::seconds(3));
  int pauses = 0;
  DrawPacing stopping(1000000, ten_rows_a_band(params), deadline, [&] {
    if (++pauses == 3) std::this_thread::sleep_until(deadline + std::chrono::milliseconds(5));
  });
  EXPECT_THROW(renderer_->render({RenderObject{gpu_cube, cube}}, params, &stopping), RenderAborted);
  EXPECT_EQ(stopping.chunks_drawn(), 3u);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_TRUE(renderer_->render({RenderObject{gpu_cube, cube}}, params).image.rgba == before.rgba);
}

}  // namespace
}  // namespace toond::render
