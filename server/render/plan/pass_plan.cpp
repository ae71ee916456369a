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

// What the colour passes' conditions read: the request, the model and
// what is decided before any pass is.
struct PassFacts {
  const RenderParams& params;
  const ModelTraits& model;
  // The vector drawing (render/vector/line_drawing.h) draws what the lines
  // layer would: it is planned as one, though nothing of it is rasterised.
  bool lines_only = false;
  int shadow_light = -1;
  // Crease lines join a hull or wireframe outline on a model (or by
  // request) that wants them.
  bool crease_lines = false;
  // Crease lines are drawn along the crease edges, at their cost, not the
  // pixels'. Where what decides a line is what the pixels show, the edge
  // pass finds them in screen space instead: sprite lines (only between
  // areas wide enough to read, in whole pixels) and masked materials (the
  // edges know nothing of the parts cut out), and a frame where parts may
  // cross where import did not find them (a posed model, a search that gave
  // up, objects that overlap).
  bool creases_in_screen_space = false;
};

// Shadows need a light that casts them (the first directional one) and a
// lit shading mode to darken; the lines layer shows no shading.
int shadow_light_of(const RenderParams& params, bool lines_only) {
  if (!params.shadows.enabled || params.mode == ShadingMode::Flat || lines_only) return -1;
  for (std::size_t i = 0; i < params.lights.size(); ++i) {
    if (params.lights[i].kind == LightKind::Directional) return static_cast<int>(i);
  }
  return -1;
}

PassFacts facts_of(const RenderParams& params, const ModelTraits& model) {
  PassFacts facts{.params = params, .model = model};
  facts.lines_only = params.output == Output::Lines || params.output == Output::Svg;
  facts.shadow_light = shadow_light_of(params, facts.lines_only);
  const OutlineParams& outline = params.outline;
  const bool creases_wanted =
      outline.creases == OutlineCreases::Always || (outline.creases == OutlineCreases::Auto && model.hard_edged);
  facts.crease_lines = outline.any() && !outline.edges && (outline.hull || outline.wireframe) && creases_wanted;
  facts.creases_in_screen_space =
      outline.screen_space_creases || model.has_masked_materials || model.intersections_unknown;
  return facts;
}

// The edge pass draws crease lines only (PassPlan::creases_only).
bool creases_only(const PassFacts& f) { return f.crease_lines && f.creases_in_screen_space; }

bool casts_shadow(const PassFacts& f) { return f.shadow_light >= 0; }
bool always(const PassFacts&) { return true; }
bool floor_shown(const PassFacts& f) { return f.params.floor.enabled; }
bool hull_outline(const PassFacts& f) { return f.params.outline.any() && f.params.outline.hull; }
bool wireframe_outline(const PassFacts& f) { return f.params.outline.any() && f.params.outline.wireframe; }
// A model with no edge and no crossing of parts turning that far has no
// crease line to draw.
bool creases_along_edges(const PassFacts& f) {
  return f.crease_lines && !f.creases_in_screen_space && (f.model.has_crease_edges || f.model.has_intersection_lines);
}
bool edges_in_screen_space(const PassFacts& f) {
  return (f.params.outline.any() && f.params.outline.edges) || creases_only(f);
}
bool multisampled(const PassFacts& f) { return f.params.msaa > 1; }
// The downsample divides the lines layer's premultiplied colour by its
// alpha itself; without one, a CPU step after the readback does.
bool supersampled(const PassFacts& f) { return f.params.supersample > 1; }
bool unpremultiplied_on_cpu(const PassFacts& f) { return f.lines_only && f.params.supersample == 1; }

// The colour render's passes in drawing order, each with when it runs.
struct PassRow {
  Pass pass;
  bool (*runs)(const PassFacts&);
};
constexpr PassRow kColourPasses[] = {
    {Pass::Shadow, casts_shadow},
    {Pass::Main, always},
    {Pass::Floor, floor_shown},
    {Pass::HullOutline, hull_outline},
    {Pass::Wireframe, wireframe_outline},
    {Pass::Creases, creases_along_edges},
    {Pass::EdgePrepass, edges_in_screen_space},
    {Pass::Edges, edges_in_screen_space},
    {Pass::Resolve, multisampled},
    {Pass::Downsample, supersampled},
    {Pass::Readback, always},
    {Pass::Unpremultiply, unpremultiplied_on_cpu},
};

