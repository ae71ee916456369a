#include "assimp_convert/fbx_materials.h"

#include <assimp/material.h>

namespace toond::assimp_convert {

unsigned let_textures_replace_colours(aiScene& scene) {
  unsigned changed = 0;
  const aiColor4D white(1.0f, 1.0f, 1.0f, 1.0f);
  for (unsigned m = 0; m < scene.mNumMaterials; ++m) {
    aiMaterial& material = *scene.mMaterials[m];
    if (material.GetTextureCount(aiTextureType_DIFFUSE) == 0 && material.GetTextureCount(aiTextureType_BASE_COLOR) == 0) {
      continue;
    }
    // The colour's alpha is the material's opacity, which stays.
    aiColor4D colour(1.0f, 1.0f, 1.0f, 1.0f);
    material.Get(AI_MATKEY_COLOR_DIFFUSE, colour);
    const aiColor4D replaced(white.r, white.g, white.b, colour.a);
    material.AddProperty(&replaced, 1, AI_MATKEY_COLOR_DIFFUSE);
    material.AddProperty(&replaced, 1, AI_MATKEY_BASE_COLOR);
    ++changed;
  }
  return changed;
}

}  // namespace toond::assimp_convert
