// sheet.layers without a daemon: the schema and the sheet checks refuse
// what cannot be drawn as layers with the field's path, the layers each
// answer draws, a layer's parameters, the size limits counting every
// layer, and --set filling the list from the schema.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "limit_error.h"
#include "param_schema.h"
#include "pipeline/budget.h"
#include "pipeline/frames.h"
#include "pipeline/render_params_wire.h"
#include "pipeline/sheet_checks.h"
#include "pipeline/sheet_layers.h"
#include "request_error.h"

namespace toond::pipeline {
namespace {

using json = nlohmann::json;
using render::Output;

render::RenderParams layered_params(const json& request) {
  return render_params_from_wire(proto::ParamSchema::render_params().validate_and_complete(request));
}

// The path of the 400 a request gets from the schema or the sheet checks;
// "(accepted)" when it gets none.
std::string layers_error_path(const json& request) {
  try {
    check_sheet_params(layered_params(request));
  } catch (const RequestError& e) {
    EXPECT_EQ(e.status(), 400) << request.dump();
    return e.path();
  }
  return "(accepted)";
}

TEST(SheetLayers, BadListsAndOutputsAreRefusedAtTheField) {
  const auto with = [](const json& layers, const std::string& output = "color") {
    return json{{"width", 32}, {"height", 32}, {"output", output}, {"sheet", {{"frames", 2}, {"layers", layers}}}};
  };
  EXPECT_EQ(layers_error_path(with({"color", "shadow"})), "/sheet/layers/1") << "not a layer";
  EXPECT_EQ(layers_error_path(with({"color", "color"})), "/sheet/layers") << "the same layer twice";
  EXPECT_EQ(layers_error_path(with(json::array())), "/sheet/layers") << "no layer";
  EXPECT_EQ(layers_error_path(with("color")), "/sheet/layers") << "a list, not a name";
  EXPECT_EQ(layers_error_path(with({"color", "lines"}, "depth")), "/sheet/layers") << "a data layer";
  EXPECT_EQ(layers_error_path(with({"color", "lines"}, "id")), "/sheet/layers");
  EXPECT_EQ(layers_error_path(with({"color", "lines"}, "svg")), "/sheet/layers") << "vector paths";
  EXPECT_EQ(layers_error_path(with({"lines"}, "color")), "/sheet/layers") << "the output is not among them";
  EXPECT_EQ(layers_error_path(with({"lines", "color"}, "lines")), "(accepted)");
  EXPECT_EQ(layers_error_path(with({"color"})), "(accepted)");
}

TEST(SheetLayers, OnlyTheAnswersThatNeedEveryLayerDrawThemAll) {
  const render::RenderParams grid =
      layered_params({{"output", "lines"}, {"sheet", {{"frames", 2}, {"layers", {"color", "lines"}}}}});
  EXPECT_EQ(drawn_layers(grid, SheetFile::Image), std::vector<Output>{Output::Lines}) << "the PNG of one layer";
  EXPECT_EQ(drawn_layers(grid, SheetFile::AtlasJson), std::vector<Output>{Output::Lines});
  EXPECT_EQ(drawn_layers(grid, SheetFile::Aseprite), (std::vector<Output>{Output::Lines, Output::Color}))
      << "the output first, then the others";
  const render::RenderParams packed =
      layered_params({{"output", "color"}, {"sheet", {{"frames", 2}, {"pack", true}, {"layers", {"lines", "color"}}}}});
  for (const SheetFile answer : {SheetFile::Image, SheetFile::AtlasJson, SheetFile::Godot, SheetFile::Aseprite}) {
    EXPECT_EQ(drawn_layers(packed, answer), (std::vector<Output>{Output::Color, Output::Lines}))
        << "a packed sheet is trimmed to every layer's pixels";
  }
  const render::RenderParams plain = layered_params({{"sheet", {{"frames", 2}, {"pack", true}}}});
  EXPECT_EQ(drawn_layers(plain, SheetFile::Aseprite), std::vector<Output>{Output::Color});
}

TEST(SheetLayers, TheColourLeavesItsLinesToTheLinesLayer) {
  const json outlined = {{"outline", {{"enabled", true}}}, {"contour", {{"enabled", true}}}};
  json both = outlined;
  both["sheet"] = {{"frames", 2}, {"layers", {"color", "lines"}}};
  const render::RenderParams params = layered_params(both);
  const render::RenderParams frame = drawn_frames(params, layout_of(params)).front();
  const render::RenderParams colour = layer_params(frame, Output::Color, params);
  EXPECT_EQ(colour.output, Output::Color);
  EXPECT_FALSE(colour.outline.enabled);
  EXPECT_FALSE(colour.contour.enabled);
  const render::RenderParams lines = layer_params(frame, Output::Lines, params);
  EXPECT_EQ(lines.output, Output::Lines);
  EXPECT_TRUE(lines.outline.enabled) << "the lines layer draws what output lines draws";
  EXPECT_TRUE(lines.contour.enabled);
  json alone = outlined;
  alone["sheet"] = {{"frames", 2}, {"layers", {"color"}}};
  const render::RenderParams colour_alone = layered_params(alone);
  const render::RenderParams drawn = layer_params(frame, Output::Color, colour_alone);
  EXPECT_TRUE(drawn.outline.enabled) << "without a lines layer the colour keeps its lines";
  EXPECT_TRUE(drawn.contour.enabled);
}

TEST(SheetLayers, EachLayerCountsAgainstTheOutputPixelsAndSamples) {
  RenderLimits limits;
  limits.max_output_pixels = 64 * 64 * 8;
  limits.max_samples = 64 * 64 * 8 * 4;
  const json one = {{"width", 64}, {"height", 64}, {"msaa", 4}, {"sheet", {{"frames", 8}}}};
  const render::RenderParams single = layered_params(one);
  EXPECT_NO_THROW(check_render_budget(single, layout_of(single), limits)) << "exactly at both limits";
  json two = one;
  two["sheet"]["layers"] = {"color", "lines"};
  const render::RenderParams layered = layered_params(two);
  try {
    check_render_budget(layered, layout_of(layered), limits);
    FAIL() << "two layers of a sheet at the limit passed";
  } catch (const LimitError& e) {
    EXPECT_EQ(e.status(), 422);
    EXPECT_EQ(e.limit(), "--max-output-pixels");
    EXPECT_EQ(e.path(), "/sheet/frames");
    const std::string message = e.what();
    EXPECT_NE(message.find("in 2 layers"), std::string::npos) << message;
    EXPECT_NE(message.find("fewer sheet.layers"), std::string::npos) << message;
  }
  limits.max_output_pixels *= 2;
  try {
    check_render_budget(layered, layout_of(layered), limits);
    FAIL() << "two layers' samples passed a limit of one layer's";
  } catch (const LimitError& e) {
    EXPECT_EQ(e.limit(), "--max-samples");
    EXPECT_NE(std::string(e.what()).find("16 frames in 2 layers"), std::string::npos) << e.what();
  }
}

TEST(SheetLayers, SetFromTextTakesTheListAsTheSchemaSaysIt) {
  const proto::ParamSchema& schema = proto::ParamSchema::render_params();
  json p = json::object();
  schema.set_from_text(p, "sheet.layers", "color,lines");
  EXPECT_EQ(p["sheet"]["layers"], json({"color", "lines"}));
  EXPECT_NO_THROW(schema.validate(p));
  schema.set_from_text(p, "sheet.layers", "[\"lines\"]");
  EXPECT_EQ(p["sheet"]["layers"], json({"lines"}));
}

}  // namespace
}  // namespace toond::pipeline
