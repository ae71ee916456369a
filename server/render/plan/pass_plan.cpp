#include "render/plan/pass_plan.h"

#include <algorithm>

namespace toond::render {

const char* pass_name(Pass pass) {
  switch (pass) {
    case Pass::Shadow:
      return "shadow";
    case Pass::Main:
      return "main";
    case Pass::Floor:
      return "floor";
    case Pass::HullOutline:
      return "hull_outline";
    case Pass::Wireframe:
      return "wireframe";
    case Pass::Creases:
      return "creases";
    case Pass::EdgePrepass:
      return "edge_prepass";
    case Pass::Edges:
      return "edges";
    case Pass::Layer:
      return "layer";
    case Pass::Resolve:
      return "resolve";
    case Pass::Readback:
      return "readback";
    case Pass::Unpremultiply:
      return "unpremultiply";
    case Pass::Downsample:
      return "downsample";
  }
  return "?";
}

bool PassPlan::has(Pass pass) const { return std::find(passes.begin(), passes.end(), pass) != passes.end(); }

std::string PassPlan::describe() const {
  std::string out;
  for (Pass p : passes) {
    if (!out.empty()) out += ",";
    out += pass_name(p);
    if (p == Pass::Edges && creases_only) out += "(creases)";
  }
  return out;
}

bool is_data_layer(Output output) {
  return output == Output::Depth || output == Output::Normal || output == Output::Id;
}

IdSource id_source(const RenderParams& params) {
  return params.objects.empty() ? IdSource::Material : IdSource::Object;
}

namespace {

// A depth, normal or id layer: no shading, no outline, no floor, one
// sample a pixel (a depth or an id averaged across an edge would be a
// value no surface has).
PassPlan plan_data_layer(const RenderParams& params, const ModelTraits& model) {
  PassPlan plan;
  plan.output = params.output;
  plan.passes = {Pass::Layer, Pass::Readback};
  plan.layer.set(params.output == Output::Depth    ? LayerFeature::Depth
                 : params.output == Output::Normal ? LayerFeature::Normal
                                                   : LayerFeature::Id);
  plan.layer.set(LayerFeature::AlphaMask, model.has_masked_materials);
  plan.ids_by = id_source(params);
  return plan;
}

}  // namespace

PassPlan plan_passes(const RenderParams& params, const ModelTraits& model) {
  if (is_data_layer(params.output)) return plan_data_layer(params, model);
  PassPlan plan;
  plan.output = params.output;
  // The vector drawing (render/vector/line_drawing.h) draws what the lines
  // layer would: it is planned as one, though nothing of it is rasterised.
  const bool lines_only = params.output == Output::Lines || params.output == Output::Svg;
  plan.samples = params.msaa;
  // Shadows need a light that casts them (the first directional one) and a
  // lit shading mode to darken; the lines layer shows no shading.
  if (params.shadows.enabled && params.mode != ShadingMode::Flat && !lines_only) {
    for (std::size_t i = 0; i < params.lights.size(); ++i) {
      if (params.lights[i].kind == LightKind::Directional) {
        plan.shadow_light = static_cast<int>(i);
        break;
      }
    }
  }
  if (plan.shadow_light >= 0) {
    plan.passes.push_back(Pass::Shadow);
    plan.alpha_tested_shadows = model.has_masked_materials;
    plan.shading.set(ToonFeature::Shadows);
    plan.shading.shadow_pcf = params.shadows.pcf;
  }
  plan.passes.push_back(Pass::Main);
  if (params.floor.enabled) plan.passes.push_back(Pass::Floor);

  // Without a light every point sits in the same band: no edge to smooth.
  const bool band_edges_to_smooth = params.band_aa && !params.lights.empty();
  switch (params.mode) {
    case ShadingMode::Cel:
      plan.shading.set(ToonFeature::ModeCel);
      if (!params.ramp.empty()) {
        plan.shading.set(ToonFeature::Ramp);
        plan.shading.ramp_count = static_cast<int>(params.ramp.size());
      } else if (params.two_tone.enabled) {
        plan.shading.set(ToonFeature::TwoTone);
        plan.shading.set(ToonFeature::BandAa, band_edges_to_smooth);
      } else {
        plan.shading.set(ToonFeature::BandAa, band_edges_to_smooth);
        // Rounding only matters when N·L is quantized into equal bands.
        plan.shading.set(params.rounding == Rounding::Floor   ? ToonFeature::RoundFloor
                         : params.rounding == Rounding::Round ? ToonFeature::RoundRound
                                                              : ToonFeature::RoundCeil);
      }
      break;
    case ShadingMode::Phong:
      plan.shading.set(ToonFeature::ModePhong);
      break;
    case ShadingMode::Flat:
      plan.shading.set(ToonFeature::ModeFlat);
      break;
  }
  // Lit modes loop over the lights with a compile-time bound (see toon.frag).
  if (params.mode != ShadingMode::Flat) {
    plan.shading.light_count = static_cast<int>(params.lights.size());
  }
  // A white base ignores the material, so its textures are never read.
  plan.sample_textures = model.has_textures && params.base == BaseColor::Material;
  plan.floor_textured = plan.has(Pass::Floor) && !params.floor.texture.empty() && params.base == BaseColor::Material;
  plan.shading.set(ToonFeature::BaseWhite, params.base == BaseColor::White);
  plan.shading.set(ToonFeature::VertexColor, params.base == BaseColor::Material && model.has_vertex_colors);
  // Normal maps only bend the lighting: unlit colour never reads them.
  plan.use_normal_maps = model.has_normal_maps && params.mode != ShadingMode::Flat;

  // Lighting effects change nothing on unlit (flat) colour or without lights.
  const bool lit = params.mode != ShadingMode::Flat && !params.lights.empty();
  if (lit) {
    plan.shading.set(ToonFeature::CombineSum, params.light_combine == LightCombine::Sum && params.lights.size() > 1);
    const bool any_point = std::any_of(params.lights.begin(), params.lights.end(),
                                       [](const Light& l) { return l.kind == LightKind::Point; });
    plan.shading.set(ToonFeature::HasPointLights, any_point);
    plan.shading.set(ToonFeature::Specular,
                     params.specular.enabled && params.specular.strength > 0.0f && model.has_specular_materials);
  }
  if (params.mode != ShadingMode::Flat && params.rim.enabled && params.rim.strength > 0.0f) {
    plan.shading.set(ToonFeature::Rim);
    plan.shading.set(ToonFeature::RimMaskLit, params.rim.mask == RimMask::Lit);
    plan.shading.set(ToonFeature::RimMaskShadow, params.rim.mask == RimMask::Shadow);
  }
  if (params.halftone.enabled && params.mode != ShadingMode::Flat) {
    plan.shading.set(params.halftone.style == HalftoneStyle::Dots ? ToonFeature::HalftoneDots
                                                                  : ToonFeature::HalftoneChecker);
  }
  if (params.contour.enabled) {
    plan.shading.set(params.contour.style == ContourStyle::Even ? ToonFeature::ContourEven
                                                                : ToonFeature::ContourFresnel);
  }

  if (params.outline.any()) {
    if (params.outline.hull) plan.passes.push_back(Pass::HullOutline);
    plan.stencil_mark = params.outline.hull;
    if (params.outline.wireframe) plan.passes.push_back(Pass::Wireframe);
    const bool silhouette_drawn = params.outline.hull || params.outline.wireframe;
    const bool creases_wanted = params.outline.creases == OutlineCreases::Always ||
                                (params.outline.creases == OutlineCreases::Auto && model.hard_edged);
    const bool crease_lines = !params.outline.edges && silhouette_drawn && creases_wanted;
    // Crease lines are drawn along the crease edges, at their cost, not the
    // pixels'. Where what decides a line is what the pixels show, the edge
    // pass finds them in screen space instead: sprite lines (only between
    // areas wide enough to read, in whole pixels) and masked materials
    // (the edges know nothing of the parts cut out), and a frame where parts
    // may cross where import did not find them (a posed model, a search
    // that gave up, objects that overlap). A model with no edge and no
    // crossing of parts turning that far has no crease line to draw.
    const bool in_screen_space =
        params.outline.screen_space_creases || model.has_masked_materials || model.intersections_unknown;
    plan.creases_only = crease_lines && in_screen_space;
    const bool lines_to_draw = model.has_crease_edges || model.has_intersection_lines;
    if (crease_lines && !in_screen_space && lines_to_draw) plan.passes.push_back(Pass::Creases);
    if (params.outline.edges || plan.creases_only) {
      plan.passes.push_back(Pass::EdgePrepass);
      plan.passes.push_back(Pass::Edges);
    }
    plan.alpha_tested_outlines = model.has_masked_materials;
    plan.outline.set(OutlineFeature::AlphaMask, plan.alpha_tested_outlines);
    switch (params.outline.color_mode) {
      case OutlineColorMode::Fixed:
        break;
      case OutlineColorMode::Material:
        plan.outline.set(OutlineFeature::Material);
        break;
      case OutlineColorMode::Texture:
        // Without textures the texture mode falls back to the material colour.
        plan.outline.set(plan.sample_textures ? OutlineFeature::Texture : OutlineFeature::Material);
        break;
    }
  }
  // The contour is the main pass's part of the lines; the shading it
  // would have drawn under them is left to the color render.
  plan.shading.set(ToonFeature::LinesOnly, lines_only);
  if (plan.samples > 1) plan.passes.push_back(Pass::Resolve);
  plan.supersample = params.supersample;
  // The downsample divides the lines layer's premultiplied colour by its
  // alpha itself; without one, a CPU step after the readback does.
  if (plan.supersample > 1) plan.passes.push_back(Pass::Downsample);
  plan.downsample.set(DownsampleFeature::Premultiplied, lines_only);
  plan.passes.push_back(Pass::Readback);
  if (lines_only && plan.supersample == 1) plan.passes.push_back(Pass::Unpremultiply);
  return plan;
}

}  // namespace toond::render
