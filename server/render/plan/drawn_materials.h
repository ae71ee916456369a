#pragma once
// A model's materials as one frame draws them: the file's materials with
// the request's word on them (`materials.<name>`: alpha, cutoff, an image
// of the bundle; `specular.source`; `textures.filter`). Pure, no GL: the
// pass plan reads what they need (cut-outs, blending, textures) and the
// passes draw by them.
#include <memory>
#include <vector>

#include "render/plan/render_params.h"
#include "scene/mesh/model.h"

namespace toond::render {

struct DrawnMaterial {
  // The colour texture: one of the model's (an index into
  // scene::Model::textures), or the request's image in its place; neither:
  // none.
  int texture = -1;
  std::shared_ptr<const scene::Texture> image;
  scene::AlphaMode alpha = scene::AlphaMode::Opaque;
  float alpha_cutoff = 0.5f;
  // The alpha cuts something away: a mask under whose cutoff some texel
  // (times the opacity) falls. A mask that cuts nothing is drawn opaque.
  bool cuts = false;
  // The alpha lets something show through: blended (after the opaque
  // surfaces, over them). A blend whose alpha is 1 everywhere is drawn
  // opaque.
  bool blended = false;
  bool specular = true;  // the highlight is drawn on it
  bool nearest_magnification = false;
  bool nearest_minification = false;
  scene::TextureWrap wrap_s = scene::TextureWrap::Repeat;
  scene::TextureWrap wrap_t = scene::TextureWrap::Repeat;

  bool has_texture() const { return texture >= 0 || image != nullptr; }
  // Where the alpha is tested by the passes that follow the surface
  // (outlines, shadows, the edge prepass, data layers): a mask's cutoff, a
  // blend's half way; negative where nothing is cut.
  float tested_cutoff() const;
};

// Largest side, in texels, of a texture `textures.filter: auto` magnifies
// with nearest when the file names no filter: pixel art (Minetest's 64×32
// skins, Quake-era and voxel games' textures).
inline constexpr int kPixelArtTexels = 128;

// Each of `model`'s materials as `params` draw it, in the model's order.
std::vector<DrawnMaterial> drawn_materials(const scene::Model& model, const RenderParams& params);

}  // namespace toond::render
