#include "helpers/assimp_convert/format_materials.h"

#include <cmath>
#include <string>

#include <assimp/material.h>

namespace toond::assimp_convert {
namespace {

float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

bool has_colour_texture(const aiMaterial& material) {
  return material.GetTextureCount(aiTextureType_DIFFUSE) > 0 || material.GetTextureCount(aiTextureType_BASE_COLOR) > 0;
}

// Sets both keys the glTF writer may read the base colour from.
void set_base_colour(aiMaterial& material, const aiColor4D& colour) {
  material.AddProperty(&colour, 1, AI_MATKEY_COLOR_DIFFUSE);
  material.AddProperty(&colour, 1, AI_MATKEY_BASE_COLOR);
}

}  // namespace

void let_textures_replace_colours(aiScene& scene) {
  for (unsigned m = 0; m < scene.mNumMaterials; ++m) {
    aiMaterial& material = *scene.mMaterials[m];
    if (!has_colour_texture(material)) continue;
    // The colour's alpha is the material's opacity, which stays.
    aiColor4D colour(1.0f, 1.0f, 1.0f, 1.0f);
    material.Get(AI_MATKEY_COLOR_DIFFUSE, colour);
    set_base_colour(material, aiColor4D(1.0f, 1.0f, 1.0f, colour.a));
  }
}

void linearise_display_colours(aiScene& scene) {
  for (unsigned m = 0; m < scene.mNumMaterials; ++m) {
    aiMaterial& material = *scene.mMaterials[m];
    aiColor4D colour;
    if (material.Get(AI_MATKEY_COLOR_DIFFUSE, colour) != AI_SUCCESS) continue;
    set_base_colour(material,
                    aiColor4D(srgb_to_linear(colour.r), srgb_to_linear(colour.g), srgb_to_linear(colour.b), colour.a));
  }
}

void name_md3_materials_by_surface(aiScene& scene) {
  for (unsigned m = 0; m < scene.mNumMaterials; ++m) {
    aiMaterial& material = *scene.mMaterials[m];
    aiString name;
    if (material.Get(AI_MATKEY_NAME, name) != AI_SUCCESS) continue;
    const std::string text = name.C_Str();
    const std::size_t open = text.rfind('[');
    if (!text.starts_with("MD3_[") || open == std::string::npos || text.back() != ']' || open + 2 > text.size())
      continue;
    const aiString surface(text.substr(open + 1, text.size() - open - 2));
    material.RemoveProperty(AI_MATKEY_NAME);
    material.AddProperty(&surface, AI_MATKEY_NAME);
  }
}

}  // namespace toond::assimp_convert
