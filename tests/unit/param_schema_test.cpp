#include <gtest/gtest.h>

#include "http/render_params_wire.h"
#include "param_schema.h"
#include "render/render_params.h"

namespace toond::proto {
namespace {

using nlohmann::json;

const ParamSchema& schema() { return ParamSchema::render_params(); }

std::string error_path(const json& request) {
  try {
    schema().validate(request);
  } catch (const RequestError& e) {
    return e.path();
  }
  return "(accepted)";
}

TEST(ParamSchema, EmptyRequestGetsEveryDefault) {
  const json p = schema().validate_and_complete(json::object());
  EXPECT_EQ(p["width"], 512);
  EXPECT_EQ(p["height"], 512);
  EXPECT_EQ(p["shading"]["steps"], 3);
  EXPECT_EQ(p["shading"]["rounding"], "ceil");
  EXPECT_EQ(p["outline"]["enabled"], true);
  ASSERT_EQ(p["lights"].size(), 1u);
  EXPECT_EQ(p["lights"][0]["intensity"], 1) << "defaults reach into array elements";
  EXPECT_FALSE(p.contains("model")) << "no default model: absent means the demo";
}

TEST(ParamSchema, DefaultsNeverOverrideGivenValues) {
  const json p = schema().validate_and_complete({{"outline", {{"width", 7}}}, {"lights", json::array()}});
  EXPECT_EQ(p["outline"]["width"], 7);
  EXPECT_EQ(p["outline"]["enabled"], true);
  EXPECT_TRUE(p["lights"].empty()) << "an explicit empty light list stays empty";
}

TEST(ParamSchema, EveryDefaultInTheSchemaValidates) {
  // The completed default request must itself pass validation: a default
  // outside its own range would be a schema bug.
  EXPECT_NO_THROW(schema().validate(schema().validate_and_complete(json::object())));
}

TEST(ParamSchema, ErrorPathsPointAtTheField) {
  EXPECT_EQ(error_path({{"nope", 1}}), "/nope");
  EXPECT_EQ(error_path({{"camera", {{"zoom", 0}}}}), "/camera/zoom");
  EXPECT_EQ(error_path({{"camera", {{"pitch", 90}}}}), "/camera/pitch");
  EXPECT_EQ(error_path({{"width", 8}}), "/width");
  EXPECT_EQ(error_path({{"width", 100.5}}), "/width");
  EXPECT_EQ(error_path({{"lights", {{{"type", "spot"}}}}}), "/lights/0/type");
  EXPECT_EQ(error_path({{"lights", {{{"direction", {0, 0, -1}}}}}}), "/lights/0") << "type is required";
  EXPECT_EQ(error_path({{"outline", {{"color", {0, 0}}}}}), "/outline/color");
  EXPECT_EQ(error_path({{"msaa", 4}}), "(accepted)");
}

TEST(ParamSchema, UnknownFieldErrorCode) {
  try {
    schema().validate({{"shading", {{"bands", 3}}}});
    FAIL() << "accepted an unknown field";
  } catch (const RequestError& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(e.code(), "unknown_parameter");
  }
}

TEST(ParamSchema, JsonPointerEscapes) {
  EXPECT_EQ(json_pointer({"a/b", "c~d"}), "/a~1b/c~0d");
  EXPECT_EQ(json_pointer({}), "");
}

TEST(ParamSchema, SetFromTextConvertsToTheSchemaType) {
  json p = json::object();
  schema().set_from_text(p, "outline.width", "3.5");
  schema().set_from_text(p, "shading.steps", "4");
  schema().set_from_text(p, "outline.enabled", "false");
  schema().set_from_text(p, "shading.mode", "phong");
  schema().set_from_text(p, "background", "[1,0,0]");
  schema().set_from_text(p, "lights.0.type", "directional");
  schema().set_from_text(p, "lights.0.direction", "[0,0,-1]");
  EXPECT_EQ(p["outline"]["width"], 3.5);
  EXPECT_EQ(p["shading"]["steps"], 4);
  EXPECT_TRUE(p["shading"]["steps"].is_number_integer());
  EXPECT_EQ(p["outline"]["enabled"], false);
  EXPECT_EQ(p["shading"]["mode"], "phong");
  EXPECT_EQ(p["background"], json({1, 0, 0}));
  EXPECT_EQ(p["lights"][0]["direction"], json({0, 0, -1}));
  EXPECT_NO_THROW(schema().validate(p));
}

TEST(ParamSchema, SetIntoAnAbsentArrayStartsFromItsDefault) {
  json p = json::object();
  schema().set_from_text(p, "lights.0.intensity", "2");
  ASSERT_EQ(p["lights"].size(), 1u);
  EXPECT_EQ(p["lights"][0]["type"], "directional") << "the default light, brighter";
  EXPECT_EQ(p["lights"][0]["intensity"], 2.0);
  EXPECT_NO_THROW(schema().validate(p));
}

TEST(ParamSchema, SetFromTextRejectsUnknownKeysAndBadText) {
  json p = json::object();
  EXPECT_THROW(schema().set_from_text(p, "outline.thickness", "3"), RequestError);
  EXPECT_THROW(schema().set_from_text(p, "shading.steps", "3.5"), RequestError);
  EXPECT_THROW(schema().set_from_text(p, "shading.steps", "three"), RequestError);
  EXPECT_THROW(schema().set_from_text(p, "outline.width", "wide"), RequestError);
  EXPECT_THROW(schema().set_from_text(p, "outline.enabled", "maybe"), RequestError);
  EXPECT_THROW(schema().set_from_text(p, "background", "[1,0"), RequestError);
  EXPECT_THROW(schema().set_from_text(p, "lights.x.type", "directional"), RequestError);
  EXPECT_THROW(schema().set_from_text(p, "lights.3.type", "directional"), RequestError)
      << "an index may not skip elements";
}

TEST(RenderParams, ColoursBecomeLinearAndLightsCarryIntensity) {
  json request = {{"background", {0.5, 0.5, 0.5}},
                  {"lights", {{{"type", "directional"}, {"color", {1, 1, 1}}, {"intensity", 2}}}}};
  const auto p = http::render_params_from_wire(schema().validate_and_complete(request));
  EXPECT_NEAR(p.background.r, 0.2140, 1e-3);  // sRGB 0.5 in linear light
  EXPECT_FLOAT_EQ(p.background.a, 1.0f);
  ASSERT_EQ(p.lights.size(), 1u);
  EXPECT_FLOAT_EQ(p.lights[0].color.r, 2.0f);
  EXPECT_EQ(p.mode, render::ShadingMode::Cel);
  EXPECT_EQ(p.rounding, render::Rounding::Ceil);
}

TEST(RenderParams, SrgbTransferIsMonotonicAndHitsTheEnds) {
  EXPECT_FLOAT_EQ(render::srgb_to_linear(0.0f), 0.0f);
  EXPECT_NEAR(render::srgb_to_linear(1.0f), 1.0f, 1e-6);
  float last = -1;
  for (int i = 0; i <= 255; ++i) {
    const float v = render::srgb_to_linear(static_cast<float>(i) / 255.0f);
    EXPECT_GT(v, last);
    last = v;
  }
}

}  // namespace
}  // namespace toond::proto