void set_shading_mode(ToonVariant& shading, const RenderParams& params) {
  // Without a light every point sits in the same band: no edge to smooth.
  const bool band_edges_to_smooth = params.band_aa && !params.lights.empty();
  switch (params.mode) {
    case ShadingMode::Cel:
      shading.set(ToonFeature::ModeCel);
      if (!params.ramp.empty()) {
        shading.set(ToonFeature::Ramp);
        shading.ramp_count = static_cast<int>(params.ramp.size());
      } else if (params.two_tone.enabled) {
        shading.set(ToonFeature::TwoTone);
        shading.set(ToonFeature::BandAa, band_edges_to_smooth);
      } else {
        shading.set(ToonFeature::BandAa, band_edges_to_smooth);
        // Rounding only matters when N·L is quantized into equal bands.
        shading.set(params.rounding == Rounding::Floor   ? ToonFeature::RoundFloor
                    : params.rounding == Rounding::Round ? ToonFeature::RoundRound
                                                         : ToonFeature::RoundCeil);
      }
      break;
    case ShadingMode::Phong:
      shading.set(ToonFeature::ModePhong);
      break;
    case ShadingMode::Flat:
      shading.set(ToonFeature::ModeFlat);
      break;
  }
  // Lit modes loop over the lights with a compile-time bound (see toon.frag).
  if (params.mode != ShadingMode::Flat) shading.light_count = static_cast<int>(params.lights.size());
}

void plan_shadow(PassPlan& plan, const PassFacts& facts) {
  plan.shadow_light = facts.shadow_light;
  if (!casts_shadow(facts)) return;
  plan.alpha_tested_shadows = facts.model.has_masked_materials;
  plan.shading.set(ToonFeature::Shadows);
  plan.shading.shadow_pcf = facts.params.shadows.pcf;
}

void plan_surface_inputs(PassPlan& plan, const RenderParams& params, const ModelTraits& model) {
  // A white base ignores the material, so its textures are never read.
  plan.sample_textures = model.has_textures && params.base == BaseColor::Material;
  plan.floor_textured = params.floor.enabled && !params.floor.texture.empty() && params.base == BaseColor::Material;
  plan.shading.set(ToonFeature::BaseWhite, params.base == BaseColor::White);
  plan.shading.set(ToonFeature::VertexColor, params.base == BaseColor::Material && model.has_vertex_colors);
  // Normal maps only bend the lighting: unlit colour never reads them.
  plan.use_normal_maps = model.has_normal_maps && params.mode != ShadingMode::Flat;
}

// Lighting effects change nothing on unlit (flat) colour or without lights.
void plan_light_effects(ToonVariant& shading, const RenderParams& params, const ModelTraits& model) {
  if (params.mode == ShadingMode::Flat) return;
  if (!params.lights.empty()) {
    shading.set(ToonFeature::CombineSum, params.light_combine == LightCombine::Sum && params.lights.size() > 1);
    const bool any_point = std::any_of(params.lights.begin(), params.lights.end(),
                                       [](const Light& l) { return l.kind == LightKind::Point; });
    shading.set(ToonFeature::HasPointLights, any_point);
    shading.set(ToonFeature::Specular,
                params.specular.enabled && params.specular.strength > 0.0f && model.has_specular_materials);
  }
  if (params.rim.enabled && params.rim.strength > 0.0f) {
    shading.set(ToonFeature::Rim);
    shading.set(ToonFeature::RimMaskLit, params.rim.mask == RimMask::Lit);
    shading.set(ToonFeature::RimMaskShadow, params.rim.mask == RimMask::Shadow);
  }
  if (params.halftone.enabled) {
    shading.set(params.halftone.style == HalftoneStyle::Dots ? ToonFeature::HalftoneDots
                                                             : ToonFeature::HalftoneChecker);
  }
}

void plan_outline(PassPlan& plan, const PassFacts& facts) {
  const OutlineParams& outline = facts.params.outline;
  if (!outline.any()) return;
  plan.stencil_mark = outline.hull;
  plan.creases_only = creases_only(facts);
  plan.alpha_tested_outlines = facts.model.has_masked_materials;
  plan.outline.set(OutlineFeature::AlphaMask, plan.alpha_tested_outlines);
  switch (outline.color_mode) {
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

}  // namespace

PassPlan plan_passes(const RenderParams& params, const ModelTraits& model) {
  if (is_data_layer(params.output)) return plan_data_layer(params, model);
  const PassFacts facts = facts_of(params, model);
  PassPlan plan;
  plan.output = params.output;
  plan.samples = params.msaa;
  plan.supersample = params.supersample;
  for (const PassRow& row : kColourPasses) {
    if (row.runs(facts)) plan.passes.push_back(row.pass);
  }
  plan_shadow(plan, facts);
  set_shading_mode(plan.shading, params);
  plan_surface_inputs(plan, params, model);
  plan_light_effects(plan.shading, params, model);
  if (params.contour.enabled) {
    plan.shading.set(params.contour.style == ContourStyle::Even ? ToonFeature::ContourEven
                                                                : ToonFeature::ContourFresnel);
  }
  plan_outline(plan, facts);
  // The contour is the main pass's part of the lines; the shading it
  // would have drawn under them is left to the color render.
  plan.shading.set(ToonFeature::LinesOnly, facts.lines_only);
  plan.downsample.set(DownsampleFeature::Premultiplied, facts.lines_only);
  return plan;
}

}  // namespace toond::render
