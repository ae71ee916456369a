#include "render/plan/drawn_materials.h"

#include <algorithm>

namespace toond::render {
namespace {

const scene::Texture* colour_texture(const scene::Model& model, const DrawnMaterial& drawn) {
  if (drawn.image) return drawn.image.get();
  if (drawn.texture < 0 || static_cast<std::size_t>(drawn.texture) >= model.textures.size()) return nullptr;
  return &model.textures[static_cast<std::size_t>(drawn.texture)];
}

bool nearest_magnification(const scene::Material& material, const scene::Texture* texture, TextureFilterChoice choice) {
  if (choice != TextureFilterChoice::Auto) return choice == TextureFilterChoice::Nearest;
  if (material.sampler.magnification != scene::TextureFilter::Unspecified) {
    return material.sampler.magnification == scene::TextureFilter::Nearest;
  }
  return texture != nullptr && std::max(texture->width, texture->height) <= kPixelArtTexels;
}

bool nearest_minification(const scene::Material& material, TextureFilterChoice choice) {
  if (choice != TextureFilterChoice::Auto) return choice == TextureFilterChoice::Nearest;
  return material.sampler.minification == scene::TextureFilter::Nearest;
}

}  // namespace

float DrawnMaterial::tested_cutoff() const {
  if (cuts) return alpha_cutoff;
  if (blended) return 0.5f;
  return -1.0f;
}

std::vector<DrawnMaterial> drawn_materials(const scene::Model& model, const RenderParams& params) {
  std::vector<DrawnMaterial> drawn;
  drawn.reserve(model.materials.size());
  for (const scene::Material& m : model.materials) {
    const auto asked_it = params.materials.find(m.name);
    const MaterialParams* asked = asked_it == params.materials.end() ? nullptr : &asked_it->second;
    DrawnMaterial d;
    d.texture = m.diffuse_texture;
    if (asked && asked->image) {
      d.texture = -1;
      d.image = asked->image;
    }
    const scene::Texture* texture = colour_texture(model, d);
    d.alpha = asked && asked->alpha ? *asked->alpha : m.alpha_mode;
    d.alpha_cutoff = asked && asked->alpha_cutoff ? *asked->alpha_cutoff : m.alpha_cutoff;
    const float lowest = m.opacity * (texture ? static_cast<float>(texture->min_alpha) / 255.0f : 1.0f);
    d.cuts = d.alpha == scene::AlphaMode::Mask && lowest < d.alpha_cutoff;
    d.blended = d.alpha == scene::AlphaMode::Blend && lowest < 1.0f;
    d.specular = params.specular.source == SpecularSource::All || !m.matte;
    d.nearest_magnification = nearest_magnification(m, texture, params.texture_filter);
    d.nearest_minification = nearest_minification(m, params.texture_filter);
    d.wrap_s = m.sampler.wrap_s;
    d.wrap_t = m.sampler.wrap_t;
    drawn.push_back(std::move(d));
  }
  return drawn;
}

}  // namespace toond::render
