#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "param_schema.h"
#include "pipeline/render_params_wire.h"
#include "render/plan/render_params.h"

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

// A light's space is the schema's to default, like every other field: in
// a sheet its lights turn with the camera (every direction lit alike),
// otherwise they stay with the model; a given space is kept either way.
TEST(ParamSchema, ALightsSpaceDefaultsToViewInASheetAndModelOtherwise) {
  const json light = {{"type", "directional"}};
  EXPECT_EQ(schema().validate_and_complete({{"lights", {light}}})["lights"][0]["space"], "model");
  EXPECT_EQ(schema().validate_and_complete(json::object())["lights"][0]["space"], "model");
  const json sheet = {{"frames", 4}};
  EXPECT_EQ(schema().validate_and_complete({{"lights", {light}}, {"sheet", sheet}})["lights"][0]["space"], "view");
  EXPECT_EQ(schema().validate_and_complete({{"sheet", sheet}})["lights"][0]["space"], "view")
      << "the default light too";
  json given = light;
  given["space"] = "model";
  EXPECT_EQ(schema().validate_and_complete({{"lights", {given}}, {"sheet", sheet}})["lights"][0]["space"], "model");
  // Every x-default-when names a field by pointer and gives a value its field accepts.
  EXPECT_NO_THROW(schema().validate(schema().validate_and_complete({{"sheet", sheet}})));
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
  EXPECT_EQ(error_path({{"materials", {{"Hat", {{"alpha", "glass"}}}}}}), "/materials/Hat/alpha");
  EXPECT_EQ(error_path({{"materials", {{"Hat", {{"alpha_cutoff", -0.1}}}}}}), "/materials/Hat/alpha_cutoff");
  EXPECT_EQ(error_path({{"materials", {{"Hat", {{"texture", ""}}}}}}), "/materials/Hat/texture");
  EXPECT_EQ(error_path({{"textures", {{"filter", "cubic"}}}}), "/textures/filter");
  EXPECT_EQ(error_path({{"specular", {{"source", "some"}}}}), "/specular/source");
  EXPECT_EQ(error_path({{"materials", {{"Hat", {{"alpha", "mask"}, {"alpha_cutoff", 0.3}}}}}}), "(accepted)");
}

// x-applies-when is read by the page alone, so nothing else would notice a
// condition naming a field that does not exist, a value the field cannot
// take, or a keyword the page does not evaluate (see the schema's $comment
// and client/web/applies.js).
const json* field_at_pointer(const json& root, const std::string& pointer) {
  const json* s = &root;
  std::size_t start = 1;
  while (start <= pointer.size()) {
    std::size_t slash = pointer.find('/', start);
    if (slash == std::string::npos) slash = pointer.size();
    const std::string seg = pointer.substr(start, slash - start);
    if (s->contains("properties") && (*s)["properties"].contains(seg))
      s = &(*s)["properties"][seg];
    else if (s->contains("items") && seg.find_first_not_of("0123456789") == std::string::npos)
      s = &(*s)["items"];
    else
      return nullptr;
    start = slash + 1;
  }
  return s;
}

void check_condition(const json& condition, const json& field, const std::string& where,
                     std::vector<std::string>& problems) {
  static const std::set<std::string> known = {"const",    "enum",     "not",        "anyOf",
                                              "allOf",    "type",     "properties", "contains",
                                              "minItems", "maxItems", "minLength",  "maxLength"};
  if (!condition.is_object()) {
    problems.push_back(where + ": not a schema");
    return;
  }
  for (const auto& [keyword, value] : condition.items()) {
    if (!known.contains(keyword)) problems.push_back(where + ": keyword " + keyword + " is not evaluated by the page");
  }
  // A value the field cannot take (a misspelt enum name) would hide a control for good.
  auto allowed = [&](const json& v) {
    if (!field.contains("enum")) return;
    const auto& e = field["enum"];
    if (std::find(e.begin(), e.end(), v) == e.end())
      problems.push_back(where + ": " + v.dump() + " is not in its enum");
  };
  if (condition.contains("const")) allowed(condition["const"]);
  if (condition.contains("enum"))
    for (const auto& v : condition["enum"]) allowed(v);
  for (const char* sub : {"anyOf", "allOf"}) {
    if (condition.contains(sub))
      for (const auto& s : condition[sub]) check_condition(s, field, where, problems);
  }
  if (condition.contains("not")) check_condition(condition["not"], field, where, problems);
  if (condition.contains("contains")) {
    const json* items = field.contains("items") ? &field["items"] : nullptr;
    // outline.method: a name or a list of names; its list form holds the items.
    if (!items && field.contains("oneOf")) {
      for (const auto& alt : field["oneOf"])
        if (alt.contains("items")) items = &alt["items"];
    }
    if (items)
      check_condition(condition["contains"], *items, where + " contains", problems);
    else
      problems.push_back(where + ": contains on a field without items");
  }
  if (condition.contains("properties")) {
    for (const auto& [key, sub] : condition["properties"].items()) {
      const json* child =
          field.contains("properties") && field["properties"].contains(key) ? &field["properties"][key] : nullptr;
      if (!child)
        problems.push_back(where + ": no property " + key);
      else
        check_condition(sub, *child, where + "/" + key, problems);
    }
  }
}

