// The pass plan is pure: these tests need no GL.
#include <gtest/gtest.h>

#include <algorithm>

#include "param_schema.h"
#include "pipeline/render_params_wire.h"
#include "render/plan/pass_plan.h"

namespace toond::render {
namespace {

using nlohmann::json;

RenderParams params(const json& request) {
  return pipeline::render_params_from_wire(proto::ParamSchema::render_params().validate_and_complete(request));
}

// Whether the main pass's programs get #define d.
bool has_define(const PassPlan& plan, const std::string& d) {
  const std::vector<std::string> defines = plan.shading.defines();
  return std::find(defines.begin(), defines.end(), d) != defines.end();
}

TEST(PassPlan, DefaultsDrawOutlineAndResolve) {
  const PassPlan plan = plan_passes(params(json::object()), {true});
  EXPECT_EQ(plan.describe(), "main,hull_outline,resolve,readback");
  EXPECT_TRUE(plan.sample_textures);
}

TEST(PassPlan, NoOutlinePassAtWidthZeroOrWhenDisabled) {
  EXPECT_FALSE(plan_passes(params({{"outline", {{"width", 0}}}}), {}).has(Pass::HullOutline));
  EXPECT_FALSE(plan_passes(params({{"outline", {{"enabled", false}}}}), {}).has(Pass::HullOutline));
  EXPECT_TRUE(plan_passes(params({{"outline", {{"width", 0.5}}}}), {}).has(Pass::HullOutline));
}

// Crease lines join the default outline on a hard-edged model only, and
// the request can ask for them always or never. They are drawn along the
// crease edges: a model with none draws none, even asked always.
TEST(PassPlan, CreaseLinesJoinTheOutlineOfHardEdgedModels) {
  ModelTraits smooth, hard, creased_smooth;
  hard.hard_edged = true;
  hard.has_crease_edges = true;
  creased_smooth.has_crease_edges = true;
  EXPECT_EQ(plan_passes(params(json::object()), smooth).describe(), "main,hull_outline,resolve,readback");
  const PassPlan creased = plan_passes(params(json::object()), hard);
  EXPECT_FALSE(creased.creases_only);
  EXPECT_EQ(creased.describe(), "main,hull_outline,creases,resolve,readback");
  EXPECT_FALSE(plan_passes(params({{"outline", {{"creases", "never"}}}}), hard).has(Pass::Creases));
  EXPECT_FALSE(plan_passes(params(json::object()), creased_smooth).has(Pass::Creases)) << "not hard-edged";
  EXPECT_TRUE(plan_passes(params({{"outline", {{"creases", "always"}}}}), creased_smooth).has(Pass::Creases));
  EXPECT_EQ(plan_passes(params({{"outline", {{"creases", "always"}}}}), smooth).describe(),
            "main,hull_outline,resolve,readback")
      << "no crease edge at the angle: nothing to draw";
  EXPECT_EQ(plan_passes(params({{"outline", {{"method", "wireframe"}}}}), hard).describe(),
            "main,wireframe,creases,resolve,readback");
  // The edges method draws creases with its silhouettes already.
  const PassPlan edges = plan_passes(params({{"outline", {{"method", "edges"}}}}), hard);
  EXPECT_TRUE(edges.has(Pass::Edges));
  EXPECT_FALSE(edges.has(Pass::Creases));
  EXPECT_FALSE(edges.creases_only);
  EXPECT_FALSE(plan_passes(params({{"outline", {{"width", 0}}}}), hard).has(Pass::Creases));
}

// Where what decides a crease line is what the pixels show, the edge pass
// finds crease lines in screen space: sprite lines (their rules read the
// areas on both sides of a line) and masked materials (cut-out parts the
// edges know nothing of).
TEST(PassPlan, CreaseLinesAreFoundInScreenSpaceWhereThePixelsDecide) {
  ModelTraits hard;
  hard.hard_edged = true;
  hard.has_crease_edges = true;
  RenderParams sprite = params(json::object());
  sprite.outline.screen_space_creases = true;
  const PassPlan by_pixels = plan_passes(sprite, hard);
  EXPECT_TRUE(by_pixels.creases_only);
  EXPECT_EQ(by_pixels.describe(), "main,hull_outline,edge_prepass,edges(creases),resolve,readback");
  ModelTraits masked = hard;
  masked.has_masked_materials = true;
  EXPECT_EQ(plan_passes(params(json::object()), masked).describe(),
            "main,hull_outline,edge_prepass,edges(creases),resolve,readback");
  ModelTraits masked_smooth;
  masked_smooth.has_masked_materials = true;
  EXPECT_FALSE(plan_passes(params(json::object()), masked_smooth).has(Pass::Edges));
}

TEST(PassPlan, NoResolveWithoutMsaa) {
  const PassPlan plan = plan_passes(params({{"msaa", 1}}), {});
  EXPECT_FALSE(plan.has(Pass::Resolve));
  EXPECT_EQ(plan.samples, 1);
  EXPECT_TRUE(plan_passes(params({{"msaa", 8}}), {}).has(Pass::Resolve));
}

TEST(PassPlan, NoTextureSamplingWithoutTextures) {
  EXPECT_FALSE(plan_passes(params(json::object()), {false}).sample_textures);
}

TEST(PassPlan, ShadingModeAndRoundingBecomeDefines) {
  const PassPlan cel = plan_passes(params({{"shading", {{"rounding", "floor"}}}}), {});
  EXPECT_TRUE(has_define(cel, "MODE_CEL"));
  EXPECT_TRUE(has_define(cel, "ROUND_FLOOR"));
  const PassPlan phong = plan_passes(params({{"shading", {{"mode", "phong"}, {"rounding", "floor"}}}}), {});
  EXPECT_TRUE(has_define(phong, "MODE_PHONG"));
  EXPECT_FALSE(has_define(phong, "ROUND_FLOOR")) << "rounding is irrelevant without bands";
  EXPECT_TRUE(has_define(plan_passes(params({{"shading", {{"mode", "flat"}}}}), {}), "MODE_FLAT"));
}

// The light loop's bound is compiled in (a uniform bound cost llvmpipe
// ~40 % of the cel pass); unlit colour has no loop and no variant per count.
TEST(PassPlan, TheLightCountIsPartOfTheVariant) {
  EXPECT_TRUE(has_define(plan_passes(params(json::object()), {}), "LIGHT_COUNT 1"));
  const json two = {
      {"lights", {{{"type", "directional"}, {"direction", {0, 0, -1}}}, {{"type", "point"}, {"position", {1, 1, 1}}}}}};
  EXPECT_TRUE(has_define(plan_passes(params(two), {}), "LIGHT_COUNT 2"));
  EXPECT_TRUE(has_define(plan_passes(params({{"lights", json::array()}}), {}), "LIGHT_COUNT 0"));
  const PassPlan flat = plan_passes(params({{"shading", {{"mode", "flat"}}}}), {});
  const std::vector<std::string> flat_defines = flat.shading.defines();
  EXPECT_TRUE(std::none_of(flat_defines.begin(), flat_defines.end(),
                           [](const std::string& d) { return d.rfind("LIGHT_COUNT", 0) == 0; }));
  const json ramp = {{"shading", {{"ramp", {{{"at", -1}, {"value", 0.2}}, {{"at", 0.5}, {"value", 1}}}}}}};
  EXPECT_TRUE(has_define(plan_passes(params(ramp), {}), "RAMP_COUNT 2"));
}

TEST(PassPlan, ShadowPassOnlyWithADirectionalLightThatCanCast) {
  const json on = {{"shadows", {{"enabled", true}}}};
  const PassPlan with_sun = plan_passes(params(on), {});
  EXPECT_EQ(with_sun.describe(), "shadow,main,hull_outline,resolve,readback");
  EXPECT_EQ(with_sun.shadow_light, 0);
  EXPECT_TRUE(has_define(with_sun, "SHADOWS"));

  json point_only = on;
  point_only["lights"] = {{{"type", "point"}, {"position", {0, 1, 0}}}};
  EXPECT_FALSE(plan_passes(params(point_only), {}).has(Pass::Shadow)) << "point lights cast no shadows";

  json no_lights = on;
  no_lights["lights"] = json::array();
  EXPECT_FALSE(plan_passes(params(no_lights), {}).has(Pass::Shadow));

  json flat = on;
  flat["shading"] = {{"mode", "flat"}};
  EXPECT_FALSE(plan_passes(params(flat), {}).has(Pass::Shadow)) << "unlit colour has nothing to darken";

  json second = on;
  second["lights"] = {{{"type", "point"}, {"position", {0, 1, 0}}}, {{"type", "directional"}}};
  EXPECT_EQ(plan_passes(params(second), {}).shadow_light, 1) << "the first directional light casts";

  EXPECT_FALSE(plan_passes(params(json::object()), {}).has(Pass::Shadow));
}

TEST(PassPlan, OutlineMethodsEachAddTheirPasses) {
  auto passes = [](const json& method) {
    return plan_passes(params({{"msaa", 1}, {"outline", {{"method", method}}}}), {}).describe();
  };
  EXPECT_EQ(passes("hull"), "main,hull_outline,readback");
  EXPECT_EQ(passes("wireframe"), "main,wireframe,readback");
  EXPECT_EQ(passes("edges"), "main,edge_prepass,edges,readback");
  EXPECT_EQ(passes(json{"edges", "hull"}), "main,hull_outline,edge_prepass,edges,readback");
  EXPECT_EQ(plan_passes(params({{"msaa", 1}, {"outline", {{"method", json{"wireframe", "edges"}}, {"width", 0}}}}), {})
                .describe(),
            "main,readback")
      << "width 0 draws no outline by any method";
}

TEST(PassPlan, FloorIsItsOwnPassAfterTheModel) {
  const PassPlan plan = plan_passes(params({{"floor", {{"enabled", true}}}, {"msaa", 1}}), {});
  EXPECT_EQ(plan.describe(), "main,floor,hull_outline,readback");
}

TEST(PassPlan, NoTextureSamplingForAWhiteBase) {
  const PassPlan plan = plan_passes(params({{"shading", {{"base", "white"}}}}), {true});
  EXPECT_FALSE(plan.sample_textures) << "a white base never reads the material's texture";
  EXPECT_TRUE(plan_passes(params(json::object()), {true}).sample_textures);
}

TEST(PassPlan, NoNormalMapMathsWithoutANormalMap) {
  EXPECT_FALSE(plan_passes(params(json::object()), {true, false}).use_normal_maps);
  EXPECT_TRUE(plan_passes(params(json::object()), {true, true}).use_normal_maps);
  EXPECT_FALSE(plan_passes(params({{"shading", {{"mode", "flat"}}}}), {true, true}).use_normal_maps)
      << "unlit colour never reads the normal map";
  for (const json& request : {json::object(), json{{"shading", {{"mode", "phong"}}}}}) {
    EXPECT_FALSE(has_define(plan_passes(params(request), {true, false}), "NORMAL_MAP"))
        << "NORMAL_MAP is per material, never shared";
  }
}

TEST(PassPlan, NoHalftoneMathsWhenOff) {
  auto halftone = [](const PassPlan& plan) {
    return has_define(plan, "HALFTONE_DOTS") || has_define(plan, "HALFTONE_CHECKER");
  };
  EXPECT_FALSE(halftone(plan_passes(params(json::object()), {})));
  EXPECT_FALSE(halftone(plan_passes(params({{"halftone", {{"enabled", false}, {"style", "checker"}}}}), {})));
  EXPECT_TRUE(has_define(plan_passes(params({{"halftone", {{"enabled", true}}}}), {}), "HALFTONE_DOTS"));
  EXPECT_TRUE(has_define(plan_passes(params({{"halftone", {{"enabled", true}, {"style", "checker"}}}}), {}),
                         "HALFTONE_CHECKER"));
  EXPECT_FALSE(halftone(plan_passes(params({{"halftone", {{"enabled", true}}}, {"shading", {{"mode", "flat"}}}}), {})))
      << "unlit colour has no light level to screen";
}

TEST(PassPlan, EffectsThatAreOffAddNoShaderFeature) {
  const PassPlan plan = plan_passes(
      params({{"specular", {{"enabled", false}}}, {"rim", {{"enabled", false}}}, {"contour", {{"enabled", false}}}}),
      {});
  for (const char* d : {"SPECULAR", "RIM", "CONTOUR_EVEN", "CONTOUR_FRESNEL", "SHADOWS", "COMBINE_SUM",
                        "HAS_POINT_LIGHTS", "VERTEX_COLOR", "SHADE_COLOR"}) {
    EXPECT_FALSE(has_define(plan, d)) << d;
  }
  EXPECT_FALSE(has_define(plan_passes(params({{"specular", {{"strength", 0}}}}), {}), "SPECULAR"))
      << "a highlight of strength 0 changes nothing";
  EXPECT_FALSE(has_define(plan_passes(params({{"lights", json::array()}}), {}), "SPECULAR"))
      << "no light, no highlight";
}

TEST(PassPlan, BandEdgesAreSmoothedOnlyWhereThereAreBandEdges) {
  EXPECT_TRUE(has_define(plan_passes(params(json::object()), {}), "BAND_AA")) << "on by default";
  EXPECT_TRUE(has_define(plan_passes(params({{"shading", {{"two_tone", {{"enabled", true}}}}}}), {}), "BAND_AA"));
  EXPECT_FALSE(has_define(plan_passes(params({{"shading", {{"band_aa", false}}}}), {}), "BAND_AA"));
  EXPECT_FALSE(has_define(plan_passes(params({{"shading", {{"mode", "phong"}}}}), {}), "BAND_AA"))
      << "smooth shading has no bands";
  EXPECT_FALSE(has_define(plan_passes(params({{"shading", {{"mode", "flat"}}}}), {}), "BAND_AA"));
  EXPECT_FALSE(has_define(plan_passes(params({{"lights", json::array()}}), {}), "BAND_AA"))
      << "without light every point is in the same band";
}

TEST(PassPlan, ReadbackIsAlwaysLast) {
  for (const json& request : {json::object(), json{{"msaa", 1}, {"outline", {{"enabled", false}}}}}) {
    const PassPlan plan = plan_passes(params(request), {});
    ASSERT_FALSE(plan.passes.empty());
    EXPECT_EQ(plan.passes.front(), Pass::Main);
    EXPECT_EQ(plan.passes.back(), Pass::Readback);
  }
}

// A model with masked materials has its outlines alpha-tested (the hull's
// and wireframe's programs get ALPHA_MASK; so does the edge prepass).
TEST(PassPlan, MaskedMaterialsAlphaTestTheOutlines) {
  ModelTraits masked;
  masked.has_masked_materials = true;
  const PassPlan plan = plan_passes(params(json::object()), masked);
  EXPECT_TRUE(plan.alpha_tested_outlines);
  EXPECT_TRUE(plan.outline.has(OutlineFeature::AlphaMask));
  EXPECT_FALSE(plan_passes(params(json::object()), {}).alpha_tested_outlines);
  EXPECT_FALSE(plan_passes(params({{"outline", {{"enabled", false}}}}), masked).alpha_tested_outlines);
}

// A data layer draws the Layer pass alone: no shading, shadow, floor,
// outline, resolve or downsample, whatever else the request asks for.
TEST(PassPlan, ADataLayerRunsTheLayerPassAlone) {
  const json busy = {{"shadows", {{"enabled", true}}},
                     {"floor", {{"enabled", true}}},
                     {"outline", {{"method", {"hull", "wireframe", "edges"}}}},
                     {"contour", {{"enabled", true}}},
                     {"msaa", 8},
                     {"supersample", 2}};
  ModelTraits hard;
  hard.hard_edged = true;
  for (const auto& [name, feature] : {std::pair{"depth", LayerFeature::Depth},
                                      std::pair{"normal", LayerFeature::Normal}, std::pair{"id", LayerFeature::Id}}) {
    json request = busy;
    request["output"] = name;
    const PassPlan plan = plan_passes(params(request), hard);
    EXPECT_EQ(plan.describe(), "layer,readback") << name;
    EXPECT_EQ(plan.samples, 1) << name;
    EXPECT_EQ(plan.supersample, 1) << name;
    EXPECT_EQ(plan.layer, LayerVariant{}.set(feature)) << name;
    EXPECT_EQ(plan.shadow_light, -1) << name;
  }
}

TEST(PassPlan, ALayerTestsTheAlphaOfMaskedMaterials) {
  ModelTraits masked;
  masked.has_masked_materials = true;
  EXPECT_TRUE(plan_passes(params({{"output", "normal"}}), masked).layer.has(LayerFeature::AlphaMask));
  EXPECT_FALSE(plan_passes(params({{"output", "normal"}}), {}).layer.has(LayerFeature::AlphaMask));
}

TEST(PassPlan, IdsNumberTheObjectsOfASceneOrTheMaterialsOfAModel) {
  EXPECT_EQ(plan_passes(params({{"output", "id"}}), {}).ids_by, IdSource::Material);
  const json scene = {{"output", "id"},
                      {"objects", {{{"model", "0123456789abcdef"}}, {{"model", "0123456789abcdef"}}}}};
  EXPECT_EQ(plan_passes(params(scene), {}).ids_by, IdSource::Object);
}

// The lines layer keeps every line pass and the floor (its depth hides
// lines), drops the shadow pass (no shading shows) and writes the contour
// alone. Its colour is premultiplied: the GPU downsample divides by alpha
// when supersampling, a CPU step after the readback when not.
TEST(PassPlan, TheLinesLayerKeepsTheLinePassesAndDropsTheShading) {
  ModelTraits hard;
  hard.hard_edged = true;
  hard.has_crease_edges = true;
  const json request = {
      {"output", "lines"}, {"shadows", {{"enabled", true}}}, {"floor", {{"enabled", true}}}, {"supersample", 2}};
  const PassPlan plan = plan_passes(params(request), hard);
  EXPECT_EQ(plan.describe(), "main,floor,hull_outline,creases,resolve,downsample,readback");
  EXPECT_TRUE(has_define(plan, "LINES_ONLY"));
  EXPECT_FALSE(has_define(plan, "SHADOWS"));
  EXPECT_TRUE(plan.downsample.has(DownsampleFeature::Premultiplied));
  json single = request;
  single["supersample"] = 1;
  EXPECT_EQ(plan_passes(params(single), hard).describe(),
            "main,floor,hull_outline,creases,resolve,readback,unpremultiply");
  json colour = request;
  colour.erase("output");
  const PassPlan full = plan_passes(params(colour), hard);
  EXPECT_TRUE(full.has(Pass::Shadow));
  EXPECT_FALSE(full.has(Pass::Unpremultiply));
  EXPECT_FALSE(full.downsample.has(DownsampleFeature::Premultiplied));
  EXPECT_FALSE(has_define(full, "LINES_ONLY"));
}

// Supersampling shrinks the image on the GPU before the readback, so only
// output-sized pixels come back.
TEST(PassPlan, TheDownsampleRunsBeforeTheReadback) {
  const PassPlan plan = plan_passes(params({{"supersample", 3}, {"msaa", 1}, {"outline", {{"enabled", false}}}}), {});
  EXPECT_EQ(plan.describe(), "main,downsample,readback");
  EXPECT_EQ(plan.supersample, 3);
  EXPECT_EQ(plan_passes(params({{"outline", {{"enabled", false}}}}), {}).describe(), "main,resolve,readback");
}

// Only the hull outline reads the main pass's stencil mark.
TEST(PassPlan, TheStencilIsMarkedOnlyForTheHull) {
  EXPECT_TRUE(plan_passes(params(json::object()), {}).stencil_mark);
  EXPECT_TRUE(plan_passes(params({{"outline", {{"method", {"hull", "edges"}}}}}), {}).stencil_mark);
  EXPECT_FALSE(plan_passes(params({{"outline", {{"enabled", false}}}}), {}).stencil_mark);
  EXPECT_FALSE(plan_passes(params({{"outline", {{"method", "edges"}}}}), {}).stencil_mark);
  EXPECT_FALSE(plan_passes(params({{"outline", {{"method", "wireframe"}}}}), {}).stencil_mark);
  EXPECT_FALSE(plan_passes(params({{"output", "depth"}}), {}).stencil_mark);
}

}  // namespace
}  // namespace toond::render
