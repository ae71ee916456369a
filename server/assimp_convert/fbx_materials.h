#pragma once
// In FBX a texture connected to a material's DiffuseColor takes the
// colour's place (Maya, 3ds Max and Blender draw the texture as it is),
// while assimp keeps the colour beside the texture and its glTF writer
// multiplies the two: Blender's default 0.8 grey would darken every
// textured FBX by a fifth. This makes the colour white where a texture
// replaces it.
#include <assimp/scene.h>

namespace toond::assimp_convert {

// For a scene read from an FBX file; returns how many materials changed.
unsigned let_textures_replace_colours(aiScene& scene);

}  // namespace toond::assimp_convert