void check_applies_when(const json& root, const json& node, const std::string& pointer, int& count,
                        std::vector<std::string>& problems) {
  if (!node.is_object()) return;
  if (node.contains("properties")) {
    for (const auto& [name, sub] : node["properties"].items()) {
      const std::string here = pointer + "/" + name;
      if (sub.contains("x-applies-when")) {
        for (const auto& [key, condition] : sub["x-applies-when"].items()) {
          ++count;
          const json* field = key.starts_with("/")               ? field_at_pointer(root, key)
                              : node["properties"].contains(key) ? &node["properties"][key]
                                                                 : nullptr;
          if (!field)
            problems.push_back(here + ": names no field " + key);
          else
            check_condition(condition, *field, here + " when " + key, problems);
        }
      }
      check_applies_when(root, sub, here, count, problems);
    }
  }
  if (node.contains("items")) check_applies_when(root, node["items"], pointer + "/0", count, problems);
}

TEST(ParamSchema, AppliesWhenNamesRealFieldsAndValues) {
  const json& doc = schema().document();
  int count = 0;
  std::vector<std::string> problems;
  check_applies_when(doc, doc, "", count, problems);
  EXPECT_GT(count, 40) << "the conditions were not found";
  for (const auto& p : problems) ADD_FAILURE() << p;
}

TEST(ParamSchema, AppliesWhenIsIgnoredByValidation) {
  // Conditions hide controls; they never refuse a request. A directional
  // light with a position, or a disabled rim with a power, stays valid.
  EXPECT_EQ(error_path({{"lights", {{{"type", "directional"}, {"position", {1, 2, 3}}}}}}), "(accepted)");
  EXPECT_EQ(error_path({{"rim", {{"enabled", false}, {"power", 8}}}, {"shading", {{"mode", "flat"}}}}), "(accepted)");
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
  const auto p = pipeline::render_params_from_wire(schema().validate_and_complete(request));
  EXPECT_NEAR(p.background.r, 0.2140, 1e-3);  // sRGB 0.5 in linear light
  EXPECT_FLOAT_EQ(p.background.a, 1.0f);
  ASSERT_EQ(p.lights.size(), 1u);
  EXPECT_FLOAT_EQ(p.lights[0].color.r, 2.0f);
  EXPECT_EQ(p.mode, render::ShadingMode::Cel);
  EXPECT_EQ(p.rounding, render::Rounding::Ceil);
}

TEST(RenderParams, MaterialsTexturesAndTheHighlightsSourceAreRead) {
  json request = {{"materials",
                   {{"Hat", {{"alpha", "blend"}, {"alpha_cutoff", 0.25}, {"texture", "skins/a.png"}}},
                    {"Body", {{"alpha", "opaque"}}}}},
                  {"textures", {{"filter", "nearest"}}},
                  {"specular", {{"source", "all"}}}};
  const auto p = pipeline::render_params_from_wire(schema().validate_and_complete(request));
  ASSERT_EQ(p.materials.size(), 2u);
  EXPECT_EQ(p.materials.at("Hat").alpha, scene::AlphaMode::Blend);
  EXPECT_EQ(p.materials.at("Hat").alpha_cutoff, 0.25f);
  EXPECT_EQ(p.materials.at("Hat").texture, "skins/a.png");
  EXPECT_EQ(p.materials.at("Body").alpha, scene::AlphaMode::Opaque);
  EXPECT_FALSE(p.materials.at("Body").alpha_cutoff);
  EXPECT_EQ(p.texture_filter, render::TextureFilterChoice::Nearest);
  EXPECT_EQ(p.specular.source, render::SpecularSource::All);
  const auto defaults = pipeline::render_params_from_wire(schema().validate_and_complete(json::object()));
  EXPECT_TRUE(defaults.materials.empty());
  EXPECT_EQ(defaults.texture_filter, render::TextureFilterChoice::Auto);
  EXPECT_EQ(defaults.specular.source, render::SpecularSource::Material);
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
