#pragma once
// The pass plan: which passes run and which shader features they need, as a
// pure function of (parameters, model). Nothing is drawn that would not change
// the image: no outline pass at width 0 or when disabled, no texture sampling
// for a model without textures, no resolve without MSAA. Unit-tested without GL.
#include <string>
#include <vector>

#include "render/plan/render_params.h"
#include "render/plan/shader_variant.h"

namespace toond::render {

enum class Pass {
  Shadow,         // depth from the shadow-casting light
  Main,           // cel/phong/flat shading of the model; marks the stencil for the hull
  Floor,          // the ground plane (no stencil mark: it gets no outline)
  HullOutline,    // inverted hull outside the stencil mark
  Wireframe,      // back-face edges widened into lines
  Creases,        // crease lines along the model's crease edges (scene/mesh/crease_edges.h)
  EdgePrepass,    // normals and eye distances for the edge pass
  Edges,          // screen-space depth/normal discontinuities (or creases only)
  Layer,          // a data layer (depth, normal or id) in place of the colour
  Resolve,        // multisample resolve
  Downsample,     // supersampled image averaged to the output size, on the GPU
  Readback,       // pixels back to the CPU
  Unpremultiply,  // the lines layer's colour divided by its alpha (on the CPU, without supersampling)
};
const char* pass_name(Pass pass);

// What the plan needs to know about a model.
struct ModelTraits {
  bool has_textures = false;
  bool has_normal_maps = false;
  bool has_vertex_colors = false;
  bool hard_edged = false;        // creased at the requested crease angle (scene::CreaseProfile)
  bool has_crease_edges = false;  // some edge turns by more than the crease angle (scene::CreaseEdges)
  // Some segment where parts cross turns by more than the crease angle
  // (scene/mesh/intersection_lines.h).
  bool has_intersection_lines = false;
  // Parts may cross where import did not look (render/plan/intersections_known.h).
  bool intersections_unknown = false;
  // Some material's alpha cuts it out or lets what is behind show
  // (render/plan/drawn_materials.h): the passes that follow the surface test it.
  bool has_masked_materials = false;
  // Some material gets the highlight (specular.source, scene::Material::matte).
  bool has_specular_materials = true;
};

// What an id layer numbers.
enum class IdSource { Object, Material };

struct PassPlan {
  std::vector<Pass> passes;
  // Output::Lines runs the colour passes, but the main pass writes only
  // the contour (premultiplied, over transparent), the floor only depth,
  // and the outline passes blend over that. The data layers run the Layer
  // pass alone.
  Output output = Output::Color;
  LayerVariant layer;
  IdSource ids_by = IdSource::Material;
  // The features every main-pass program of this render shares (a material
  // may add its own).
  ToonVariant shading;
  // Where the hull's and the wireframe's colour comes from.
  OutlineVariant outline;
  DownsampleVariant downsample;
  bool sample_textures = false;
  bool use_normal_maps = false;  // per material: NORMAL_MAP where it has one
  bool floor_textured = false;   // the floor pass samples floor.texture
  int samples = 1;
  int supersample = 1;
  int shadow_light = -1;  // index into RenderParams::lights, -1: no shadows
  // Outlines follow what the main pass drew of masked materials: the hull,
  // the wireframe and the edge prepass test the same alpha.
  bool alpha_tested_outlines = false;
  bool alpha_tested_shadows = false;  // the shadow pass tests it too
  // The edge pass draws crease lines only: it joins a hull or wireframe
  // outline (which draws the silhouette) on a hard-edged model where the
  // crease lines are found in screen space (see plan_passes).
  bool creases_only = false;
  // The main pass marks the samples it covers in the stencil: only for the
  // hull outline, which draws outside the mark (a stencil test costs
  // llvmpipe about 0.5 ms on the bunny at 512², MSAA 4).
  bool stencil_mark = false;

  bool has(Pass pass) const;
  // The passes as a comma-separated list, e.g. for the Server-Timing header.
  std::string describe() const;
};

PassPlan plan_passes(const RenderParams& params, const ModelTraits& model);

// Whether `output` is a data layer (depth, normal, id): drawn by the Layer
// pass, one sample a pixel, read back as floats.
bool is_data_layer(Output output);

// What an id layer numbers: the objects of a scene, or the materials of a
// lone model.
IdSource id_source(const RenderParams& params);

}  // namespace toond::render
