// The schema owns the defaults. RenderParams is only ever built from a
// request the schema completed, but its members carry initial values too
// (tests and tools build parts of it by hand): each must be the schema's,
// so a value read from an empty request and one left at its initial value
// never disagree.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "param_schema.h"
#include "pipeline/render_params_wire.h"
#include "render/plan/render_params.h"

namespace toond::render {
namespace {

using json = nlohmann::json;

struct Mismatch {
  std::vector<std::string> fields;
  template <typename T>
  void check(const char* name, const T& from_schema, const T& initial) {
    if (!(from_schema == initial)) fields.emplace_back(name);
  }
};

TEST(RenderParamsDefaults, EveryInitialValueIsTheSchemasDefault) {
  const RenderParams schema = pipeline::render_params_from_wire(
      proto::ParamSchema::render_params().validate_and_complete(nlohmann::json::object()));
  const RenderParams initial;
  Mismatch m;
  m.check("width", schema.width, initial.width);
  m.check("height", schema.height, initial.height);
  m.check("background", schema.background, initial.background);
  m.check("camera.projection", schema.camera.projection, initial.camera.projection);
  m.check("camera.yaw", schema.camera.yaw_deg, initial.camera.yaw_deg);
  m.check("camera.pitch", schema.camera.pitch_deg, initial.camera.pitch_deg);
  m.check("camera.fov", schema.camera.fov_deg, initial.camera.fov_deg);
  m.check("camera.distance", schema.camera.distance, initial.camera.distance);
  m.check("camera.zoom", schema.camera.zoom, initial.camera.zoom);
  m.check("camera.shift", schema.camera.shift, initial.camera.shift);
  ASSERT_EQ(schema.lights.size(), 1u);
  const Light light;
  m.check("lights[0].type", schema.lights[0].kind, light.kind);
  m.check("lights[0].radius", schema.lights[0].radius, light.radius);
  m.check("lights[0].color", schema.lights[0].color, light.color);
  m.check("light_combine", schema.light_combine, initial.light_combine);
  m.check("ambient", schema.ambient, initial.ambient);
  m.check("shading.mode", schema.mode, initial.mode);
  m.check("shading.base", schema.base, initial.base);
  m.check("shading.steps", schema.steps, initial.steps);
  m.check("shading.rounding", schema.rounding, initial.rounding);
  m.check("shading.band_aa", schema.band_aa, initial.band_aa);
  m.check("shading.two_tone.enabled", schema.two_tone.enabled, initial.two_tone.enabled);
  m.check("shading.two_tone.threshold", schema.two_tone.threshold, initial.two_tone.threshold);
  m.check("shading.two_tone.shadow_factor", schema.two_tone.shadow_factor, initial.two_tone.shadow_factor);
  m.check("specular.enabled", schema.specular.enabled, initial.specular.enabled);
  m.check("specular.color", schema.specular.color, initial.specular.color);
  m.check("specular.shininess", schema.specular.shininess, initial.specular.shininess);
  m.check("specular.threshold", schema.specular.threshold, initial.specular.threshold);
  m.check("specular.strength", schema.specular.strength, initial.specular.strength);
  m.check("specular.source", schema.specular.source, initial.specular.source);
  m.check("textures.filter", schema.texture_filter, initial.texture_filter);
  m.check("materials", schema.materials.size(), initial.materials.size());
  m.check("rim.enabled", schema.rim.enabled, initial.rim.enabled);
  m.check("rim.color", schema.rim.color, initial.rim.color);
  m.check("rim.power", schema.rim.power, initial.rim.power);
  m.check("rim.strength", schema.rim.strength, initial.rim.strength);
  m.check("rim.threshold", schema.rim.threshold, initial.rim.threshold);
  m.check("rim.mask", schema.rim.mask, initial.rim.mask);
  m.check("halftone.enabled", schema.halftone.enabled, initial.halftone.enabled);
  m.check("halftone.style", schema.halftone.style, initial.halftone.style);
  m.check("halftone.cell", schema.halftone.cell_px, initial.halftone.cell_px);
  m.check("halftone.angle", schema.halftone.angle_deg, initial.halftone.angle_deg);
  m.check("halftone.ink", schema.halftone.ink, initial.halftone.ink);
  m.check("halftone.ink_mix", schema.halftone.ink_mix, initial.halftone.ink_mix);
  m.check("contour.enabled", schema.contour.enabled, initial.contour.enabled);
  m.check("contour.style", schema.contour.style, initial.contour.style);
  m.check("contour.width", schema.contour.width_px, initial.contour.width_px);
  m.check("contour.threshold", schema.contour.threshold, initial.contour.threshold);
  m.check("contour.color", schema.contour.color, initial.contour.color);
  m.check("shadows.enabled", schema.shadows.enabled, initial.shadows.enabled);
  m.check("shadows.map_size", schema.shadows.map_size, initial.shadows.map_size);
  m.check("shadows.pcf", schema.shadows.pcf, initial.shadows.pcf);
  m.check("shadows.bias", schema.shadows.bias_texels, initial.shadows.bias_texels);
  m.check("floor.enabled", schema.floor.enabled, initial.floor.enabled);
  m.check("floor.color", schema.floor.color, initial.floor.color);
  m.check("floor.size", schema.floor.size, initial.floor.size);
  m.check("floor.texture", schema.floor.texture, initial.floor.texture);
  m.check("floor.texture_repeat", schema.floor.texture_repeat, initial.floor.texture_repeat);
  m.check("outline.enabled", schema.outline.enabled, initial.outline.enabled);
  m.check("outline.method (hull)", schema.outline.hull, initial.outline.hull);
  m.check("outline.method (wireframe)", schema.outline.wireframe, initial.outline.wireframe);
  m.check("outline.method (edges)", schema.outline.edges, initial.outline.edges);
  m.check("outline.width", schema.outline.width, initial.outline.width);
  m.check("outline.units", schema.outline.units, initial.outline.units);
  m.check("outline.color", schema.outline.color, initial.outline.color);
  m.check("outline.color_mode", schema.outline.color_mode, initial.outline.color_mode);
  m.check("outline.darken", schema.outline.darken, initial.outline.darken);
  m.check("outline.creases", schema.outline.creases, initial.outline.creases);
  m.check("outline.crease_angle", schema.outline.crease_angle_deg, initial.outline.crease_angle_deg);
  m.check("outline.depth_threshold", schema.outline.depth_threshold, initial.outline.depth_threshold);
  m.check("msaa", schema.msaa, initial.msaa);
  m.check("supersample", schema.supersample, initial.supersample);
  m.check("lod", schema.lod_auto, initial.lod_auto);
  m.check("lod_error_px", schema.lod_error_px, initial.lod_error_px);
  m.check("png_compression", schema.png_compression, initial.png_compression);
  std::string list;
  for (const std::string& f : m.fields) list += " " + f;
  EXPECT_TRUE(m.fields.empty()) << "initial values that are not the schema's default:" << list;
}

// A sheet's clip entry has its defaults in either of its forms (one entry,
// or a list of them: the schema's two alternatives), and `animation` in its
// one.
TEST(RenderParamsDefaults, AClipEntrysInitialValuesAreTheSchemasDefaults) {
  const SheetClip initial_clip;
  const json entry = {{"clip", "Walk"}};
  for (const json& animation : {entry, json::array({entry, entry})}) {
    const RenderParams schema = pipeline::render_params_from_wire(
        proto::ParamSchema::render_params().validate_and_complete({{"sheet", {{"animation", animation}}}}));
    ASSERT_TRUE(schema.sheet) << animation;
    ASSERT_FALSE(schema.sheet->clips.empty()) << animation;
    for (const SheetClip& clip : schema.sheet->clips) {
      EXPECT_EQ(clip.loop, initial_clip.loop) << "sheet.animation.loop in " << animation;
      EXPECT_EQ(clip.range.has_value(), initial_clip.range.has_value()) << "sheet.animation.range in " << animation;
    }
  }
  const RenderParams sheet = pipeline::render_params_from_wire(
      proto::ParamSchema::render_params().validate_and_complete({{"sheet", json::object()}}));
  ASSERT_TRUE(sheet.sheet);
  const SheetParams initial_sheet;
  EXPECT_EQ(sheet.sheet->pack, initial_sheet.pack) << "sheet.pack";
  EXPECT_EQ(sheet.sheet->power_of_two, initial_sheet.power_of_two) << "sheet.power_of_two";
  const RenderParams schema = pipeline::render_params_from_wire(
      proto::ParamSchema::render_params().validate_and_complete({{"animation", entry}}));
  ASSERT_TRUE(schema.animation);
  const AnimationParams initial;
  EXPECT_EQ(schema.animation->time, initial.time) << "animation.time";
  EXPECT_EQ(schema.animation->range.has_value(), initial.range.has_value()) << "animation.range";
}

}  // namespace
}  // namespace toond::render
