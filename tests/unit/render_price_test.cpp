// A request is priced before it is queued: refused over --max-render-cost
// with what would fit, never for the shared models at any size the schema
// allows with any preset; paced when long. No GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

#include "limit_error.h"
#include "pipeline/frames.h"
#include "pipeline/plan.h"
#include "pipeline/price.h"
#include "pipeline/render_limits.h"
#include "presets.h"
#include "render/plan/sheet_layout.h"
#include "scene/import/bundle_import.h"
#include "scene/import/obj_import.h"
#include "support/costly_models.h"
#include "support/in_process_render.h"
#include "support/shared_models.h"

namespace toond::pipeline {
namespace {

std::shared_ptr<const scene::Model> obj_model(const std::string& obj) {
  scene::Bundle bundle;
  bundle.add("m.obj", obj);
  return std::make_shared<const scene::Model>(scene::import_obj_bundle(bundle));
}

Request job_of(std::shared_ptr<const scene::Model> model, const nlohmann::json& request) {
  Request job;
  job.objects.push_back({"m", std::move(model), glm::dmat4(1.0), nullptr});
  job.params = test::complete_params(request);
  job.layout = layout_of(job.params);
  return job;
}

// Every frame of the request at rest.
std::vector<ObjectPoses> rest_poses(const Request& job) {
  return std::vector<ObjectPoses>(job.layout ? job.layout->frames.size() : 1, ObjectPoses{nullptr});
}

// What the pipeline prices: its frames' plans.
RenderPrice price_render(const Request& job) { return price_of(plan_frames(job, rest_poses(job))); }

void check_render_cost(const Request& job, const RenderPrice& price, const RenderLimits& limits) {
  pipeline::check_render_cost(job, rest_poses(job), price, limits);
}

TEST(RenderPrice, TheIssuesStackIsRefusedWithWhatWouldFit) {
  const Request job = job_of(obj_model(test::nearly_coincident_triangles(60000)), nlohmann::json::object());
  const RenderPrice price = price_render(job);
  EXPECT_GT(price.total.units(), RenderLimits{}.max_render_cost);
  try {
    check_render_cost(job, price, RenderLimits{});
    FAIL() << "not refused: " << price.total.describe();
  } catch (const LimitError& e) {
    EXPECT_EQ(e.status(), 422);
    EXPECT_EQ(e.limit(), "--max-render-cost");
    const std::string message = e.what();
    EXPECT_NE(message.find("Msamples"), std::string::npos) << message;
    EXPECT_NE(message.find("--max-render-cost = 5000"), std::string::npos) << message;
    EXPECT_NE(message.find("30000 layers deep"), std::string::npos) << message;
    // Half the size is a quarter of the samples, and so on: some size fits.
    EXPECT_NE(message.find("width and height"), std::string::npos) << message;
  }
}

TEST(RenderPrice, TheWaysOfferedDoFit) {
  const auto model = obj_model(test::nearly_coincident_triangles(4000));
  const Request job = job_of(model, {{"width", 1024}, {"height", 1024}});
  RenderLimits limits;
  limits.max_render_cost = price_render(job).total.units() / 3;
  try {
    check_render_cost(job, price_render(job), limits);
    FAIL() << "not refused";
  } catch (const LimitError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("width and height 512 × 512"), std::string::npos) << message;
    // msaa 4 → 1 takes the surface samples to a quarter: under a third.
    EXPECT_NE(message.find("msaa 1"), std::string::npos) << message;
    const Request smaller = job_of(model, {{"width", 512}, {"height", 512}});
    EXPECT_LE(price_render(smaller).total.units(), limits.max_render_cost);
    const Request one_sample = job_of(model, {{"width", 1024}, {"height", 1024}, {"msaa", 1}});
    EXPECT_LE(price_render(one_sample).total.units(), limits.max_render_cost);
  }
}

TEST(RenderPrice, ZeroMeansNoLimit) {
  const Request job = job_of(obj_model(test::nearly_coincident_triangles(60000)), nlohmann::json::object());
  RenderLimits limits;
  limits.max_render_cost = 0;
  EXPECT_NO_THROW(check_render_cost(job, price_render(job), limits));
}

// Each frame at its own view: the sum of the single renders of those views.
TEST(RenderPrice, ASheetCostsAllItsFramesEachFromItsView) {
  const auto model = obj_model(test::stacked_triangles(100));
  const Request job = job_of(model, {{"width", 128}, {"height", 128}, {"sheet", {{"frames", 8}}}});
  const RenderPrice sheet = price_render(job);
  EXPECT_EQ(sheet.frames, 8u);
  double singles = 0;
  double least = 1e300, most = 0;
  for (const render::SheetFrame& frame : render::layout_sheet(*job.params.sheet, 128, 128).frames) {
    const render::RenderCost one =
        price_render(
            job_of(model,
                   {{"width", 128}, {"height", 128}, {"camera", {{"yaw", frame.yaw_deg}, {"pitch", frame.pitch_deg}}}}))
            .total;
    singles += one.units();
    least = std::min(least, one.samples);
    most = std::max(most, one.samples);
  }
  EXPECT_NEAR(sheet.total.units(), singles, 1e-9 * singles);
  EXPECT_NEAR(sheet.per_frame().units(), singles / 8, 1e-9 * singles);
  // The stack faces +Z: seen from the side its frames cover fewer samples.
  EXPECT_GT(most, least * 1.5);
}

// sheet.layers: a sheet that draws both layers pays for both, the price of
// its colour without lines and of its lines each asked for alone; refused,
// it says so.
TEST(RenderPrice, ASheetPaysForEveryLayerItDraws) {
  const auto model = obj_model(test::nearly_coincident_triangles(4000));
  const nlohmann::json size = {{"width", 128}, {"height", 128}};
  const auto sheet_job = [&](const nlohmann::json& fields) {
    nlohmann::json request = size;
    request.update(fields);
    return job_of(model, request);
  };
  const Request packed = sheet_job({{"sheet", {{"frames", 4}, {"pack", true}, {"layers", {"color", "lines"}}}}});
  const RenderPrice both = price_render(packed);
  EXPECT_EQ(both.frames, 8u) << "4 frames × 2 layers";
  const double colour =
      price_render(sheet_job({{"outline", {{"enabled", false}}}, {"sheet", {{"frames", 4}}}})).total.units();
  const double lines = price_render(sheet_job({{"output", "lines"}, {"sheet", {{"frames", 4}}}})).total.units();
  EXPECT_NEAR(both.total.units(), colour + lines, 1e-9 * (colour + lines));
  Request grid = sheet_job({{"sheet", {{"frames", 4}, {"layers", {"color", "lines"}}}}});
  EXPECT_EQ(price_render(grid).frames, 4u) << "the PNG of an unpacked sheet draws its output alone";
  EXPECT_NEAR(price_render(grid).total.units(), colour, 1e-9 * colour) << "the colour without its lines";
  grid.answer.file = SheetFile::Aseprite;
  EXPECT_EQ(price_render(grid).frames, 8u) << "the .aseprite file holds both";
  RenderLimits limits;
  limits.max_render_cost = (colour + lines) * 0.75;
  try {
    check_render_cost(packed, both, limits);
    FAIL() << "not refused";
  } catch (const LimitError& e) {
    EXPECT_EQ(e.status(), 422);
    const std::string message = e.what();
    EXPECT_NE(message.find("for its 4 frames × 2 layers"), std::string::npos) << message;
    EXPECT_NE(message.find("width and height"), std::string::npos) << "what would fit: " << message;
  }
}

TEST(RenderPrice, OnlyLongFramesArePacedInChunksOfAboutTheChunkCost) {
  render::RenderCost cheap;
  cheap.samples = 10e6;
  cheap.triangles = 1e5;
  EXPECT_EQ(paced_chunk_triangles(cheap), 0u);
  render::RenderCost dear;
  dear.samples = 50000e6;
  dear.triangles = 120000;
  const std::size_t chunk = paced_chunk_triangles(dear);
  ASSERT_GT(chunk, 0u);
  const double chunks = dear.triangles / static_cast<double>(chunk);
  // Whole triangles a chunk: 59 of them where 59.99 would be exact.
  EXPECT_NEAR(chunks / (dear.units() / kPacedChunkCost), 1.0, 0.05);
}

// The edge pass is drawn in bands of its own: a frame dear only for its
// edge pass chunks its triangles at the geometry's own cost, and its bands
// read a chunk's worth of texels.
TEST(RenderPrice, TheEdgePassIsPacedInBandsNotInSmallerChunks) {
  render::RenderCost drawing;
  drawing.samples = 100e6;
  drawing.triangles = 1e5;
  EXPECT_EQ(paced_band_texels(drawing), 0u);
  render::RenderCost with_edges = drawing;
  with_edges.edge_texels = 1000e6;
  ASSERT_GE(with_edges.units(), kPacedFrameCost);
  const std::size_t chunk = paced_chunk_triangles(with_edges);
  EXPECT_NEAR(static_cast<double>(chunk), std::floor(kPacedChunkCost / (drawing.units() / drawing.triangles)), 1.0);
  EXPECT_NEAR(static_cast<double>(paced_band_texels(with_edges)) * render::kEdgeTexelSamples / 1e6, kPacedChunkCost,
              1e-3);
}

// The shared models, as users upload them: never refused at the schema's
// largest size with any preset (the budget's false refusals are 0).
TEST(RenderPrice, SharedModelsAreNeverRefused) {
  TOOND_REQUIRE_SHARED_MODELS();
  std::vector<std::string> presets = {""};
  for (const auto& item : proto::Presets::builtin().document().items()) presets.push_back(item.key());
  double dearest = 0;
  std::string dearest_what;
  for (const auto& entry : std::filesystem::directory_iterator(test::shared_models_dir())) {
    if (!entry.is_directory() || entry.path().filename() == "edge-cases") continue;
    scene::Bundle bundle;
    for (const auto& file : std::filesystem::recursive_directory_iterator(entry.path())) {
      if (!file.is_regular_file()) continue;
      const std::string ext = file.path().extension().string();
      if (ext != ".obj" && ext != ".mtl" && ext != ".png" && ext != ".jpg") continue;
      bundle.add(std::filesystem::relative(file.path(), entry.path()).generic_string(), test::read_file(file.path()));
    }
    const auto model = std::make_shared<const scene::Model>(scene::import_bundle(bundle));
    for (const std::string& preset : presets) {
      for (int side : {512, 2048, 4096}) {
        nlohmann::json request = {{"width", side}, {"height", side}, {"msaa", 8}};
        if (!preset.empty()) request["preset"] = preset;
        const Request job = job_of(model, request);
        const RenderPrice price = price_render(job);
        if (price.total.units() > dearest) {
          dearest = price.total.units();
          dearest_what = entry.path().filename().string() + " " + (preset.empty() ? "default" : preset) + " " +
                         std::to_string(side) + "²";
        }
        EXPECT_NO_THROW(check_render_cost(job, price, RenderLimits{}))
            << entry.path().filename() << " " << preset << " " << side;
      }
    }
  }
  std::cout << "dearest shared render: " << dearest << " Msamples (" << dearest_what << ")\n";
}

}  // namespace
}  // namespace toond::pipeline
